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
    """Incremental solving for the VCs of one file: while each VC's facts extend
    the previous VC's (the common case along a path), only the new facts are asserted,
    and the goal is asked inside push/pop. The budget is per question."""

    def __init__(self, rlimit: int = RLIMIT) -> None:
        self.rlimit = rlimit
        self._facts: tuple[object, ...] = ()
        self._solver: Any = None
        self._encoder = Encoder()

    def check(self, vc: VC) -> Verdict:
        self._assert_facts(vc.facts)
        solver, encoder = self._solver, self._encoder
        goal = encoder.boolean(vc.goal)
        probes = [encoder.encode(p) for p in vc.probes]
        solver.push()
        try:
            solver.add(z3.Not(goal))
            first = solver.check()
            if first == z3.unsat:
                return Proved()
            if first == z3.unknown:
                return Undecided(solver.reason_unknown())
            model = solver.model()
            values = tuple(_show(model.eval(p, model_completion=True)) for p in probes)
            wanted = {s.ident for s in _syms(vc)}
            syms = tuple(
                (ident, _show(model.eval(sym, model_completion=True)))
                for ident, sym in sorted(encoder.syms.items())
                if ident in wanted
            )
        finally:
            solver.pop()
        solver.push()
        try:
            solver.add(goal)
            second = solver.check()
        finally:
            solver.pop()
        if second == z3.unsat:
            return Violated(values)
        if second == z3.unknown:
            return Undecided(solver.reason_unknown())
        return Unproven(values, syms)

    def _assert_facts(self, facts: tuple[object, ...]) -> None:
        known = self._facts
        extends = (
            self._solver is not None
            and len(facts) >= len(known)
            and all(a is b for a, b in zip(known, facts, strict=False))
        )
        if not extends:
            self._solver = z3.Solver()
            self._solver.set("random_seed", 0)
            self._solver.set("rlimit", self.rlimit)
            known = ()
        for fact in facts[len(known) :]:
            self._solver.add(self._encoder.boolean(fact))  # type: ignore[arg-type]
        self._facts = facts


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
