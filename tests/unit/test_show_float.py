"""A number that is a float's binary value (`math.pi` from another module's
refinement) is shown as Python shows the float, not as its 49-digit expansion;
short exact decimals are shown as before; a constant put in from another module is
shown by its name."""

from __future__ import annotations

import math
from fractions import Fraction

from robotfix.annotations import ast as A


def test_a_float_constant_is_shown_as_python_shows_it() -> None:
    assert A.show(A.Num(Fraction(math.pi), False)) == "3.141592653589793"
    assert A.show(A.Num(Fraction(-math.pi / 2), False)) == "-1.5707963267948966"


def test_exact_decimals_are_unchanged() -> None:
    assert A.show(A.Num(Fraction(1, 8), False)) == "0.125"
    assert A.show(A.Num(Fraction(1, 10), False)) == "0.1"
    assert A.show(A.Num(Fraction(1, 3), False)) == "0.333333"


def test_a_labelled_constant_is_shown_by_its_name_and_compares_by_value() -> None:
    """A constant put into a refinement from another module keeps its name for
    messages (`project/summary._labelled`); to the solver it is its value."""
    pi = A.Num(Fraction(math.pi), False, label="math.pi")
    assert A.show(A.Binary("<=", A.Name("heading"), pi)) == "heading <= math.pi"
    assert A.show(A.Unary("-", pi)) == "-math.pi"
    low = A.Num(Fraction(-1), True, label="LOW")
    assert A.show(A.Binary("-", A.Name("x"), low)) == "x - LOW"  # no parentheses
    assert A.show(A.Binary("==", A.Name("mode"), A.Str("auto", label="AUTO"))) == (
        "mode == AUTO"
    )
    assert pi == A.Num(Fraction(math.pi), False)
    assert hash(pi) == hash(A.Num(Fraction(math.pi), False))


def test_a_long_exact_value_is_shown_as_the_float_near_it() -> None:
    """A value the solver works out exactly (`radians(10.0)` as a rational) is shown
    as the float Python computes, marked as near, not as a 35-digit fraction; short
    fractions and floats stay as they were."""
    from robotfix.smt.shown import _decimal

    ten_degrees = Fraction(25152845340545565, 144115188075855872)
    assert _decimal(ten_degrees) == "about 0.17453292519943295"
    assert _decimal(Fraction(1, 3)) == "1/3"
    assert _decimal(Fraction(1, 8)) == "0.125"
    assert _decimal(Fraction(math.pi)) == repr(math.pi)  # a float: exact
    assert _decimal(Fraction(7)) == "7"
