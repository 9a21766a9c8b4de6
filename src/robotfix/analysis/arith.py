"""The arithmetic of values, without reports: which literal factors a product
or quotient carries (`factors_of_product`), the kind (`numeric_kind`) and the
unit (`unit_of_product`) of its result, and the value of a term of number literals
(`constant_value`). The unit of a sum or comparison, which can be a finding, is
the checks' (`checks.Checker.unit_of_sum`).
"""

from __future__ import annotations

import math
from fractions import Fraction

from robotfix.analysis import frames
from robotfix.analysis.values import Value
from robotfix.annotations import ast as A
from robotfix.annotations.units import DIMENSIONLESS, Factors, Unit

# A literal this large (or this finely divided) is an unknown number of its kind:
# folded with others it would overflow floats, z3's input and the texts shown.
MAX_NUMBER: int = 10**100
LEAVES = (A.Sym, A.Str, A.Bool, A.Num)
KIND_ORDER = ("bool", "int", "float")


def factors_of_product(left: Value, right: Value, op: str) -> Factors:
    """Literal factors carried along (see `Value.factors`), each literal of a
    chain on its own: `rpm * 2.0 * math.pi / 60.0` holds 2, pi and 1/60, which
    together are the rpm -> rad/s conversion, and `2 * d_cm / 100` a gain of 2
    and the cm -> m conversion (`units.fit` tells them apart)."""
    if left.literal == right.literal:
        if left.literal:
            return ()
        return left.factors + (
            right.factors if op == "*" else tuple(1 / f for f in right.factors)
        )
    number = constant_value(right.term if right.literal else left.term)
    if number is None or number == 0:
        return ()
    if right.literal:
        factor = number if op == "*" else 1 / number
        held = left.factors
    else:  # `1000.0 / hz`: a period (1/Hz) scaled by 1000, i.e. in ms
        factor = number
        held = right.factors if op == "*" else tuple(1 / f for f in right.factors)
    if factor == 1:
        return held
    return (*held, factor)


def numeric_kind(left: Value, right: Value, op: str) -> str | None:
    kinds = {left.kind, right.kind}
    if not kinds <= {"int", "float", "bool", "unknown"}:
        return None
    if "unknown" in kinds:
        return "unknown"
    if op == "/" or "float" in kinds:
        return "float"
    return "int"


def unit_of_product(left: Value, right: Value, op: str) -> tuple[Unit | None, bool]:
    if left.literal and right.literal:
        return None, True
    lu = DIMENSIONLESS if left.literal else left.unit
    ru = DIMENSIONLESS if right.literal else right.unit
    if lu is None or ru is None:
        return None, False
    # a number that is not a literal (`math.cos(yaw)`) may rotate a coordinate
    # into another frame: the product's frame is not known
    if ru == DIMENSIONLESS:
        return (lu if right.literal else frames.unframed(lu)), False
    if lu == DIMENSIONLESS and op == "*":
        return (ru if left.literal else frames.unframed(ru)), False
    return (lu * ru if op == "*" else lu / ru), False


def constant_value(term: A.Expr | None) -> float | None:
    """The value of a term built from number literals only, if a float holds it
    (None beyond floats: math.inf, or a literal near it)."""
    try:
        found = _constant_value(term)
    except OverflowError:
        return None
    return found if found is None or math.isfinite(found) else None


def _constant_value(term: A.Expr | None) -> float | None:
    if isinstance(term, A.Num):
        return float(term.value)
    if isinstance(term, A.Unary) and term.op == "-":
        inner = _constant_value(term.operand)
        return None if inner is None else -inner
    if isinstance(term, A.Binary) and term.op in "+-*/":
        left, right = _constant_value(term.left), _constant_value(term.right)
        if left is None or right is None or (term.op == "/" and right == 0):
            return None
        return {"+": left + right, "-": left - right, "*": left * right}.get(
            term.op, left / right if right else 0.0
        )
    return None


def literal(term: A.Expr | None) -> Fraction | str | None:
    """A dict key or index as Python compares it (`1 == 1.0 == True`)."""
    if isinstance(term, A.Num):
        return term.value
    if isinstance(term, A.Bool):
        return Fraction(int(term.value))
    if isinstance(term, A.Str):
        return term.value
    if isinstance(term, A.Unary) and term.op == "-" and isinstance(term.operand, A.Num):
        return -term.operand.value
    return None


def has_length(unit: Unit) -> bool:
    return dict(unit.dims).get("meter", 0) != 0


def too_large(value: Fraction) -> bool:
    return abs(value.numerator) >= MAX_NUMBER or value.denominator >= MAX_NUMBER


def sorts_differ(left: Value, right: Value) -> bool:
    """An unknown (a real in the solver) against a str or a bool, both leaves."""
    kinds = {left.kind, right.kind}
    return (
        "unknown" in kinds
        and bool(kinds & {"str", "bool"})
        and isinstance(left.term, LEAVES)
        and isinstance(right.term, LEAVES)
    )
