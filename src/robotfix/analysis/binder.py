"""The statement walker's first layer: names read and bound (cf. mypy's binder).

`Binder` holds what the walk of one body knows besides the path `State`: its
scope, the module's statics, the function, the bodies met but not yet run
(`pending`). It answers a name read (`lookup_name`: a local, an enclosing
function's, a module name read once per function, a builtin), binds targets
(`bind`, `bind_attribute`; a list changed in place goes back by `store`),
evaluates comprehensions, and binds a function's parameters. It calls down only
(the expression and call evaluators, the collaborators `check`, `refined`,
`fields`, `lookups`); the layers above (`paths`, `compound`, `interpreter`) use it.
"""

from __future__ import annotations

import ast
from collections.abc import Callable
from functools import partial

from robotfix.analysis import containers, decisions, frames, heap, hover, typeterms
from robotfix.analysis.callfacts import CallFacts
from robotfix.analysis.calls import CallEvaluator
from robotfix.analysis.collaborators import Collaborators
from robotfix.analysis.context import FileContext, Scope
from robotfix.analysis.program import Function, Program
from robotfix.analysis.state import MAYBE, MaybeUnbound, State
from robotfix.analysis.stmtsyntax import BUILTINS, PY2_BUILTINS
from robotfix.analysis.values import MUTABLE, SEQUENCES, Items, Uninit, Value, replace
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Refinement
from robotfix.diagnostics import Span

_BUILTIN_VALUES: dict[str, Value] = {}  # a builtin's name -> its value, once made
STATIC_KINDS = frozenset({"module", "msgclass", "interface", "function", "class"})


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


class Binder(CallEvaluator):
    def __init__(
        self,
        ctx: FileContext,
        program: Program,
        scope: Scope,
        statics: dict[str, Value],
        function: Function | None = None,
        parts: Collaborators | None = None,
    ) -> None:
        CallEvaluator.__init__(self, ctx, program, parts)  # (named: see calls.py)
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
        # which calls end a path, may end it, or only read a message
        self.facts = CallFacts(ctx, program, scope, function, self.nested)
        self._shared: dict[str, bool] = {}  # local list -> whether it may be shared
        # per loop being run, innermost last: the states at its `break`s, kept only
        # while a loop's first iteration is run again (`_first_breaks`), else None
        self._breaking: list[list[State] | None] = []

    # -- names ---------------------------------------------------------------
    def eval_Name(self, node: ast.Name, state: State) -> Value:  # noqa: N802
        """`lookup_name`, and a hover where the editor asks for one. Most names
        read are locals holding a value: its first answer, without its call."""
        if self.ctx.hovers is not None:
            return CallEvaluator.eval_Name(self, node, state)
        name = node.id
        if name in self.scope.local_names:
            bound = state.env.get(name)
            if type(bound) is Value and bound.kind != "list":
                return state.use(bound) if state.shared.defs else bound
        return self.lookup_name(name, state, node)

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
        if name in self.statics:
            return self.statics[name]
        module = scope.module()
        if scope is not module and name in module.local_names:
            if name in self.ctx.constants.changed_globals:
                decl = module.decls.get(name)
                return self._assumed_or_unknown(decl, name, state, node)
            return self._global(name, state)
        if name in BUILTINS:  # (values are never changed: one per builtin)
            found = _BUILTIN_VALUES.get(name)
            if found is None:
                found = _BUILTIN_VALUES[name] = Value("builtin", name=name)
            return found
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
            reader = type(self)(
                self.ctx, self.program, self.scope, statics, parts=self.parts
            )
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
        if type(target) is ast.Name:
            scope = self.scope  # (most bodies declare nothing: no call then)
            declares = scope.decls or scope.global_names
            decl = self.decl_for(target.id) if declares else None
            if decl is not None:
                lookup = self.refinement_lookup(decl, state)
                value = self.refined.assign_refined(
                    state, target.id, decl, value, self.site, lookup
                )
            bound = state.env[target.id] = value.settled()
            self.lists_seen = self.lists_seen or value.kind == "list"
            if self.ctx.hovers is not None:  # the editor asks (`partial`, not a
                # closure: what a closure captures is a cell made at every call)
                self.note_hover(
                    target, partial(self.describe_name, target.id, bound, state)
                )
            if self.scope.kind == "module" or (
                self.scope.kind == "class" and self.scope.parent is self.scope.module()
            ):
                self.ctx.constants.record(
                    self.scope.kind, self.scope.name, target.id, bound
                )
        elif isinstance(target, ast.Attribute):
            owner, attr = target.value, target.attr  # (each read once: see calls.py)
            base = self.eval(owner, state)
            if base.kind == "instance" and type(owner) is ast.Name:
                var = owner.id
                self.bind_attribute(base, var, attr, value, state)
                stored = state.env[f"{var}.{attr}"]
                assert isinstance(stored, Value)
                if self.ctx.hovers is not None:
                    describe = self.lookups.describe_attribute
                    self.note_hover(
                        target, partial(describe, base, var, attr, stored, state)
                    )
            elif base.kind == "msg" and base.ref in state.heap:
                ref = base.ref
                if self.ctx.hovers is not None:  # the editor asks: else no closure
                    self.note_hover(
                        target, partial(hover.field, self.ctx, state, ref, attr)
                    )
                text = self.ctx.source.segment(target) or attr
                self.fields.write_field(state, ref, attr, value, self.site, text)
            else:
                state.changed(base, firm=True)
        elif isinstance(target, (ast.Tuple, ast.List)):
            parts = value.elements if value.kind in SEQUENCES else None
            starred = any(isinstance(e, ast.Starred) for e in target.elts)
            if parts is None and value.kind in SEQUENCES and not starred:
                found = []  # (a loop: a generator would make cells at every bind)
                for element in target.elts:
                    found.append(self.lookups.element(value, element, state))
                parts = tuple(found)
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
            shared = self._shared.get(name)
            if shared is None:  # a walk of what names it, at its first read
                shared = self._shared[name] = containers.shares(
                    self.scope.node, name, self.ctx.source.lines
                )
            if not shared:  # (nor lent to a call yet: `lends`)
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
        self.facts.scope = self.scope
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
            self.scope = self.facts.scope = saved
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
            name = arg.arg  # (read once: an AST node's attribute costs a lookup)
            decl = self.scope.decls.get(name)
            annotation = getattr(arg, "annotation", None)
            msg_type = (
                self.ctx.msg_type_of(annotation) if annotation is not None else None
            )
            if decl is not None and decl.base == "msg":
                msg_type = decl.msg_type
            if index == 0 and function.is_method:
                value = Value("instance", name=function.class_name or "")
            elif name in arriving:
                value = arriving[name](state)
                if decl is not None and decl.base == "msg" and value.ref is not None:
                    # what the refinement says holds of what arrives: the
                    # senders prove it (contracts across nodes)
                    lookup = self.refinement_lookup(decl, state)
                    rules = self.fields.message_rules(decl, name, lookup)
                    self.fields.assume_rules(state, value.ref, rules, name)
                    frames.received_in(self.ctx, state, value.ref, decl.unit)
            elif decl is not None and decl.base == "msg":
                lookup = self.refinement_lookup(decl, state)
                value = self.refined.assumed(state, name, decl, lookup)
            elif msg_type is not None:
                value = heap.new_message(
                    self.ctx, state, msg_type, "received", label=name
                )
            elif decl is not None:
                lookup = self.refinement_lookup(decl, state)
                value = self.refined.assumed(state, name, decl, lookup)
            elif annotation is not None and (
                typed := self.program.types.parameter(function, name)
            ):  # `driver: MotorDriver`, `scans: list[LaserScan]`
                value = self.lookups.typed(typed, arg, state, name)
            else:
                value = self.ctx.fresh(
                    "unknown", f"parameter `{name}` of {function.name}()"
                )
            state.env[name] = value
            self.lists_seen = self.lists_seen or value.kind == "list"
            if self.ctx.hovers is not None:  # the editor asks: else no span
                self.note_hover(
                    self._name_span(arg),
                    partial(self.describe_name, name, value, state),
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
