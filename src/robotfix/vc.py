"""Verification conditions and the verdicts the solver layer returns for them.

Pure data: the analysis builds `VC`s; `smt.solver` answers with a `Verdict`.
"""

from __future__ import annotations

from dataclasses import dataclass

from robotfix.annotations import ast as A


@dataclass(frozen=True)
class VC:
    """Do `facts` imply `goal`? `probes` are terms a counterexample should show."""

    facts: tuple[A.Expr, ...]
    goal: A.Expr
    probes: tuple[A.Expr, ...] = ()
    # Only whether the goal is proved matters (a path's feasibility), not how it
    # fails: then no counterexample is needed.
    question: bool = False


@dataclass(frozen=True)
class Proved:
    """The goal holds on every execution the facts allow."""


@dataclass(frozen=True)
class Violated:
    """The goal fails on every execution the facts allow: an error."""

    probe_values: tuple[str | None, ...]


@dataclass(frozen=True)
class Unproven:
    """Some allowed execution breaks the goal, some keeps it: a warning."""

    probe_values: tuple[str | None, ...]
    sym_values: tuple[tuple[int, str], ...]  # a counterexample over unknown inputs


@dataclass(frozen=True)
class Undecided:
    """Neither proved nor refuted (the reason says why)."""

    reason: str
    out_of_budget: bool = False  # the file's work budget was used up


Verdict = Proved | Violated | Unproven | Undecided
# a question asked once the file's work budget (`robotfix.budget`) is spent
OUT_OF_BUDGET = Undecided("the file's work budget is used up", out_of_budget=True)


def shared_facts(known: tuple[A.Expr, ...], facts: tuple[A.Expr, ...]) -> int:
    """How many leading facts `facts` has in common with `known` (equal facts: the
    same objects, mostly, as the analysis extends a path's facts), found by tuple
    comparisons, which run in C: a VC of a long function carries thousands of facts,
    and the next VC mostly extends them."""
    count = min(len(known), len(facts))
    if (known if len(known) == count else known[:count]) == (
        facts if len(facts) == count else facts[:count]
    ):
        return count
    low, high = 0, count - 1  # known[:low] == facts[:low], known[:high + 1] differs
    while low < high:
        middle = (low + high + 1) // 2
        if known[:middle] == facts[:middle]:
            low = middle
        else:
            high = middle - 1
    return low
