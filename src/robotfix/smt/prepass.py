"""A cheap, sound pre-pass before z3 that only ever answers "proved".

Most goals the analysis asks are bound checks (`abs(v) <= limit` under `v > 0`,
`speed <= 5` with `0 <= speed <= 2` among the facts). This module proves such goals
with exact interval arithmetic on linear terms, in pure Python, and returns False
whenever it is not sure: the VC then goes to z3 as before. It never says "violated",
so it cannot invent a finding; what it proves, z3 proves too (a goal the facts imply,
or any goal under facts no value satisfies), except where z3 would give up (unknown,
the file's budget), where a proof is the better answer. Floored `//` and `%` are
never linear terms here.

What it reads, all else is ignored (ignoring a fact only weakens what is known):
- facts that are conjunctions of comparisons with one symbol, `2 * x + 1 < 5`, whose
  intervals are intersected per symbol;
- goals that are conjunctions or disjunctions of comparisons between linear terms over
  int and real symbols and exact numbers, with `abs` of a term whose sign the bounds
  fix rewritten to the term or its negation, and any other `abs` kept as an atom
  with its own interval; a goal that is one of the facts' conjuncts is proved as is.
Only terms the encoder gives their true meaning are read: no names (fresh constants
to z3), no strings, booleans, division by a term, products of two terms, or numbers
the encoder would not hand to z3.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

from robotfix.analysis.vc import VC
from robotfix.annotations import ast as A
from robotfix.smt.fold import fold

_ZERO, _ONE, _MINUS_ONE = Fraction(0), Fraction(1), Fraction(-1)
_TOO_LONG = 10**1_000  # the encoder's MAX_DIGITS: longer numbers are fresh to z3
_FLIP = {"<": ">", "<=": ">=", ">": "<", ">=": "<=", "==": "==", "!=": "!="}
_ORDER = frozenset({"<", "<=", ">", ">=", "==", "!="})


@dataclass(frozen=True)
class _Bound:
    value: Fraction | None  # None: unbounded on that side
    strict: bool = False


_NONE = _Bound(None)


@dataclass(frozen=True)
class _Interval:
    low: _Bound = _NONE
    high: _Bound = _NONE

    def empty(self) -> bool:
        low, high = self.low, self.high
        if low.value is None or high.value is None:
            return False
        if low.value > high.value:
            return True
        return low.value == high.value and (low.strict or high.strict)


# A linear term: coefficients of atoms (a Sym, or an `abs(...)` kept whole) + constant.
_Linear = tuple[dict[A.Expr, Fraction], Fraction]


def proves(vc: VC) -> bool:
    """True only when the facts imply the goal (or contradict each other)."""
    constraints = [c for fact in vc.facts for c in _constraints(fact, False)]
    bounds = _fact_bounds(constraints)
    if bounds is None:  # facts no value satisfies: every goal holds
        return True
    return _holds(vc.goal, bounds, constraints, False)


# `coefficients . atoms + constant  op  0`, op one of <, <=, ==
_Constraint = tuple[dict[A.Expr, Fraction], Fraction, str]
_NEGATED = {"<": ">=", "<=": ">", ">": "<=", ">=": "<", "==": "!=", "!=": "=="}


def _constraints(fact: A.Expr, negated: bool) -> list[_Constraint]:
    """The linear constraints a fact's conjuncts state (`not` pushed inwards); the
    parts it cannot read are left out, which only weakens what is known."""
    if isinstance(fact, A.Unary) and fact.op == "not":
        return _constraints(fact.operand, not negated)
    if not isinstance(fact, A.Binary):
        return []
    if fact.op == ("or" if negated else "and"):
        return _constraints(fact.left, negated) + _constraints(fact.right, negated)
    if fact.op not in _ORDER:
        return []
    found = _normal(fact, negated)
    return [] if found is None else [found]


def _normal(
    compare: A.Binary, negated: bool, bounds: dict[A.Expr, _Interval] | None = None
) -> _Constraint | None:
    """A comparison (negated or not) as `terms op 0` with op <, <= or ==; None for
    `!=` or terms that are not linear."""
    op = _NEGATED[compare.op] if negated else compare.op
    left = _linear(compare.left, bounds)
    right = _linear(compare.right, bounds)
    if left is None or right is None or op == "!=":
        return None
    if op in (">", ">="):
        left, right, op = right, left, _FLIP[op]
    coeffs, constant = _minus(left, right)
    return coeffs, constant, op


def _holds(
    goal: A.Expr,
    bounds: dict[A.Expr, _Interval],
    constraints: list[_Constraint],
    negated: bool,
) -> bool:
    if isinstance(goal, A.UnitIs):
        return True  # units are the analysis's: the encoder makes this True
    if isinstance(goal, A.Unary) and goal.op == "not":
        return _holds(goal.operand, bounds, constraints, not negated)
    if isinstance(goal, A.Binary):
        if goal.op in ("and", "or"):
            both = (goal.op == "and") != negated
            left = _holds(goal.left, bounds, constraints, negated)
            if both and not left:
                return False
            if not both and left:
                return True
            return _holds(goal.right, bounds, constraints, negated)
        if goal.op in _ORDER:
            return _compare_holds(goal, negated, bounds, constraints)
    value = fold(goal)
    return isinstance(value, bool) and value != negated


def _compare_holds(
    goal: A.Binary,
    negated: bool,
    bounds: dict[A.Expr, _Interval],
    constraints: list[_Constraint],
) -> bool:
    op = _NEGATED[goal.op] if negated else goal.op
    # abs(t) < u  iff  t < u and -t < u (and the same for <=; u > abs(t) likewise)
    small, large = (goal.left, goal.right) if op in ("<", "<=") else (None, None)
    if op in (">", ">="):
        small, large = goal.right, goal.left
    if isinstance(small, A.Func) and small.name == "abs" and len(small.args) == 1:
        assert large is not None
        strict = "<" if op in ("<", ">") else "<="
        inner = small.args[0]
        return all(
            _compare_holds(A.Binary(strict, term, large), False, bounds, constraints)
            for term in (inner, A.Unary("-", inner))
        )
    if op == "!=":
        return _interval_holds(goal, negated, bounds)
    found = _normal(goal, negated, bounds)
    if found is None:
        return False
    if _implied(found, constraints):
        return True
    return _interval_holds(goal, negated, bounds)


def _implied(goal: _Constraint, constraints: list[_Constraint]) -> bool:
    """Whether one fact, scaled, gives the goal: goal = k * fact + d, fact op 0 and
    d small enough (k > 0, or any k when the fact is an equation)."""
    coeffs, constant, op = goal
    if not coeffs:
        return False
    atom, value = next(iter(coeffs.items()))
    for f_coeffs, f_constant, f_op in constraints:
        if f_coeffs.keys() != coeffs.keys() or atom not in f_coeffs:
            continue
        scale = value / f_coeffs[atom]
        if any(f_coeffs[a] * scale != v for a, v in coeffs.items()):
            continue
        rest = constant - scale * f_constant  # goal terms = scale * fact + rest
        if f_op == "==":
            if op == "==" and rest == 0:
                return True
            if (op == "<=" and rest <= 0) or (op == "<" and rest < 0):
                return True
            continue
        if scale <= 0 or op == "==":
            continue
        if rest < 0 or (rest == 0 and (op == "<=" or f_op == "<")):
            return True
    return False


def _interval_holds(
    goal: A.Binary, negated: bool, bounds: dict[A.Expr, _Interval]
) -> bool:
    left = _linear(goal.left, bounds)
    right = _linear(goal.right, bounds)
    if left is None or right is None:
        return False
    coeffs, constant = _minus(left, right)
    span = _interval_of(coeffs, constant, bounds)
    low, high = span.low, span.high
    op = _NEGATED[goal.op] if negated else goal.op
    if op == "==":
        return not coeffs and constant == 0
    below = high.value is not None and (
        high.value < 0 or (high.value == 0 and high.strict)
    )
    above = low.value is not None and (low.value > 0 or (low.value == 0 and low.strict))
    if op == "<":
        return below
    if op == "<=":
        return high.value is not None and high.value <= 0
    if op == ">":
        return above
    if op == ">=":
        return low.value is not None and low.value >= 0
    return below or above  # !=


def _fact_bounds(constraints: list[_Constraint]) -> dict[A.Expr, _Interval] | None:
    """Each symbol's interval from the one-symbol constraints; None when some symbol
    has none left (the facts contradict each other)."""
    bounds: dict[A.Expr, _Interval] = {}
    for coeffs, constant, op in constraints:
        if len(coeffs) != 1:
            if not coeffs and not _constant_holds(constant, op):
                return None
            continue
        ((sym, coeff),) = coeffs.items()
        if not isinstance(sym, A.Sym):
            continue
        value = -constant / coeff  # sym  op'  value
        op = op if coeff > 0 else _FLIP[op]
        if op == "==":
            new = _Interval(_Bound(value), _Bound(value))
        elif op in ("<", "<="):
            new = _Interval(high=_Bound(value, op == "<"))
        else:
            new = _Interval(low=_Bound(value, op == ">"))
        old = bounds.get(sym, _Interval())
        merged = _Interval(
            _tighter(old.low, new.low, lower=True),
            _tighter(old.high, new.high, lower=False),
        )
        if merged.empty():
            return None
        bounds[sym] = merged
    return bounds


def _constant_holds(constant: Fraction, op: str) -> bool:
    return constant < 0 if op == "<" else constant <= 0 if op == "<=" else constant == 0


def _tighter(a: _Bound, b: _Bound, lower: bool) -> _Bound:
    if a.value is None:
        return b
    if b.value is None:
        return a
    if a.value == b.value:
        return _Bound(a.value, a.strict or b.strict)
    if lower:
        return a if a.value > b.value else b
    return a if a.value < b.value else b


def _linear(
    expr: A.Expr, bounds: dict[A.Expr, _Interval] | None = None
) -> _Linear | None:
    """`expr` as a linear term, or None when it is not one the encoder gives its
    arithmetic meaning. With `bounds`, `abs(t)` becomes `t` or `-t` when the bounds
    fix t's sign, else an atom; without them, every `abs` is an atom."""
    if isinstance(expr, A.Num):
        value = expr.value
        if abs(value.numerator) >= _TOO_LONG or value.denominator >= _TOO_LONG:
            return None
        return {}, value
    if isinstance(expr, A.Sym):
        if expr.sort not in ("int", "real"):
            return None
        return {expr: _ONE}, _ZERO
    if isinstance(expr, A.Unary):
        if expr.op != "-":
            return None
        inner = _linear(expr.operand, bounds)
        return None if inner is None else _scale(inner, _MINUS_ONE)
    if isinstance(expr, A.Func):
        if expr.name != "abs" or len(expr.args) != 1:
            return None
        inner = _linear(expr.args[0], bounds)
        if inner is None:
            return None
        if bounds is not None:
            span = _interval_of(inner[0], inner[1], bounds)
            if span.low.value is not None and span.low.value >= 0:
                return inner
            if span.high.value is not None and span.high.value <= 0:
                return _scale(inner, _MINUS_ONE)
        return {expr: _ONE}, _ZERO
    if isinstance(expr, A.Binary) and expr.op in A.ARITH_OPS:
        left, right = _linear(expr.left, bounds), _linear(expr.right, bounds)
        if left is None or right is None:
            return None
        if expr.op == "+":
            return _minus(left, _scale(right, _MINUS_ONE))
        if expr.op == "-":
            return _minus(left, right)
        if expr.op == "*":
            if not left[0]:
                return _scale(right, left[1])
            if not right[0]:
                return _scale(left, right[1])
            return None
        if expr.op == "/" and not right[0] and right[1] != 0:  # by a constant
            return _scale(left, 1 / right[1])
    return None


def _scale(term: _Linear, factor: Fraction) -> _Linear:
    coeffs, constant = term
    if factor == 0:
        return {}, _ZERO
    return {k: v * factor for k, v in coeffs.items()}, constant * factor


def _minus(left: _Linear, right: _Linear) -> _Linear:
    coeffs = dict(left[0])
    for atom, value in right[0].items():
        total = coeffs.get(atom, _ZERO) - value
        if total:
            coeffs[atom] = total
        else:
            coeffs.pop(atom, None)
    return coeffs, left[1] - right[1]


def _interval_of(
    coeffs: dict[A.Expr, Fraction], constant: Fraction, bounds: dict[A.Expr, _Interval]
) -> _Interval:
    low = _Bound(constant)
    high = _Bound(constant)
    for atom, coeff in coeffs.items():
        span = _atom_interval(atom, bounds)
        lo, hi = (span.low, span.high) if coeff > 0 else (span.high, span.low)
        low = _add(low, lo, coeff)
        high = _add(high, hi, coeff)
    return _Interval(low, high)


def _atom_interval(atom: A.Expr, bounds: dict[A.Expr, _Interval]) -> _Interval:
    if isinstance(atom, A.Func):  # abs(t), t's sign not fixed: [0, max(|lo|, |hi|)]
        inner = _linear(atom.args[0], bounds)
        if inner is None:
            return _Interval(_Bound(_ZERO))
        span = _interval_of(inner[0], inner[1], bounds)
        if span.low.value is None or span.high.value is None:
            return _Interval(_Bound(_ZERO))
        top = max(-span.low.value, span.high.value)
        return _Interval(_Bound(_ZERO), _Bound(top))
    return bounds.get(atom, _Interval())


def _add(total: _Bound, bound: _Bound, coeff: Fraction) -> _Bound:
    if total.value is None or bound.value is None:
        return _NONE
    return _Bound(total.value + coeff * bound.value, total.strict or bound.strict)
