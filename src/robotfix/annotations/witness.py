"""A cheap witness for a satisfiable refinement: values of its names that make it true.

`0 < _ <= 2` holds at 1, `abs(v) <= limit` at v = 0, limit = 0. Finding such values
by trying a few candidates (the predicate's constants, their neighbours and midpoints)
shows that a refinement is satisfiable without asking the solver (RF509's question,
asked of every refinement). Exact: the predicate is evaluated with fractions, with the
meaning the solver gives it, and anything else (strings, booleans, units, unknown
functions, division by zero, too many names or candidates) answers "no witness", so
the solver decides as before. A witness is never a guess: it is checked.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from fractions import Fraction
from functools import lru_cache

from robotfix.annotations import ast as A

MAX_NAMES = 3
MAX_TRIES = 2_000
_LIMIT = 10**100  # candidates and values beyond this are not tried


def has_witness(predicate: A.Expr, sort: Callable[[str], str]) -> bool:
    """Whether some values of the names (of sort `sort(name)`, int or real) make
    `predicate` true, found by trying candidates."""
    names = sorted({n.name for n in A.names(predicate)})
    if not names or len(names) > MAX_NAMES:
        return False
    sorts = tuple(sort(name) for name in names)
    if any(s not in ("int", "real") for s in sorts):
        return False
    return _search(predicate, tuple(names), sorts)


@lru_cache(maxsize=4096)
def _search(predicate: A.Expr, names: tuple[str, ...], sorts: tuple[str, ...]) -> bool:
    """Memoised: a refinement is met again at every use of its name or type."""
    constants = _constants(predicate)
    if constants is None:
        return False
    per_name = [_candidates(constants, s == "int") for s in sorts]
    tries = 1
    for options in per_name:
        tries *= len(options)
    if tries > MAX_TRIES:
        return False
    for values in itertools.product(*per_name):
        if _value(predicate, dict(zip(names, values, strict=True))) is True:
            return True
    return False


def _constants(expr: A.Expr) -> set[Fraction] | None:
    found: set[Fraction] = set()
    for node in A.walk(expr):
        if isinstance(node, A.Num):
            if abs(node.value.numerator) > _LIMIT or node.value.denominator > _LIMIT:
                return None
            found.add(node.value)
        elif not isinstance(node, (A.Name, A.Unary, A.Binary, A.Func, A.Ite)):
            return None  # strings, booleans, units, symbols: the solver's
    return found


def _candidates(constants: set[Fraction], integer: bool) -> list[Fraction]:
    points = sorted({Fraction(0), *constants, *(-c for c in constants)})
    found = set(points)
    for c in points:
        found.update((c - 1, c + 1))
    for a, b in itertools.pairwise(points):
        found.add((a + b) / 2)
    if integer:
        found = {Fraction(int(c)) for c in found if c.denominator == 1}
    return sorted(found, key=lambda c: (abs(c), c))


Value = Fraction | bool | None


def _value(expr: A.Expr, values: dict[str, Fraction]) -> Value:
    """The exact value, or None where the solver's meaning is not a number's."""
    if isinstance(expr, A.Num):
        return expr.value
    if isinstance(expr, A.Name):
        return values.get(expr.name)
    if isinstance(expr, A.Unary):
        inner = _value(expr.operand, values)
        if expr.op == "not":
            return (not inner) if isinstance(inner, bool) else None
        return -inner if isinstance(inner, Fraction) else None
    if isinstance(expr, A.Func):
        args = [_value(a, values) for a in expr.args]
        numbers = [a for a in args if isinstance(a, Fraction)]
        if len(numbers) != len(args) or not numbers:
            return None
        if expr.name == "abs" and len(numbers) == 1:
            return abs(numbers[0])
        if expr.name in ("min", "max") and len(numbers) == 2:
            return min(numbers) if expr.name == "min" else max(numbers)
        return None
    if isinstance(expr, A.Ite):
        cond = _value(expr.cond, values)
        if not isinstance(cond, bool):
            return None
        return _value(expr.then if cond else expr.orelse, values)
    if isinstance(expr, A.Binary):
        return _binary(expr, values)
    return None


def _binary(expr: A.Binary, values: dict[str, Fraction]) -> Value:
    left, right = _value(expr.left, values), _value(expr.right, values)
    op = expr.op
    if op in ("and", "or"):
        if not isinstance(left, bool) or not isinstance(right, bool):
            return None
        return (left and right) if op == "and" else (left or right)
    if not isinstance(left, Fraction) or not isinstance(right, Fraction):
        return None  # booleans compared, or an unknown part
    if op == "/":
        return None if right == 0 else left / right
    if op in ("+", "-", "*"):
        result = (
            left + right if op == "+" else left - right if op == "-" else left * right
        )
        big = abs(result.numerator) > _LIMIT or result.denominator > _LIMIT
        return None if big else result
    return {
        "<": left < right,
        "<=": left <= right,
        ">": left > right,
        ">=": left >= right,
        "==": left == right,
        "!=": left != right,
    }.get(op)
