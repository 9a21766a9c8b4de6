"""The abstract state of one path: bindings, message heap, and path facts.

A state is mutated while one straight-line path is interpreted and copied (`fork`)
where paths split; `join` merges two paths back into one. Facts are kept as a list
whose common prefix is shared, so a join only has to disjoin what the branches added.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from robotfix.analysis.values import MsgObj, Value
from robotfix.annotations import ast as A


@dataclass(frozen=True)
class MaybeUnbound:
    """A name bound on some paths only: reading it is unknown, not an error."""


MAYBE = MaybeUnbound()
Binding = Value | MaybeUnbound


@dataclass
class State:
    env: dict[str, Binding] = field(default_factory=dict)
    heap: dict[int, MsgObj] = field(default_factory=dict)
    facts: list[A.Expr] = field(default_factory=list)
    reachable: bool = True

    def fork(self) -> State:
        return State(
            dict(self.env),
            {k: v.copy() for k, v in self.heap.items()},
            list(self.facts),
            self.reachable,
        )

    def assume(self, fact: A.Expr | None) -> None:
        if fact is not None and fact != A.TRUE:
            self.facts.append(fact)


def join(a: State, b: State, fresh: Callable[[Value, Value], Value]) -> State:
    """Merge two paths; `fresh(x, y)` makes the value for a name they disagree on.

    The merged value `s` is tied to each side by a fact (`s == x` on the first path,
    `s == y` on the second) inside the disjunction of what the paths assumed.
    """
    if not a.reachable:
        return b
    if not b.reachable:
        return a
    extra_a: list[A.Expr] = []
    extra_b: list[A.Expr] = []

    def merge(x: Value, y: Value) -> Value:
        if x == y:
            return x
        value = fresh(x, y)
        if value.term is not None and x.term is not None and y.term is not None:
            extra_a.append(A.Binary("==", value.term, x.term))
            extra_b.append(A.Binary("==", value.term, y.term))
        return value

    env: dict[str, Binding] = {}
    for name in sorted(a.env.keys() | b.env.keys()):
        x, y = a.env.get(name, MAYBE), b.env.get(name, MAYBE)
        both = isinstance(x, Value) and isinstance(y, Value)
        env[name] = merge(x, y) if both else (x if x == y else MAYBE)  # type: ignore[arg-type]
    heap: dict[int, MsgObj] = {}
    for ref in sorted(a.heap.keys() | b.heap.keys()):
        x_obj, y_obj = a.heap.get(ref), b.heap.get(ref)
        if x_obj is None or y_obj is None:
            heap[ref] = (x_obj or y_obj).copy()  # type: ignore[union-attr]
            continue
        origin = x_obj.origin if x_obj.origin == y_obj.origin else "unknown"
        merged = MsgObj(
            x_obj.type,
            origin,
            owner=x_obj.owner,
            reported=x_obj.reported | y_obj.reported,
            # settled on one path: its facts hold there only, and stay there
            pending=x_obj.pending and y_obj.pending,
            label=x_obj.label,
        )
        for fname in sorted(x_obj.fields.keys() | y_obj.fields.keys()):
            fx, fy = x_obj.fields.get(fname), y_obj.fields.get(fname)
            if fx is not None and fy is not None:
                merged.fields[fname] = merge(fx, fy)
            else:  # set on one path only: neither its value nor its default is sure
                only = fx or fy
                assert only is not None
                merged.fields[fname] = fresh(only, only)
                merged.reported.add(fname)
        heap[ref] = merged
    facts = _join_facts(a.facts + extra_a, b.facts + extra_b)
    return State(env, heap, facts, True)


def _join_facts(a: list[A.Expr], b: list[A.Expr]) -> list[A.Expr]:
    common = 0
    while common < min(len(a), len(b)) and a[common] is b[common]:
        common += 1
    rest_a, rest_b = a[common:], b[common:]
    if not rest_a or not rest_b:
        return a[:common]
    return [*a[:common], A.Binary("or", A.conjoin(rest_a), A.conjoin(rest_b))]
