"""A number that is a float's binary value (`math.pi` from another module's
refinement) is shown as Python shows the float, not as its 49-digit expansion;
short exact decimals are shown as before."""

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
