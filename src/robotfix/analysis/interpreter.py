"""Statements: the abstract interpreter over one module (cf. mypy's checker.py).

Module code runs first, top to bottom; then every function and method is analysed as
an entry point of its own, its parameters unknown unless refined (a parameter whose
annotation is a message class is a message that arrived: its refinements hold).
Loops and `try` are handled by havoc: what they may change becomes unknown, while
refined variables keep their refinement, which every assignment maintains.
"""

from __future__ import annotations

import ast
import builtins
from collections.abc import Callable
from dataclasses import replace

from robotfix import messages
from robotfix.analysis import heap, hover, imported
from robotfix.analysis.calls import CallEvaluator
from robotfix.analysis.constants import scan
from robotfix.analysis.context import FileContext, Scope, build_scope
from robotfix.analysis.index import index_module
from robotfix.analysis.program import Function, Program, collect
from robotfix.analysis.state import MAYBE, State, join
from robotfix.analysis.values import CONTAINERS, NONE, Uninit, Value
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Refinement
from robotfix.annotations.numbers import named_number
from robotfix.astwalk import walk
from robotfix.diagnostics import Span

BUILTINS = frozenset(dir(builtins)) | {"__file__", "__name__", "__doc__", "__spec__"}
# Python packages with a `msg`/`srv`/`action` module that is not an interface package.
CLIENT_LIBRARIES = frozenset(
    {"rclpy", "rospy", "actionlib", "tf", "tf2_ros", "rosbag", "launch", "launch_ros"}
)
STATIC_KINDS = frozenset({"module", "msgclass", "interface", "function", "class"})


def analyze_module(ctx: FileContext) -> None:
    tree = ctx.source.tree
    assert tree is not None
    ctx.record_imports(index_module(tree))
    ctx.constants = scan(tree, ctx.index, ctx.qualname, ":=" in ctx.source.text)
    module = build_scope(ctx, "module", "<module>", tree, None)
    program = collect(ctx, tree, module)
    top = Interpreter(ctx, program, module, {})
    state = top.exec_block(tree.body, State())
    statics = {
        k: v
        for k, v in state.env.items()
        if isinstance(v, Value) and v.kind in STATIC_KINDS
    }
    statics.update(ctx.constants.module_constants())
    pending: list[tuple[ast.AST, Scope]] = list(top.pending)
    for statement in tree.body:
        if isinstance(statement, ast.ClassDef):
            pending.append((statement, module))
    for function in list(program.functions.values()):
        pending.append((function.node, function.parent))
    seen: set[int] = set()
    while pending:
        node, parent = pending.pop(0)
        if id(node) not in seen:
            seen.add(id(node))
            pending.extend(_analyze_body(ctx, program, node, parent, statics))
    ctx.metadata_notes()


def _analyze_body(
    ctx: FileContext,
    program: Program,
    node: ast.AST,
    parent: Scope,
    statics: dict[str, Value],
) -> list[tuple[ast.AST, Scope]]:
    if isinstance(node, ast.ClassDef):
        scope = program.classes.get(node.name) if parent.parent is None else None
        scope = scope or build_scope(ctx, "class", node.name, node, parent)
        interp = Interpreter(ctx, program, scope, statics)
        interp.exec_block(node.body, State())
        return [(n, parent) for n, _ in interp.pending]  # methods don't see class names
    function = _function_for(program, node, parent)
    scope = program.signature(ctx, function)
    interp = Interpreter(ctx, program, scope, statics, function)
    state = State()
    interp.bind_parameters(state)
    if isinstance(function.node, ast.Lambda):
        interp.site = function.node
        interp.eval(function.node.body, state)
    else:
        interp.exec_block(function.node.body, state)
    return interp.pending


def _function_for(program: Program, node: ast.AST, parent: Scope) -> Function:
    known = program.by_node.get(id(node))
    if known is not None:
        return known
    assert isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda))
    key = f"<nested {getattr(node, 'name', 'lambda')}@{node.lineno}>"
    return program.add(Function(key, node, parent))


class Interpreter(CallEvaluator):
    def __init__(
        self,
        ctx: FileContext,
        program: Program,
        scope: Scope,
        statics: dict[str, Value],
        function: Function | None = None,
    ) -> None:
        super().__init__(ctx, program)
        self.scope = scope
        self.statics = statics
        self.function = function
        self.pending: list[tuple[ast.AST, Scope]] = []
        # module names read in this function, which no function rebinds: one value
        # (and the fact its refinement gives) for the whole run of the function
        self.globals_read: dict[str, tuple[Value, A.Expr | None]] = {}

    # -- blocks --------------------------------------------------------------
    def exec_block(self, body: list[ast.stmt], state: State) -> State:
        for stmt in body:
            if not state.reachable:
                break
            self.ctx.step(stmt)
            self.site = stmt
            method = getattr(self, f"visit_{type(stmt).__name__}", None)
            state = method(stmt, state) if method else self.generic(stmt, state)
        return state

    def generic(self, stmt: ast.stmt, state: State) -> State:
        self.havoc(state, [stmt])
        return state

    # -- names ---------------------------------------------------------------
    def lookup_name(self, name: str, state: State, node: ast.AST) -> Value:
        scope = self.scope
        if name in scope.local_names:
            bound = state.env.get(name)
            if isinstance(bound, Value):
                return bound
            decl = scope.decls.get(name)
            if bound is MAYBE:
                return self.unknown(
                    node, decl.base if decl else "unknown", decl.unit if decl else None
                )
            value = Value("unknown", uninit=Uninit(name, decl is not None))
            if decl is not None:
                self.check.report_uninit(value, self.site)
            return value
        outer = scope.parent
        while outer is not None and outer.parent is not None:
            if outer.kind == "function" and name in outer.local_names:
                return self._assumed_or_unknown(
                    outer.decls.get(name), name, state, node
                )
            outer = outer.parent
        module = scope.module()
        if name in self.statics:
            return self.statics[name]
        if scope is not module and name in module.local_names:
            if name in self.ctx.constants.changed_globals:
                decl = module.decls.get(name)
                return self._assumed_or_unknown(decl, name, state, node)
            return self._global(name, state)
        if name in BUILTINS:
            return Value("builtin", name=name)
        closure = self.function is not None and (
            isinstance(self.function.node, ast.Lambda)
            or self.function.key.startswith("<")
        )
        if self.ctx.star_import or closure or name in module.global_names:
            return self.unknown(node)
        return Value("unknown", uninit=Uninit(name, False))

    def _global(self, name: str, state: State) -> Value:
        """A module name no function rebinds: the same value at every read in this
        function, satisfying its refinement."""
        if name in self.globals_read:
            value, fact = self.globals_read[name]
            if fact is not None and not any(f is fact for f in state.facts):
                state.assume(fact)
            return value
        decl = self.scope.module().decls.get(name)
        if decl is not None and decl.elements is not None:
            value = self.check.assumed(
                state, name, decl, self.refinement_lookup(decl, state)
            )
            self.globals_read[name] = (value, None)
            return value
        value = self.ctx.fresh(
            decl.base if decl else "unknown", f"`{name}`", decl.unit if decl else None
        )
        self.globals_read[name] = (value, None)  # before the lookup: it may cycle
        if decl is not None and value.term is not None:
            fact = A.substitute(
                decl.assumable,
                {**self.refinement_lookup(decl, state), "_": value.term},
            )
            self.globals_read[name] = (value, fact)
            state.assume(fact)
        return value

    def static_value(self, name: str) -> Value | None:
        return self.statics.get(name)

    def refinement_term(self, name: str, state: State) -> A.Expr | None:
        """Names in refinements resolve as in code: a local, a constant, a module
        name; `self.LIMIT` and `Node.LIMIT` to class constants."""
        bound = state.env.get(name)
        if isinstance(bound, Value) and bound.term is not None:
            return bound.term
        head, _, rest = name.partition(".")
        local = self._is_local(head)
        if local and rest:
            owner = state.env.get(head)
            if isinstance(owner, Value) and owner.kind == "instance":
                found = self.class_constant(owner.name, rest)
                return found.term if found is not None else None
        if local:
            return None
        constant = self.scoped_constant(name, state, self._class_name())
        if constant is not None:
            return constant.term
        return None if rest else self.global_term(name, state)

    def global_term(self, name: str, state: State) -> A.Expr | None:
        module = self.scope.module()
        if (
            self.scope is module
            or name not in module.local_names
            or name in self.ctx.constants.changed_globals
        ):
            return None  # module code: the name's binding on this path, if any
        return self._global(name, state).term

    def _class_name(self) -> str | None:
        if self.function is not None:
            return self.function.class_name
        return self.scope.name if self.scope.kind == "class" else None

    def _is_local(self, name: str) -> bool:
        """Bound in this function (or an enclosing one), not a module name."""
        scope: Scope | None = self.scope
        while scope is not None and scope.parent is not None:
            visible = scope.kind != "class" or scope is self.scope
            if visible and name in scope.local_names:
                return True
            scope = scope.parent
        return False

    def is_read_only_table(self, node: ast.expr) -> bool:
        return (
            isinstance(node, ast.Name)
            and node.id in self.ctx.constants.read_only
            and not self._is_local(node.id)
        )

    def _assumed_or_unknown(
        self, decl: Refinement | None, name: str, state: State, node: ast.AST
    ) -> Value:
        if decl is None:
            return self.unknown(node)
        return self.check.assumed(
            state, name, decl, self.refinement_lookup(decl, state)
        )

    def decl_of(self, name: str) -> Refinement | None:
        scope: Scope | None = self.scope
        while scope is not None:
            if name in scope.decls:
                return scope.decls[name]
            scope = scope.parent
        return None

    def decl_for(self, name: str) -> Refinement | None:
        if name in self.scope.global_names:
            return self.scope.module().decls.get(name)
        return self.scope.decls.get(name)

    # -- binding -------------------------------------------------------------
    def bind(self, target: ast.expr, value: Value, state: State) -> None:
        if isinstance(target, ast.Name):
            decl = self.decl_for(target.id)
            if decl is not None:
                lookup = self.refinement_lookup(decl, state)
                value = self.check.assign_refined(
                    state, target.id, decl, value, self.site, lookup
                )
            bound = state.env[target.id] = replace(value, uninit=None, default_of=None)
            self.note_hover(target, lambda: self.describe_name(target.id, bound, state))
            if self.scope.kind == "module" or (
                self.scope.kind == "class" and self.scope.parent is self.scope.module()
            ):
                self.ctx.constants.record(
                    self.scope.kind, self.scope.name, target.id, bound
                )
        elif isinstance(target, ast.Attribute):
            base = self.eval(target.value, state)
            if base.kind == "instance" and isinstance(target.value, ast.Name):
                var = target.value.id
                self.bind_attribute(base, var, target.attr, value, state)
                stored = state.env[f"{var}.{target.attr}"]
                assert isinstance(stored, Value)
                self.note_hover(
                    target,
                    lambda: self.describe_attribute(
                        base, var, target.attr, stored, state
                    ),
                )
            elif base.kind == "msg" and base.ref in state.heap:
                ref = base.ref
                self.note_hover(
                    target, lambda: hover.field(self.ctx, state, ref, target.attr)
                )
                text = self.ctx.source.segment(target) or target.attr
                self.check.write_field(
                    state, base.ref, target.attr, value, self.site, text
                )
        elif isinstance(target, (ast.Tuple, ast.List)):
            parts = value.elements if value.kind == "tuple" else None
            if parts is None or len(parts) != len(target.elts):
                parts = None
            for index, element in enumerate(target.elts):
                inner = element.value if isinstance(element, ast.Starred) else element
                if parts is not None and inner is element:
                    self.bind(inner, parts[index], state)
                else:
                    parts = None  # after a starred target the positions shift
                    self.bind(inner, self.unknown(inner), state)
        elif isinstance(target, ast.Subscript):
            self.eval(target.value, state)
            self.eval(target.slice, state)
        elif isinstance(target, ast.Starred):
            self.bind(target.value, self.unknown(target), state)

    def bind_attribute(
        self, base: Value, var: str, attr: str, value: Value, state: State
    ) -> None:
        key = f"{var}.{attr}"
        decl = self.program.attributes.get(base.name, {}).get(attr)
        if decl is not None:
            lookup = self.refinement_lookup(decl, state)
            value = self.check.assign_refined(
                state, key, decl, value, self.site, lookup
            )
        state.env[key] = replace(value, uninit=None, default_of=None)

    def bind_parameters(self, state: State) -> None:
        """Parameters: `self`, messages that arrive at a callback, refined values."""
        assert self.function is not None
        function = self.function
        args = function.node.args
        every = [*args.posonlyargs, *args.args, *args.kwonlyargs]
        every += [a for a in (args.vararg, args.kwarg) if a is not None]
        arriving = self._arriving(every)
        for index, arg in enumerate(every):
            decl = self.scope.decls.get(arg.arg)
            annotation = getattr(arg, "annotation", None)
            msg_type = (
                self.ctx.msg_type_of(annotation) if annotation is not None else None
            )
            if decl is not None and decl.base == "msg":
                msg_type = decl.msg_type
            if index == 0 and function.is_method:
                value = Value("instance", name=function.class_name or "")
            elif arg.arg in arriving:
                value = arriving[arg.arg](state)
            elif msg_type is not None:
                value = heap.new_message(
                    self.ctx, state, msg_type, "received", label=arg.arg
                )
            elif decl is not None:
                lookup = self.refinement_lookup(decl, state)
                value = self.check.assumed(state, arg.arg, decl, lookup)
            else:
                value = self.ctx.fresh(
                    "unknown", f"parameter `{arg.arg}` of {function.name}()"
                )
            state.env[arg.arg] = value
            self.note_hover(
                self._name_span(arg),
                lambda: self.describe_name(arg.arg, value, state),  # noqa: B023
            )

    def _name_span(self, arg: ast.arg) -> Span:
        """Where a parameter's name is written (not its annotation)."""
        col = self.ctx.source.char_col(arg.lineno, arg.col_offset)
        return Span(arg.lineno, col, arg.lineno, col + len(arg.arg))

    def _arriving(self, params: list[ast.arg]) -> dict[str, Callable[[State], Value]]:
        """What a ROS callback's parameters hold, by the registration that names it."""
        assert self.function is not None
        callback = self.program.callbacks.get(self.function.key)
        if callback is None or callback.interface is None:
            return {}
        skip = callback.bound + (1 if self.function.is_method else 0)
        names = [p.arg for p in params[skip:]]
        iface = callback.interface

        if callback.kind == "action":
            return (
                {names[0]: lambda state: Value("goal_handle", name=iface)}
                if names
                else {}
            )
        sections = {
            "subscription": [(iface, "received")],
            "service": [
                (f"{iface}_Request", "received"),
                (f"{iface}_Response", "constructed"),
            ],
            "service1": [(f"{iface}_Request", "received")],
            "action1": [(f"{iface}_Goal", "received")],
        }.get(callback.kind, [])
        if not sections or self.ctx.catalog.lookup(sections[0][0]) is None:
            return {}
        return {
            name: self._message_maker(type_, origin, name)
            for name, (type_, origin) in zip(names, sections, strict=False)
        }

    def _message_maker(
        self, type_: str, origin: str, label: str
    ) -> Callable[[State], Value]:
        return lambda state: heap.new_message(
            self.ctx, state, type_, origin, label=label
        )

    def _forgotten(
        self,
        name: ast.Name,
        before: object,
        keeps_unit: set[str],
        after: State | None,
    ) -> Value:
        """The unknown value of a name a loop or `try` may change: a sum keeps its
        unit; one that started as a literal (`total = 0.0`) takes the unit the loop
        body gave it, and until then, as a literal, the unit of its context."""
        if not isinstance(before, Value) or name.id not in keeps_unit:
            return self.unknown(name)
        if not before.literal:
            return self.unknown(name, unit=before.unit)
        found = (
            after.env.get(name.id) if after is not None and after.reachable else None
        )
        if isinstance(found, Value) and found.unit is not None and not found.literal:
            return self.unknown(name, unit=found.unit)
        return replace(self.unknown(name), literal=True)

    def havoc(
        self, state: State, nodes: list[ast.stmt], after: State | None = None
    ) -> None:
        """Forget what `nodes` may write: assigned names and mentioned messages.

        An unannotated name only ever changed by `+=`/`-=` keeps its unit (`+` and
        `-` need equal units, so every path that does not report one keeps it)."""
        keeps_unit = _accumulated(nodes)
        for node in nodes:
            for child in walk(node):
                if (
                    isinstance(child, ast.Attribute)
                    and isinstance(child.ctx, ast.Store)
                    and isinstance(child.value, ast.Name)
                ):
                    state.env.pop(f"{child.value.id}.{child.attr}", None)
                if not isinstance(child, ast.Name):
                    continue
                bound = state.env.get(child.id)
                if isinstance(bound, Value) and bound.ref is not None:
                    heap.havoc(state, bound.ref)
                if (
                    isinstance(child.ctx, ast.Store)
                    and child.id in self.scope.local_names
                ):
                    decl = self.decl_for(child.id)
                    if decl is not None:
                        lookup = self.refinement_lookup(decl, state)
                        state.env[child.id] = self.check.assumed(
                            state, child.id, decl, lookup
                        )
                    else:
                        state.env[child.id] = self._forgotten(
                            child, state.env.get(child.id), keeps_unit, after
                        )

    # -- simple statements ---------------------------------------------------
    def visit_Expr(self, node: ast.Expr, state: State) -> State:
        self.eval(node.value, state)
        return state

    def visit_Assign(self, node: ast.Assign, state: State) -> State:
        if (
            len(node.targets) == 1
            and isinstance(node.targets[0], (ast.Tuple, ast.List))
            and isinstance(node.value, (ast.Tuple, ast.List))
            and len(node.targets[0].elts) == len(node.value.elts)
            and not any(isinstance(e, ast.Starred) for e in node.value.elts)
        ):
            values = [self.eval(v, state) for v in node.value.elts]
            for target, value in zip(node.targets[0].elts, values, strict=True):
                self.bind(target, value, state)
            return state
        value = self.eval(node.value, state)
        for target in node.targets:
            self.bind(target, value, state)
            self._record_flow(node.value, target, state)
        return state

    def _record_flow(self, source: ast.expr, target: ast.expr, state: State) -> None:
        """For `robotfix suggest`: an unannotated variable assigned where a unit is
        known (a refined variable, a message field with a unit)."""
        flows = self.ctx.unit_flows
        if (
            flows is None
            or not isinstance(source, ast.Name)
            or self.decl_for(source.id)
        ):
            return
        if source.id not in self.scope.local_names:
            return
        unit, kind = None, "float"
        if isinstance(target, ast.Name):
            decl = self.decl_for(target.id)
            if decl is not None and decl.unit is not None:
                unit, kind = decl.unit, decl.base
        elif isinstance(target, ast.Attribute):
            base = self.eval(target.value, state)
            if base.kind == "msg" and base.ref in state.heap:
                unit = heap.field_unit(self.ctx, state, base.ref, target.attr)[0]
                spec = heap.field_spec(self.ctx, state, base.ref, target.attr)
                kind = spec.kind if spec is not None else kind
        if unit is not None and unit.text:
            units, kinds = flows.setdefault(
                (self.scope.node, source.id), (set(), set())
            )
            units.add(unit.text)
            kinds.add(kind)

    def visit_AnnAssign(self, node: ast.AnnAssign, state: State) -> State:
        if node.value is not None:
            self.bind(node.target, self.eval(node.value, state), state)
        elif isinstance(node.target, ast.Name):  # a declaration: what it will hold
            name, declared = node.target.id, Value("unknown")
            self.note_hover(
                node.target, lambda: self.describe_name(name, declared, state)
            )
        return state

    def visit_AugAssign(self, node: ast.AugAssign, state: State) -> State:
        load: ast.expr
        if isinstance(node.target, ast.Name):
            load = ast.Name(node.target.id, ast.Load())
        elif isinstance(node.target, ast.Attribute):
            load = ast.Attribute(node.target.value, node.target.attr, ast.Load())
        else:
            return self.generic(node, state)
        combined = ast.BinOp(ast.copy_location(load, node.target), node.op, node.value)
        self.bind(
            node.target, self.eval(ast.copy_location(combined, node), state), state
        )
        return state

    def visit_Assert(self, node: ast.Assert, state: State) -> State:
        state.assume(self.condition(node.test, state))
        return state

    def visit_Return(self, node: ast.Return, state: State) -> State:
        value = self.eval(node.value, state) if node.value is not None else NONE
        function = self.function
        if function is not None and function.returns is not None:
            lookup = self.refinement_lookup(function.returns, state)
            self.check.assign_refined(
                state, f"{function.name}()", function.returns, value, node, lookup
            )
        callback = self.program.callbacks.get(function.key) if function else None
        leaves = callback is not None and callback.kind in (
            "service",
            "service1",
            "action",
        )
        if leaves and value.kind == "msg" and value.ref is not None:
            self.check.check_whole(state, value.ref, node, publishing=True)
        state.reachable = False
        return state

    def visit_Raise(self, node: ast.Raise, state: State) -> State:
        if node.exc is not None:
            self.eval(node.exc, state)
        state.reachable = False
        return state

    def visit_Break(self, node: ast.stmt, state: State) -> State:
        state.reachable = False
        return state

    visit_Continue = visit_Break

    def visit_Pass(self, node: ast.stmt, state: State) -> State:
        return state

    visit_Global = visit_Nonlocal = visit_Pass

    def visit_Delete(self, node: ast.Delete, state: State) -> State:
        for target in node.targets:
            if isinstance(target, ast.Name):
                state.env.pop(target.id, None)
            else:
                self.eval_children(target, state)
        return state

    def visit_Import(self, node: ast.Import, state: State) -> State:
        for alias in node.names:
            if alias.asname:
                state.env[alias.asname] = Value("module", name=alias.name)
            else:
                top = alias.name.split(".")[0]
                state.env[top] = Value("module", name=top)
        return state

    def visit_ImportFrom(self, node: ast.ImportFrom, state: State) -> State:
        for alias in node.names:
            if alias.name == "*":
                continue
            qualified = (
                f"{node.module}.{alias.name}"
                if node.module and not node.level
                else alias.name
            )
            base = self.ctx.absolute(node.level, node.module) if node.level else None
            if base is not None:  # from .limits import MAX_SPEED
                qualified = f"{base}.{alias.name}"
            msg_type = self.ctx.msg_type_named(qualified) if not node.level else None
            interface = self.ctx.interface_named(qualified) if not node.level else None
            number = named_number(qualified) if not node.level else None
            found = (
                None
                if msg_type or interface
                else imported.constant(self.ctx.resolver, qualified)
            )
            if number is not None:  # from math import pi
                value = Value("float", A.Num(number, False), literal=True)
            elif found is not None:  # a constant of a module of the tree
                value = found
            elif msg_type:
                value = Value("msgclass", name=msg_type)
            elif interface:
                value = Value("interface", name=interface)
            else:
                value = Value("module", name=qualified)
                self._note_unknown_interface(node, qualified)
            state.env[alias.asname or alias.name] = value
            if number is not None or found is not None:
                self.ctx.constants.record(
                    self.scope.kind, self.scope.name, alias.asname or alias.name, value
                )
        return state

    def _note_unknown_interface(self, node: ast.ImportFrom, qualified: str) -> None:
        """RF508, only in files that use refinements: unannotated code stays silent."""
        parts = qualified.split(".")
        if (
            len(parts) == 3
            and parts[1] in ("msg", "srv", "action")
            and parts[0] not in CLIENT_LIBRARIES
            and "Annotated" in self.ctx.source.text
        ):
            self.ctx.report(
                messages.unknown_message_class(
                    self.ctx.source.path, self.ctx.source.span(node), qualified
                )
            )

    def visit_FunctionDef(
        self, node: ast.FunctionDef | ast.AsyncFunctionDef, state: State
    ) -> State:
        for expr in [
            *node.decorator_list,
            *node.args.defaults,
            *[d for d in node.args.kw_defaults if d is not None],
        ]:
            self.eval(expr, state)
        key = (
            node.name
            if self.scope.kind == "module"
            else f"<nested {node.name}@{node.lineno}>"
        )
        state.env[node.name] = Value("function", name=key)
        top_level_method = (
            self.scope.kind == "class"
            and self.scope.parent is not None
            and self.scope.parent.kind == "module"
        )
        if self.scope.kind != "module" and not top_level_method:
            self.pending.append((node, self.scope))  # the pre-pass knows only top level
        return state

    visit_AsyncFunctionDef = visit_FunctionDef

    def visit_ClassDef(self, node: ast.ClassDef, state: State) -> State:
        for expr in [*node.decorator_list, *node.bases]:
            self.eval(expr, state)
        state.env[node.name] = Value("class", name=node.name)
        if self.scope.kind != "module":
            self.pending.append((node, self.scope))
        return state

    # -- compound statements -------------------------------------------------
    def visit_If(self, node: ast.If, state: State) -> State:
        cond = self.condition(node.test, state)
        then_state, else_state = state.fork(), state.fork()
        then_state.assume(cond)
        else_state.assume(A.Unary("not", cond))
        then_state = self.exec_block(node.body, then_state)
        else_state = self.exec_block(node.orelse, else_state)
        return self._join(then_state, else_state)

    def _join(self, a: State, b: State) -> State:
        """`join`, after a received message read on one path only has had its
        invariants assumed on the other one too (its values are the same)."""
        if a.reachable and b.reachable:
            for ref in sorted(a.heap.keys() & b.heap.keys()):
                if a.heap[ref].pending != b.heap[ref].pending:
                    heap.settle(self.ctx, a if a.heap[ref].pending else b, ref)
        return join(a, b, self._merged)

    def _merged(self, x: Value, y: Value) -> Value:
        kinds = {x.kind, y.kind}
        kind = (
            x.kind
            if len(kinds) == 1
            else ("float" if kinds <= {"int", "float", "bool"} else "unknown")
        )
        unit = x.unit if x.unit == y.unit else None
        if x.literal != y.literal:  # `d = 0.0`, then `d = scan.range_min`: m
            unit = y.unit if x.literal else x.unit
        if kind in CONTAINERS:  # different tables on the two paths
            return Value("unknown")
        if (
            x.kind == "msg"
            or y.kind == "msg"
            or kind not in ("int", "float", "bool", "str", "unknown")
        ):
            same = x.kind == y.kind and x.ref == y.ref and x.name == y.name
            return x if same else Value("unknown")
        merged = self.ctx.fresh(kind, "a value set on several paths", unit)
        source = y if x.literal else x  # the side that gave the unit
        if unit is not None and (x.literal != y.literal or x.scale == y.scale):
            merged = replace(merged, scale=source.scale, rad_free=source.rad_free)
        return replace(merged, literal=x.literal and y.literal)

    def visit_While(self, node: ast.While, state: State) -> State:
        self.havoc(state, [node])
        body_state = state.fork()
        body_state.assume(self.condition(node.test, body_state))
        end = self.exec_block(node.body, body_state)
        self.havoc(state, [node], after=end)
        return self.exec_block(node.orelse, state)

    def visit_For(self, node: ast.For | ast.AsyncFor, state: State) -> State:
        self.eval(node.iter, state)
        self.havoc(state, [node])
        body_state = state.fork()
        self.bind(node.target, self.unknown(node.target), body_state)
        end = self.exec_block(node.body, body_state)
        self.havoc(state, [node], after=end)
        return self.exec_block(node.orelse, state)

    visit_AsyncFor = visit_For

    def visit_With(self, node: ast.With | ast.AsyncWith, state: State) -> State:
        for item in node.items:
            self.eval(item.context_expr, state)
            if item.optional_vars is not None:
                self.bind(item.optional_vars, self.unknown(item.optional_vars), state)
        return self.exec_block(node.body, state)

    visit_AsyncWith = visit_With

    def visit_Try(self, node: ast.Try, state: State) -> State:
        entry = state.fork()
        self.havoc(entry, node.body)
        result = self.exec_block(node.orelse, self.exec_block(node.body, state))
        for handler in node.handlers:
            handler_state = entry.fork()
            if handler.type is not None:
                self.eval(handler.type, handler_state)
            if handler.name:
                handler_state.env[handler.name] = self.unknown(handler)
            result = self._join(result, self.exec_block(handler.body, handler_state))
        if node.finalbody:
            if not result.reachable:
                self.havoc(entry, node.handlers)  # type: ignore[arg-type]
                self.exec_block(node.finalbody, entry)
                return result
            result = self.exec_block(node.finalbody, result)
        return result

    visit_TryStar = visit_Try


def _accumulated(nodes: list[ast.stmt]) -> set[str]:
    """Names whose every store under `nodes` is `name += e` or `name -= e`."""
    summed: set[str] = set()
    targets: set[int] = set()
    stores: list[ast.Name] = []
    for child in walk(nodes):
        if (
            isinstance(child, ast.AugAssign)
            and isinstance(child.target, ast.Name)
            and isinstance(child.op, (ast.Add, ast.Sub))
        ):
            summed.add(child.target.id)
            targets.add(id(child.target))
        elif isinstance(child, ast.Name) and isinstance(child.ctx, ast.Store):
            stores.append(child)
    if not summed:
        return summed
    return summed - {n.id for n in stores if id(n) not in targets}
