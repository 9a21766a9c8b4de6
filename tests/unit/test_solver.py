"""The two certainty questions on hand-built VCs."""

from __future__ import annotations

from fractions import Fraction

import pytest

from robotfix.annotations import ast as A
from robotfix.smt.fold import fold
from robotfix.smt.solver import check
from robotfix.vc import VC, Proved, Unproven, Violated

X = A.Sym(1, "real")


def num(n: int) -> A.Num:
    return A.Num(Fraction(n), True)


def test_proved_violated_unproven() -> None:
    assert check(VC((A.Binary("<", X, num(1)),), A.Binary("<", X, num(2)))) == Proved()
    violated = check(VC((A.Binary("==", X, num(5)),), A.Binary("<", X, num(2)), (X,)))
    assert isinstance(violated, Violated) and violated.probe_values == ("5",)
    assert isinstance(check(VC((), A.Binary("<", X, num(2)))), Unproven)


def test_sort_confusion_weakens_never_refutes() -> None:
    text = A.Str("a")
    assert not isinstance(check(VC((), A.Binary("<", text, num(2)))), Violated)


def test_nonlinear_goal_gives_a_verdict() -> None:
    y = A.Sym(2, "real")
    goal = A.Binary(">", A.Binary("*", X, y), A.Binary("*", X, A.Binary("*", y, y)))
    assert check(VC((), goal), rlimit=50_000) is not None


def test_a_counterexample_is_no_value_where_a_term_was_approximated(
    monkeypatch: object,
) -> None:
    """A product of too high a degree becomes a fresh constant, so z3's model is
    no execution's values: nothing is shown when that model is the last resort
    (the witness search, which found `x` but had no value for the probe, once
    reset the flag the goal had set)."""
    import pytest

    from robotfix.smt import solver

    assert isinstance(monkeypatch, pytest.MonkeyPatch)
    monkeypatch.setattr(solver.Session, "_example", lambda self, vc: None)
    quartic = A.Binary("*", A.Binary("*", X, X), A.Binary("*", X, X))
    label = A.Sym(9, "str")  # no value the witness knows: the model is asked
    found = check(VC((), A.Binary("<", quartic, num(5)), (label,)))
    assert isinstance(found, Unproven)
    assert found.probe_values == (None,) and found.sym_values == ()


FLOORED = [Fraction(n) for n in (-7, -3, -1, 0, 1, 2, 7)] + [
    Fraction(-7, 2),
    Fraction(5, 4),
]


@pytest.mark.parametrize("op", ["//", "%"])
def test_floored_division_is_pythons(op: str) -> None:
    """`a // b` and `a % b` mean what Python computes, for ints and floats and
    either sign of the divisor (z3's int div and mod are Euclidean), folded and
    encoded alike, the divisor a symbol or a constant."""
    for a in FLOORED:
        for b in FLOORED:
            if b == 0:
                continue
            expected = eval(f"{float(a)!r} {op} {float(b)!r}")
            exact = Fraction(a // b) if op == "//" else a % b
            assert float(exact) == expected
            left = _sym_or_int(1, a)
            right = _sym_or_int(2, b)
            facts = (A.Binary("==", left, _num(a)), A.Binary("==", right, _num(b)))
            for divisor in (right, _num(b)):
                goal = A.Binary("==", A.Binary(op, left, divisor), _num(exact))
                assert check(VC(facts, goal)) == Proved(), (a, op, b)
            assert fold(A.Binary(op, _num(a), _num(b))) == exact


def _num(value: Fraction) -> A.Num:
    return A.Num(value, value.denominator == 1)


def _sym_or_int(ident: int, value: Fraction) -> A.Sym:
    """An int symbol for a whole number (int // int stays an int), else a real."""
    return A.Sym(ident, "int") if value.denominator == 1 else A.Sym(ident + 10, "real")
