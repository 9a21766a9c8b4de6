"""The abstract state of one path: bindings, message heap, and path facts.

A state is mutated while one straight-line path is interpreted and copied (`fork`)
where paths split; `join` merges two paths back into one. Facts are kept as a list
whose common prefix is shared, so a join only has to disjoin what the branches added.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Protocol

from robotfix.analysis.values import Defs, MaybeDefault, MsgObj, Value
from robotfix.annotations import ast as A


@dataclass(frozen=True)
class MaybeUnbound:
    """A name bound on some paths only. `when` is the condition, over the selectors
    of the joins it went through, under which it is unbound; None when that is not
    known (a `del`, a loop variable): reading it is then unknown, never an error."""

    when: A.Expr | None = None


MAYBE = MaybeUnbound()
Binding = Value | MaybeUnbound


@dataclass
class State:
    env: dict[str, Binding] = field(default_factory=dict)
    heap: dict[int, MsgObj] = field(default_factory=dict)
    facts: list[A.Expr] = field(default_factory=list)
    reachable: bool = True
    # How often an unknown object (by its term) may have been changed on this path:
    # its attributes read at one version are the same values.
    versions: dict[A.Expr, int] = field(default_factory=dict)
    defined: set[int] = field(default_factory=set)  # keys of the Defs in `facts`
    # What the values merged at joins are, by symbol: the facts (keyed, to be added
    # once) that tie each to what each path held. They join a path's facts only
    # where the value is read (`use`), so that a merge nobody reads costs the solver
    # nothing. One table for the states of one function (symbols are unique).
    defs: dict[int, Defs] = field(default_factory=dict)

    def fork(self) -> State:
        return State(
            dict(self.env),
            {k: v.copy() for k, v in self.heap.items()},
            list(self.facts),
            self.reachable,
            dict(self.versions),
            set(self.defined),
            self.defs,
        )

    def use(self, value: Value) -> Value:
        """A value is read: if it was merged at a join, what it is holds from here."""
        term = value.term
        if type(term) is A.Sym and term.ident in self.defs:
            for key, fact in self.defs[term.ident]:
                if key not in self.defined:
                    self.defined.add(key)
                    self.facts.append(fact)
        return value

    def defs_of(self, value: Value) -> Defs:
        term = value.term
        return self.defs.get(term.ident, ()) if isinstance(term, A.Sym) else ()

    def pending(self, defs: Defs) -> list[A.Expr]:
        """The facts of `defs` this path does not hold yet."""
        return [fact for key, fact in defs if key not in self.defined]

    def changed(self, value: Value) -> None:
        """Code may have changed this object: its attributes are read anew."""
        if value.kind == "unknown" and isinstance(value.term, A.Sym):
            self.versions[value.term] = self.versions.get(value.term, 0) + 1

    def assume(self, fact: A.Expr | None) -> None:
        if fact is not None and fact != A.TRUE:
            self.facts.append(fact)


class Joiner(Protocol):
    def merged(self, x: Value, y: Value) -> Value:
        """A fresh value for two that differ (tied to each by a fact)."""

    def selector(self) -> A.Expr:
        """A fresh boolean: true on the first path of a join, false on the second."""

    def ties(self, merged: Value, side: Value, state: State) -> list[A.Expr]:
        """Facts that hold of a merged value of unknown kind on the path where it
        is `side`: whether it is None, whether it is true (`x = None` on one
        path, an object on the other, and `if x:` after)."""

    def complete(self, state: State, ref: int, name: str) -> Value:
        """What `state` holds in field `name` of message `ref`, which it never
        touched (its default, an unknown, or the sub-message of the same id)."""


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
    common = _common(a.facts, b.facts)
    rest_a, rest_b = a.facts[common:], b.facts[common:]
    chosen: list[tuple[A.Expr, Defs]] = []

    def selector() -> tuple[A.Expr, Defs]:
        """The join's selector and the fact that defines it."""
        if not chosen:
            p = joiner.selector()
            assert isinstance(p, A.Sym)
            defines = A.Binary(
                "or",
                A.Binary("and", p, A.conjoin(rest_a)),
                A.Binary("and", A.Unary("not", p), A.conjoin(rest_b)),
            )
            chosen.append((p, ((p.ident, defines),)))
        return chosen[0]

    def merge(x: Value, y: Value) -> Value:
        if x is y and x.default_of is None and x.unset is None:
            return x
        ux, uy = _unset(x), _unset(y)
        if x == y and ux == uy:
            return x
        value = x
        if x != y:
            value = joiner.merged(x, y)
            if isinstance(value.term, A.Sym):
                p, defines = selector()
                tie = _tie(value, x, y, a, b, p, joiner)
                if tie is not None:
                    a.defs[value.term.ident] = (*defines, (value.term.ident, tie))
        known = ux or uy
        if known is not None:
            when = _either(
                selector(),
                None if ux is None else ux.when,
                None if uy is None else uy.when,
            )
            unset = MaybeDefault(when, known.default, known.owner)
            value = replace(value, default_of=None, unset=unset)
        return value

    env: dict[str, Binding] = {}
    for name in sorted(a.env.keys() | b.env.keys()):
        x, y = a.env.get(name), b.env.get(name)
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
            env[name] = MaybeUnbound(_either(selector(), wa, wb) if known else None)
    heap = _join_heaps(a, b, joiner, merge)
    facts = a.facts[:common]
    if rest_a and rest_b:
        facts.append(A.Binary("or", A.conjoin(rest_a), A.conjoin(rest_b)))
    versions = dict(a.versions)
    for term, version in b.versions.items():
        if versions.get(term, 0) != version:
            versions[term] = max(versions.get(term, 0), version) + 1
    if b.defs is not a.defs:
        a.defs.update(b.defs)
    return State(env, heap, facts, True, versions, a.defined & b.defined, a.defs)


def _join_heaps(
    a: State, b: State, joiner: Joiner, merge: Callable[[Value, Value], Value]
) -> dict[int, MsgObj]:
    if not a.heap and not b.heap:
        return {}
    # A field one path touched and the other did not: the other reads it now.
    done: set[int] = set()
    while True:
        todo = sorted((a.heap.keys() & b.heap.keys()) - done)
        if not todo:
            break
        for ref in todo:
            done.add(ref)
            x_obj, y_obj = a.heap[ref], b.heap[ref]
            if x_obj.fields.keys() == y_obj.fields.keys():
                continue
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
            extra=x_obj.extra + tuple(e for e in y_obj.extra if e not in x_obj.extra),
        )
        for fname in sorted(x_obj.fields.keys() | y_obj.fields.keys()):
            fx, fy = x_obj.fields.get(fname), y_obj.fields.get(fname)
            if fx is None:  # never read on that path, so nothing ties the two
                fx = joiner.complete(a, ref, fname)
            if fy is None:
                fy = joiner.complete(b, ref, fname)
            merged.fields[fname] = merge(fx, fy)
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
    sides: list[list[A.Expr]] = []
    for side, state in ((x, a), (y, b)):
        parts: list[A.Expr] = []
        if merged.term is not None and side.term is not None:
            parts.append(A.Binary("==", merged.term, side.term))
        if merged.kind == "unknown":
            parts += joiner.ties(merged, side, state)
        parts += state.pending(state.defs_of(side))
        sides.append(parts)
    if not sides[0] and not sides[1]:
        return None
    return A.Binary(
        "or",
        A.Binary("and", p, A.conjoin(sides[0])),
        A.Binary("and", A.Unary("not", p), A.conjoin(sides[1])),
    )


def _unset(value: Value) -> MaybeDefault | None:
    """When a field value is still its ROS default (None: never)."""
    if value.default_of is not None and value.term is not None:
        return MaybeDefault(A.TRUE, value.term, value.default_of)
    return value.unset


def _unbound(binding: Binding | None) -> tuple[bool, A.Expr | None]:
    """Whether it is known when a binding is unbound, and when: never (None), always
    (TRUE, an absent name), or under a condition."""
    if binding is None:
        return True, A.TRUE
    if isinstance(binding, MaybeUnbound):
        return binding.when is not None, binding.when
    return True, None


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


def _common(a: list[A.Expr], b: list[A.Expr]) -> int:
    common = 0
    while common < min(len(a), len(b)) and a[common] is b[common]:
        common += 1
    return common
