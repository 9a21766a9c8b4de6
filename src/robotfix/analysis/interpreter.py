"""Statements: the abstract interpreter over one module (cf. mypy's checker.py).

Module code runs first, top to bottom; then every function and method is analysed as
an entry point of its own, its parameters unknown unless refined (a parameter whose
annotation is a message class is a message that arrived: its refinements hold).
Loops and `try` are handled by havoc: what they may change becomes unknown, while
refined variables keep their refinement, which every assignment maintains.

The walker is built in layers, a module each, each using only those below it:
`binder` (names read and bound, parameters), `paths` (havoc, calls that end a
path, joins), `compound` (`if`, loops, `with`, `try`) and `Interpreter` here
(blocks, simple statements, imports, definitions, the module's walk and its
entry points); what statements say by their syntax alone is `stmtsyntax`.
"""

from __future__ import annotations

import ast
from collections.abc import Callable
from fractions import Fraction
from functools import partial
from typing import TYPE_CHECKING, cast

from robotfix import messages
from robotfix.analysis import heap, imported
from robotfix.analysis.binder import module_statics
from robotfix.analysis.collaborators import Collaborators
from robotfix.analysis.compound import CompoundWalker
from robotfix.analysis.constants import scan
from robotfix.analysis.context import (
    BudgetExceededError,
    FileContext,
    Scope,
    build_scope,
)
from robotfix.analysis.index import index_of
from robotfix.analysis.program import Function, Program, collect
from robotfix.analysis.state import MAYBE, State
from robotfix.analysis.stmtsyntax import augmented_op
from robotfix.analysis.values import NONE, Value
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Refinement
from robotfix.annotations.numbers import named_code, named_number
from robotfix.interface_names import interface_class

if TYPE_CHECKING:  # only `robotfix suggest` keeps flows: a check never loads them
    from robotfix.analysis.flows import FlowLog, Where


def analyze_module(ctx: FileContext) -> None:
    tree = ctx.source.tree
    assert tree is not None
    ctx.record_imports(index_of(tree))
    source = ctx.source
    ctx.constants = scan(
        tree, ctx.index, ctx.qualname, ":=" in source.text, source.lines
    )
    module = build_scope(ctx, "module", "<module>", tree, None)
    program = collect(ctx, tree, module)
    if ctx.unit_flows is not None:  # a `FlowLog`, set by api.py alone
        cast("FlowLog", ctx.unit_flows).program = program
    parts = Collaborators(ctx, program)  # one set for every body of the file
    top = Interpreter(ctx, program, module, {}, parts=parts)
    state = top.exec_block(tree.body, State())
    statics = module_statics(ctx, state)
    pending: list[tuple[ast.AST, Scope]] = list(top.pending)
    for statement in tree.body:
        if isinstance(statement, ast.ClassDef):
            pending.append((statement, module))
    # a lambda registered as a callback is analysed where its enclosing body meets
    # it (`eval_Lambda`), so it sees that body's names; on its own only if never met
    later: list[tuple[ast.AST, Scope]] = []
    for function in list(program.functions.values()):
        queue = later if isinstance(function.node, ast.Lambda) else pending
        queue.append((function.node, function.parent))
    seen: set[int] = set()
    # the editor's memo of items analysed by an earlier check (analysis/unitmemo.py)
    units = ctx.unit_memo
    memo = None
    if units is not None:  # only the editor keeps one: a check never loads unitmemo
        from robotfix.analysis.unitmemo import UnitMemo

        if isinstance(units, UnitMemo):
            memo = units.begin(ctx, program, tree, statics)
    while pending or later:
        node, parent = pending.pop(0) if pending else later.pop(0)
        if id(node) not in seen:
            seen.add(id(node))
            if memo is None:
                pending.extend(
                    _analyze_body(ctx, program, node, parent, statics, parts)
                )
                ctx.flush()
                continue
            pending.extend(
                memo.analyze(
                    node,
                    parent,
                    partial(_body_scope, ctx, program),
                    partial(_run_body, ctx, program, statics=statics, parts=parts),
                )
            )
    ctx.flush()
    ctx.metadata_notes()


def class_body(
    ctx: FileContext,
    program: Program,
    node: ast.ClassDef,
    parent: Scope,
    statics: dict[str, Value],
) -> Interpreter:
    """Run a class body (its constants are recorded; its methods are pending)."""
    scope, _ = _body_scope(ctx, program, node, parent)
    interp = Interpreter(ctx, program, scope, statics)
    interp.exec_block(node.body, State())
    return interp


def _analyze_body(
    ctx: FileContext,
    program: Program,
    node: ast.AST,
    parent: Scope,
    statics: dict[str, Value],
    parts: Collaborators,
) -> list[tuple[ast.AST, Scope]]:
    scope, function = _body_scope(ctx, program, node, parent)
    return _run_body(
        ctx, program, node, parent, scope, function, statics=statics, parts=parts
    )


def _body_scope(
    ctx: FileContext, program: Program, node: ast.AST, parent: Scope
) -> tuple[Scope, Function | None]:
    """The scope of a class body or a function (its signature, built once)."""
    if isinstance(node, ast.ClassDef):
        scope = program.classes.get(node.name) if parent.parent is None else None
        return scope or build_scope(ctx, "class", node.name, node, parent), None
    function = _function_for(program, node, parent)
    return program.signature(ctx, function), function


def _run_body(
    ctx: FileContext,
    program: Program,
    node: ast.AST,
    parent: Scope,
    scope: Scope,
    function: Function | None,
    *,
    statics: dict[str, Value],
    parts: Collaborators,
) -> list[tuple[ast.AST, Scope]]:
    if function is None:
        assert isinstance(node, ast.ClassDef)
        interp = Interpreter(ctx, program, scope, statics, parts=parts)
        interp.exec_block(node.body, State())
        return [(n, parent) for n, _ in interp.pending]  # methods don't see class names
    interp = Interpreter(ctx, program, scope, statics, function, parts)
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
        if isinstance(node, ast.Lambda) and known.scope is None:
            known.parent = parent  # a callback met in the body that defines it
        return known
    assert isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda))
    key = f"<nested {getattr(node, 'name', 'lambda')}@{node.lineno}>"
    return program.add(Function(key, node, parent))


# an assignment's sides that are unpacked element by element (`a, b = x, y`)
_SEQUENCES = frozenset({ast.Tuple, ast.List})

# walker class -> statement class -> its `visit_<statement class>` function, or
# None: `exec_block`'s dispatch without building a name and a bound method
_VISIT: dict[type, dict[type, Callable[..., State] | None]] = {}


class Interpreter(CompoundWalker):
    # -- blocks --------------------------------------------------------------
    def exec_block(
        self, body: list[ast.stmt], state: State, flush: bool = True
    ) -> State:
        """Run statements; each one's deferred reports are made after it (not
        `flush`: a helper's body run inside the caller's statement)."""
        visits = _VISIT.setdefault(type(self), {})
        ctx = self.ctx
        budget = ctx.budget
        limit = budget.limit  # (fixed for the file; `used` grows in each statement)
        for stmt in body:
            if not state.reachable:
                break
            used = budget.used + 1  # `FileContext.step`, inline: a call per statement
            budget.used = used
            if used > limit:
                raise BudgetExceededError(getattr(stmt, "lineno", 1))
            self.site = stmt
            kind = type(stmt)
            try:  # (as `eval`'s dispatch)
                method = visits[kind]
            except KeyError:  # the walker's class's method for this statement
                method = visits[kind] = getattr(
                    type(self), f"visit_{kind.__name__}", None
                )
            state = method(self, stmt, state) if method else self.generic(stmt, state)
            if flush and ctx.deferred:  # (no call for the many that defer nothing)
                ctx.flush()
        return state

    def generic(self, stmt: ast.stmt, state: State) -> State:
        self.havoc(state, [stmt])
        return state

    def helper_evaluator(self, function: Function) -> Interpreter:
        """An interpreter for a helper's expression evaluated at a call."""
        scope = self.program.signature(self.ctx, function)
        sub = Interpreter(
            self.ctx, self.program, scope, self.statics, function, self.parts
        )
        sub.inlined = (*self.inlined, function.key)
        sub.site = self.site
        return sub

    # -- simple statements ---------------------------------------------------
    def visit_Expr(self, node: ast.Expr, state: State) -> State:
        value = node.value
        self.eval(value, state)
        if type(value) is ast.Call:
            facts, func = self.facts, value.func
            if facts.never_returns(func):
                state.reachable = False  # sys.exit(1) ends this path
            elif facts.may_stop(func):
                state.exits += 1
        return state

    def visit_Assign(self, node: ast.Assign, state: State) -> State:
        targets = node.targets
        if len(targets) == 1:  # (most assignments: one target, a name)
            target = targets[0]
            if type(target) in _SEQUENCES and type(node.value) in _SEQUENCES:
                elts = node.value.elts  # type: ignore[attr-defined]
                if len(target.elts) == len(elts) and not any(  # type: ignore[attr-defined]
                    isinstance(e, ast.Starred) for e in elts
                ):
                    values = []  # (a loop: a comprehension would make cells for
                    for v in elts:  # `self` and `state` at every call of this)
                        values.append(self.eval(v, state))
                    for one, value in zip(target.elts, values, strict=True):  # type: ignore[attr-defined]
                        self.bind(one, value, state)
                    return state
            value = self.eval(node.value, state)
            self.bind(target, value, state)
            if self.ctx.unit_flows is not None:
                self._record_flow(node.value, target, value, state)
            return state
        value = self.eval(node.value, state)
        for target in targets:
            self.bind(target, value, state)
        return state

    def flow_where(self) -> Where:
        from robotfix.analysis.flows import Where  # asked only when flows are kept

        return Where(self.scope, self.function)

    def _record_flow(
        self, source: ast.expr, target: ast.expr, value: Value, state: State
    ) -> None:
        """For `robotfix suggest` (analysis/flows.py): `source` reached a place with
        a unit (a refined name or attribute, a message field with a unit), or an
        unannotated name or attribute takes its value."""
        log = self.flow_log()
        if log is None:
            return
        from robotfix.analysis.flows import array_kind

        decl: Refinement | None = None
        if isinstance(target, ast.Name):
            decl = self.decl_for(target.id)
        elif isinstance(target, ast.Attribute):
            base = self.eval(target.value, state)
            if base.kind == "msg" and base.ref in state.heap:
                unit = heap.field_unit(self.ctx, state, base.ref, target.attr)[0]
                spec = heap.field_spec(self.ctx, state, base.ref, target.attr)
                integer = spec is not None and spec.kind == "int"
                log.sink(
                    self.flow_where(), source, unit, value, array_kind(spec), integer
                )
                held = state.heap[base.ref].fields.get(target.attr)
                if isinstance(source, ast.Call) and held is not None and held.ref:
                    # `odom.twist.twist = Twist(Vector3(tv, ...))`: the fields below
                    log.message_sinks(
                        self.ctx, state, self.flow_where(), held.ref, source
                    )
                return
            if base.kind != "instance":
                log.attribute_field(self.flow_where(), target, source, value)
                return
            decl = self.program.attributes.get(base.name, {}).get(target.attr)
        if decl is None:
            log.bind(self.flow_where(), target, source, value)
        else:
            integer = decl.base == "int"
            log.sink(self.flow_where(), source, decl.unit, value, integer=integer)

    def visit_AnnAssign(self, node: ast.AnnAssign, state: State) -> State:
        if node.value is not None:
            value = self.eval(node.value, state)
            self.bind(node.target, value, state)
            self._record_flow(node.value, node.target, value, state)
        elif isinstance(node.target, ast.Name):  # a declaration: what it will hold
            name, declared = node.target.id, Value("unknown")
            self.note_hover(
                node.target, lambda: self.describe_name(name, declared, state)
            )
        return state

    def visit_AugAssign(self, node: ast.AugAssign, state: State) -> State:
        combined = self.program.augmented.get(id(node))
        if combined is None:
            combined = self.program.augmented[id(node)] = augmented_op(node)
        if combined is None:
            return self.generic(node, state)
        value = self.eval(combined, state)
        self.bind(node.target, value, state)
        if isinstance(node.op, (ast.Add, ast.Sub)):  # `x += d`: d has x's unit
            self._record_flow(node.value, node.target, value, state)
        return state

    def visit_Assert(self, node: ast.Assert, state: State) -> State:
        state.assume(self.condition(node.test, state))
        self._decided(node.test, state)
        return state

    def visit_Return(self, node: ast.Return, state: State) -> State:
        value = self.eval(node.value, state) if node.value is not None else NONE
        function = self.function
        if function is not None and function.returns is not None:
            lookup = self.refinement_lookup(function.returns, state)
            self.refined.assign_refined(
                state, f"{function.name}()", function.returns, value, node, lookup
            )
            if node.value is not None:
                returns = function.returns
                self.note_sink(node.value, returns.unit, value, returns.base == "int")
        callback = self.program.callbacks.get(function.key) if function else None
        leaves = callback is not None and callback.kind in (
            "service",
            "service1",
            "action",
        )
        if leaves and value.kind == "msg" and value.ref is not None:
            self.fields.check_whole(state, value.ref, node, publishing=True)
        if leaves and self.ctx.obligations and function is not None:
            # what the service's clients assume of the response it returns
            self._contracts([value], state, f"return:{function.key}")
        state.reachable = False
        return state

    def visit_Raise(self, node: ast.Raise, state: State) -> State:
        if node.exc is not None:
            self.eval(node.exc, state)
        state.reachable = False
        return state

    def visit_Pass(self, node: ast.stmt, state: State) -> State:
        return state

    visit_Global = visit_Nonlocal = visit_Pass

    def visit_Delete(self, node: ast.Delete, state: State) -> State:
        for target in node.targets:
            if isinstance(target, ast.Name):
                state.env[target.id] = MAYBE  # deleted: unknown, never an error
            else:
                self.eval_children(target, state)
                self._changed_root(target, state, firm=True)
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
            interface = (  # (a message class is no interface: not asked)
                self.ctx.interface_named(qualified)
                if not node.level and not msg_type
                else None
            )
            number = named_number(qualified) if not node.level else None
            found = (
                None
                if msg_type or interface
                else imported.constant(self.ctx.resolver, qualified)
            )
            code = named_code(qualified) if not node.level else None
            if number is not None:  # from math import pi
                value = Value("float", A.Num(number, False), literal=True)
            elif code is not None:  # from errno import EINTR
                value = Value("int", A.Num(Fraction(code), True), literal=True)
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
        if (
            qualified.count(".") == 2
            and interface_class(qualified)
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
        args = node.args
        for expr in node.decorator_list:
            self.eval(expr, state)
        for expr in args.defaults:
            self.eval(expr, state)
        for default in args.kw_defaults:
            if default is not None:
                self.eval(default, state)
        scope = self.scope
        kind = scope.kind
        key = node.name if kind == "module" else f"<nested {node.name}@{node.lineno}>"
        state.env[node.name] = Value("function", name=key)
        if kind == "function":
            self.nested[node.name] = node
        top_level_method = (
            kind == "class"
            and scope.parent is not None
            and scope.parent.kind == "module"
        )
        if kind != "module" and not top_level_method:
            self.pending.append((node, scope))  # the pre-pass knows only top level
        return state

    visit_AsyncFunctionDef = visit_FunctionDef

    def visit_ClassDef(self, node: ast.ClassDef, state: State) -> State:
        for expr in [*node.decorator_list, *node.bases]:
            self.eval(expr, state)
        state.env[node.name] = Value("class", name=node.name)
        if self.scope.kind != "module":
            self.pending.append((node, self.scope))
        return state
