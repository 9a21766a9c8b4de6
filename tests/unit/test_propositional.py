"""Path questions decided on the boolean skeleton, without z3."""

from fractions import Fraction

from robotfix.annotations import ast as A
from robotfix.api import Discharger
from robotfix.smt.propositional import satisfiable
from robotfix.vc import VC, Proved, Unproven

P, Q = A.Sym(1, "bool"), A.Sym(2, "bool")
X = A.Sym(3, "real")
ONE = A.Num(Fraction(1), False)


def test_contradictory_tests_have_no_model() -> None:
    assert satisfiable([P, A.Unary("not", P)]) is False
    # `x <= 1` is `not (x > 1)`: the same proposition, whatever x is
    assert satisfiable([A.Binary(">", X, ONE), A.Binary("<=", X, ONE)]) is False


def test_boolean_skeleton_with_a_model_decides() -> None:
    assert satisfiable([A.Binary("or", P, Q), A.Unary("not", P)]) is True
    assert satisfiable([A.Binary("==", P, Q), P, A.Unary("not", Q)]) is False


def test_numbers_are_left_to_the_solver() -> None:
    # a model of the skeleton, and `x * x < 0` has none: not decided here
    square = A.Binary("*", X, X)
    assert satisfiable([A.Binary("<", square, A.Num(Fraction(0), False))]) is None
    # two symbols: `x > y and y > x` is no comparison of one symbol with a constant
    y = A.Sym(4, "real")
    assert satisfiable([A.Binary(">", X, y), A.Binary(">", y, X)]) is None


def test_bounds_of_one_symbol_rule_out_each_other() -> None:
    """A pair of comparisons of one symbol with constants that no number meets
    is a clause of the skeleton (`_exclusions`); a pair some number meets is not."""
    zero, minus = A.Num(Fraction(0), False), A.Num(Fraction(-111), True)
    assert satisfiable([A.Binary(">", X, ONE), A.Binary("<", X, zero)]) is False
    assert satisfiable([A.Binary("==", X, minus), A.Binary(">", X, zero)]) is False
    # `not x <= 0` with `x == -111`, the sides swapped: `0 < x`
    assert satisfiable([A.Binary("==", minus, X), A.Binary("<", zero, X)]) is False
    assert satisfiable([A.Binary("<=", X, minus), A.Binary(">=", X, zero)]) is False
    # x == 1 and not x < 1 and not x > 1: each pair is met by 1
    assert (
        satisfiable(
            [A.Binary("==", X, ONE), A.Binary(">=", X, ONE), A.Binary("<=", X, ONE)]
        )
        is None
    )
    # between two constants: 0 < x < 1 is met by 1/2 (over the reals)
    assert satisfiable([A.Binary(">", X, zero), A.Binary("<", X, ONE)]) is None


def test_a_feasibility_question_needs_no_solver() -> None:
    discharge = Discharger()
    assert isinstance(discharge(VC((P,), A.Unary("not", Q), question=True)), Unproven)
    assert isinstance(discharge(VC((P,), P, question=True)), Proved)
    assert discharge._session is None  # z3 was never started
