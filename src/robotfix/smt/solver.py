"""Discharge verification conditions with Z3 and answer with a `Verdict`.

Two questions (SPEC §4 "Certainty"): can the goal fail under the facts (if not:
Proved)? If it can, can it also hold? If not, it fails on every execution that
reaches it along that path: Violated (an error). If it can: Unproven (a warning).
`unknown` from z3 is Undecided, never a pass.

Every session has a z3 context of its own, so the answers for a file never depend on
what was checked before in the same process. z3's work (its rlimit count) is charged
to the file's work budget (`robotfix.budget`), shared with every other stage of the
check, so no file can keep the solver busy for long.
"""

from __future__ import annotations

import operator
from fractions import Fraction
from typing import Any

import z3

from robotfix.annotations import ast as A
from robotfix.annotations import witness
from robotfix.budget import ENCODE_STEPS, RLIMIT, Z3_UNITS_PER_STEP, Budget
from robotfix.smt import shown
from robotfix.smt.encode import Encoder
from robotfix.vc import (
    OUT_OF_BUDGET,
    VC,
    Proved,
    Undecided,
    Unproven,
    Verdict,
    Violated,
    shared_facts,
)

# Two of z3's nonlinear heuristics hardly count their work: Groebner bases and Horner
# schemes ran for minutes within a small rlimit. Without them (and with products of
# high degree left out by the encoder) nonlinear questions stay bounded, and the ones
# real code asks (v * t + v * v / (2 * a) < d) are still decided.
SETTINGS = {
    "random_seed": 0,
    "smt.arith.nl.grobner": False,
    "smt.arith.nl.horner": False,
}


def check(vc: VC, rlimit: int = RLIMIT) -> Verdict:
    """One VC on a fresh solver."""
    return Session(rlimit).check(vc)


class Session:
    """Incremental solving for the VCs of one file. One solver holds the facts of
    the current path, one push frame per fact: a VC whose facts share a prefix with
    the previous VC's pops back to it and asserts only the rest. The goal is asked as
    a check assumption. Each question may use `rlimit` units of z3's work, charged to
    `budget` (the file's, a step per `Z3_UNITS_PER_STEP` units); once that is spent,
    every question is Undecided."""

    def __init__(self, rlimit: int = RLIMIT, budget: Budget | None = None) -> None:
        self._ctx = z3.Context()
        self._solver = self._new_solver()
        self._scratch: Any = None  # for questions without facts
        self._rlimit = rlimit
        self._budget = budget if budget is not None else Budget()
        self._units = 0  # z3's work in this session's context so far
        self._paid = 0  # the steps charged for it
        self._limit = rlimit
        self._facts: tuple[A.Expr, ...] = ()
        self._approximated: list[bool] = []  # per fact asserted
        self._encoder = Encoder(self._ctx)

    @property
    def exhausted(self) -> bool:
        return self._budget.spent

    def check(self, vc: VC) -> Verdict:
        if self.exhausted:
            return OUT_OF_BUDGET
        built = self._encoder.built
        try:
            return self._check(vc)
        finally:  # the terms built for it, through z3's (slow) Python API
            self._budget.spend((self._encoder.built - built) * ENCODE_STEPS)

    def _check(self, vc: VC) -> Verdict:
        self._encoder.start()
        if not vc.facts:
            # a question without facts (RF509's: can a refinement hold?) is asked of
            # a solver of its own, so it leaves the path's facts asserted and the
            # answers on the path the same whether it was asked or not
            self._scratch = self._scratch or self._new_solver()
            solver, self._solver = self._solver, self._scratch
            try:
                return self._decide(vc)
            finally:
                self._solver = solver
        self._assert_facts(vc.facts)
        return self._decide(vc)

    def _new_solver(self) -> Any:
        solver = z3.Solver(ctx=self._ctx)
        for name, value in SETTINGS.items():
            solver.set(name, value)
        return solver

    def _decide(self, vc: VC) -> Verdict:
        solver, encoder = self._solver, self._encoder
        goal = encoder.boolean(vc.goal)
        first = self._ask(z3.Not(goal))
        if first == z3.unsat:
            return Proved()
        if first == z3.unknown:
            return self._undecided()
        # A term z3 saw as a fresh constant makes the model no execution's values.
        approximated = encoder.approximated or (
            bool(vc.facts) and any(self._approximated)
        )
        example = self._witnessed(vc) or self._example(vc)
        if example is None:  # not found on its own: the session's model
            example = _values(vc, solver.model(), encoder, approximated, self._budget)
        values, syms = example
        second = self._ask(goal)
        if second == z3.unsat:
            return Violated(values)
        if second == z3.unknown:
            return self._undecided()
        return Unproven(values, syms)

    def _witnessed(self, vc: VC) -> Example | None:
        """The values shown for a VC whose goal can fail: first values found by
        trying candidates, exactly checked against the facts and the goal's
        negation (`witness.example`). Like `_example`'s, they depend on the VC
        alone, and they cost no solver call; None when none is found or a probe
        has no exact value."""
        found = witness.example(
            [*vc.facts, A.Unary("not", vc.goal)], budget=self._budget
        )
        if found is None:
            return None
        encoder, ctx = self._encoder, self._ctx
        constants = {sym: _constant(sym, value, ctx) for sym, value in found.items()}
        pairs = [(encoder.sym(sym), const) for sym, const in constants.items()]
        values: list[str | None] = []
        for probe in vc.probes:
            encoder.approximated = False
            term = encoder.encode(probe)
            shown = z3.simplify(z3.substitute(term, *pairs) if pairs else term)
            if encoder.approximated or not _is_value(shown):
                return None
            values.append(_show(shown))
        syms = tuple(
            (sym.ident, _show(constants[sym]))
            for sym in sorted(constants, key=lambda sym: sym.ident)
        )
        return tuple(values), syms

    def _example(self, vc: VC) -> Example | None:
        """The values shown for a VC whose goal can fail when no candidate is one
        (`_witnessed`): from a context of their own with the symbols named in the
        order they are met, so they depend on the VC alone, never on what the
        session was asked before; so the editor, which keeps verdicts across edits
        (`smt.memo`) and asks fewer questions, shows what a fresh check shows. None
        when that solver does not find a model within the question's limit."""
        if self.exhausted:
            return None
        ctx = z3.Context()
        solver = z3.Solver(ctx=ctx)
        for name, value in SETTINGS.items():
            solver.set(name, value)
        encoder = Encoder(ctx, canonical=True)
        for fact in vc.facts:
            solver.add(encoder.boolean(fact))
        goal = encoder.boolean(vc.goal)
        self._budget.spend(encoder.built * ENCODE_STEPS)
        limit = min(self._rlimit, self._units_left())
        if limit <= 0:  # never ask with rlimit 0: to z3 that means no limit
            return None
        solver.set("rlimit", limit)
        found = solver.check(z3.Not(goal))
        units = _work_done(solver)
        self._budget.spend(-(-units // Z3_UNITS_PER_STEP))  # rounded up
        if found != z3.sat:
            return None
        built = encoder.built
        example = _values(
            vc, solver.model(), encoder, encoder.approximated, self._budget
        )
        self._budget.spend((encoder.built - built) * ENCODE_STEPS)
        return example

    def _units_left(self) -> int:
        return self._budget.left * Z3_UNITS_PER_STEP

    def _ask(self, assumption: Any) -> Any:
        """One question, within what is left of the file's budget."""
        self._limit = min(self._rlimit, self._units_left())
        if self._limit <= 0:  # never ask with rlimit 0: to z3 that means no limit
            return z3.unknown
        self._solver.set("rlimit", self._limit)
        result = self._solver.check(assumption)
        self._units = max(self._units, _work_done(self._solver))
        owed = -(-self._units // Z3_UNITS_PER_STEP) - self._paid  # rounded up
        self._budget.spend(owed)
        self._paid += owed
        return result

    def _undecided(self) -> Undecided:
        if self._limit <= 0 or self.exhausted:  # stopped by the file's budget
            return OUT_OF_BUDGET
        return Undecided(self._solver.reason_unknown())

    def _assert_facts(self, facts: tuple[A.Expr, ...]) -> None:
        known = self._facts
        common = _identical(known, facts)
        for _ in range(len(known) - common):
            self._solver.pop()
        del self._approximated[common:]
        encoder = self._encoder
        for fact in facts[common:]:
            encoder.approximated = False
            self._solver.push()
            self._solver.add(encoder.boolean(fact))
            self._approximated.append(encoder.approximated)
        self._facts = facts
        encoder.approximated = False


Example = tuple[tuple[str | None, ...], tuple[tuple[int, str], ...]]


def _values(
    vc: VC, model: Any, encoder: Encoder, approximated: bool, budget: Budget
) -> Example:
    """The VC's probes and unknown inputs in `model` (its facts and goal encoded
    by `encoder`, `approximated` if a term of theirs was); none when a term was
    approximated: the model is then no execution's values. The facts read for
    their symbols are charged to `budget`, a step each."""
    encoder.approximated = False
    probes = [encoder.encode(p) for p in vc.probes]
    exact = not encoder.approximated and not approximated
    values = tuple(
        _show(model.eval(p, model_completion=True)) if exact else None for p in probes
    )
    wanted: set[int] = set()
    if exact:
        budget.spend(1 + len(vc.facts))
        wanted = {s.ident for s in A.syms(vc.goal, *vc.facts)}
    syms = tuple(
        (ident, _show(model.eval(sym, model_completion=True)))
        for ident, sym in sorted(encoder.syms.items())
        if ident in wanted
    )
    return values, syms


def _constant(sym: A.Sym, value: Fraction | bool | str, ctx: Any) -> Any:
    """`value` as a z3 value of `sym`'s sort (shown as a model's would be)."""
    if isinstance(value, bool):
        return z3.BoolVal(value, ctx)
    if isinstance(value, str):
        return z3.StringVal(value, ctx)
    if sym.sort == "int":
        return z3.IntVal(value.numerator, ctx)
    return z3.RealVal(value, ctx)


def _is_value(term: Any) -> bool:
    return bool(
        z3.is_int_value(term)
        or z3.is_rational_value(term)
        or z3.is_true(term)
        or z3.is_false(term)
        or z3.is_string_value(term)
    )


def _identical(known: tuple[A.Expr, ...], facts: tuple[A.Expr, ...]) -> int:
    """How many leading facts are the very objects asserted: equal ones found by
    `shared_facts` (in C), then checked for identity, since a fact with a name
    encodes to a fresh constant each time it is asserted."""
    common = shared_facts(known, facts)
    if all(map(operator.is_, known, facts[:common])):
        return common
    return next(i for i in range(common) if known[i] is not facts[i])


def _work_done(solver: Any) -> int:
    """The units of work the session's context has spent so far."""
    stats = solver.statistics()
    names = stats.keys()
    return int(stats.get_key_value("rlimit count")) if "rlimit count" in names else 0


def _show(value: Any) -> str:
    if z3.is_int_value(value):
        return shown.integer(value.as_string())
    if z3.is_rational_value(value):
        numerator = value.numerator().as_string()
        return shown.rational(numerator, value.denominator().as_string())
    if z3.is_algebraic_value(value):
        return str(value.as_decimal(6)).rstrip("?")
    if z3.is_true(value) or z3.is_false(value):
        return "True" if z3.is_true(value) else "False"
    if z3.is_string_value(value):
        return repr(value.as_string())
    return str(value)
