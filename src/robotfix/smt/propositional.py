"""Questions about paths decided without z3, over the boolean skeleton of a VC.

Whether a path can run (`if c: ... if not c: ...`) is mostly a question about the
tests taken, not about numbers. Each comparison, and each other term that is not a
connective, is one proposition (`x <= 1` is `not (x > 1)`); boolean symbols are
propositions too. If the skeleton has no model, neither has the VC, whatever the
numbers are. If it has one and every proposition is a boolean symbol, so has the
VC. Otherwise the question needs z3.

The nodes walked and searched are charged to the file's work budget when one is
given (`robotfix.budget`).
"""

from __future__ import annotations

import itertools
import operator
from fractions import Fraction
from typing import Any

from robotfix.annotations import ast as A
from robotfix.annotations.witness import closed_value
from robotfix.budget import Budget

# Search nodes one question may visit before it is left to z3.
BUDGET = 4000
MAX_ATOMS = 64
NEGATED = {"<=": ">", ">=": "<", "!=": "=="}
COMPARISONS = frozenset({"==", "!=", "<", "<=", ">", ">="})
Formula = tuple[Any, ...]  # ("and", f...), ("or", f...), ("not", f), ("atom", i)


class _Skeleton:
    def __init__(self) -> None:
        self.atoms: dict[object, int] = {}
        self.arithmetic = False  # some proposition is not a boolean symbol
        self.nodes = 0  # terms read

    def atom(self, key: object, boolean: bool) -> Formula:
        if not boolean:
            self.arithmetic = True
        index = self.atoms.setdefault(key, len(self.atoms))
        return ("atom", index)

    def formula(self, expr: A.Expr) -> Formula:
        self.nodes += 1
        kind = type(expr)
        if kind is A.Bool:
            return ("const", expr.value)  # type: ignore[union-attr]
        if kind is A.Sym:
            return self.atom(expr, expr.sort == "bool")  # type: ignore[union-attr]
        if kind is A.Unary and expr.op == "not":  # type: ignore[union-attr]
            return ("not", self.formula(expr.operand))  # type: ignore[union-attr]
        if kind is A.Binary:
            op = expr.op  # type: ignore[union-attr]
            left, right = expr.left, expr.right  # type: ignore[union-attr]
            if op in ("and", "or"):
                return (op, self.formula(left), self.formula(right))
            if op in ("==", "!=") and _boolean(left) and _boolean(right):
                same = ("iff", self.formula(left), self.formula(right))
                return same if op == "==" else ("not", same)
            if op in COMPARISONS:
                known = closed_value(expr)  # `10 <= 0`: a constant, not a proposition
                if isinstance(known, bool):
                    return ("const", known)
            if op in NEGATED:
                return ("not", self.atom(A.Binary(NEGATED[op], left, right), False))
            if op in COMPARISONS:
                return self.atom(expr, False)
        if kind is A.Ite and _boolean(expr):
            cond = self.formula(expr.cond)  # type: ignore[union-attr]
            then = self.formula(expr.then)  # type: ignore[union-attr]
            orelse = self.formula(expr.orelse)  # type: ignore[union-attr]
            return ("or", ("and", cond, then), ("and", ("not", cond), orelse))
        return self.atom(expr, False)


def _boolean(expr: A.Expr) -> bool:
    kind = type(expr)
    if kind is A.Bool:
        return True
    if kind is A.Sym:
        return expr.sort == "bool"  # type: ignore[union-attr]
    if kind is A.Unary:
        return expr.op == "not"  # type: ignore[union-attr]
    if kind is A.Binary:
        return expr.op in COMPARISONS or expr.op in ("and", "or")  # type: ignore[union-attr]
    if kind is A.Ite:
        return _boolean(expr.then) and _boolean(expr.orelse)  # type: ignore[union-attr]
    return False


def _value(f: Formula, model: dict[int, bool]) -> bool | None:
    """Three-valued: None while an atom it needs has no value yet."""
    tag = f[0]
    if tag == "atom":
        return model.get(f[1])
    if tag == "const":
        return bool(f[1])
    if tag == "not":
        inner = _value(f[1], model)
        return None if inner is None else not inner
    if tag == "iff":
        a, b = _value(f[1], model), _value(f[2], model)
        return None if a is None or b is None else a == b
    a = _value(f[1], model)
    decisive = tag == "or"  # True decides an `or`, False an `and`
    if a is decisive:
        return decisive
    b = _value(f[2], model)
    if b is decisive:
        return decisive
    return None if a is None or b is None else not decisive


def satisfiable(parts: list[A.Expr], budget: Budget | None = None) -> bool | None:
    """Do `parts` have a model? None: not decided here (ask z3)."""
    skeleton = _Skeleton()
    formulas = [skeleton.formula(p) for p in parts]
    if budget is not None:
        budget.spend(skeleton.nodes)
    if len(skeleton.atoms) > MAX_ATOMS:
        return None
    formulas += _exclusions(skeleton.atoms)
    found = _search(formulas, len(skeleton.atoms), budget)
    if found is None:
        return None
    if not found:
        return False  # no model of the skeleton: none of the VC
    return None if skeleton.arithmetic else True


def _exclusions(atoms: dict[object, int]) -> list[Formula]:
    """What the numbers say of two comparisons of one symbol with constants: `s == 1`
    and `s == -1` are not both true, nor `s == -111` and `s > 0`, and `s < 0` holds
    whenever `s < -5` does. One clause per truth values of such a pair that no real
    number takes (true of an integer symbol too), so that a path that sets a symbol
    to a constant, or bounds it, and tests it against another constant is ruled out
    as it is by the numbers (the only arithmetic the skeleton knows)."""
    seen: dict[A.Sym, list[tuple[str, Fraction, int]]] = {}
    for key, index in atoms.items():
        if not isinstance(key, A.Binary) or key.op not in _BOUNDS:
            continue
        for sym, other, op in (
            (key.left, key.right, key.op),
            (key.right, key.left, _MIRRORED[key.op]),
        ):
            value = closed_value(other)
            if isinstance(sym, A.Sym) and isinstance(value, Fraction):
                seen.setdefault(sym, []).append((op, value, index))
    clauses: list[Formula] = []
    for found in seen.values():
        for (op_a, a, i), (op_b, b, j) in itertools.combinations(found, 2):
            points = (a, b, (a + b) / 2, min(a, b) - 1, max(a, b) + 1)
            for truth_a, truth_b in _TRUTHS:
                if not any(
                    _BOUNDS[op_a](x, a) is truth_a and _BOUNDS[op_b](x, b) is truth_b
                    for x in points
                ):
                    clauses.append(
                        ("not", ("and", _literal(i, truth_a), _literal(j, truth_b)))
                    )
    return clauses


# The comparisons an atom may be (`NEGATED` leaves no other), and the same with
# its sides swapped. Between and beyond two constants every real number compares
# with both as one of the five points tried does.
_BOUNDS = {"==": operator.eq, "<": operator.lt, ">": operator.gt}
_MIRRORED = {"==": "==", "<": ">", ">": "<"}
_TRUTHS = ((True, True), (True, False), (False, True), (False, False))


def _literal(index: int, truth: bool) -> Formula:
    return ("atom", index) if truth else ("not", ("atom", index))


def components(parts: list[A.Expr], budget: Budget | None = None) -> list[list[A.Expr]]:
    """`parts` in groups that share no solver symbol, in order of first part. The
    parts have a model together exactly when each group has one (a name, or any
    term the encoder cannot read, is a fresh constant at each occurrence, so it
    joins nothing), and a small group is searched quickly."""
    parent: dict[int, int] = {}
    nodes = 0

    def root(ident: int) -> int:
        while parent[ident] != ident:
            parent[ident] = parent[parent[ident]]
            ident = parent[ident]
        return ident

    owners: list[list[int]] = []
    for part in parts:
        walked = A.walk(part)
        nodes += len(walked)
        idents = list(dict.fromkeys(n.ident for n in walked if isinstance(n, A.Sym)))
        for ident in idents:
            parent.setdefault(ident, ident)
        for other in idents[1:]:
            parent[root(other)] = root(idents[0])
        owners.append(idents)
    groups: dict[object, list[A.Expr]] = {}
    for index, (part, idents) in enumerate(zip(parts, owners, strict=True)):
        key: object = root(idents[0]) if idents else ("closed", index)
        groups.setdefault(key, []).append(part)
    if budget is not None:
        budget.spend(nodes)
    return list(groups.values())


def _search(
    formulas: list[Formula], count: int, budget: Budget | None = None
) -> bool | None:
    """Backtracking over the atoms in order, pruning on a false formula. The
    three-valued `_value` is monotone (a formula decided under part of a model stays
    so under any extension), so each node only evaluates the formulas its parent
    left undecided."""
    model: dict[int, bool] = {}
    visited = 0
    evaluated = 0  # formulas evaluated: the work charged

    def go(index: int, pending: list[Formula]) -> bool | None:
        nonlocal visited, evaluated
        visited += 1
        if visited > BUDGET:
            return None
        evaluated += len(pending)
        undecided: list[Formula] = []
        for f in pending:
            value = _value(f, model)
            if value is False:
                return False
            if value is None:
                undecided.append(f)
        if not undecided:
            return True
        if index >= count:
            return False
        for choice in (True, False):
            model[index] = choice
            found = go(index + 1, undecided)  # noqa: F821 (deleted after the search)
            if found is not False:
                del model[index]
                return found
        del model[index]
        return False

    try:
        return go(0, formulas)
    finally:
        del go  # it calls itself through its cell: a cycle only the collector frees
        if budget is not None:
            budget.spend(evaluated)
