"""How a counterexample's value is written: one spelling whether the value came from
z3's model (`smt.solver`) or from exact evaluation (`annotations.witness`, when a
check is decided without z3 in `api`), so a verdict reads the same either way."""

from __future__ import annotations

import math
from fractions import Fraction

from robotfix.annotations.numbers import shown_as_infinity

SHOWN_DIGITS = 40  # longer model values are shown rounded
SHOWN_FRACTION = 15  # longer exact fractions are shown as the float near them


def exact(value: Fraction | bool | str | None) -> str | None:
    """An exact value (of a witness) as z3 would show it, whether z3 took it for an
    integer or a real; None for none, for a string (z3 spells its characters its
    own way), and for a number too long to show in full (its rounding differs
    between the two)."""
    if isinstance(value, bool):
        return "True" if value else "False"
    if not isinstance(value, Fraction):
        return None
    numerator, denominator = str(value.numerator), str(value.denominator)
    if len(numerator) + len(denominator) > SHOWN_DIGITS:
        return None
    return numerator if denominator == "1" else rational(numerator, denominator)


def integer(digits: str) -> str:
    return digits if len(digits) <= SHOWN_DIGITS else _scientific(digits, "1")


def rational(numerator: str, denominator: str) -> str:
    """numerator/denominator, in lowest terms, as decimal texts of any length."""
    if len(numerator) + len(denominator) > SHOWN_DIGITS:
        if len(numerator.lstrip("-")) - len(denominator) > 309:  # beyond a double
            return "-inf" if numerator.startswith("-") else "inf"
        return _scientific(numerator, denominator)
    return _decimal(Fraction(int(numerator), int(denominator)))


def _scientific(numerator: str, denominator: str) -> str:
    """numerator/denominator (decimal texts, of any length) as 1.23457e+400."""
    sign = "-" if numerator.startswith("-") else ""
    numerator = numerator.lstrip("-")
    if numerator == "0":
        return "0"
    log = (
        math.log10(int(numerator[:17]))
        + len(numerator[17:])
        - math.log10(int(denominator[:17]))
        - len(denominator[17:])
    )
    exponent = math.floor(log)
    return f"{sign}{10 ** (log - exponent):.6g}e{exponent:+d}"


def _decimal(value: Fraction) -> str:
    infinite = shown_as_infinity(value)
    if infinite is not None:
        return infinite
    if value.denominator == 1:
        return str(value.numerator)
    as_float = float(value)
    if Fraction(as_float) == value or len(repr(as_float)) < 12:
        return repr(as_float)
    exact = f"{value.numerator}/{value.denominator}"
    if len(exact) <= SHOWN_FRACTION:  # 1/3, 22/7: exact and readable
        return exact
    # e.g. radians(10.0) worked out exactly, 25152845340545565/144115188075855872:
    # the float Python would compute, said to be near
    return f"about {as_float!r}"
