"""The abstract state of one path: bindings, message heap, and path facts.

A state is mutated while one straight-line path is interpreted and copied (`fork`)
where paths split (the last path to start goes on in the state itself: nothing reads
it after); `join` merges two paths back into one. Facts are kept as a list whose
common prefix is shared, so a join only has to disjoin what the branches added.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Protocol

from robotfix.analysis.decisions import Decisions, merged
from robotfix.analysis.values import (
    Choice,
    Choices,
    Defs,
    MaybeDefault,
    MsgObj,
    Value,
    replace,
)
from robotfix.annotations import ast as A


@dataclass(frozen=True)
class MaybeUnbound:
    """A name bound on some paths only. `when` is the condition, over the selectors
    of the joins it went through, under which it is unbound; None when that is not
    known (a `del`, a loop variable): reading it is then unknown, never an error."""

    when: A.Expr | None = None
    # The branch decisions of the paths on which it is unbound (`decisions.py`).
    tests: Decisions = field(default=(), compare=False)
    # The ids of the decisions taken before the paths split (where it became
    # unbound): ties among those alone do not make the read less sure.
    early: frozenset[int] = field(default=frozenset(), compare=False)
    # What it holds on the paths where it is bound (merged as any value is, so a
    # read that did not raise still knows it: `code = -1` on the path that left the
    # loop early), if known.
    value: Value | None = field(default=None, compare=False)


MAYBE = MaybeUnbound()
Binding = Value | MaybeUnbound


@dataclass
class Shared:
    """What the states of one function share (symbols are unique to it)."""

    # What the values merged at joins are, by symbol: the facts (keyed, to be added
    # once) that tie each to what each path held. They join a path's facts only
    # where the value is read (`State.use`), so that a merge nobody reads costs the
    # solver nothing.
    defs: dict[int, Defs] = field(default_factory=dict)
    extras: bool = False  # some message carries a variable's refinement
    # Unknown objects whose attributes, truth or length were read: only their
    # changes need a new version.
    watched: set[int] = field(default_factory=set)
    # Objects the code itself changed (`xs.append(v)`, `d[k] = v`), not only
    # handed to code the analysis cannot see.
    firm: set[object] = field(default_factory=set)


@dataclass
class State:
    """The abstract state on one path: bindings, heap, facts, decisions."""

    env: dict[str, Binding] = field(default_factory=dict)
    heap: dict[int, MsgObj] = field(default_factory=dict)
    facts: list[A.Expr] = field(default_factory=list)
    reachable: bool = True
    # How often an unknown object (by its symbol) may have been changed on this
    # path: what was read of it at one version is the same value.
    versions: dict[int, int] | None = None
    defined: set[int] | None = None  # keys of the Shared.defs in `facts`
    shared: Shared = field(default_factory=Shared)
    # Points on this path after which it may not go on, for all the analysis can
    # tell: a call it cannot see (`self.fail(...)`, `parser.exit(...)`), the
    # implicit `else` of an `elif` chain its author may have made exhaustive.
    exits: int = 0
    tests: Decisions = ()  # the branch decisions taken on this path

    def fork(self) -> State:
        return State(
            dict(self.env),
            {k: v.copy() for k, v in self.heap.items()} if self.heap else {},
            list(self.facts),
            self.reachable,
            dict(self.versions) if self.versions else None,
            set(self.defined) if self.defined else None,
            self.shared,
            self.exits,
            self.tests,
        )

    def use(self, value: Value) -> Value:
        """A value is read: if it was merged at a join, what it is holds from here."""
        term = value.term
        defs = self.shared.defs
        if type(term) is A.Sym and term.ident in defs:
            if self.defined is None:
                self.defined = set()
            for key, fact in defs[term.ident]:
                if key not in self.defined:
                    self.defined.add(key)
                    self.facts.append(fact)
        return value

    def defs_of(self, value: Value) -> Defs:
        term = value.term
        if isinstance(term, A.Sym):
            return self.shared.defs.get(term.ident, ())
        return ()

    def pending(self, defs: Defs) -> list[A.Expr]:
        """The facts of `defs` this path does not hold yet."""
        defined = self.defined or set()
        return [fact for key, fact in defs if key not in defined]

    def changed(self, value: Value, firm: bool = False) -> None:
        """Code may have changed this object: its attributes are read anew.
        (`firm`: this code surely changed it.)"""
        term = value.term
        if firm and type(term) is A.Sym:
            self.shared.firm.add(term.ident)
        if type(term) is A.Sym and term.ident in self.shared.watched:
            if self.versions is None:
                self.versions = {}
            self.versions[term.ident] = self.versions.get(term.ident, 0) + 1

    def version(self, term: A.Sym) -> int:
        """The version of an unknown object, which from now on is watched."""
        self.shared.watched.add(term.ident)
        return self.versions.get(term.ident, 0) if self.versions else 0

    def assume(self, fact: A.Expr | None) -> None:
        # (only a Bool equals TRUE: other terms are not compared, which asks two
        # generated `__eq__`s for a `Binary`)
        if fact is not None and (type(fact) is not A.Bool or fact != A.TRUE):
            self.facts.append(fact)


class Joiner(Protocol):
    def merged(self, x: Value, y: Value) -> Value:
        """A fresh value for two that differ (tied to each by a fact)."""

    def selector(self) -> A.Expr:
        """A fresh boolean: true on the first path of a join, false on the second."""

    def ties(
        self, merged: Value, sides: tuple[tuple[Value, State], ...]
    ) -> list[list[A.Expr]]:
        """Facts that hold of a merged value of unknown kind on each path (`sides`:
        what it is there, and the path's state): whether it is None, whether it is
        true (`x = None` on one path, an object on the other, and `if x:` after)."""

    def complete(self, state: State, ref: int, name: str) -> Value:
        """What `state` holds in field `name` of message `ref`, which it never
        touched (its default, an unknown, or the sub-message of the same id)."""

    def kept(self, name: str, state: State, ref: int) -> bool:
        """Whether no code lets the message `name` holds (`ref` in `state`) escape
        where the analysis does not follow it (a container, a callee that may
        keep it)."""


def join(a: State, b: State, joiner: Joiner) -> State:
    """Merge two paths.

    The facts become the common prefix and the disjunction `A or B` of what each
    path added. A merged value `s` gets a selector `p` for the join, defined by
    `(p and A) or (not p and B)`, and `(p and s == x) or (not p and s == y)`: both
    are added to a path's facts only where `s` is read (`State.use`). The same
    selector says when a name is unbound or a field unset ("when not p"), for a
    read to ask under its own facts.
    """
    if not a.reachable:
        return b
    if not b.reachable:
        return a
    b = _one_message(a, b, joiner)
    common = _common(a.facts, b.facts)
    rest_a, rest_b = a.facts[common:], b.facts[common:]
    path_a, path_b = A.conjoin(rest_a), A.conjoin(rest_b)
    chosen: list[tuple[A.Expr, Defs]] = []

    def selector() -> tuple[A.Expr, Defs]:
        """The join's selector and the fact that defines it."""
        if not chosen:
            p = joiner.selector()
            assert isinstance(p, A.Sym)
            defines = A.Binary(
                "or",
                A.Binary("and", p, path_a),
                A.Binary("and", A.Unary("not", p), path_b),
            )
            chosen.append((p, ((p.ident, defines),)))
        return chosen[0]

    def merge(x: Value, y: Value) -> Value:
        if x is y or x == y:
            return x
        value = joiner.merged(x, y)
        if isinstance(value.term, A.Sym):
            p, defines = selector()
            tie = _tie(value, x, y, a, b, p, joiner)
            if tie is not None:
                a.shared.defs[value.term.ident] = (*defines, (value.term.ident, tie))
            if value.unit is None and not value.literal and value.is_number:
                value = _with_choices(value, x, y, p, defines)
        return value

    def unset(ux: MaybeDefault | None, uy: MaybeDefault | None) -> MaybeDefault | None:
        """A field default on the paths where `ux` (`uy`) holds, if any."""
        if ux == uy:
            return ux
        known = ux or uy
        assert known is not None
        when = _either(
            selector(),
            None if ux is None else ux.when,
            None if uy is None else uy.when,
        )
        return MaybeDefault(when, known.default, known.owner)

    tests = a.tests[: _common(a.tests, b.tests)]  # the decisions before the split
    early: list[frozenset[int]] = []

    def common_tests() -> frozenset[int]:
        if not early:
            early.append(frozenset(one[0] for one in tests))
        return early[0]

    env: dict[str, Binding] = {}
    get_a, get_b = a.env.get, b.env.get
    for name in sorted(a.env.keys() | b.env.keys()):
        x, y = get_a(name), get_b(name)
        if x is y:
            env[name] = x  # type: ignore[assignment]
        elif isinstance(x, Value) and isinstance(y, Value):
            env[name] = merge(x, y)
        elif x == y:
            env[name] = x  # type: ignore[assignment]
        elif "." in name:  # a cached `self.x`: read again
            env[name] = MAYBE
        else:
            (known_a, wa), (known_b, wb) = _unbound(x), _unbound(y)
            known = known_a and known_b
            va, vb = _bound_value(x), _bound_value(y)
            env[name] = MaybeUnbound(
                _either(selector(), wa, wb) if known else None,
                merged(_tests(x, a), _tests(y, b)),
                _early(x, common_tests()) & _early(y, common_tests()),
                merge(va, vb) if va is not None and vb is not None else va or vb,
            )
    heap = _join_heaps(a, b, joiner, merge, unset)
    facts = a.facts[:common]
    if rest_a and rest_b:
        facts.append(A.Binary("or", path_a, path_b))
    versions = dict(a.versions) if a.versions else None
    for term, version in (b.versions or {}).items():
        versions = versions or {}
        if versions.get(term, 0) != version:
            versions[term] = max(versions.get(term, 0), version) + 1
    defined = a.defined & b.defined if a.defined and b.defined else None
    exits = max(a.exits, b.exits)
    return State(env, heap, facts, True, versions, defined, a.shared, exits, tests)


# Choices a merged number keeps at most (an `elif` chain of constants in one unit
# each): past that, its unit is unknown, as any other merged number's.
MAX_CHOICES = 8


def _with_choices(value: Value, x: Value, y: Value, p: A.Expr, defines: Defs) -> Value:
    """A merged number of no unit, with the units it has on each path (`Choices`)."""
    options = (*_options(x, p, defines), *_options(y, A.Unary("not", p), defines))
    if not options or len(options) > MAX_CHOICES:
        return value
    assert isinstance(value.term, A.Sym)
    return replace(value, choices=Choices(value.term.ident, options))


def _options(side: Value, when: A.Expr, defines: Defs) -> tuple[Choice, ...]:
    """What `side`, merged on the paths where `when` holds, is there per unit."""
    inner = side.options()
    if inner:
        return tuple(
            Choice(c.value, A.Binary("and", when, c.when), (*defines, *c.defs))
            for c in inner
        )
    if side.unit is None or side.literal or not side.is_number:
        return ()
    return (Choice(side, when, defines),)


def _join_heaps(
    a: State,
    b: State,
    joiner: Joiner,
    merge: Callable[[Value, Value], Value],
    unset: Callable[[MaybeDefault | None, MaybeDefault | None], MaybeDefault | None],
) -> dict[int, MsgObj]:
    if not a.heap and not b.heap:
        return {}
    # A sub-message one path touched and the other did not: the other reads it
    # now (it gets the same id), so that its fields join one by one.
    done: set[int] = set()
    while True:
        todo = []
        for ref, x_obj in a.heap.items():
            y_obj = b.heap.get(ref)
            if (
                y_obj is not None
                and x_obj.fields.keys() != y_obj.fields.keys()
                and ref not in done
            ):
                todo.append(ref)
        if not todo:
            break
        todo.sort()
        for ref in todo:
            done.add(ref)
            x_obj, y_obj = a.heap[ref], b.heap[ref]
            for fname in sorted(x_obj.fields.keys() - y_obj.fields.keys()):
                if x_obj.fields[fname].ref is not None:
                    joiner.complete(b, ref, fname)
            for fname in sorted(y_obj.fields.keys() - x_obj.fields.keys()):
                if y_obj.fields[fname].ref is not None:
                    joiner.complete(a, ref, fname)
    heap: dict[int, MsgObj] = {}
    for ref in sorted(a.heap.keys() | b.heap.keys()):
        if ref not in a.heap or ref not in b.heap:
            heap[ref] = (a.heap.get(ref) or b.heap[ref]).copy()
            continue
        x_obj, y_obj = a.heap[ref], b.heap[ref]
        origin = x_obj.origin if x_obj.origin == y_obj.origin else "unknown"
        merged = MsgObj(
            x_obj.type,
            origin,
            owner=x_obj.owner,
            reported=x_obj.reported | y_obj.reported,
            # settled on one path: its facts hold there only, and stay there
            pending=x_obj.pending and y_obj.pending,
            label=x_obj.label,
            extra=x_obj.extra
            if not y_obj.extra or y_obj.extra == x_obj.extra
            else x_obj.extra + tuple(e for e in y_obj.extra if e not in x_obj.extra),
        )
        for fname in sorted(x_obj.fields.keys() | y_obj.fields.keys()):
            fx, fy = x_obj.fields.get(fname), y_obj.fields.get(fname)
            if fx is None:  # never read on that path, so nothing ties the two
                fx = joiner.complete(a, ref, fname)
            if fy is None:
                fy = joiner.complete(b, ref, fname)
            ux, uy = _unset(x_obj, fname, fx), _unset(y_obj, fname, fy)
            if ux is None and uy is None:
                merged.fields[fname] = merge(fx, fy)
                continue
            if fx.default_of is not None and fy.default_of is not None:
                continue  # its default on both paths: unset, as it was
            found = unset(ux, uy)
            if found is not None:
                merged.unset = merged.unset or {}
                merged.unset[fname] = found
            merged.fields[fname] = replace(merge(fx, fy), default_of=None)
        heap[ref] = merged
    return heap


def _tie(
    merged: Value,
    x: Value,
    y: Value,
    a: State,
    b: State,
    p: A.Expr,
    joiner: Joiner,
) -> A.Expr | None:
    """`merged` is x where p holds, y where it does not (and what x and y are, if
    they were merged earlier and their paths never read them)."""
    paths = ((x, a), (y, b))
    ties = joiner.ties(merged, paths) if merged.kind == "unknown" else ([], [])
    sides: list[list[A.Expr]] = []
    for (side, state), tied in zip(paths, ties, strict=True):
        parts: list[A.Expr] = []
        if merged.term is not None and side.term is not None:
            parts.append(A.Binary("==", merged.term, side.term))
        parts += tied
        parts += state.pending(state.defs_of(side))
        sides.append(parts)
    if not sides[0] and not sides[1]:
        return None
    return A.Binary(
        "or",
        A.Binary("and", p, A.conjoin(sides[0])),
        A.Binary("and", A.Unary("not", p), A.conjoin(sides[1])),
    )


def _unset(obj: MsgObj, name: str, value: Value) -> MaybeDefault | None:
    """When field `name` of `obj` (holding `value`) still has its ROS default."""
    if value.default_of is not None and value.term is not None:
        return MaybeDefault(A.TRUE, value.term, value.default_of)
    return obj.unset.get(name) if obj.unset else None


def _unbound(binding: Binding | None) -> tuple[bool, A.Expr | None]:
    """Whether it is known when a binding is unbound, and when: never (None), always
    (TRUE, an absent name), or under a condition."""
    if binding is None:
        return True, A.TRUE
    if isinstance(binding, MaybeUnbound):
        return binding.when is not None, binding.when
    return True, None


def _bound_value(binding: Binding | None) -> Value | None:
    """What a binding holds where it is bound, if known."""
    if isinstance(binding, MaybeUnbound):
        return binding.value
    return binding


def _tests(binding: Binding | None, side: State) -> Decisions:
    """The decisions of the paths through `side` on which `binding` is unbound."""
    if binding is None:
        return side.tests
    if isinstance(binding, MaybeUnbound):
        return merged(binding.tests, side.tests)
    return ()


def _early(binding: Binding | None, common: frozenset[int]) -> frozenset[int]:
    """The decisions before `binding` became unbound (`common`: before this join)."""
    if isinstance(binding, MaybeUnbound) and binding.when is not None:
        return binding.early
    return common


def _either(
    chosen: tuple[A.Expr, Defs], on_a: A.Expr | None, on_b: A.Expr | None
) -> A.Expr:
    """`on_a` on the path where the selector holds, `on_b` on the other (None:
    false), with the selector's definition: a condition a read can ask alone."""
    p, defines = chosen
    parts = []
    if on_a is not None:
        parts.append(p if on_a == A.TRUE else A.Binary("and", p, on_a))
    if on_b is not None:
        not_p = A.Unary("not", p)
        parts.append(not_p if on_b == A.TRUE else A.Binary("and", not_p, on_b))
    result = parts[0]
    for part in parts[1:]:
        result = A.Binary("or", result, part)
    return A.conjoin([fact for _, fact in defines] + [result])


def rebound(a: State, b: State, kind: str) -> list[str]:
    """The names `a` binds to a value of `kind` that `b` binds otherwise, sorted."""
    other = b.env.get  # (most names hold the same value on both paths: asked first)
    return sorted(
        [
            name
            for name, x in a.env.items()
            if other(name) is not x and isinstance(x, Value) and x.kind == kind
        ]
    )


def _one_message(a: State, b: State, joiner: Joiner) -> State:
    """A name bound to a different message of one type on each path (`twist =
    Twist()`, and on one branch `twist = go_straight(1.0)`): when nothing else on
    either path holds either message or a part of it, `b`'s is given the ids of
    `a`'s, so that the heap join merges the two field by field (as it does one
    message set on both paths). Otherwise the name is unknown after the join."""
    if not a.heap or not b.heap:
        return b
    for name in rebound(a, b, "msg"):
        x, y = a.env[name], b.env.get(name)
        if (
            isinstance(x, Value)
            and isinstance(y, Value)
            and y.kind == "msg"
            and x.name == y.name
            and x.ref is not None
            and y.ref is not None
            and x.ref != y.ref
            and x.ref in a.heap
            and y.ref in b.heap
        ):
            pairs = _pairs(a, b, name, x.ref, y.ref, joiner)
            if pairs is not None:
                b = _renamed(b, name, *pairs)
    return b


def _pairs(
    a: State, b: State, name: str, ra: int, rb: int, joiner: Joiner
) -> tuple[dict[int, int], set[int]] | None:
    """`b`'s ids of `name`'s message and its sub-messages -> `a`'s, and the ids
    of `b` to drop (what `b` had of `a`'s message, which it no longer holds);
    None when another name, field or container holds a part of either."""
    if not joiner.kept(name, b, rb):
        return None
    held_a = _held(a, name)
    held_b = _held(b, name)
    pairs: dict[int, int] = {}
    todo = [(rb, ra)]
    while todo:
        sb, sa = todo.pop()
        ob, oa = b.heap.get(sb), a.heap.get(sa)
        if sb in pairs or ob is None or oa is None or ob.type != oa.type:
            return None
        pairs[sb] = sa
        for fname in sorted(ob.fields):
            fb = ob.fields[fname]
            if fb.elements is not None or fb.keys is not None or fb.items is not None:
                return None  # an array field's messages are not followed here
            if fb.kind != "msg":
                continue
            fa = oa.fields.get(fname)
            if fa is None:
                fa = joiner.complete(a, sa, fname)
            if fb.ref is None or fa.kind != "msg" or fa.ref is None:
                return None
            todo.append((fb.ref, fa.ref))
    ours_a = _parts(a, set(pairs.values()))
    ours_b = _parts(b, set(pairs))
    drop = _parts(b, set(pairs.values()))
    if ours_a & held_a or (ours_b | drop) & held_b or set(pairs) & ours_a:
        return None
    return pairs, drop - set(pairs)


def _held(state: State, name: str) -> set[int]:
    """The messages the names other than `name` hold, and their parts."""
    found: set[int] = set()
    todo: list[Binding | None] = [v for n, v in state.env.items() if n != name]
    while todo:
        value = todo.pop()
        if isinstance(value, MaybeUnbound):
            value = value.value
        if value is None:
            continue
        if value.kind == "msg" and value.ref is not None and value.ref not in found:
            found.add(value.ref)
            obj = state.heap.get(value.ref)
            if obj is not None:
                todo.extend(obj.fields.values())
        todo.extend(value.elements or ())
        todo.extend(value.keys or ())
    return found


def _parts(state: State, roots: set[int]) -> set[int]:
    """`roots` and every message of `state` that is a part of one (by owner)."""
    found = set(roots)
    grew = True
    while grew:
        grew = False
        for ref, obj in state.heap.items():
            if ref not in found and obj.owner is not None and obj.owner[0] in found:
                found.add(ref)
                grew = True
    return found


def _renamed(b: State, name: str, pairs: dict[int, int], drop: set[int]) -> State:
    """`b` with the messages of `pairs` under their new ids (`b` is not changed)."""

    def moved(value: Value) -> Value:
        ref = pairs.get(value.ref) if value.kind == "msg" and value.ref else None
        owner = value.default_of
        if owner is not None and owner[0] in pairs:
            value = replace(value, default_of=(pairs[owner[0]], owner[1]))
        return value if ref is None else replace(value, ref=ref)

    heap: dict[int, MsgObj] = {}
    for ref, obj in b.heap.items():
        if ref in drop:
            continue
        if ref in pairs:
            obj = obj.copy()
            obj.fields = {k: moved(v) for k, v in obj.fields.items()}
            if obj.owner is not None and obj.owner[0] in pairs:
                obj.owner = (pairs[obj.owner[0]], obj.owner[1])
            if obj.unset:
                obj.unset = {
                    k: replace(u, owner=(pairs.get(u.owner[0], u.owner[0]), u.owner[1]))
                    for k, u in obj.unset.items()
                }
        heap[pairs.get(ref, ref)] = obj
    env = dict(b.env)
    env[name] = moved(b.env[name])  # type: ignore[arg-type]
    return State(
        env,
        heap,
        b.facts,
        b.reachable,
        b.versions,
        b.defined,
        b.shared,
        b.exits,
        b.tests,
    )


def _common(a: Sequence[object], b: Sequence[object]) -> int:
    """The length of the prefix `a` and `b` share (the same objects)."""
    common = 0
    for x, y in zip(a, b, strict=False):
        if x is not y:
            break
        common += 1
    return common
