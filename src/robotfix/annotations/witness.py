"""A cheap witness for a satisfiable refinement: values of its names that make it true.

`0 < _ <= 2` holds at 1, `abs(v) <= limit` at v = 0, limit = 0. Finding such values
by trying a few candidates (the predicate's constants, their neighbours and midpoints)
shows that a refinement is satisfiable without asking the solver (RF509's question,
asked of every refinement). Exact: the predicate is evaluated with fractions, with the
meaning the solver gives it, and anything else (strings, booleans, units, unknown
functions, division by zero, too many names or candidates) answers "no witness", so
the solver decides as before. A witness is never a guess: it is checked.

Each search counts its work (the nodes it walks and evaluates): one question stops at
`MAX_WORK`, or where the file's `Budget` runs out, and answers "no witness"; the
work is charged to that budget.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Iterable, Sequence
from fractions import Fraction
from functools import lru_cache

from robotfix.annotations import ast as A
from robotfix.budget import Budget

MAX_NAMES = 3
MAX_TRIES = 2_000
MAX_SYMBOLS = 64  # a path question with more symbols is left to the solver
MAX_STEPS = 2_000  # values one path question may try
MAX_WORK = 50_000  # nodes one question may walk and evaluate (the cases: 25k)
_LIMIT = 10**100  # candidates and values beyond this are not tried


def has_witness(
    predicate: A.Expr, sort: Callable[[str], str], budget: Budget | None = None
) -> bool:
    """Whether some values of the names (of sort `sort(name)`, int or real) make
    `predicate` true, found by trying candidates; the nodes evaluated are charged
    to `budget` (the same whether the answer was kept from an earlier search)."""
    names = sorted({n.name for n in A.names(predicate)})
    if not names or len(names) > MAX_NAMES:
        return False
    sorts = tuple(sort(name) for name in names)
    if any(s not in ("int", "real") for s in sorts):
        return False
    found, work = _search(predicate, tuple(names), sorts)
    if budget is not None:
        budget.spend(work)
    return found


@lru_cache(maxsize=4096)
def _search(
    predicate: A.Expr, names: tuple[str, ...], sorts: tuple[str, ...]
) -> tuple[bool, int]:
    """Memoised: a refinement is met again at every use of its name or type. With
    the answer, the nodes walked and evaluated to find it."""
    nodes = A.walk(predicate)
    constants = _constants(nodes)
    if constants is None:
        return False, len(nodes)
    per_name = [_candidates(constants, s == "int") for s in sorts]
    tries = 1
    for options in per_name:
        tries *= len(options)
    if tries > MAX_TRIES:
        return False, len(nodes)
    for count, values in enumerate(itertools.product(*per_name), 2):
        named: Values = dict(zip(names, values, strict=True))
        if _value(predicate, named) is True:
            return True, count * len(nodes)
    return False, (tries + 1) * len(nodes)


def _constants(nodes: list[A.Expr]) -> set[Fraction] | None:
    found: set[Fraction] = set()
    for node in nodes:
        if isinstance(node, A.Num):
            if abs(node.value.numerator) > _LIMIT or node.value.denominator > _LIMIT:
                return None
            found.add(node.value)
        elif not isinstance(node, (A.Name, A.Unary, A.Binary, A.Func, A.Ite)):
            return None  # strings, booleans, units, symbols: the solver's
    return found


def _candidates(constants: Iterable[Fraction | str], integer: bool) -> list[Fraction]:
    numbers = {c for c in constants if isinstance(c, Fraction)}
    points = sorted({Fraction(0), *numbers, *(-c for c in numbers)})
    found = set(points)
    for c in points:
        found.update((c - 1, c + 1))
    for a, b in itertools.pairwise(points):
        found.add((a + b) / 2)
    if integer:
        found = {Fraction(int(c)) for c in found if c.denominator == 1}
    return sorted(found, key=lambda c: (abs(c), c))


def holds_somewhere(
    parts: Sequence[A.Expr], budget: Budget | None = None, most: int = MAX_WORK
) -> bool:
    """Whether some values of the solver symbols in `parts` make every part true
    (a path question: can this condition hold under these facts?): `example`."""
    return example(parts, bounds=False, budget=budget, most=most) is not None


class _Work:
    """The nodes one search has walked and evaluated, within what it may."""

    def __init__(self, budget: Budget | None, most: int) -> None:
        self.done = 0
        self.allowed = most if budget is None else min(most, budget.left)

    def add(self, nodes: int) -> None:
        self.done += nodes
        if self.done > self.allowed:
            raise _OutOfWorkError


class _OutOfWorkError(Exception):
    pass


def example(
    parts: Sequence[A.Expr],
    bounds: bool = True,
    budget: Budget | None = None,
    most: int = MAX_WORK,
) -> dict[A.Sym, Scalar] | None:
    """Values of the solver symbols in `parts` that make every part true (a path
    question, or a counterexample: the facts and the goal's negation). Each symbol
    tries the constants of the conjuncts it occurs in, their neighbours and
    midpoints, and first the value an equation with earlier symbols gives it (a
    symbol an equation defines comes after the others), and last, with `bounds`,
    one past each bound on it (`v > limit`: a counterexample's usual shape; the
    path questions, asked of every branch, go without: there it cost 4% of a
    corpus run); a conjunct is evaluated exactly once its last
    symbol has a value. They depend on `parts` alone (the same values in every
    run); None says none was found, not that none exists (nor when the search
    ran out of work: `most`, or what is left of `budget`, which is charged). The
    search's order does not depend on `most`: a search stopped sooner finds what a
    longer one finds first, or nothing."""
    work = _Work(budget, most)
    try:
        return _example(parts, bounds, work)
    except _OutOfWorkError:
        return None
    finally:
        if budget is not None:
            budget.spend(work.done)


def _example(
    parts: Sequence[A.Expr], bounds: bool, work: _Work
) -> dict[A.Sym, Scalar] | None:
    conjuncts: list[tuple[A.Expr, list[A.Sym]]] = []
    sizes: dict[int, int] = {}  # id(conjunct or term) -> its nodes
    first: dict[A.Sym, None] = {}  # the symbols in order of appearance
    constants: dict[A.Sym, set[Fraction | str]] = {}
    defined: set[A.Sym] = set()
    for part in parts:
        for conjunct in A.conjuncts(part):
            syms: list[A.Sym] = []
            nodes = A.walk(conjunct)
            work.add(len(nodes))
            sizes[id(conjunct)] = len(nodes)
            for node in nodes:
                if isinstance(node, A.Sym):
                    first.setdefault(node)
                    syms.append(node)
                elif isinstance(node, A.Num):
                    if abs(node.value.numerator) > _LIMIT:
                        return None
                    if node.value.denominator > _LIMIT:
                        return None
                elif isinstance(node, (A.Name, A.UnitIs)):
                    return None  # not a value the solver's meaning gives here
            numbers = {n.value for n in nodes if isinstance(n, (A.Num, A.Str))}
            for sym in syms:
                constants.setdefault(sym, set()).update(numbers)
            work.add(len(nodes))  # a side of an equation walked for its symbols
            defined.update(_defines(conjunct))
            conjuncts.append((conjunct, syms))
    if len(first) > MAX_SYMBOLS:
        return None
    symbols = sorted(first, key=lambda s: s in defined)  # stable: appearance
    order = {sym: index for index, sym in enumerate(symbols)}
    # each with the nodes an evaluation of it visits at most (its conjunct's)
    due: list[list[tuple[A.Expr, int]]] = [[] for _ in symbols]
    hints: list[list[tuple[A.Expr, int]]] = [[] for _ in symbols]
    # `s > term`: term's value +- 1
    near: list[list[tuple[A.Expr, int]]] = [[] for _ in symbols]
    crossings: list[list[tuple[A.Binary, int]]] = [[] for _ in symbols]  # sides meet
    for conjunct, syms in conjuncts:
        size = sizes[id(conjunct)]
        if not syms:
            work.add(size)
            if _value(conjunct, {}) is not True:
                return None
            continue
        last = max(syms, key=order.__getitem__)
        due[order[last]].append((conjunct, size))
        work.add(2 * size)  # the sides of equations and comparisons walked
        for sym, term in _definitions(conjunct):
            if sym == last:
                hints[order[last]].append((term, size))
        for sym, term in _bounds(conjunct) if bounds else ():
            if sym == last:
                near[order[last]].append((term, size))
        compared = _comparison(conjunct) if bounds else None
        if compared is not None:
            crossings[order[last]].append((compared, 2 * size))
    domains: list[list[Scalar]] = [
        [True, False]
        if sym.sort == "bool"
        else _texts(constants.get(sym, set()))
        if sym.sort == "str"
        else list(_candidates(constants.get(sym, set()), sym.sort == "int"))
        for sym in symbols
    ]
    return _assign(symbols, domains, due, hints, near, crossings, work)


def _texts(constants: set[Fraction | str]) -> list[Scalar]:
    """A string symbol's candidates: the strings its conjuncts compare it with,
    then one that is none of them."""
    texts = sorted(c for c in constants if isinstance(c, str))
    other = "x"
    while other in texts:
        other += "x"
    return [*texts, other]


def _definitions(conjunct: A.Expr) -> list[tuple[A.Sym, A.Expr]]:
    """`s == term` (either way round) with `s` not in `term`."""
    return _sides(conjunct, ("==",))


def _bounds(conjunct: A.Expr) -> list[tuple[A.Sym, A.Expr]]:
    """`s < term` (or <=, >, >=; either way round) with `s` not in `term`: a
    value just past the term's is worth trying (`s > limit`)."""
    return _sides(conjunct, ("<", "<=", ">", ">="))


def _sides(conjunct: A.Expr, ops: tuple[str, ...]) -> list[tuple[A.Sym, A.Expr]]:
    if not isinstance(conjunct, A.Binary) or conjunct.op not in ops:
        return []
    return [
        (side, other)
        for side, other in (
            (conjunct.left, conjunct.right),
            (conjunct.right, conjunct.left),
        )
        if isinstance(side, A.Sym) and side not in A.syms(other)
    ]


def _comparison(conjunct: A.Expr) -> A.Binary | None:
    """The comparison a conjunct makes (`a < b`, or `not a < b`)."""
    if isinstance(conjunct, A.Unary) and conjunct.op == "not":
        conjunct = conjunct.operand
    if isinstance(conjunct, A.Binary) and conjunct.op in ("<", "<=", ">", ">="):
        return conjunct
    return None


def _crossing(conjunct: A.Binary, sym: A.Sym, values: Values) -> Fraction | None:
    """Where the two sides of a comparison meet as `sym` varies, the others fixed,
    taking the difference as linear in `sym` (two points; `abs(k * x) > c` gives
    `x = c / k`); None when it is not a number or does not vary."""
    difference = A.Binary("-", conjunct.left, conjunct.right)
    at = [_value(difference, {**values, sym: Fraction(x)}) for x in (0, 1)]
    if not all(isinstance(v, Fraction) for v in at) or at[0] == at[1]:
        return None
    low, high = at[0], at[1]
    assert isinstance(low, Fraction) and isinstance(high, Fraction)
    root = -low / (high - low)
    return None if abs(root.numerator) > _LIMIT or root.denominator > _LIMIT else root


def _defines(conjunct: A.Expr) -> set[A.Sym]:
    return {sym for sym, _ in _definitions(conjunct)}


def _assign(
    symbols: list[A.Sym],
    domains: list[list[Scalar]],
    due: list[list[tuple[A.Expr, int]]],
    hints: list[list[tuple[A.Expr, int]]],
    near: list[list[tuple[A.Expr, int]]],
    crossings: list[list[tuple[A.Binary, int]]],
    work: _Work,
) -> dict[A.Sym, Scalar] | None:
    """Backtracking over the symbols in order: the first values found; None when
    there are none or the steps ran out. A symbol tries first what its equations
    give it, then its domain, then one past each bound (`s > limit`) and past
    where each comparison's sides meet."""
    values: Values = {}
    steps = 0
    stack: list[tuple[int, list[Scalar]]] = []

    def evaluated(term: A.Expr, size: int) -> Value:
        work.add(size)
        return _value(term, values)

    def options(index: int) -> list[Scalar]:
        first: list[Scalar] = []
        for term, size in hints[index]:
            value = evaluated(term, size)
            if _fits(value, symbols[index].sort):
                first.append(value)  # type: ignore[arg-type]
        sym = symbols[index]
        points = [evaluated(term, size) for term, size in near[index]]
        for compared, size in crossings[index]:
            work.add(size)
            points.append(_crossing(compared, sym, values))
        last: list[Scalar] = []
        for value in points:
            if isinstance(value, Fraction):
                last += [v for v in (value + 1, value - 1) if _fits(v, sym.sort)]
                if sym.sort == "int" and value.denominator != 1:
                    last += [
                        Fraction(value.numerator // value.denominator + k)
                        for k in (0, 1)
                    ]
        return first + domains[index] + last

    if not symbols:
        return {}
    stack.append((0, options(0)))
    while stack:
        index, pending = stack[-1]
        if not pending:
            stack.pop()
            values.pop(symbols[index], None)
            continue
        steps += 1
        if steps > MAX_STEPS:
            return None
        values[symbols[index]] = pending.pop(0)
        if all(evaluated(c, size) is True for c, size in due[index]):
            if index + 1 == len(symbols):
                return {sym: values[sym] for sym in symbols}
            stack.append((index + 1, options(index + 1)))
    return None


def closed_value(expr: A.Expr) -> Fraction | bool | None:
    """The exact value of a term without names or symbols (`10 <= 0`), as the
    solver gives it; None for anything else."""
    found = _exact(expr, {})
    return None if isinstance(found, str) else found


def value_at(term: A.Expr, values: dict[A.Sym, Scalar]) -> Value:
    """The exact value of `term` where its solver symbols take `values` (a
    counterexample's probe), as the solver gives it; None where a symbol has no
    value or `closed_value` would give none."""
    return _exact(term, {sym: value for sym, value in values.items()})


def _exact(term: A.Expr, values: Values) -> Value:
    """`_value`, once every node of `term` is one the solver reads as written: no
    names, no number beyond `_LIMIT`, no symbol without a value."""
    for node in A.walk(term):
        if isinstance(node, A.Num):
            if abs(node.value.numerator) > _LIMIT or node.value.denominator > _LIMIT:
                return None
        elif isinstance(node, A.Sym):
            if node not in values:
                return None
        elif not isinstance(node, (A.Bool, A.Unary, A.Binary, A.Func, A.Ite)):
            return None
    return _value(term, values)


def _fits(value: object, sort: str) -> bool:
    """A value a symbol of `sort` can take."""
    if isinstance(value, bool):
        return sort == "bool"
    if isinstance(value, str):
        return sort == "str"
    if isinstance(value, Fraction):
        return sort == "real" or (sort == "int" and value.denominator == 1)
    return False


Scalar = Fraction | bool | str
Value = Scalar | None
# A name's value by its name (RF509's refinements), a solver symbol's by the symbol.
Values = dict[object, Scalar]


def _value(expr: A.Expr, values: Values) -> Value:
    """The exact value, or None where the solver's meaning is not a number's or a
    boolean's as the encoder (`smt.encode`) gives it."""
    if isinstance(expr, A.Num):
        return expr.value
    if isinstance(expr, A.Name):
        return values.get(expr.name)
    if isinstance(expr, A.Sym):
        return values.get(expr)
    if isinstance(expr, A.Bool):
        return expr.value
    if isinstance(expr, A.Str):
        return expr.value
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
        then, orelse = _value(expr.then, values), _value(expr.orelse, values)
        if isinstance(then, bool) != isinstance(orelse, bool):
            return None  # branches of two sorts: the encoder's Ite is not this one
        return then if cond else orelse
    if isinstance(expr, A.Binary):
        return _binary(expr, values)
    return None


def _binary(expr: A.Binary, values: Values) -> Value:
    left, right = _value(expr.left, values), _value(expr.right, values)
    op = expr.op
    if op in ("and", "or"):
        if not isinstance(left, bool) or not isinstance(right, bool):
            return None
        return (left and right) if op == "and" else (left or right)
    if op in ("==", "!=") and (
        (isinstance(left, bool) and isinstance(right, bool))
        or (isinstance(left, str) and isinstance(right, str))
    ):
        return (left == right) if op == "==" else (left != right)
    if not isinstance(left, Fraction) or not isinstance(right, Fraction):
        return None  # booleans compared, or an unknown part
    if op in A.ARITH_OPS:
        result = A.arith(op, left, right)
        if result is None or op == "/":
            return result
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
