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

from robotfix.annotations import ast as A
from robotfix.smt.fold import fold
from robotfix.vc import VC, shared_facts

_ZERO, _ONE, _MINUS_ONE = Fraction(0), Fraction(1), Fraction(-1)
_TOO_LONG = 10**1_000  # the encoder's MAX_DIGITS: longer numbers are fresh to z3
_FLIP = {"<": ">", "<=": ">=", ">": "<", ">=": "<=", "==": "==", "!=": "!="}
_ORDER = frozenset({"<", "<=", ">", ">=", "==", "!="})


@dataclass(frozen=True)
class _Bound:
    """One side of an interval: a value, strict or not."""

    value: Fraction | None  # None: unbounded on that side
    strict: bool = False


_NONE = _Bound(None)


@dataclass(frozen=True)
class _Interval:
    """The values a term may take."""

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
    return Prepass().proves(vc)


# `coefficients . atoms + constant  op  0`, op one of <, <=, ==
_Constraint = tuple[dict[A.Expr, Fraction], Fraction, str]
_NEGATED = {"<": ">=", "<=": ">", ">": "<=", ">=": "<", "==": "!=", "!=": "=="}
_MEMO_ENTRIES = 200_000  # terms whose linear form is kept; then forgotten all at once


@dataclass
class _Pushed:
    """What one fact changed, to take it back: symbols' old intervals (None: had
    none) and the keys of the constraints it indexed."""

    bounds: list[tuple[A.Expr, _Interval | None]]
    keys: list[frozenset[A.Expr]]


class Prepass:
    """The pre-pass of one file. Its facts are kept as a stack, as the solver keeps
    them: a VC whose facts extend the previous VC's reads only the new ones (the
    facts' intervals are intersected one fact at a time, and the constraints are
    indexed by the atoms they name), and a term's linear form is worked out once
    (by identity: the analysis shares a term's sub-terms, so in `x1 = x0 + 1`,
    `x2 = x1 + 1`, ... each link is read once, not once per VC). `work` counts the
    nodes and constraints visited: the steps the file's budget is charged."""

    def __init__(self) -> None:
        self.work = 0
        self._facts: tuple[A.Expr, ...] = ()
        self._pushed: list[_Pushed] = []
        self._bounds: dict[A.Expr, _Interval] = {}
        self._index: dict[frozenset[A.Expr], list[_Constraint]] = {}
        self._dead: int | None = None  # facts from which no value satisfies them
        self._linear: dict[int, tuple[A.Expr, _Linear | None]] = {}
        self._read: dict[int, tuple[A.Expr, list[_Constraint]]] = {}

    def proves(self, vc: VC) -> bool:
        """True only when the facts imply the goal (or contradict each other)."""
        self._sync(vc.facts)
        if self._dead is not None:  # facts no value satisfies: every goal holds
            return True
        return self._holds(vc.goal, False)

    # -- the facts, as a stack ---------------------------------------------------
    def _sync(self, facts: tuple[A.Expr, ...]) -> None:
        common = shared_facts(self._facts, facts)
        while len(self._pushed) > common:
            self._pop()
        for fact in facts[common:]:
            self._push(fact)
        self._facts = facts

    def _push(self, fact: A.Expr) -> None:
        pushed = _Pushed([], [])
        self._pushed.append(pushed)
        if self._dead is not None:
            return
        for constraint in self._constraints_of(fact):
            self.work += 1
            key = frozenset(constraint[0])
            self._index.setdefault(key, []).append(constraint)
            pushed.keys.append(key)
            if not self._bound(constraint, pushed):
                self._dead = len(self._pushed)
                return

    def _pop(self) -> None:
        pushed = self._pushed.pop()
        if self._dead is not None and len(self._pushed) < self._dead:
            self._dead = None
        for key in reversed(pushed.keys):
            self._index[key].pop()
        for sym, old in reversed(pushed.bounds):
            if old is None:
                del self._bounds[sym]
            else:
                self._bounds[sym] = old

    def _bound(self, constraint: _Constraint, pushed: _Pushed) -> bool:
        """Narrow a symbol's interval by a one-symbol constraint; False when the
        facts contradict each other now."""
        coeffs, constant, op = constraint
        if len(coeffs) != 1:
            return bool(coeffs) or _constant_holds(constant, op)
        ((sym, coeff),) = coeffs.items()
        if not isinstance(sym, A.Sym):
            return True
        value = -constant / coeff  # sym  op'  value
        op = op if coeff > 0 else _FLIP[op]
        if op == "==":
            new = _Interval(_Bound(value), _Bound(value))
        elif op in ("<", "<="):
            new = _Interval(high=_Bound(value, op == "<"))
        else:
            new = _Interval(low=_Bound(value, op == ">"))
        old = self._bounds.get(sym)
        known = old or _Interval()
        merged = _Interval(
            _tighter(known.low, new.low, lower=True),
            _tighter(known.high, new.high, lower=False),
        )
        pushed.bounds.append((sym, old))
        self._bounds[sym] = merged
        return not merged.empty()

    def _constraints_of(self, fact: A.Expr) -> list[_Constraint]:
        found = self._read.get(id(fact))
        if found is not None and found[0] is fact:
            return found[1]
        constraints = self._constraints(fact, False)
        if len(self._read) >= _MEMO_ENTRIES:
            self._read.clear()
        self._read[id(fact)] = (fact, constraints)
        return constraints

    def _constraints(self, fact: A.Expr, negated: bool) -> list[_Constraint]:
        """The linear constraints a fact's conjuncts state (`not` pushed inwards);
        the parts it cannot read are left out, which only weakens what is known."""
        self.work += 1
        if isinstance(fact, A.Unary) and fact.op == "not":
            return self._constraints(fact.operand, not negated)
        if not isinstance(fact, A.Binary):
            return []
        if fact.op == ("or" if negated else "and"):
            left = self._constraints(fact.left, negated)
            return left + self._constraints(fact.right, negated)
        if fact.op not in _ORDER:
            return []
        found = self._normal(fact, negated, None)
        return [] if found is None else [found]

    # -- the goal ----------------------------------------------------------------
    def _normal(
        self,
        compare: A.Binary,
        negated: bool,
        bounds: dict[A.Expr, _Interval] | None,
    ) -> _Constraint | None:
        """A comparison (negated or not) as `terms op 0` with op <, <= or ==; None
        for `!=` or terms that are not linear."""
        op = _NEGATED[compare.op] if negated else compare.op
        left = self._linear_of(compare.left, bounds)
        right = self._linear_of(compare.right, bounds)
        if left is None or right is None or op == "!=":
            return None
        if op in (">", ">="):
            left, right, op = right, left, _FLIP[op]
        coeffs, constant = _minus(left, right)
        return coeffs, constant, op

    def _holds(self, goal: A.Expr, negated: bool) -> bool:
        self.work += 1
        if isinstance(goal, A.UnitIs):
            return True  # units are the analysis's: the encoder makes this True
        if isinstance(goal, A.Unary) and goal.op == "not":
            return self._holds(goal.operand, not negated)
        if isinstance(goal, A.Binary):
            if goal.op in ("and", "or"):
                both = (goal.op == "and") != negated
                left = self._holds(goal.left, negated)
                if both and not left:
                    return False
                if not both and left:
                    return True
                return self._holds(goal.right, negated)
            if goal.op in _ORDER:
                return self._compare_holds(goal, negated)
        value = fold(goal)
        return isinstance(value, bool) and value != negated

    def _compare_holds(self, goal: A.Binary, negated: bool) -> bool:
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
                self._compare_holds(A.Binary(strict, term, large), False)
                for term in (inner, A.Unary("-", inner))
            )
        if op == "!=":
            return self._interval_holds(goal, negated)
        found = self._normal(goal, negated, self._bounds)
        if found is None:
            return False
        if self._implied(found):
            return True
        return self._interval_holds(goal, negated)

    def _implied(self, goal: _Constraint) -> bool:
        """Whether one fact, scaled, gives the goal: goal = k * fact + d, fact op 0
        and d small enough (k > 0, or any k when the fact is an equation)."""
        coeffs, constant, op = goal
        if not coeffs:
            return False
        atom, value = next(iter(coeffs.items()))
        for f_coeffs, f_constant, f_op in self._index.get(frozenset(coeffs), ()):
            self.work += 1
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

    def _interval_holds(self, goal: A.Binary, negated: bool) -> bool:
        bounds = self._bounds
        left = self._linear_of(goal.left, bounds)
        right = self._linear_of(goal.right, bounds)
        if left is None or right is None:
            return False
        coeffs, constant = _minus(left, right)
        span = self._interval_of(coeffs, constant)
        low, high = span.low, span.high
        op = _NEGATED[goal.op] if negated else goal.op
        if op == "==":
            return not coeffs and constant == 0
        below = high.value is not None and (
            high.value < 0 or (high.value == 0 and high.strict)
        )
        above = low.value is not None and (
            low.value > 0 or (low.value == 0 and low.strict)
        )
        if op == "<":
            return below
        if op == "<=":
            return high.value is not None and high.value <= 0
        if op == ">":
            return above
        if op == ">=":
            return low.value is not None and low.value >= 0
        return below or above  # !=

    # -- terms -------------------------------------------------------------------
    def _linear_of(
        self, expr: A.Expr, bounds: dict[A.Expr, _Interval] | None
    ) -> _Linear | None:
        """`expr` as a linear term, or None when it is not one the encoder gives
        its arithmetic meaning. With `bounds`, `abs(t)` becomes `t` or `-t` when
        the bounds fix t's sign, else an atom; without them, every `abs` is an
        atom. The form without bounds is kept for the term (its readers never
        change it); it is the form with bounds too when it has no `abs` atom (the
        bounds only ever replace an `abs` atom by a linear term)."""
        self.work += 1
        found = self._linear.get(id(expr))
        if found is not None and found[0] is expr:
            free = found[1]
        else:
            free = self._linear_term(expr, None)
            if len(self._linear) >= _MEMO_ENTRIES:
                self._linear.clear()
            self._linear[id(expr)] = (expr, free)
        if bounds is None:
            return free
        if free is not None and not any(type(atom) is A.Func for atom in free[0]):
            return free
        return self._linear_term(expr, bounds)

    def _linear_term(
        self, expr: A.Expr, bounds: dict[A.Expr, _Interval] | None
    ) -> _Linear | None:
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
            inner = self._linear_of(expr.operand, bounds)
            return None if inner is None else _scale(inner, _MINUS_ONE)
        if isinstance(expr, A.Func):
            if expr.name != "abs" or len(expr.args) != 1:
                return None
            inner = self._linear_of(expr.args[0], bounds)
            if inner is None:
                return None
            if bounds is not None:
                span = self._interval_of(inner[0], inner[1])
                if span.low.value is not None and span.low.value >= 0:
                    return inner
                if span.high.value is not None and span.high.value <= 0:
                    return _scale(inner, _MINUS_ONE)
            return {expr: _ONE}, _ZERO
        if isinstance(expr, A.Binary) and expr.op in A.ARITH_OPS:
            left = self._linear_of(expr.left, bounds)
            right = self._linear_of(expr.right, bounds)
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

    def _interval_of(
        self, coeffs: dict[A.Expr, Fraction], constant: Fraction
    ) -> _Interval:
        low = _Bound(constant)
        high = _Bound(constant)
        for atom, coeff in coeffs.items():
            span = self._atom_interval(atom)
            lo, hi = (span.low, span.high) if coeff > 0 else (span.high, span.low)
            low = _add(low, lo, coeff)
            high = _add(high, hi, coeff)
        return _Interval(low, high)

    def _atom_interval(self, atom: A.Expr) -> _Interval:
        self.work += 1
        if isinstance(atom, A.Func):  # abs(t), sign not fixed: [0, max(|lo|, |hi|)]
            inner = self._linear_of(atom.args[0], self._bounds)
            if inner is None:
                return _Interval(_Bound(_ZERO))
            span = self._interval_of(inner[0], inner[1])
            if span.low.value is None or span.high.value is None:
                return _Interval(_Bound(_ZERO))
            top = max(-span.low.value, span.high.value)
            return _Interval(_Bound(_ZERO), _Bound(top))
        return self._bounds.get(atom, _Interval())


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


def _add(total: _Bound, bound: _Bound, coeff: Fraction) -> _Bound:
    if total.value is None or bound.value is None:
        return _NONE
    return _Bound(total.value + coeff * bound.value, total.strict or bound.strict)
