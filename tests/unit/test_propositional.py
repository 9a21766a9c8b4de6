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
    # a model of the skeleton, but `x > 1 and x < 0` has none: not decided here
    assert (
        satisfiable(
            [A.Binary(">", X, ONE), A.Binary("<", X, A.Num(Fraction(0), False))]
        )
        is None
    )


def test_a_feasibility_question_needs_no_solver() -> None:
    discharge = Discharger()
    assert isinstance(discharge(VC((P,), A.Unary("not", Q), question=True)), Unproven)
    assert isinstance(discharge(VC((P,), P, question=True)), Proved)
    assert discharge._session is None  # z3 was never started
