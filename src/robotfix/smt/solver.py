"""Discharge verification conditions with Z3 and answer with a `Verdict`.

Two questions (SPEC §4 "Certainty"): can the goal fail under the facts (if not:
Proved)? If it can, can it also hold? If not, it fails on every execution that
reaches it along that path: Violated (an error). If it can: Unproven (a warning).
`unknown` from z3 is Undecided, never a pass.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import z3

from robotfix.analysis.vc import VC, Proved, Undecided, Unproven, Verdict, Violated
from robotfix.annotations import ast as A
from robotfix.smt.encode import Encoder

# A work budget, not wall-clock time: the same input stops at the same point on any
# machine. Linear problems of a node take a few thousand units; a million is ample.
RLIMIT = 2_000_000


def check(vc: VC, rlimit: int = RLIMIT) -> Verdict:
    """One VC on a fresh solver."""
    return Session(rlimit).check(vc)


class Session:
    """Incremental solving for the VCs of one file. One solver holds the facts of
    the current path, one push frame per fact: a VC whose facts share a prefix with
    the previous VC's pops back to it and asserts only the rest. The goal is asked as
    a check assumption. The budget (rlimit) is set once and bounds each question.
    Each session has a z3 context of its own: in z3's global context, the models
    (the values a note shows) depend on what the process solved before, so a file
    checked in another worker (`-j`) could show other values."""

    def __init__(self, rlimit: int = RLIMIT) -> None:
        self._ctx = z3.Context()
        self._solver = z3.Solver(ctx=self._ctx)
        self._solver.set("random_seed", 0)
        self._solver.set("rlimit", rlimit)
        self._facts: list[object] = []
        self._encoder = Encoder(self._ctx)

    def check(self, vc: VC) -> Verdict:
        self._assert_facts(vc.facts)
        solver, encoder = self._solver, self._encoder
        goal = encoder.boolean(vc.goal)
        first = solver.check(z3.Not(goal))
        if first == z3.unsat:
            return Proved()
        if first == z3.unknown:
            return Undecided(solver.reason_unknown())
        model = solver.model()
        values = tuple(
            _show(model.eval(encoder.encode(p), model_completion=True))
            for p in vc.probes
        )
        wanted = {s.ident for s in _syms(vc)}
        syms = tuple(
            (ident, _show(model.eval(sym, model_completion=True)))
            for ident, sym in sorted(encoder.syms.items())
            if ident in wanted
        )
        second = solver.check(goal)
        if second == z3.unsat:
            return Violated(values)
        if second == z3.unknown:
            return Undecided(solver.reason_unknown())
        return Unproven(values, syms)

    def _assert_facts(self, facts: tuple[object, ...]) -> None:
        known = self._facts
        common = 0
        while common < min(len(known), len(facts)) and known[common] is facts[common]:
            common += 1
        for _ in range(len(known) - common):
            self._solver.pop()
        del known[common:]
        for fact in facts[common:]:
            self._solver.push()
            self._solver.add(self._encoder.boolean(fact))  # type: ignore[arg-type]
            known.append(fact)


def _syms(vc: VC) -> set[A.Sym]:
    found = A.syms(vc.goal)
    for fact in vc.facts:
        found |= A.syms(fact)
    return found


def _show(value: Any) -> str:
    if z3.is_int_value(value):
        return str(value.as_long())
    if z3.is_rational_value(value):
        exact = Fraction(value.numerator_as_long(), value.denominator_as_long())
        return _decimal(exact)
    if z3.is_algebraic_value(value):
        return str(value.as_decimal(6)).rstrip("?")
    if z3.is_true(value) or z3.is_false(value):
        return "True" if z3.is_true(value) else "False"
    if z3.is_string_value(value):
        return repr(value.as_string())
    return str(value)


def _decimal(value: Fraction) -> str:
    if value.denominator == 1:
        return str(value.numerator)
    as_float = float(value)
    if Fraction(as_float) == value or len(repr(as_float)) < 12:
        return repr(as_float)
    return f"{value.numerator}/{value.denominator}"
