"""Exact evaluation of closed terms (no symbols) with Python fractions.

A closed goal that folds to True is proved whatever the facts are, without z3. A
closed goal that folds to False still goes to z3: on a dead path (inconsistent facts)
it is not a violation.
"""

from __future__ import annotations

from fractions import Fraction

from robotfix.annotations import ast as A

Constant = Fraction | bool | str


def fold(expr: A.Expr) -> Constant | None:
    """The value of a closed term, or None if it has symbols or is not foldable."""
    if isinstance(expr, A.Num):
        return expr.value
    if isinstance(expr, (A.Bool, A.Str)):
        return expr.value
    if isinstance(expr, A.Unary):
        inner = fold(expr.operand)
        if expr.op == "not":
            return (not inner) if isinstance(inner, bool) else None
        return -inner if isinstance(inner, Fraction) else None
    if isinstance(expr, A.Binary):
        return _binary(expr)
    if isinstance(expr, A.Ite):
        cond = fold(expr.cond)
        if not isinstance(cond, bool):
            return None
        return fold(expr.then if cond else expr.orelse)
    if isinstance(expr, A.Func) and expr.name != "len":
        args = [fold(a) for a in expr.args]
        if not all(isinstance(a, Fraction) for a in args):
            return None
        numbers = [a for a in args if isinstance(a, Fraction)]
        return (
            abs(numbers[0])
            if expr.name == "abs"
            else (min(numbers) if expr.name == "min" else max(numbers))
        )
    return None


def _binary(expr: A.Binary) -> Constant | None:
    left, right = fold(expr.left), fold(expr.right)
    if left is None or right is None:
        return None
    op = expr.op
    if op in ("and", "or"):
        if not isinstance(left, bool) or not isinstance(right, bool):
            return None
        return (left and right) if op == "and" else (left or right)
    if op in ("==", "!="):
        if isinstance(left, bool) != isinstance(right, bool) or isinstance(
            left, str
        ) != isinstance(right, str):
            return None
        return (left == right) if op == "==" else (left != right)
    if not isinstance(left, Fraction) or not isinstance(right, Fraction):
        return None
    if op in A.ARITH_OPS:
        return A.arith(op, left, right)
    return {
        "<": left < right,
        "<=": left <= right,
        ">": left > right,
        ">=": left >= right,
    }.get(op)
