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
import copy
from collections.abc import Callable, Hashable
from fractions import Fraction
from functools import partial

from robotfix import messages
from robotfix.analysis import (
    containers,
    decisions,
    frames,
    heap,
    hover,
    imported,
    typeterms,
    writes,
)
from robotfix.analysis.calls import LEAVING, MUTATORS, CallEvaluator
from robotfix.analysis.constants import bound_names, plain_kind, scan
from robotfix.analysis.context import FileContext, Scope, build_scope
from robotfix.analysis.flows import FlowLog, Where, array_kind
from robotfix.analysis.index import index_of
from robotfix.analysis.program import (
    Function,
    Program,
    attribute_key,
    collect,
    never_returns,
)
from robotfix.analysis.state import MAYBE, MaybeUnbound, State, join
from robotfix.analysis.unitmemo import UnitMemo
from robotfix.analysis.values import (
    CONTAINERS,
    MUTABLE,
    NONE,
    SEQUENCES,
    Items,
    Uninit,
    Value,
    replace,
)
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Refinement
from robotfix.annotations.numbers import named_code, named_number
from robotfix.astwalk import children, walk
from robotfix.diagnostics import Span

NO_RETURN = frozenset(
    {
        "sys.exit",
        "os._exit",
        "os.abort",
        "pytest.fail",
        "pytest.skip",
        "pytest.exit",
        "pytest.xfail",
        "typing.assert_never",
        "typing_extensions.assert_never",
        "_pytest.outcomes.fail",
        "_pytest.outcomes.skip",
        "_pytest.outcomes.exit",
    }
)
# Python 2's builtins: `raw_input = raw_input` in a module's Python 2 branch.
PY2_BUILTINS = frozenset(
    {"raw_input", "unicode", "basestring", "long", "xrange", "unichr", "file"}
    | {"execfile", "reload", "cmp", "buffer", "apply", "intern", "coerce"}
)
BUILTINS = frozenset(dir(builtins)) | {"__file__", "__name__", "__doc__", "__spec__"}
# Python packages with a `msg`/`srv`/`action` module that is not an interface package.
CLIENT_LIBRARIES = frozenset(
    {"rclpy", "rospy", "actionlib", "tf", "tf2_ros", "rosbag", "launch", "launch_ros"}
)
STATIC_KINDS = frozenset({"module", "msgclass", "interface", "function", "class"})


def analyze_module(ctx: FileContext) -> None:
    tree = ctx.source.tree
    assert tree is not None
    ctx.record_imports(index_of(tree))
    ctx.constants = scan(tree, ctx.index, ctx.qualname, ":=" in ctx.source.text)
    module = build_scope(ctx, "module", "<module>", tree, None)
    program = collect(ctx, tree, module)
    if isinstance(ctx.unit_flows, FlowLog):
        ctx.unit_flows.program = program
    top = Interpreter(ctx, program, module, {})
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
    memo = (
        units.begin(ctx, program, tree, statics)
        if isinstance(units, UnitMemo)
        else None
    )
    while pending or later:
        node, parent = pending.pop(0) if pending else later.pop(0)
        if id(node) not in seen:
            seen.add(id(node))
            if memo is None:
                pending.extend(_analyze_body(ctx, program, node, parent, statics))
                ctx.flush()
                continue
            pending.extend(
                memo.analyze(
                    node,
                    parent,
                    partial(_body_scope, ctx, program),
                    partial(_run_body, ctx, program, statics=statics),
                )
            )
    ctx.flush()
    ctx.metadata_notes()


def module_statics(ctx: FileContext, state: State) -> dict[str, Value]:
    """What a function or class body may take a module name to hold, after the
    module code ran to `state`: its modules, classes, functions and constants."""
    statics = {
        k: v
        for k, v in state.env.items()
        if isinstance(v, Value) and v.kind in STATIC_KINDS
    }
    statics.update(ctx.constants.module_constants())
    return statics


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


def _refined_types(ctx: FileContext) -> bool:
    """Whether a message, service or action type the file imports (or a message
    inside one) has refinements. Only imported types are looked up, so the answer
    depends on what the file's cache entry already depends on."""
    todo: list[str] = []
    for qualified in ctx.imports.values():
        found = ctx.msg_type_named(qualified)
        interface = None if found else ctx.interface_named(qualified)
        if found:
            todo.append(found)
        elif interface:
            todo += [f"{interface}_{s}" for s in ("Request", "Response", "Goal")]
            todo += [f"{interface}_{s}" for s in ("Result", "Feedback")]
    seen: set[str] = set()
    while todo and len(seen) < 200:
        name = todo.pop()
        spec = None if name in seen else ctx.catalog.lookup(name)
        seen.add(name)
        if spec is None:
            continue
        if spec.invariants:
            return True
        todo += [f.msg_type for f in spec.fields.values() if f.msg_type]
    return False


def _analyze_body(
    ctx: FileContext,
    program: Program,
    node: ast.AST,
    parent: Scope,
    statics: dict[str, Value],
) -> list[tuple[ast.AST, Scope]]:
    scope, function = _body_scope(ctx, program, node, parent)
    return _run_body(ctx, program, node, parent, scope, function, statics=statics)


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
) -> list[tuple[ast.AST, Scope]]:
    if function is None:
        assert isinstance(node, ast.ClassDef)
        interp = Interpreter(ctx, program, scope, statics)
        interp.exec_block(node.body, State())
        return [(n, parent) for n, _ in interp.pending]  # methods don't see class names
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
        if isinstance(node, ast.Lambda) and known.scope is None:
            known.parent = parent  # a callback met in the body that defines it
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
        self.elifs: set[int] = set()  # `if` statements that are an `elif`
        self.guarded = 0  # inside a `try` body whose handlers catch NameError
        self.nested: dict[str, ast.AST] = {}  # functions defined in this body
        self._shared: set[str] | None = None  # names whose lists may be shared
        # per loop being run, innermost last: the states at its `break`s, kept only
        # while a loop's first iteration is run again (`_first_breaks`), else None
        self._breaking: list[list[State] | None] = []

    # -- blocks --------------------------------------------------------------
    def exec_block(
        self, body: list[ast.stmt], state: State, flush: bool = True
    ) -> State:
        """Run statements; each one's deferred reports are made after it (not
        `flush`: a helper's body run inside the caller's statement)."""
        for stmt in body:
            if not state.reachable:
                break
            self.ctx.step(stmt)
            self.site = stmt
            method = getattr(self, f"visit_{type(stmt).__name__}", None)
            state = method(stmt, state) if method else self.generic(stmt, state)
            if flush:
                self.ctx.flush()
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
                if bound.kind == "list" and containers.followed(bound):
                    return self._unshared(name, bound)
                return state.use(bound) if state.shared.defs else bound
            decl = scope.decls.get(name)
            if isinstance(bound, MaybeUnbound):
                if (
                    bound.when is not None
                    and not decisions.correlated(
                        decisions.merged(bound.tests, state.tests), bound.early
                    )
                    and self._unbound_is_error(name, bound.when != A.TRUE)
                    and self.check.unbound_here(
                        state, bound.when, name, self.site, node
                    )
                ):
                    if bound.value is None:
                        state.env[name] = MAYBE  # one bug, one diagnostic
                        return Value("unknown", uninit=Uninit(name, decl is not None))
                    state.env[name] = bound.value  # past the read, it was bound
                if bound.value is not None:
                    return state.use(bound.value) if state.shared.defs else bound.value
                return self.unknown(
                    node, decl.base if decl else "unknown", decl.unit if decl else None
                )
            value = Value("unknown", uninit=Uninit(name, decl is not None))
            if decl is not None:
                self.check.report_uninit(value, self.site, state)
            elif self.guarded or (  # `try: X` read it: past this, X exists
                self._unbound_is_error(name)
                and self.check.unbound_here(
                    state, A.TRUE, name, self.site, node, self.scope.node
                )
            ):
                state.env[name] = MAYBE
            return value
        outer = scope.parent
        while outer is not None and outer.parent is not None:
            if outer.kind == "function" and name in outer.local_names:
                return self._enclosing(outer, name, state, node)
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
        if decl is not None and (decl.elements is not None or decl.item is not None):
            # a tuple of refined elements, or a refined list or tuple
            value = self.refined.assumed(
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

    def helper_evaluator(self, function: Function) -> Interpreter:
        """An interpreter for a helper's expression evaluated at a call."""
        scope = self.program.signature(self.ctx, function)
        sub = Interpreter(self.ctx, self.program, scope, self.statics, function)
        sub.inlined = (*self.inlined, function.key)
        sub.site = self.site
        return sub

    def refinement_term(self, name: str, state: State) -> A.Expr | None:
        """Names in refinements resolve as in code: a local, a constant, a module
        name; `self.LIMIT` and `Node.LIMIT` to class constants."""
        bound = state.env.get(name)
        if isinstance(bound, Value) and bound.term is not None:
            return state.use(bound).term
        head, _, rest = name.partition(".")
        local = self._is_local(head)
        if local and rest:
            owner = state.env.get(head)
            if isinstance(owner, Value) and owner.kind == "instance":
                found = self.lookups.class_constant(owner.name, rest)
                return found.term if found is not None else None
        if local:
            return None
        reader = self
        if self.scope.kind == "module":  # module code: the statics are not made yet,
            # its imports and classes are bound on this path (`math.pi`, `Limits.MAX`)
            statics = module_statics(self.ctx, state)
            reader = Interpreter(self.ctx, self.program, self.scope, statics)
        constant = reader.scoped_constant(name, state, self._class_name())
        if constant is not None:
            return constant.term
        return None if rest else self.global_term(name, state)

    def global_term(self, name: str, state: State) -> A.Expr | None:
        module = self.scope.module()
        if self.scope is module:  # module code: the name's binding on this path
            bound = state.env.get(name)  # (`from .limits import MAX_SPEED`)
            if isinstance(bound, Value) and bound.term is not None:
                return state.use(bound).term
            return None
        if name not in module.local_names or name in self.ctx.constants.changed_globals:
            return None  # not a module name, or one a function rebinds
        return self._global(name, state).term

    def _class_name(self) -> str | None:
        if self.function is not None:
            return self.function.class_name
        return self.scope.name if self.scope.kind == "class" else None

    def _is_local(self, name: str) -> bool:
        """Bound in this function (or an enclosing one), not a module name."""
        return self._local_scope(name) is not None

    def _local_scope(self, name: str) -> Scope | None:
        """The function (or class body) that binds `name` as the code being
        interpreted sees it; None for a module name."""
        scope: Scope | None = self.scope
        while scope is not None and scope.parent is not None:
            visible = scope.kind != "class" or scope is self.scope
            if visible and name in scope.local_names:
                return scope
            scope = scope.parent
        return None

    def is_read_only_table(self, node: ast.expr) -> bool:
        return (
            isinstance(node, ast.Name)
            and node.id in self.ctx.constants.read_only
            and not self._is_local(node.id)
        )

    def _unbound_is_error(self, name: str, some_paths: bool = False) -> bool:
        """Reading an unbound local raises, unless a handler of the enclosing `try`
        catches NameError, or (outside functions) the name falls back to a builtin
        or, in a class body, to a module name. Module and class code that binds a
        name on some paths only mostly tests the platform or Python version, which
        the analysis cannot tell; a star import may bind any name."""
        if self.guarded:
            return False
        if self.scope.kind == "function":
            return True
        if some_paths or name in BUILTINS or name in PY2_BUILTINS:
            return False
        if self.ctx.star_import:
            return False
        return self.scope.kind != "class" or name not in self.scope.module().local_names

    def _enclosing(self, outer: Scope, name: str, state: State, node: ast.AST) -> Value:
        """A name of an enclosing function, read by a nested function or lambda
        (which may run after it changed): what its refinement says, else an object
        of its type (`talker: Talker`, or `talker = Talker(...)` bound once), else
        unknown."""
        decl = outer.decls.get(name)
        function = self.program.by_node.get(id(outer.node))
        if (
            function is not None
            and function.is_method
            and name == function.first_parameter
        ):
            return Value("instance", name=function.class_name or "")
        if decl is None and function is not None:
            # a parameter's annotated type, or the one type of a local bound once
            typed = self.program.types.infer(
                ast.Name(id=name, ctx=ast.Load()), function
            )
            if typed is not None:
                return self.lookups.typed(typed, node, state, name)
        return self._assumed_or_unknown(decl, name, state, node)

    def _assumed_or_unknown(
        self, decl: Refinement | None, name: str, state: State, node: ast.AST
    ) -> Value:
        if decl is None:
            return self.unknown(node)
        return self.refined.assumed(
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
                value = self.refined.assign_refined(
                    state, target.id, decl, value, self.site, lookup
                )
            bound = state.env[target.id] = value.settled()
            self.lists_seen = self.lists_seen or value.kind == "list"
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
                    lambda: self.lookups.describe_attribute(
                        base, var, target.attr, stored, state
                    ),
                )
            elif base.kind == "msg" and base.ref in state.heap:
                ref = base.ref
                self.note_hover(
                    target, lambda: hover.field(self.ctx, state, ref, target.attr)
                )
                text = self.ctx.source.segment(target) or target.attr
                self.fields.write_field(
                    state, base.ref, target.attr, value, self.site, text
                )
            else:
                state.changed(base, firm=True)
        elif isinstance(target, (ast.Tuple, ast.List)):
            parts = value.elements if value.kind in SEQUENCES else None
            starred = any(isinstance(e, ast.Starred) for e in target.elts)
            if parts is None and value.kind in SEQUENCES and not starred:
                parts = tuple(
                    self.lookups.element(value, e, state) for e in target.elts
                )
            if parts is None or len(parts) != len(target.elts):
                parts = None
            for index, element in enumerate(target.elts):
                inner = element.value if isinstance(element, ast.Starred) else element
                if parts is not None and inner is element:  # a list inside is shared
                    self.bind(inner, containers.stripped(parts[index]), state)
                else:
                    parts = None  # after a starred target the positions shift
                    self.bind(inner, self.unknown(inner), state)
        elif isinstance(target, ast.Subscript):
            receiver = self.receiver(target.value, state)
            key = self.eval(target.slice, state)
            if receiver.kind == "list":
                self._assign_element(target, receiver, key, value, state)
            else:  # `d[k] = v`: d is not empty now
                self._changed_root(target, state, firm=True)
        elif isinstance(target, ast.Starred):
            self.bind(target.value, self.unknown(target), state)

    def bind_attribute(
        self, base: Value, var: str, attr: str, value: Value, state: State
    ) -> None:
        key = f"{var}.{attr}"
        state.shared.firm.add(("attribute", key))
        decl = self.program.attributes.get(base.name, {}).get(attr)
        if decl is not None:
            lookup = self.refinement_lookup(decl, state)
            value = self.refined.assign_refined(
                state, key, decl, value, self.site, lookup
            )
        value = containers.stripped(value)  # an attribute's list is shared
        self.lists_seen = self.lists_seen or value.kind == "list"
        state.env[key] = value.settled()
        if base.kind == "instance":
            frames.remember(self.ctx, base.name, attr, value)

    # -- lists ---------------------------------------------------------------
    def follows_lists(self) -> bool:
        """Whether what local lists hold element by element can matter in this
        file: it has refinements, or a type it imports has (decided once)."""
        if self.ctx.follow_lists is None:
            self.ctx.follow_lists = "Annotated" in self.ctx.source.text or (
                _refined_types(self.ctx)
            )
        return self.ctx.follow_lists

    def _unshared(self, name: str, value: Value) -> Value:
        """A local list as read: what it holds element by element only if no other
        name, attribute or callee can change it (else what its declaration says)."""
        if self.scope.kind != "class":
            if self._shared is None:  # one walk of the body, at the first such read
                self._shared = containers.shared_names(
                    getattr(self.scope.node, "body", []), lent=set()
                )
            if name not in self._shared:  # (nor lent to a call yet: `lends`)
                if self.follows_lists():
                    return value
                # its elements do not matter here, its length (truth) may
                stripped = containers.stripped(value)
                items = stripped.items or Items(containers.item_kind(value))
                size = containers.size_of(value)
                return replace(stripped, items=replace(items, size=size))
        return containers.stripped(value)

    def _assign_element(
        self,
        target: ast.Subscript,
        receiver: Value,
        key: Value,
        value: Value,
        state: State,
    ) -> None:
        """`xs[i] = v` (or `xs[a:b] = ys`): the new elements keep the list's
        declaration; the list is stored back."""
        kept = receiver.items.kept if receiver.items is not None else None
        ok = True
        if isinstance(target.slice, ast.Slice):
            if kept is not None:
                ok = self.check.check_items(
                    state, value, containers.each_only(kept), self.site
                )
            updated = containers.forgetting(receiver)
        else:
            if kept is not None:
                index = self.ctx.source.segment(target.slice) or "i"
                element = Value("list", elements=(value,))
                ok = self.check.check_items(
                    state,
                    element,
                    containers.each_only(kept),
                    self.site,
                    labels=(f"{kept.label}[{index}]",),
                )
            position = key.term
            index_value = (
                int(position.value)
                if isinstance(position, A.Num) and position.is_int
                else None
            )
            updated = containers.with_element(
                receiver, value, index=index_value, grows=False
            )
        if not ok and kept is not None:  # reported: from here on, its declaration
            updated = containers.declared(receiver.kind, kept)
        self.store(target.value, containers.holding(updated), state)

    def store(self, target: ast.expr, value: Value, state: State) -> None:
        """Put a list that changed back where it lives: a local name, `self.x`, or a
        message's array field (as its declaration)."""
        self.lists_seen = True
        if isinstance(target, ast.Name):  # (a read strips it if it is shared)
            if target.id in self.scope.local_names:
                state.env[target.id] = value
            return
        if not isinstance(target, ast.Attribute):
            return
        base = self.eval(target.value, state)
        if base.kind == "instance" and isinstance(target.value, ast.Name):
            state.env[f"{target.value.id}.{target.attr}"] = containers.stripped(value)
        elif base.kind == "msg" and base.ref in state.heap:
            assert base.ref is not None
            obj = state.heap[base.ref]
            kept = value.items.kept if value.items is not None else None
            obj.fields[target.attr] = (
                containers.declared("list", kept)
                if kept is not None
                else containers.stripped(value)
            )
            obj.reported.discard(target.attr)

    def comprehension(
        self, node: ast.ListComp | ast.GeneratorExp, kind: str, state: State
    ) -> Value:
        """`[r for r in ranges if r > 0.1]`: its elements are what the iteration
        and the conditions say of one element (facts about one element's own
        symbols only, so that they hold of every element)."""
        if any(g.is_async for g in node.generators):
            return Value(kind, items=Items())
        inner = state.fork()
        mark, known = self.ctx.last_id(), len(inner.facts)
        saved = self.scope
        names = self.ctx.index.scopes.get(id(node))
        own = set(names.local_names) if names is not None else set()
        self.scope = Scope(
            saved.kind,
            saved.name,
            saved.node,
            saved.parent,
            {k: v for k, v in saved.decls.items() if k not in own},
            saved.local_names | own,
            saved.global_names - own,
        )
        size: A.Expr = A.TRUE
        try:
            for generator in node.generators:
                iterable = self.eval(generator.iter, inner)
                if len(node.generators) == 1 and iterable.kind in SEQUENCES:
                    size = containers.comprehension_size(iterable, bool(generator.ifs))
                element = (
                    self.lookups.element(iterable, generator.target, inner)
                    if iterable.kind in SEQUENCES
                    else self.unknown(generator.target)
                )
                self._bind_plain(generator.target, element, inner)
                for test in generator.ifs:
                    inner.assume(self.condition(test, inner))
            value = self.eval(node.elt, inner)
        finally:
            self.scope = saved
        each: A.Expr = A.TRUE
        term = value.term
        if term is not None and value.kind in (
            "int",
            "float",
            "bool",
            "str",
            "unknown",
        ):
            # each element is the value for some iteration: the symbols this one
            # made are its own (bound names), the facts it added hold of them
            each = containers.bound(
                A.conjoin(
                    [A.Binary("==", containers.SELF, term), *inner.facts[known:]]
                ),
                mark,
            )
            if A.larger_than(each, 300):
                each = A.TRUE
        item = (
            value.kind if value.kind in ("int", "float", "bool", "str") else "unknown"
        )
        unit = None if value.literal else value.unit
        factors = () if value.literal else value.factors  # `[r * 100 for r in ranges]`
        message = (value.name, "unknown") if value.kind == "msg" else None
        of = (
            typeterms.Obj(value.name)
            if value.kind == "instance"
            else typeterms.Lib(value.name)
            if value.kind == "object"
            else None
        )
        items = Items(item, each, size, message=message, of=of)
        made = Value(kind, unit=unit, items=items, factors=factors)
        if kind != "list":
            return made
        # one length for each `len()` of it and each `len(_)` it is checked against
        text = A.excerpt(" ".join((self.ctx.source.segment(node) or "[...]").split()))
        return self.check.with_length(made, text)

    def _bind_plain(self, target: ast.expr, value: Value, state: State) -> None:
        """Bind a comprehension's target (its own names: no refinement applies)."""
        if isinstance(target, ast.Name):
            state.env[target.id] = value
        elif isinstance(target, (ast.Tuple, ast.List)):
            parts = value.elements if value.kind == "tuple" else None
            if parts is None or len(parts) != len(target.elts):
                parts = tuple(self.unknown(e) for e in target.elts)
            for element, part in zip(target.elts, parts, strict=True):
                self._bind_plain(element, part, state)
        elif isinstance(target, ast.Starred):
            self._bind_plain(target.value, Value("list", items=Items()), state)

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
            elif decl is not None and decl.base == "msg":
                lookup = self.refinement_lookup(decl, state)
                value = self.refined.assumed(state, arg.arg, decl, lookup)
            elif msg_type is not None:
                value = heap.new_message(
                    self.ctx, state, msg_type, "received", label=arg.arg
                )
            elif decl is not None:
                lookup = self.refinement_lookup(decl, state)
                value = self.refined.assumed(state, arg.arg, decl, lookup)
            elif annotation is not None and (
                typed := self.program.types.parameter(function, arg.arg)
            ):  # `driver: MotorDriver`, `scans: list[LaserScan]`
                value = self.lookups.typed(typed, arg, state, arg.arg)
            else:
                value = self.ctx.fresh(
                    "unknown", f"parameter `{arg.arg}` of {function.name}()"
                )
            state.env[arg.arg] = value
            self.lists_seen = self.lists_seen or value.kind == "list"
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
        name: str,
        node: ast.AST,
        before: object,
        keeps_unit: set[str],
        after: State | None,
    ) -> Value:
        """The unknown value of a name a loop or `try` may change: a sum keeps its
        unit; one that started as a literal (`total = 0.0`) takes the unit the loop
        body gave it, and until then, as a literal, the unit of its context."""
        if not isinstance(before, Value) or name not in keeps_unit:
            return self.unknown(node)
        if not before.literal:
            return self.unknown(node, unit=before.unit)
        found = after.env.get(name) if after is not None and after.reachable else None
        if isinstance(found, Value) and found.unit is not None and not found.literal:
            return self.unknown(node, unit=found.unit)
        return replace(self.unknown(node), literal=True)

    def _loop_units(self, loop: State, end: State, nodes: list[ast.stmt]) -> None:
        """A sum that started as a literal (`total = 0.0`) takes, after the loop,
        the unit its body gave it."""
        if not end.reachable:
            return
        for name in _accumulated(nodes):
            value, found = loop.env.get(name), end.env.get(name)
            if (
                isinstance(value, Value)
                and value.literal
                and value.unit is None
                and isinstance(found, Value)
                and found.unit is not None
                and not found.literal
            ):
                loop.env[name] = replace(value, unit=found.unit, literal=False)

    def havoc(
        self, state: State, nodes: list[ast.stmt], loop: bool = False
    ) -> set[str]:
        """Forget what `nodes` may write: bound names and mentioned messages. A
        name only ever set to constants of the kind it has keeps that kind (a flag
        stays a bool), so that tests of it agree with what was set. A loop that
        calls anything (`rospy.sleep`, `spin_once`) lets callbacks run: the node's
        attributes and the globals that functions set may change there too.
        What lists they change (`xs.append(v)`, `xs[i] = v`) hold is forgotten.
        Returns the names they may bind."""
        calls = False
        lists: set[str] = set()  # names of lists that `nodes` mention
        # what `_accumulated(nodes)` reads, gathered by the walk below
        summed: set[str] = set()
        sum_targets: set[int] = set()
        stores: list[ast.Name] = []
        watched = state.shared.watched  # only their changes need a new version
        bound_at: dict[str, ast.AST] = {}
        constant: dict[str, set[str]] = {}
        other_binders: set[str] = set()  # bound otherwise than by `=` or `op=`
        assigned: set[int] = set()  # the name nodes `=` and `op=` bind
        objects: dict[str, int] = {}  # names of messages that `nodes` mention
        for node in nodes:
            for child in walk(node):
                kind = type(child)
                if kind is ast.Name:
                    bound = state.env.get(child.id)  # type: ignore[attr-defined]
                    if isinstance(bound, Value) and bound.ref is not None:
                        objects.setdefault(child.id, bound.ref)  # type: ignore[attr-defined]
                    elif isinstance(bound, Value) and bound.kind == "list":
                        lists.add(child.id)  # type: ignore[attr-defined]
                    if type(child.ctx) is not ast.Load:  # type: ignore[attr-defined]
                        bound_at.setdefault(child.id, child)  # type: ignore[attr-defined]
                        if id(child) not in assigned:
                            other_binders.add(child.id)  # type: ignore[attr-defined]
                        if type(child.ctx) is ast.Store:  # type: ignore[attr-defined]
                            stores.append(child)  # type: ignore[arg-type]
                elif kind is ast.Attribute:
                    if type(child.ctx) is ast.Store:  # type: ignore[attr-defined]
                        key = attribute_key(child)  # type: ignore[arg-type]
                        state.env.pop(key or "", None)
                        if watched:
                            self._changed_root(child, state, firm=True)
                    elif self.lists_seen:  # `self.xs.append(v)`: forget what it held
                        key = attribute_key(child) or ""  # type: ignore[arg-type]
                        kept = state.env.get(key)
                        if isinstance(kept, Value) and kept.kind == "list":
                            state.env.pop(key, None)
                elif kind is ast.Subscript:
                    if watched and type(child.ctx) is not ast.Load:  # type: ignore[attr-defined]
                        self._changed_root(child, state, firm=True)
                elif kind is ast.Call:
                    calls = True
                    if watched:
                        call: ast.Call = child  # type: ignore[assignment]
                        method = getattr(call.func, "attr", "")
                        self._changed_root(call.func, state, method in MUTATORS)
                        for arg in [*call.args, *call.keywords]:
                            self._changed_root(arg, state)
                elif kind is ast.Assign or kind is ast.AugAssign:
                    _constant_stores(child, constant, self.statics)  # type: ignore[arg-type]
                    assigned.update(map(id, _targets(child)))  # type: ignore[arg-type]
                    _note_sum(child, summed, sum_targets)
                elif kind in BINDER_KINDS:
                    for name in _binds(child):
                        bound_at.setdefault(name, child)
                        other_binders.add(name)
        self._changed_objects(state, nodes, objects)
        keeps_unit = _sums(summed, sum_targets, stores)
        if lists:  # those `nodes` may change (`xs.append(v)`, `xs[i] = v`, `b = xs`)
            if self.follows_lists():
                lists &= containers.shared_names(nodes, changes=True)
            for name in lists:
                bound = state.env.get(name)
                if isinstance(bound, Value):
                    state.env[name] = containers.forgetting(bound)
        if loop and calls:
            for key in [k for k in state.env if "." in k]:
                del state.env[key]  # `while self.scan is None: rospy.sleep(0.1)`
            for name in sorted(self.program.shared_globals):
                bound_at.setdefault(name, nodes[0])  # `while not received: ...`
        for name, child in bound_at.items():
            if name not in self.scope.local_names:
                continue
            decl = self.decl_for(name)
            before = state.env.get(name)
            if decl is not None:
                lookup = self.refinement_lookup(decl, state)
                state.env[name] = self.refined.assumed(state, name, decl, lookup)
            elif isinstance(before, Value) and constant.get(name, {"?"}) <= _KEEPS.get(
                before.kind, set()
            ):
                kept = self.unknown(child, before.kind, before.unit)
                # a literal set to literals only (`z = 0.0`, then `z = table[k][1]`)
                # stays a number that takes the unit of its context
                plain = before.literal and name not in other_binders
                state.env[name] = replace(kept, literal=True) if plain else kept
            else:
                state.env[name] = self._forgotten(name, child, before, keeps_unit, None)
        return set(bound_at)

    def _changed_objects(
        self, state: State, nodes: list[ast.stmt], objects: dict[str, int]
    ) -> None:
        """Forget what `nodes` may change of the messages of `objects`: the fields
        they store into (`p.header.stamp = now`), or all of one they call a method
        of or hand to a call that may keep or change it, directly or through an
        alias, or that escaped in this function or module (another name, an
        attribute, a container or a callee holds it)."""
        if not objects:
            return
        leaf = partial(self._leaf, state, objects)
        found = writes.uses(nodes, set(objects), leaf, self.only_reads)
        kept = {name for name, kinds in found.items() if not kinds & WHOLE}
        if kept:
            tree = self.ctx.source.tree
            scope = [self.function.node] if self.function is not None else [tree]
            escapes = writes.uses(scope, kept, leaf, self.only_reads)  # type: ignore[arg-type]
            kept -= {name for name, kinds in escapes.items() if writes.ESCAPE in kinds}
        whole = {ref for name, ref in objects.items() if name not in kept}
        for ref in whole:
            heap.havoc(state, ref)
        for name in sorted(kept):
            if objects[name] in whole:
                continue
            for path in sorted(p for p in found[name] if isinstance(p, tuple)):
                heap.forget(self.ctx, state, objects[name], path)

    def _leaf(
        self, state: State, objects: dict[str, int], root: str, path: tuple[str, ...]
    ) -> bool:
        """Whether the field at `path` of message `root` is a number or a string."""
        ref = objects.get(root)
        obj = state.heap.get(ref) if ref is not None else None
        spec = self.ctx.catalog.lookup(obj.type) if obj is not None else None
        field, index = None, 0
        while index < len(path):
            field = spec.fields.get(path[index]) if spec is not None else None
            if field is None:
                return False
            if field.array:  # the list itself can be changed, not a number in it
                if path[index + 1 : index + 2] != ("[]",):
                    return False
                index += 1
            spec = self.ctx.catalog.lookup(field.msg_type) if field.msg_type else None
            index += 1
        return field is not None and field.kind != "msg"

    def only_reads(self, call: ast.Call, arg: ast.expr, depth: int = 0) -> bool:
        """Whether `call` only reads the argument `arg` (a message): a builtin that
        reads, `math`, logging, publishing, a tf2 transform, or a function of this
        file that only reads that parameter. Syntactic, so kept per call and
        argument (asked again on every pass of a loop)."""
        key = (id(call), id(arg), depth)
        found = self.program.reading_calls.get(key)
        if found is None:
            found = self.program.reading_calls[key] = self._only_reads(call, arg, depth)
        return found

    def _only_reads(self, call: ast.Call, arg: ast.expr, depth: int) -> bool:
        func = call.func
        user = self._user_function(func)
        if user is not None:
            return depth < 2 and self._reads_parameter(user, call, arg, depth + 1)
        if isinstance(func, ast.Name):
            return (
                func.id in READING_BUILTINS
                and func.id not in self.scope.module().local_names
            )
        if not isinstance(func, ast.Attribute):
            return False
        name = func.attr
        if name in LEAVING or name in ROS_LOGGING:
            return True
        if frames.is_tf2(name):  # unless this file defines a method of that name
            return not any(k.rpartition(".")[2] == name for k in self.program.functions)
        receiver = func.value
        if isinstance(receiver, ast.Name) and receiver.id == "math":
            return True
        return self._logs(func)

    def _user_function(self, func: ast.expr) -> Function | None:
        """The function of this file a call's `func` names, syntactically."""
        if isinstance(func, ast.Name):
            return self.program.functions.get(func.id)
        if (
            isinstance(func, ast.Attribute)
            and isinstance(func.value, ast.Name)
            and self.function is not None
            and self.function.class_name is not None
            and func.value.id == self.function.first_parameter
        ):
            return self.program.functions.get(f"{self.function.class_name}.{func.attr}")
        return None

    def _reads_parameter(
        self, function: Function, call: ast.Call, arg: ast.expr, depth: int
    ) -> bool:
        node = function.node
        if isinstance(node, ast.Lambda):
            return False
        params = [a.arg for a in [*node.args.posonlyargs, *node.args.args]]
        if function.is_method and isinstance(call.func, ast.Attribute):
            params = params[1:]
        name = next((k.arg for k in call.keywords if k.value is arg), None)
        if name is None and arg in call.args:
            index = call.args.index(arg)
            starred = any(isinstance(a, ast.Starred) for a in call.args[: index + 1])
            name = params[index] if index < len(params) and not starred else None
        if name is None:
            return False
        found = writes.uses(
            node.body,
            {name},
            lambda root, path: False,
            partial(self.only_reads, depth=depth),
        )
        return not found[name]

    def _changed_root(self, node: ast.AST, state: State, firm: bool = False) -> None:
        """The object at the root of `x.a.b` (or a call's argument `x`) may change
        (`firm`: the code stores into it)."""
        while isinstance(
            node, (ast.Attribute, ast.keyword, ast.Starred, ast.Subscript)
        ):
            node = node.value
        if isinstance(node, ast.Name):
            bound = state.env.get(node.id)
            if isinstance(bound, Value) and bound.kind in MUTABLE:
                state.changed(bound, firm)

    # -- simple statements ---------------------------------------------------
    def visit_Expr(self, node: ast.Expr, state: State) -> State:
        self.eval(node.value, state)
        if isinstance(node.value, ast.Call):
            if self._never_returns(node.value.func):
                state.reachable = False  # sys.exit(1) ends this path
            elif self._may_stop(node.value.func):
                state.exits += 1
        return state

    def _logs(self, func: ast.Attribute) -> bool:
        """`self.get_logger().error(...)`, `logger.error(...)`; not `parser.error`:
        a logging method called on something its code calls a logger."""
        receiver = self.ctx.source.segment(func.value) or ""
        return func.attr in LOGGING and "log" in receiver.lower()

    def _may_stop(self, func: ast.expr) -> bool:
        """A call whose result is dropped, which may never return for all the
        analysis can tell: a function of this file that can raise, or one it
        cannot see (`self.fail(msg)`, `parser.exit(1)`), unless its name says it
        returns (`print`, `logger.error`, `pub.publish`)."""
        name = func.id if isinstance(func, ast.Name) else getattr(func, "attr", "")
        if name in RETURNS:
            return False
        if name in LOGGING and isinstance(func, ast.Attribute):
            return not self._logs(func)
        known: Function | None = None
        if isinstance(func, ast.Name):
            if func.id in self.nested:
                return self._function_may_raise(self.nested[func.id])
            if func.id in BUILTINS and func.id not in self.scope.module().local_names:
                return False
            known = self.program.functions.get(func.id)
        elif (
            isinstance(func, ast.Attribute)
            and self.function is not None
            and self.function.class_name is not None
            and isinstance(func.value, ast.Name)
        ):
            method = f"{self.function.class_name}.{func.attr}"
            known = self.program.functions.get(method)
        if known is not None:
            return self._function_may_raise(known.node)
        return True

    def _function_may_raise(self, node: ast.AST) -> bool:
        key = -id(node)  # `ends` holds never-returns by id(node); this by -id(node)
        found = self.program.ends.get(key)
        if found is None:
            found = self.program.ends[key] = _may_raise(node)
        return found

    def _may_not_return(self, func: ast.expr) -> bool:
        """A cheap first look: a name that could be one of the calls below."""
        if isinstance(func, ast.Name):
            name = func.id
            return (
                name in NO_RETURN_NAMES
                or name in self.ctx.imports
                or name in self.program.functions
                or name in self.nested
            )
        name = getattr(func, "attr", "")
        if name in NO_RETURN_NAMES:
            return True
        return (
            self.function is not None
            and self.function.class_name is not None
            and isinstance(getattr(func, "value", None), ast.Name)
            and f"{self.function.class_name}.{name}" in self.program.functions
        )

    def _never_returns(self, func: ast.expr) -> bool:
        """`sys.exit()`, `pytest.fail()`, or a function of this file that can only
        raise: the path ends there."""
        if not self._may_not_return(func):
            return False
        module = self.scope.module()
        known: Function | None = None
        if isinstance(func, ast.Name):
            if func.id in self.nested:  # a helper defined in this function
                return self._function_never_returns(self.nested[func.id])
            if func.id in self.scope.local_names:  # `from pytest import fail` here
                return _no_return(self.ctx.qualname(func))
            if func.id in ("exit", "quit") and func.id not in module.local_names:
                return True
            known = self.program.functions.get(func.id)
        elif (
            isinstance(func, ast.Attribute)
            and isinstance(func.value, ast.Name)
            and self.function is not None
            and self.function.is_method
            and func.value.id == self.function.first_parameter
        ):
            method = f"{self.function.class_name}.{func.attr}"
            known = self.program.functions.get(method)
        if known is not None:
            return self._function_never_returns(known.node)
        return _no_return(self.ctx.qualname(func))

    def _function_never_returns(self, node: ast.AST) -> bool:
        known = self.program.ends.get(id(node))
        if known is None:
            known = self.program.ends[id(node)] = never_returns(node, self._ends_path)
        return known

    def _ends_path(self, stmt: ast.stmt) -> bool:
        """A last statement after which a function cannot go on."""
        if isinstance(stmt, ast.Raise):
            return True
        if not isinstance(stmt, ast.Expr) or not isinstance(stmt.value, ast.Call):
            return False
        func = stmt.value.func
        name = func.id if isinstance(func, ast.Name) else getattr(func, "attr", "")
        if name in ("exit", "quit") and isinstance(func, ast.Name):
            return True
        if name not in NO_RETURN_NAMES and name not in self.ctx.imports:
            return False
        return _no_return(self.ctx.qualname(func))

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
            if len(node.targets) == 1:
                self._record_flow(node.value, target, value, state)
        return state

    def flow_where(self) -> Where:
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
            combined = self.program.augmented[id(node)] = _combined(node)
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
        state.reachable = False
        return state

    def visit_Raise(self, node: ast.Raise, state: State) -> State:
        if node.exc is not None:
            self.eval(node.exc, state)
        state.reachable = False
        return state

    def visit_Break(self, node: ast.stmt, state: State) -> State:
        kept = self._breaking[-1] if self._breaking else None
        if kept is not None:
            kept.append(state.fork())
        state.reachable = False
        return state

    def visit_Continue(self, node: ast.stmt, state: State) -> State:
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
            interface = self.ctx.interface_named(qualified) if not node.level else None
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
        if self.scope.kind == "function":
            self.nested[node.name] = node
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
        if _truth(cond) is None:  # `if self.verbose:` right after setting it: no choice
            self._decided(node.test, then_state, else_state)
        elif _literal_test(node.test):  # `if True:`, `if False: ... else:`, `if 0:`
            (else_state if _truth(cond) else then_state).reachable = False
        if len(node.orelse) == 1 and type(node.orelse[0]) is ast.If:
            self.elifs.add(id(node.orelse[0]))
        elif not node.orelse and id(node) in self.elifs and _is_case(node.test):
            # past `if m == A: ... elif m == B: ...` its author may know no case
            # is left (an enum, a closed set of strings)
            else_state.exits += 1
        since = state.exits
        then_state = self.exec_block(node.body, then_state)
        else_state = self.exec_block(node.orelse, else_state)
        return self._join(then_state, else_state, since)

    def _decided(self, test: ast.expr, *states: State) -> None:
        """`test` was decided on the paths of `states` (`decisions.py`)."""
        env = states[0].env

        def tracked(name: str) -> Hashable:
            bound = env.get(name)
            term = bound.term if isinstance(bound, Value) else None
            return term.ident if isinstance(term, A.Sym) else None

        one = decisions.decision(
            test, self.scope.local_names, tracked, self.attribute_terms
        )
        for state in states:
            state.tests = (*state.tests, one)

    def _join(self, a: State, b: State, since: int | None = None) -> State:
        """`join`, after a received message read on one path only has had its
        invariants assumed on the other one too (its values are the same). With
        `since` (the exits of the state where the paths split): a name bound on
        one path only, where the other may have ended since (`exits`), is not
        surely unbound there; reading it is never an error."""
        if since is not None and a.reachable and b.reachable:
            for side, other in ((a, b), (b, a)):
                if side.exits > since:
                    _excuse(side, other)
        if a.reachable and b.reachable:
            self._tie_lengths(a, b)
        if a.reachable and b.reachable:
            for ref in sorted(a.heap.keys() & b.heap.keys()):
                if a.heap[ref].pending != b.heap[ref].pending:
                    heap.settle(self.ctx, a if a.heap[ref].pending else b, ref)
        return join(a, b, self)

    def _tie_lengths(self, a: State, b: State) -> None:
        """A list of a known length on each path (`hits = []`, `hits = [r]`): one
        length symbol, equal to each on its path, so that a later `if hits:` agrees
        with the path that filled it."""
        for name in sorted(a.env.keys() & b.env.keys()):
            x, y = a.env[name], b.env[name]
            if (
                not isinstance(x, Value)
                or not isinstance(y, Value)
                or x.kind != "list"
                or y.kind != "list"
                or x == y
                or any(v.items is not None and v.items.kept for v in (x, y))
            ):
                continue
            lx, ly = containers.length_term(x), containers.length_term(y)
            if lx is None or ly is None or lx == ly:
                continue
            length = self.ctx.fresh("int", f"`len({name})`").known_term
            a.assume(A.Binary("==", length, lx))
            b.assume(A.Binary("==", length, ly))
            kind = containers.item_kind(x)
            items = Items(
                kind if kind == containers.item_kind(y) else "unknown",
                A.Binary("or", containers.each_of(x), containers.each_of(y)),
                A.Binary("==", containers.SELF, length),
            )
            unit = x.unit if x.unit == y.unit else None
            a.env[name] = Value("list", unit=unit, items=items)
            b.env[name] = Value("list", unit=unit, items=items)

    # The Joiner hooks (see state.join).
    def kept(self, name: str, state: State, ref: int) -> bool:
        """Whether no code of this function lets the message `name` holds (`ref`)
        escape (stored elsewhere, handed to a call that may keep it, returned:
        `writes.py`), nor a name assigned to `name` (`twist = cmd`)."""
        scope = self.function.node if self.function is not None else None
        tree = scope or self.ctx.source.tree
        if tree is None:
            return False
        roots = {name} | {
            node.value.id
            for node in walk(tree)
            if isinstance(node, ast.Assign)
            and isinstance(node.value, ast.Name)
            and any(isinstance(t, ast.Name) and t.id == name for t in node.targets)
        }
        leaf = partial(self._leaf, state, dict.fromkeys(roots, ref))
        found = writes.uses([tree], roots, leaf, self.only_reads)
        return not any(writes.ESCAPE in kinds for kinds in found.values())

    def merged(self, x: Value, y: Value) -> Value:
        kinds = {x.kind, y.kind}
        kind = (
            x.kind
            if len(kinds) == 1
            else ("float" if kinds <= {"int", "float", "bool"} else "unknown")
        )
        unit = x.unit if x.unit == y.unit else None
        if x.literal != y.literal:  # `d = 0.0`, then `d = scan.range_min`: m
            unit = y.unit if x.literal else x.unit
        if x.kind in SEQUENCES and y.kind in SEQUENCES:
            return containers.joined(x, y)
        if kind in CONTAINERS:  # different tables on the two paths: one of them
            kind = "unknown"
        if (
            x.kind == "msg"
            or y.kind == "msg"
            or kind not in ("int", "float", "bool", "str", "unknown")
        ):
            same = x.kind == y.kind and x.ref == y.ref and x.name == y.name
            return x if same else Value("unknown")
        merged = self.ctx.fresh(kind, "a value set on several paths", unit)
        source = y if x.literal else x  # the side that gave the unit
        if unit is not None and (x.literal != y.literal or x.factors == y.factors):
            merged = replace(merged, factors=source.factors, rad_free=source.rad_free)
        return replace(merged, literal=x.literal and y.literal)

    def selector(self) -> A.Expr:
        return self.ctx.fresh("bool", "the path taken").known_term

    def complete(self, state: State, ref: int, name: str) -> Value:
        return heap.read_raw(self.ctx, state, ref, name, f"`{name}`")

    def ties(self, merged: Value, side: Value, state: State) -> list[A.Expr]:
        found: list[A.Expr] = []
        is_none = self._none_test(merged)
        side_none = self._none_test(side)
        if is_none is not None and side_none is not None:
            found.append(A.Binary("==", is_none, side_none))
        truth = self.truthy(merged, self.site)
        side_truth = self._truth_of(side, state)
        if side_truth is not None:
            found.append(A.Binary("==", truth, side_truth))
        return found

    def _none_test(self, value: Value) -> A.Expr | None:
        if value.kind == "none":
            return A.TRUE
        if isinstance(value.term, A.Sym) and value.kind == "unknown":
            key = ("is None", value.term.ident)
            return self.ctx.derived(key, "bool", "`is None`").term
        if value.kind in ("int", "float", "bool", "str", "instance", *CONTAINERS):
            return A.Bool(False)
        return None

    def _truth_of(self, value: Value, state: State) -> A.Expr | None:
        if value.kind == "none":
            return A.Bool(False)
        if value.term is not None and value.kind in ("int", "float", "bool", "str"):
            return self.truthy(value, self.site, state)
        if isinstance(value.term, A.Sym) and value.kind in MUTABLE:
            return self.truthy(value, self.site, state)
        if value.kind == "tuple" and value.elements is not None:
            return A.Bool(len(value.elements) > 0)
        return None

    # -- loops ---------------------------------------------------------------
    def visit_While(self, node: ast.While, state: State) -> State:
        entry = state
        loop = entry.fork()
        stored = self.havoc(loop, [_iteration(node)], loop=True)
        body_state = loop.fork()
        body_state.assume(self.condition(node.test, body_state))
        self._decided(node.test, body_state, loop)
        end = self._iterate(node.body, body_state)
        self._loop_units(loop, end, [node])
        breaks = _breaks(node.body)
        first: list[State] = []
        if self._first_may_break(node.body, breaks, stored, entry):
            start = entry.fork()
            cond = self.condition(node.test, start)
            start.assume(cond)
            if _truth(cond) is not False:
                first = self._first_breaks(node.body, start)
        # Normal exits: the condition is false, after some iterations or none.
        # (With a break, `normal` stands for the exits by break too.)
        normal = loop.fork() if breaks and node.orelse else loop
        if isinstance(node.test, ast.Constant):
            if not breaks or node.orelse:  # else `normal` holds the exits by break
                normal.reachable = not node.test.value and normal.reachable
        elif not breaks:
            cond = self.condition(node.test, normal)
            if _truth(cond) is True:
                normal.reachable = False
            normal.assume(A.Unary("not", cond))
        if self._binds_new_names(stored, entry):
            zero = entry.fork()
            cond = self.condition(node.test, zero)
            zero.reachable = _truth(cond) is not True  # `done = False; while not done`
            zero.assume(A.Unary("not", cond))
            normal = self._join(zero, normal)
        failed = self._all_attempts_failed(node, entry, loop)
        if failed is not None:
            normal = self._join(failed, normal)
        return self._after_loop(node, normal, loop, breaks, first)

    def visit_For(self, node: ast.For | ast.AsyncFor, state: State) -> State:
        empty, nonempty, iterable = self._empty_when(node.iter, state)
        entry = state
        loop = entry.fork()
        stored = self.havoc(loop, [_iteration(node)], loop=True)
        body_state = loop.fork()
        body_state.assume(nonempty)  # an iteration: the iterable had an element
        if empty is None:
            # `if ... in kwargs.values(): hints = ...`, then a loop over the
            # `...` of kwargs: that it runs may imply the earlier test, for all
            # the analysis can tell
            for name, bound in list(body_state.env.items()):
                if isinstance(bound, MaybeUnbound) and bound.when is not None:
                    body_state.env[name] = MAYBE
        self._bind_element(node, iterable, body_state)
        end = self._iterate(node.body, body_state)
        self._loop_units(loop, end, [node])
        breaks = _breaks(node.body)
        first: list[State] = []
        if self._first_may_break(node.body, breaks, stored, entry):
            start = entry.fork()
            start.assume(nonempty)
            self._bind_element(node, iterable, start)
            first = self._first_breaks(node.body, start)
        normal = loop.fork() if breaks and node.orelse else loop
        targets = {t.id for t in walk(node.target) if isinstance(t, ast.Name)}
        if (
            empty is not None
            and empty != A.Bool(False)
            and self._binds_new_names(stored - targets, entry)
        ):
            zero = entry.fork()
            zero.assume(empty)
            for target in targets:
                if target not in zero.env:
                    zero.env[target] = MAYBE  # a loop variable: never an error
            normal = self._join(zero, normal)
        failed = self._all_attempts_failed(node, entry, loop)
        if failed is not None:
            normal = self._join(failed, normal)
        return self._after_loop(node, normal, loop, breaks, first)

    def _bind_element(
        self, node: ast.For | ast.AsyncFor, iterable: Value | None, state: State
    ) -> None:
        element = (
            self.lookups.element(iterable, node.target, state)
            if iterable is not None
            and iterable.kind in SEQUENCES
            and isinstance(node, ast.For)
            else self.unknown(node.target)
        )
        self.bind(node.target, element, state)

    def _iterate(self, body: list[ast.stmt], state: State) -> State:
        """A loop's body, run once from the loop head: its `break`s are exits the
        loop head's state already stands for."""
        self._breaking.append(None)
        try:
            return self.exec_block(body, state)
        finally:
            self._breaking.pop()

    def _first_may_break(
        self, body: list[ast.stmt], breaks: bool, stored: set[str], entry: State
    ) -> bool:
        """Whether a `break` of the first iteration may leave a name the loop binds
        unbound: the loop has a `break`, binds a name unbound on entry that no
        plain assignment before the first statement holding a `break` binds, and
        is not inside a first iteration run again (which would double the work at
        every level of nesting)."""
        if not breaks or any(kept is not None for kept in self._breaking):
            return False
        local = self.scope.local_names
        new = {
            n for n in stored if n in local and not isinstance(entry.env.get(n), Value)
        }
        for stmt in body:
            if not new or _breaks([stmt]):
                break
            if isinstance(stmt, ast.Assign | ast.AnnAssign) and stmt.value is not None:
                new -= bound_names([stmt])
        return bool(new)

    def _first_breaks(self, body: list[ast.stmt], start: State) -> list[State]:
        """The states at the `break`s of the loop's first iteration, run again from
        the state before the loop (`start`, its test assumed): a name the iteration
        binds after a `break` is unbound there (`if not line: break` before
        `value = parse(line)`), and a guard flag still holds its value from before
        the loop. Run muted: the body's reports were made by the run from the loop
        head."""
        kept: list[State] = []
        self._breaking.append(kept)
        try:
            with self.ctx.quiet():
                self.exec_block(body, start)
        finally:
            self._breaking.pop()
        return kept

    def _all_attempts_failed(
        self, node: ast.For | ast.AsyncFor | ast.While, entry: State, loop: State
    ) -> State | None:
        """The exit of a retry loop after every attempt raised and was handled: a
        name that only its `try` body binds (`conn = connect()`) is unbound there.
        Only where each iteration surely can take that path: plain statements
        before the `try`, something that may raise before the binding, a handler of
        plain statements that goes on, nothing after it that may leave the
        function. What the `try` body binds from the binding on keeps its value
        from before the loop (a guard flag `ok = True` is still False)."""
        body = node.body
        for index, stmt in enumerate(body):
            if not isinstance(stmt, ast.Try) or stmt.finalbody:
                continue
            prefix, suffix = body[:index], body[index + 1 :]
            if not all(self._plain(s) for s in prefix):
                continue
            at = next(
                (i for i, one in enumerate(stmt.body) if self._new_names([one], entry)),
                None,
            )
            if at is None:
                continue
            first, new = stmt.body[at], self._new_names([stmt.body[at]], entry)
            binding = [*stmt.body[at:]]
            elsewhere = bound_names(
                [*prefix, *suffix, *stmt.body[:at], *stmt.handlers, *stmt.orelse]
            ) | bound_names([node.test if isinstance(node, ast.While) else node.target])
            new -= elsewhere
            if not new or not any(
                isinstance(n, ast.Call) for n in walk([*stmt.body[:at], _head(first)])
            ):
                continue
            for handler in stmt.handlers:
                goes_on = isinstance(handler.body[-1], ast.Continue)
                plain = handler.body[:-1] if goes_on else handler.body
                if not all(self._plain(s) for s in plain) or (
                    not goes_on and not self._may_follow(suffix)
                ):
                    continue
                failed = loop.fork()
                for name in bound_names(binding) - elsewhere:
                    before = entry.env.get(name)
                    if isinstance(before, Value):
                        failed.env[name] = before
                    else:
                        failed.env.pop(name, None)
                if isinstance(node, ast.While):
                    cond = self.condition(node.test, failed)
                    if _truth(cond) is True:
                        return None
                    failed.assume(A.Unary("not", cond))
                return failed
        return None

    def _new_names(self, nodes: list[ast.stmt], entry: State) -> set[str]:
        """The locals `nodes` bind that are unbound on entry."""
        return {
            n
            for n in bound_names(nodes)
            if n in self.scope.local_names and not isinstance(entry.env.get(n), Value)
        }

    def _plain(self, stmt: ast.stmt) -> bool:
        """A statement that runs through on some run: a simple one, whose calls
        return as far as the analysis knows."""
        if not isinstance(stmt, PLAIN):
            return False
        return not isinstance(stmt, ast.Expr) or not (
            isinstance(stmt.value, ast.Call) and self._may_stop(stmt.value.func)
        )

    def _may_follow(self, suffix: list[ast.stmt]) -> bool:
        """Whether these statements, after a handler, may go on to the next
        iteration or leave the loop by a `break`: no `return`, `raise` or call that
        may not return."""
        for node in walk(suffix):
            if isinstance(node, (ast.Return, ast.Raise)) or (
                isinstance(node, ast.Expr)
                and isinstance(node.value, ast.Call)
                and self._may_stop(node.value.func)
            ):
                return False
        return True

    def _empty_when(
        self, iterable: ast.expr, state: State
    ) -> tuple[A.Expr | None, A.Expr | None, Value | None]:
        """Evaluate a `for` loop's iterable: when is it empty (a path with no
        iteration), what holds in an iteration, and its value (None for `range`)?
        The first is known for `range()` of numbers and for literals only: that a
        list that arrived may be empty is not taken for a path."""
        call = iterable
        if (
            isinstance(call, ast.Call)
            and isinstance(call.func, ast.Name)
            and 1 <= len(call.args) <= 2
            and not call.keywords
            and not any(isinstance(a, ast.Starred) for a in call.args)
            and self.eval(call.func, state) == Value("builtin", name="range")
        ):
            bounds = [self.eval(a, state) for a in call.args]
            if len(bounds) == 1:
                bounds.insert(0, Value("int", A.Num(Fraction(0), True)))
            low, high = bounds
            if {low.kind, high.kind} <= {"int", "unknown"} and low.term and high.term:
                empty = A.Binary("<=", high.term, low.term)
                return empty, A.Unary("not", empty), None
            return None, None, None
        value = self.eval(iterable, state)
        if isinstance(iterable, (ast.List, ast.Tuple, ast.Set, ast.Dict)):
            nonempty = _surely_nonempty(iterable)
            return A.Bool(not nonempty), A.Bool(nonempty), value
        if isinstance(value.term, A.Sym) and value.kind in MUTABLE:
            # `if items: first = ...` then `for x in items: use(first)`
            return None, self.truthy(value, iterable, state), value
        return None, None, value

    visit_AsyncFor = visit_For

    def _after_loop(
        self,
        node: ast.For | ast.AsyncFor | ast.While,
        normal: State,
        loop: State,
        breaks: bool,
        first: list[State],
    ) -> State:
        """`else` runs on normal exits; a `break` leaves with what the body may have
        changed (the havocked loop state), or, in the first iteration, with what
        it changed so far (`first`)."""
        if node.orelse:
            result = self.exec_block(node.orelse, normal)
            normal = self._join(result, loop) if breaks else result
        # (without an `else`, `normal` already stands for the later exits by break)
        for exit in first:
            normal = self._join(normal, exit)
        return normal

    def _binds_new_names(self, stored: set[str], entry: State) -> bool:
        """Is one of these names a local unbound on entry? Only then can skipping
        the statements that bind them (no iteration, an early exception) leave a
        name unbound."""
        return any(
            name in self.scope.local_names
            and not isinstance(entry.env.get(name), Value)
            for name in stored
        )

    def visit_With(self, node: ast.With | ast.AsyncWith, state: State) -> State:
        for item in node.items:
            self.eval(item.context_expr, state)
            if item.optional_vars is not None:
                self.bind(item.optional_vars, self.unknown(item.optional_vars), state)
        return self.exec_block(node.body, state)

    visit_AsyncWith = visit_With

    def visit_Try(self, node: ast.Try, state: State) -> State:
        body = node.body
        safe = 0  # `try: final = None` binds before anything can raise
        while safe < len(body) and _cannot_raise(body[safe]):
            safe += 1
        if safe and node.handlers:
            state = self.exec_block(body[:safe], state)
            body = body[safe:]
        entry = state.fork()
        raised = entry.fork()  # an exception somewhere in the body
        stored = self.havoc(raised, body)
        inside = raised
        binds = bool(node.handlers) and self._binds_new_names(stored, entry)
        if binds:
            raised = self._join(entry.fork(), inside.fork())  # ... or before binding
        guards = any(_catches_name_error(h.type) for h in node.handlers)
        self.guarded += guards
        state = self.exec_block(body, state)
        self.guarded -= guards
        result = self.exec_block(node.orelse, state)
        for handler in node.handlers:
            first = _bound_before_raising(body, handler) if binds else set()
            handler_state = raised.fork()
            if first & self.scope.local_names:
                before = entry.fork()  # it raised after these were bound
                for name in sorted(first & self.scope.local_names):
                    before.env[name] = self.unknown(node)
                handler_state = self._join(before, inside.fork())
            since = handler_state.exits
            if handler.type is not None:  # evaluated only if no earlier one matched
                self.guarded += 1
                self.eval(handler.type, handler_state)
                self.guarded -= 1
            if handler.name:
                handler_state.env[handler.name] = self.unknown(handler)
            handled = self.exec_block(handler.body, handler_state)
            result = self._join(result, handled, since)
        if node.finalbody:
            if not result.reachable:
                self.havoc(raised, node.handlers)  # type: ignore[arg-type]
                self.exec_block(node.finalbody, raised)
                return result
            result = self.exec_block(node.finalbody, result)
        return result

    visit_TryStar = visit_Try


# Calls whose result is dropped and which return: logging, output, containers,
# ROS publishing and sleeping (a call may still raise; these are not written to).
RETURNS = frozenset(
    {
        "print",
        "log",
        "loginfo",
        "logwarn",
        "logerr",
        "logdebug",
        "logfatal",
        "loginfo_throttle",
        "logwarn_throttle",
        "logerr_throttle",
        "write",
        "flush",
        "append",
        "extend",
        "insert",
        "add",
        "update",
        "remove",
        "discard",
        "clear",
        "pop",
        "sort",
        "reverse",
        "setdefault",
        "publish",
        "sleep",
        "spin_once",
        "spin_until_future_complete",
        "destroy_node",
        "shutdown",
        "close",
        "join",
        "start",
        "put",
        "send",
        "set",
        "wait",
        "acquire",
        "release",
    }
)


# rospy's logging functions, and builtins that only read what they are given
ROS_LOGGING = frozenset(n for n in RETURNS if n.startswith("log"))
READING_BUILTINS = frozenset(
    {"len", "print", "str", "repr", "isinstance", "type", "id", "hash", "bool"}
    | {"float", "int", "abs", "round", "format", "hasattr", "callable"}
)

# Logging methods: they return when called on a logger, not on any object
# (`parser.error(msg)` exits).
LOGGING = frozenset(
    {"debug", "info", "warn", "warning", "error", "exception", "critical", "fatal"}
)


def _may_raise(node: ast.AST) -> bool:
    """A function with a `raise` or an `assert` in its own body."""
    todo: list[ast.AST] = list(getattr(node, "body", []))
    while todo:
        child = todo.pop()
        if isinstance(child, (ast.Raise, ast.Assert)):
            return True
        if not isinstance(
            child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)
        ):
            todo.extend(ast.iter_child_nodes(child))
    return False


def _is_case(test: ast.expr) -> bool:
    """`m == A`, `m is A`, `m in (A, B)`, `isinstance(m, A)`, `is_array(m)`: one
    case of a case analysis, which may cover every value the subject can have."""
    if isinstance(test, ast.Compare):
        return len(test.ops) == 1 and isinstance(test.ops[0], (ast.Eq, ast.Is, ast.In))
    if isinstance(test, ast.BoolOp) and isinstance(test.op, ast.Or):
        return all(_is_case(v) for v in test.values)
    # a predicate call: `isinstance(x, A)`, `is_array(v)`, `self.check_event(E)`
    return isinstance(test, ast.Call)


BROAD_ERRORS = frozenset({"Exception", "BaseException", "TypeError"})


def _bound_before_raising(body: list[ast.stmt], handler: ast.ExceptHandler) -> set[str]:
    """Names surely bound before anything `handler` catches can be raised: with a
    `try` body that is one `for` loop (one `with` block), a handler of named
    exceptions (not a broad one, which may come from iterating something that is
    not iterable) catch what its body raised, after its target (the names after
    `as`) and the leading `x = y` of the body were bound."""
    block = body[-1] if body and _without_calls(body[:-1], handler) else None
    if isinstance(block, ast.For) and isinstance(block.target, ast.Name):
        names = {block.target.id}  # a tuple: unpacking may raise first
        if block.orelse:
            return set()
    elif isinstance(block, ast.With) and all(
        isinstance(item.optional_vars, (ast.Name, type(None))) for item in block.items
    ):
        names = {
            item.optional_vars.id
            for item in block.items
            if isinstance(item.optional_vars, ast.Name)
        }
    else:
        return set()
    if handler.type is None or _catches(handler.type, BROAD_ERRORS):
        return set()
    for stmt in block.body:
        if not isinstance(stmt, ast.Assign) or not (
            _cannot_raise(stmt) or isinstance(stmt.value, ast.Name)
        ):
            break
        names |= {t.id for t in stmt.targets if isinstance(t, ast.Name)}
    return names


def _without_calls(stmts: list[ast.stmt], handler: ast.ExceptHandler) -> bool:
    """Statements that cannot raise what `handler` catches: none, or (a handler of
    exceptions that are not builtin ones, which only a call or a `raise` raises,
    not `self.level += 1`) statements without a call, `raise`, `assert` or `yield`."""
    if not stmts:
        return True
    if _catches(handler.type, BUILTIN_ERRORS):
        return False
    return not any(
        isinstance(
            n,
            (
                ast.Call,
                ast.Raise,
                ast.Assert,
                ast.Await,
                ast.Yield,
                ast.YieldFrom,
                ast.FunctionDef,
                ast.ClassDef,
                ast.Delete,
            ),
        )
        for n in walk(stmts)
    )


BUILTIN_ERRORS = frozenset(
    name
    for name in dir(builtins)
    if isinstance(getattr(builtins, name), type)
    and issubclass(getattr(builtins, name), BaseException)
)


def _cannot_raise(stmt: ast.stmt) -> bool:
    """`x = None`, `n = 0`, `a = b = ""`, `pass`: a statement that never raises."""
    if isinstance(stmt, ast.Pass):
        return True
    if not isinstance(stmt, ast.Assign) or not all(
        isinstance(t, ast.Name) for t in stmt.targets
    ):
        return False
    value = stmt.value
    if isinstance(value, ast.UnaryOp) and isinstance(value.op, ast.USub):
        value = value.operand
    if isinstance(value, ast.Dict):
        return not value.keys
    if isinstance(value, (ast.List, ast.Tuple)):
        return not value.elts
    return isinstance(value, ast.Constant)


def _excuse(side: State, other: State) -> None:
    """Names bound on `other` but not on `side`, which may have ended: unbound
    there only if it went on, which the analysis cannot tell."""
    for name, bound in other.env.items():
        if "." in name or not isinstance(bound, Value):
            continue
        mine = side.env.get(name)
        if not isinstance(mine, Value) or mine.uninit is not None:
            side.env[name] = MAYBE


def _accumulated(nodes: list[ast.stmt]) -> set[str]:
    """Names whose every store under `nodes` is `name += e` or `name -= e`."""
    summed: set[str] = set()
    targets: set[int] = set()
    stores: list[ast.Name] = []
    for child in walk(nodes):
        if isinstance(child, ast.AugAssign):
            _note_sum(child, summed, targets)
        elif isinstance(child, ast.Name) and isinstance(child.ctx, ast.Store):
            stores.append(child)
    return _sums(summed, targets, stores)


def _note_sum(node: ast.AST, summed: set[str], targets: set[int]) -> None:
    """`name += e` or `name -= e`: `name` is summed, and its target no plain store."""
    if (
        isinstance(node, ast.AugAssign)
        and isinstance(node.target, ast.Name)
        and isinstance(node.op, (ast.Add, ast.Sub))
    ):
        summed.add(node.target.id)
        targets.add(id(node.target))


def _sums(summed: set[str], targets: set[int], stores: list[ast.Name]) -> set[str]:
    """The summed names that no other store under the same nodes binds."""
    if not summed:
        return summed
    return summed - {n.id for n in stores if id(n) not in targets}


NAME_ERRORS = frozenset(
    {"NameError", "UnboundLocalError", "Exception", "BaseException"}
)


def _catches_name_error(kind: ast.expr | None) -> bool:
    return _catches(kind, NAME_ERRORS)


def _catches(kind: ast.expr | None, errors: frozenset[str]) -> bool:
    """Whether a handler of `kind` catches one of `errors` (a bare one: all)."""
    if kind is None:
        return True
    if isinstance(kind, ast.Tuple):
        return any(_catches(e, errors) for e in kind.elts)
    return isinstance(kind, ast.Name) and kind.id in errors


NO_RETURN_NAMES = frozenset(
    {q.rsplit(".", 1)[-1] for q in NO_RETURN} | {"exit", "quit", "assert_never"}
)


def _no_return(qualified: str | None) -> bool:
    return qualified is not None and (
        qualified in NO_RETURN or qualified.endswith(".assert_never")
    )


_LITERAL_TEST = (
    ast.Constant,
    ast.BoolOp,
    ast.UnaryOp,
    ast.Compare,
    ast.boolop,
    ast.unaryop,
    ast.cmpop,
)


def _literal_test(test: ast.expr) -> bool:
    """A test written with literals only (`True`, `not 0`, `1 and False`): Python
    takes one branch only. A name's value (`TYPE_CHECKING`, a flag) is not folded."""
    return all(isinstance(n, _LITERAL_TEST) for n in ast.walk(test))


def _truth(cond: A.Expr) -> bool | None:
    """The value of a condition made of constants (`True`, `1 != 0`, `not False`),
    or None."""
    if isinstance(cond, A.Bool):
        return cond.value
    if isinstance(cond, A.Unary) and cond.op == "not":
        inner = _truth(cond.operand)
        return None if inner is None else not inner
    if isinstance(cond, A.Binary):
        if cond.op in ("and", "or"):
            left, right = _truth(cond.left), _truth(cond.right)
            decisive = cond.op == "or"  # True decides an `or`, False an `and`
            if decisive in (left, right):
                return decisive
            return None if left is None or right is None else not decisive
        if isinstance(cond.left, A.Num) and isinstance(cond.right, A.Num):
            a, b = cond.left.value, cond.right.value
            return {
                "==": a == b,
                "!=": a != b,
                "<": a < b,
                "<=": a <= b,
                ">": a > b,
                ">=": a >= b,
            }.get(cond.op)
    return None


# Constant kinds a store may have and keep a variable's kind.
_KEEPS = {
    "bool": {"bool"},
    "int": {"int"},
    "float": {"int", "float"},
    "str": {"str"},
}


def _constant_stores(
    node: ast.Assign | ast.AugAssign,
    found: dict[str, set[str]],
    constants: dict[str, Value],
) -> None:
    """The kind of constant each plain name target gets (`?` when not a constant):
    a literal, or a number of a constant table of literals (`constants`)."""
    value = node.value
    kind = "?"
    if isinstance(value, ast.Constant) and not isinstance(value.value, complex):
        kind = {bool: "bool", int: "int", float: "float", str: "str"}.get(
            type(value.value), "?"
        )
    else:  # `-1.0`, `moveBindings[key][1]`
        kind = plain_kind(value, constants)
    if isinstance(node, ast.AugAssign) and kind == "str":
        kind = "?"
    for target in _targets(node):
        if isinstance(target, ast.Name):
            found.setdefault(target.id, set()).add(kind)
        else:
            for inner in walk(target):
                if isinstance(inner, ast.Name):
                    found.setdefault(inner.id, set()).add("?")


def _targets(node: ast.Assign | ast.AugAssign) -> list[ast.expr]:
    return node.targets if isinstance(node, ast.Assign) else [node.target]


BINDERS = (
    ast.Import,
    ast.ImportFrom,
    ast.FunctionDef,
    ast.AsyncFunctionDef,
    ast.ClassDef,
    ast.ExceptHandler,
    ast.MatchAs,
    ast.MatchStar,
    ast.MatchMapping,
)


BINDER_KINDS = frozenset(BINDERS)


def _binds(node: ast.AST) -> list[str]:
    """Names a node binds other than by an `ast.Name` target: imports, definitions,
    exception and pattern names."""
    if not isinstance(node, BINDERS):
        return []
    if isinstance(node, (ast.Import, ast.ImportFrom)):
        return [a.asname or a.name.split(".")[0] for a in node.names if a.name != "*"]
    name = node.rest if isinstance(node, ast.MatchMapping) else node.name
    return [name] if name else []


WHOLE = frozenset({writes.CHANGE, writes.ESCAPE})
PLAIN = (ast.Assign, ast.AnnAssign, ast.AugAssign, ast.Expr, ast.Pass)


def _head(stmt: ast.stmt) -> ast.AST:
    """What a statement surely evaluates before it binds: an assignment's value, a
    `with`'s context managers."""
    if isinstance(stmt, (ast.Assign, ast.AnnAssign, ast.AugAssign)):
        return stmt.value or stmt
    if isinstance(stmt, (ast.With, ast.AsyncWith)):
        return ast.Tuple([i.context_expr for i in stmt.items], ast.Load())
    return ast.Pass()  # a compound statement may bind before it calls


def _iteration(node: ast.While | ast.For | ast.AsyncFor) -> ast.stmt:
    """The loop without its `else`: what its iterations may change. A `break`
    leaves with that state, so a name the `else` alone binds is unbound there."""
    if not node.orelse:
        return node
    plain = copy.copy(node)
    plain.orelse = []
    return plain


def _breaks(body: list[ast.stmt]) -> bool:
    """Does a `break` in `body` leave this loop (not a nested one)?"""
    todo: list[ast.AST] = list(body)
    while todo:
        node = todo.pop()
        kind = type(node)
        if kind is ast.Break:
            return True
        if kind in LOOPS:
            todo.extend(node.orelse)  # type: ignore[attr-defined]
        elif kind in COMPOUND:
            todo.extend(children(node))
    return False


LOOPS = frozenset({ast.For, ast.AsyncFor, ast.While})
# Statements with statements inside (a `break` cannot hide in an expression).
COMPOUND = frozenset(
    {ast.If, ast.With, ast.AsyncWith, ast.Try, ast.TryStar, ast.Match, ast.match_case}
    | {ast.ExceptHandler}
)


def _surely_nonempty(node: ast.expr) -> bool:
    """An iterable that has an element on every path: a non-empty literal, or
    `range`, `enumerate`, `reversed`... of one."""
    if isinstance(node, (ast.List, ast.Tuple, ast.Set)):
        return any(not isinstance(e, ast.Starred) for e in node.elts)
    if isinstance(node, ast.Dict):
        return any(k is not None for k in node.keys)
    if isinstance(node, ast.Constant):
        return isinstance(node.value, (str, bytes)) and len(node.value) > 0
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
        name, args = node.func.id, node.args
        if node.keywords or any(isinstance(a, ast.Starred) for a in args):
            return False
        if name == "range" and 1 <= len(args) <= 2:
            bounds = [_int_constant(a) for a in args]
            if any(b is None for b in bounds):
                return False
            low, high = (0, bounds[0]) if len(bounds) == 1 else bounds
            return low is not None and high is not None and low < high
        if name in ("enumerate", "reversed", "sorted", "list", "tuple") and args:
            return _surely_nonempty(args[0])
        if name == "zip" and args:
            return all(_surely_nonempty(a) for a in args)
    return False


def _int_constant(node: ast.expr) -> int | None:
    if isinstance(node, ast.Constant) and type(node.value) is int:
        return node.value
    if (
        isinstance(node, ast.UnaryOp)
        and isinstance(node.op, ast.USub)
        and isinstance(node.operand, ast.Constant)
        and type(node.operand.value) is int
    ):
        return -node.operand.value
    return None


def _combined(node: ast.AugAssign) -> ast.BinOp | None:
    """`x += d` as the expression `x + d`, at the statement (kept in
    `Program.augmented`)."""
    load: ast.expr
    if isinstance(node.target, ast.Name):
        load = ast.Name(node.target.id, ast.Load())
    elif isinstance(node.target, ast.Attribute):
        load = ast.Attribute(node.target.value, node.target.attr, ast.Load())
    elif isinstance(node.target, ast.Subscript):  # `ranges[i] += d`
        load = ast.Subscript(node.target.value, node.target.slice, ast.Load())
    else:
        return None
    combined = ast.BinOp(ast.copy_location(load, node.target), node.op, node.value)
    return ast.copy_location(combined, node)
