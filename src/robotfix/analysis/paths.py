"""The statement walker's second layer: what statements do to the paths.

`PathWalker` forgets what code may change (`havoc`: bound names, messages it may
write or let escape, lists, and, in a loop that calls out, what callbacks set),
and joins two paths (`_join`, with the hooks `state.join` asks: `kept`, `merged`,
`selector`, `complete`, `ties`); whether a call only reads a message it asks the
walker's `facts` (`callfacts.CallFacts`). It uses the `Binder` below it and
`stmtsyntax`; `compound` and `interpreter` use it.
"""

from __future__ import annotations

import ast
from collections.abc import Hashable
from functools import partial

from robotfix.analysis import containers, decisions, heap, writes
from robotfix.analysis.binder import Binder
from robotfix.analysis.calls import MUTATORS
from robotfix.analysis.program import attribute_key
from robotfix.analysis.state import State, join, rebound
from robotfix.analysis.stmtsyntax import (
    BINDER_KINDS,
    KEEPS,
    WHOLE,
    bound_by,
    constant_stores,
    excuse,
    note_sum,
    sums,
)
from robotfix.analysis.values import (
    CONTAINERS,
    MUTABLE,
    SEQUENCES,
    Items,
    Value,
    replace,
)
from robotfix.annotations import ast as A
from robotfix.astwalk import FIELDS, SHAPES, fields, walk


class PathWalker(Binder):
    def only_reads(self, call: ast.Call, arg: ast.expr) -> bool:
        return self.facts.only_reads(call, arg)

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

    def _loop_units(self, loop: State, end: State, summed: set[str]) -> None:
        """A sum that started as a literal (`total = 0.0`) takes, after the loop,
        the unit its body gave it (`summed`: the loop's `accumulated` names)."""
        if not end.reachable:
            return
        for name in summed:
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
        return self.havoc_sums(state, nodes, loop)[0]

    def havoc_sums(
        self, state: State, nodes: list[ast.stmt], loop: bool = False
    ) -> tuple[set[str], set[str]]:
        """Forget what `nodes` may write: bound names and mentioned messages. A
        name only ever set to constants of the kind it has keeps that kind (a flag
        stays a bool), so that tests of it agree with what was set. A loop that
        calls anything (`rospy.sleep`, `spin_once`) lets callbacks run: the node's
        attributes and the globals that functions set may change there too.
        What lists they change (`xs.append(v)`, `xs[i] = v`) hold is forgotten.
        Returns the names they may bind, and `accumulated(nodes)` (read by the
        same walk)."""
        calls = False
        lists: set[str] = set()  # names of lists that `nodes` mention
        # what `accumulated(nodes)` reads, gathered by the walk below
        summed: set[str] = set()
        sum_targets: set[int] = set()
        stores: list[ast.Name] = []
        watched = state.shared.watched  # only their changes need a new version
        bound_at: dict[str, ast.AST] = {}
        # the assignments, whose constants (`constant_stores`) are read only if a
        # name they bind held a number, a bool or a string
        assigns: list[ast.Assign | ast.AugAssign] = []
        constant: dict[str, set[str]] | None = None
        other_binders: set[str] = set()  # bound otherwise than by `=` or `op=`
        assigned: set[int] = set()  # the name nodes `=` and `op=` bind
        objects: dict[str, int] = {}  # names of messages that `nodes` mention
        looked: set[str] = set()  # the names whose binding was looked at
        get = state.env.get
        lists_seen = self.lists_seen  # (the walk binds nothing)
        # `walk` of each node in turn (the order `bound_at` keeps): the commonest
        # classes push their children themselves, in the order of their fields
        # (each is a node or a list of nodes), the classes of `SHAPES` by their
        # shape, the rest through `fields`, testing each child; the classes are
        # local names (a module attribute costs a look-up a node)
        name_node, attribute_node, call_node = ast.Name, ast.Attribute, ast.Call
        constant_node, expr_node, assign_node = ast.Constant, ast.Expr, ast.Assign
        load, store = ast.Load, ast.Store
        todo: list[ast.AST] = [*reversed(nodes)]
        push, extend, pop = todo.append, todo.extend, todo.pop
        shape_of = SHAPES.get
        while todo:
            child = pop()
            kind = type(child)
            if kind is name_node:  # (a name and a constant have no children)
                name: str = child.id  # type: ignore[attr-defined]
                if name not in looked:  # (the walk pops dotted keys only)
                    looked.add(name)
                    bound = get(name)
                    if isinstance(bound, Value) and bound.ref is not None:
                        objects[name] = bound.ref
                    elif isinstance(bound, Value) and bound.kind == "list":
                        lists.add(name)
                if type(child.ctx) is not load:  # type: ignore[attr-defined]
                    bound_at.setdefault(name, child)
                    if id(child) not in assigned:
                        other_binders.add(name)
                    if type(child.ctx) is store:  # type: ignore[attr-defined]
                        stores.append(child)  # type: ignore[arg-type]
                continue
            if kind is attribute_node:
                push(child.value)  # type: ignore[attr-defined]
                if type(child.ctx) is store:  # type: ignore[attr-defined]
                    key = attribute_key(child)  # type: ignore[arg-type]
                    state.env.pop(key or "", None)
                    if watched:
                        self._changed_root(child, state, firm=True)
                elif lists_seen:  # `self.xs.append(v)`: forget what it held
                    key = attribute_key(child) or ""  # type: ignore[arg-type]
                    kept = state.env.get(key)
                    if isinstance(kept, Value) and kept.kind == "list":
                        state.env.pop(key, None)
                continue
            if kind is call_node:
                call: ast.Call = child  # type: ignore[assignment]
                push(call.func)
                extend(call.args)
                extend(call.keywords)
                calls = True
                if watched:
                    method = getattr(call.func, "attr", "")
                    self._changed_root(call.func, state, method in MUTATORS)
                    for arg in call.args:
                        if type(arg) is not constant_node:  # (changes no object)
                            self._changed_root(arg, state)
                    for keyword in call.keywords:
                        self._changed_root(keyword, state)
                continue
            if kind is constant_node:
                continue
            if kind is expr_node:
                push(child.value)  # type: ignore[attr-defined]
                continue
            if kind is assign_node:
                extend(child.targets)  # type: ignore[attr-defined]
                push(child.value)  # type: ignore[attr-defined]
                assigns.append(child)  # type: ignore[arg-type]
                assigned.update(map(id, child.targets))  # type: ignore[attr-defined]
                continue
            shape = shape_of(kind)
            if shape is not None:
                for field in shape[0]:
                    push(getattr(child, field))
                for field in shape[1]:
                    extend(getattr(child, field))
            else:
                for field in FIELDS.get(kind) or fields(kind):  # `children`, inline
                    value = getattr(child, field, None)
                    if value.__class__ is list:
                        for one in value:
                            if isinstance(one, ast.AST):
                                push(one)
                    elif isinstance(value, ast.AST):
                        push(value)
            if kind is ast.Subscript:
                if watched and type(child.ctx) is not load:  # type: ignore[attr-defined]
                    self._changed_root(child, state, firm=True)
            elif kind is ast.AugAssign:
                assigns.append(child)  # type: ignore[arg-type]
                assigned.add(id(child.target))  # type: ignore[attr-defined]
                note_sum(child, summed, sum_targets)
            elif kind in BINDER_KINDS:
                for name in bound_by(child):
                    bound_at.setdefault(name, child)
                    other_binders.add(name)
        self._changed_objects(state, nodes, objects)
        keeps_unit = sums(summed, sum_targets, stores)
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
        scope = self.scope
        declares = scope.decls or scope.global_names  # (most bodies declare nothing)
        for name, child in bound_at.items():
            if name not in scope.local_names:
                continue
            decl = self.decl_for(name) if declares else None
            before = state.env.get(name)
            keeps = KEEPS.get(before.kind) if isinstance(before, Value) else None
            if keeps and decl is None and constant is None:  # once, when first asked
                constant = {}
                for assign in assigns:
                    constant_stores(assign, constant, self.statics)
            if decl is not None:
                lookup = self.refinement_lookup(decl, state)
                state.env[name] = self.refined.assumed(state, name, decl, lookup)
            elif (
                isinstance(before, Value)
                and keeps
                and constant is not None
                and constant.get(name, {"?"}) <= keeps
            ):
                kept = self.unknown(child, before.kind, before.unit)
                # a literal set to literals only (`z = 0.0`, then `z = table[k][1]`)
                # stays a number that takes the unit of its context
                plain = before.literal and name not in other_binders
                state.env[name] = replace(kept, literal=True) if plain else kept
            else:
                state.env[name] = self._forgotten(name, child, before, keeps_unit, None)
        return set(bound_at), keeps_unit

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
        found = writes.uses(nodes, set(objects), leaf, self.facts.only_reads)
        kept = {name for name, kinds in found.items() if not kinds & WHOLE}
        if kept:
            tree = self.ctx.source.tree
            scope = [self.function.node] if self.function is not None else [tree]
            escapes = writes.uses(scope, kept, leaf, self.facts.only_reads)  # type: ignore[arg-type]
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
                    excuse(side, other)
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
        for name in rebound(a, b, "list"):
            x, y = a.env[name], b.env.get(name)
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
        found = writes.uses([tree], roots, leaf, self.facts.only_reads)
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

    def ties(
        self, merged: Value, sides: tuple[tuple[Value, State], ...]
    ) -> list[list[A.Expr]]:
        found: list[list[A.Expr]] = []
        # what `merged` is asked once (it is the same on every side), in the order
        # of the first side's questions: the symbols they make are numbered so
        is_none: A.Expr | None = None
        truth: A.Expr = A.TRUE
        for side, state in sides:
            facts: list[A.Expr] = []
            if not found:
                is_none = self._none_test(merged)
            side_none = self._none_test(side)
            if is_none is not None and side_none is not None:
                facts.append(A.Binary("==", is_none, side_none))
            if not found:
                truth = self.truthy(merged, self.site)
            side_truth = self._truth_of(side, state)
            if side_truth is not None:
                facts.append(A.Binary("==", truth, side_truth))
            found.append(facts)
        return found

    def _none_test(self, value: Value) -> A.Expr | None:
        if value.kind == "none":
            return A.TRUE
        if isinstance(value.term, A.Sym) and value.kind == "unknown":
            key = ("is None", value.term.ident)
            return self.ctx.derived_term(key, "bool", "`is None`")
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
