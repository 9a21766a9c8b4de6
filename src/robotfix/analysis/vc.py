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
    pass


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
    reason: str
    out_of_budget: bool = False  # the file's solver budget was used up


Verdict = Proved | Violated | Unproven | Undecided
