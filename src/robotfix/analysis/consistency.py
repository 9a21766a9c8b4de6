"""Refinements that no value satisfies (RF509), found with the solver callback.

Such a refinement would make every path that assumes it dead, and a dead path proves
everything: so it is reported where it is declared and then treated as absent. Unit,
Frame and Tag parts are not part of the question (they are not in the predicate).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass

from robotfix.analysis.values import sort_of
from robotfix.annotations import ast as A
from robotfix.annotations.witness import has_witness
from robotfix.budget import Budget
from robotfix.ros.catalog import Invariant, MsgCatalog, MsgSpec, Origin
from robotfix.vc import VC, Proved, Verdict

Discharge = Callable[[VC], Verdict]


def contradictory(
    discharge: Discharge,
    predicate: A.Expr,
    sort: Callable[[str], str],
    idents: Iterator[int],
    budget: Budget | None = None,
) -> bool:
    """Whether no values of its names (each of sort `sort(name)`, a symbol with the
    next of `idents`) satisfy `predicate`. Undecided counts as satisfiable. The
    search for a witness is charged to `budget` (the file's)."""
    if predicate == A.TRUE or _one_bound_each(predicate):
        return False
    if has_witness(predicate, sort, budget):  # values that satisfy it: no solver
        return False
    names = sorted({n.name for n in A.names(predicate)})
    mapping: dict[str, A.Expr] = {
        name: A.Sym(next(idents), sort(name)) for name in names
    }
    verdict = discharge(VC((), A.Unary("not", A.substitute(predicate, mapping))))
    return isinstance(verdict, Proved)


def _one_bound_each(predicate: A.Expr) -> bool:
    """`_ > 0`, `a < 3 and b != 1`: one bound per name, which some value meets (no
    solver needed, the common case)."""
    bounded: list[str] = []
    for part in A.conjuncts(predicate):
        if not (isinstance(part, A.Binary) and part.op in ("<", "<=", ">", ">=", "!=")):
            return False
        name, number = (
            (part.left, part.right)
            if isinstance(part.left, A.Name)
            else (part.right, part.left)
        )
        if not isinstance(name, A.Name) or not isinstance(number, A.Num):
            return False
        bounded.append(name.name)
    return len(bounded) == len(set(bounded))


@dataclass(frozen=True)
class Contradiction:
    """The refinements of one interface-file line that no message satisfies, alone
    or with the refinements of its type declared before them (`earlier`)."""

    spec: str
    origin: Origin
    text: str
    earlier: Origin | None


def consistent_invariants(
    discharge: Discharge,
    catalog: MsgCatalog,
    spec: MsgSpec,
    idents: Iterator[int],
    budget: Budget | None = None,
) -> tuple[list[Invariant], list[Contradiction]]:
    """The invariants of `spec` that can hold together, declaration by declaration
    (one annotation line) in order, and the declarations left out."""

    def sort(path: str) -> str:
        found = catalog.field_at(spec.name, path)
        return sort_of(found.kind) if found is not None else "real"

    kept: list[Invariant] = []
    left_out: list[Contradiction] = []
    for origin, parts in _declarations(spec.invariants):
        text = " and ".join(p.text for p in parts)
        own = A.conjoin([p.predicate for p in parts])
        if contradictory(discharge, own, sort, idents, budget):
            left_out.append(Contradiction(spec.name, origin, text, None))
        elif kept and contradictory(
            discharge,
            A.conjoin([p.predicate for p in kept + parts]),
            sort,
            idents,
            budget,
        ):
            left_out.append(Contradiction(spec.name, origin, text, kept[0].origin))
        else:
            kept.extend(parts)
    return kept, left_out


def _declarations(
    invariants: list[Invariant],
) -> Iterator[tuple[Origin, list[Invariant]]]:
    groups: dict[Origin, list[Invariant]] = {}
    for inv in invariants:
        groups.setdefault(inv.origin, []).append(inv)
    yield from groups.items()
