"""Terms of `annotations.ast` -> z3 expressions.

Total by design: a term used at a sort it does not have (an unknown value used as a
condition, a string compared with a number) becomes a fresh constant of the needed
sort, which can only weaken what is known, never invent a violation.
"""

from __future__ import annotations

from typing import Any

import z3

from robotfix.annotations import ast as A

# Digits beyond which a number is not handed to z3: z3 takes numbers as decimal
# text, and Python refuses to write an int of more than 4,300 digits.
MAX_DIGITS = 1_000
_TOO_LONG: int = 10**MAX_DIGITS
MAX_DEGREE = 3
MEMO_ENTRIES = 100_000  # terms whose z3 form a session keeps; then forgotten at once


class Encoder:
    def __init__(self, ctx: Any, canonical: bool = False) -> None:
        self.ctx = ctx  # the z3 context of the session
        self.syms: dict[int, Any] = {}
        # name symbols in the order they are met, not by their identity: the same
        # question is then the same text to z3, whatever the analysis numbered
        self._canonical = canonical
        self._fresh = 0
        self._degrees: dict[int, int] = {}  # id(term) -> degree, for one question
        self.approximated = False  # a term became a fresh constant
        self.built = 0  # terms built through z3's API: the work the file is charged
        # id(term) -> (term, its z3 form), for terms without a fresh constant: the
        # analysis shares sub-terms between facts (`x2 = x1 + 1`, `x3 = x2 + 1`),
        # and each is encoded once, not once per fact that holds it
        self._encoded: dict[int, tuple[A.Expr, Any]] = {}

    def start(self) -> None:
        """A new question: forget the terms seen and whether any was approximated."""
        self._degrees.clear()
        self.approximated = False

    def sym(self, node: A.Sym) -> Any:
        if node.ident not in self.syms:
            name = f"s{len(self.syms) if self._canonical else node.ident}"
            make = {"int": z3.Int, "bool": z3.Bool, "str": z3.String}.get(
                node.sort, z3.Real
            )
            self.syms[node.ident] = make(name, self.ctx)
        return self.syms[node.ident]

    def fresh(self, sort: str) -> Any:
        self.approximated = True
        self._fresh += 1
        make = {"bool": z3.Bool, "real": z3.Real, "int": z3.Int}[sort]
        return make(f"_f{self._fresh}", self.ctx)

    def encode(self, node: A.Expr) -> Any:
        found = self._encoded.get(id(node))
        if found is not None and found[0] is node:
            return found[1]
        fresh = self._fresh
        self.built += 1
        value = self._encode(node)
        if fresh == self._fresh and A.children(node):  # no fresh constant in it
            if len(self._encoded) >= MEMO_ENTRIES:
                self._encoded.clear()
            self._encoded[id(node)] = (node, value)
        return value

    def _encode(self, node: A.Expr) -> Any:
        if isinstance(node, A.Num):
            return self._number(node)
        if isinstance(node, A.Bool):
            return z3.BoolVal(node.value, self.ctx)
        if isinstance(node, A.Str):
            return z3.StringVal(node.value, self.ctx)
        if isinstance(node, A.Sym):
            return self.sym(node)
        if isinstance(node, A.Name):  # an unresolved name: nothing is known of it
            return self.fresh("real")
        if isinstance(node, A.UnitIs):
            # units are checked by the analysis, not here
            return z3.BoolVal(True, self.ctx)
        if isinstance(node, A.Unary):
            if node.op == "not":
                return z3.Not(self.boolean(node.operand))
            return -self.arith(node.operand)
        if isinstance(node, A.Binary):
            return self._binary(node)
        if isinstance(node, A.Ite):
            then, orelse = self.encode(node.then), self.encode(node.orelse)
            then, orelse = self._same_sort(then, orelse)
            return z3.If(self.boolean(node.cond), then, orelse)
        if isinstance(node, A.Func):
            return self._func(node)
        raise TypeError(f"cannot encode {node!r}")

    def _number(self, node: A.Num) -> Any:
        value = node.value
        if _too_long(value.numerator) or _too_long(value.denominator):
            return self.fresh("real")
        if node.is_int and value.denominator == 1:
            return z3.IntVal(value.numerator, self.ctx)
        return z3.Q(value.numerator, value.denominator, self.ctx)

    def boolean(self, node: A.Expr) -> Any:
        value = self.encode(node)
        return value if z3.is_bool(value) else self.fresh("bool")

    def arith(self, node: A.Expr) -> Any:
        value = self.encode(node)
        return value if z3.is_arith(value) else self.fresh("real")

    def _binary(self, node: A.Binary) -> Any:
        op = node.op
        if op in ("and", "or"):
            parts = [self.boolean(node.left), self.boolean(node.right)]
            return z3.And(*parts) if op == "and" else z3.Or(*parts)
        if op in ("==", "!="):
            left, right = self.encode(node.left), self.encode(node.right)
            if not _comparable(left, right):
                return self.fresh("bool")
            left, right = self._same_sort(left, right)
            return left == right if op == "==" else left != right
        if op in _PRODUCTS and self._product_degree(node) > MAX_DEGREE:
            return self.fresh("real")
        left, right = self.arith(node.left), self.arith(node.right)
        if op in ("//", "%"):
            return _floored(op, left, right)
        if op == "/":
            return (
                z3.ToReal(left) / z3.ToReal(right)
                if _is_int(left) and _is_int(right)
                else _real(left) / _real(right)
            )
        left, right = self._same_sort(left, right)
        return {
            "+": lambda: left + right,
            "-": lambda: left - right,
            "*": lambda: left * right,
            "<": lambda: left < right,
            "<=": lambda: left <= right,
            ">": lambda: left > right,
            ">=": lambda: left >= right,
        }[op]()

    def _product_degree(self, node: A.Binary) -> int:
        return self._degree(node.left) + self._degree(node.right)

    def _degree(self, node: A.Expr) -> int:
        """The polynomial degree of a term as encoded (a capped product counts 1)."""
        found = self._degrees.get(id(node))
        if found is not None:
            return found
        if isinstance(node, (A.Sym, A.Name)):
            found = 1
        elif isinstance(node, A.Binary) and node.op in _PRODUCTS:
            found = self._product_degree(node)
            found = 1 if found > MAX_DEGREE else found
        elif isinstance(node, A.Ite):
            found = max(self._degree(node.then), self._degree(node.orelse))
        else:
            found = max((self._degree(c) for c in A.children(node)), default=0)
        self._degrees[id(node)] = found
        return found

    def _func(self, node: A.Func) -> Any:
        if node.name == "len":  # a length the analysis did not resolve: unknown
            return self.fresh("int")
        args = [self.arith(a) for a in node.args]
        if node.name == "abs":
            return z3.If(args[0] >= 0, args[0], -args[0])
        result = args[0]
        for other in args[1:]:
            result, other = self._same_sort(result, other)
            pick = result <= other if node.name == "min" else result >= other
            result = z3.If(pick, result, other)
        return result

    def _same_sort(self, left: Any, right: Any) -> tuple[Any, Any]:
        if z3.is_arith(left) and z3.is_arith(right) and _is_int(left) != _is_int(right):
            return _real(left), _real(right)
        if left.sort() != right.sort():
            return left, left  # incomparable branches: the Ite is as good as unknown
        return left, right


_PRODUCTS = frozenset({"*", "/", "//", "%"})


def _floored(op: str, left: Any, right: Any) -> Any:
    """Python's `left // right` and `left % right`: the quotient floored, the
    remainder with the divisor's sign. Ints use z3's div and mod (Euclidean: floored
    for a positive divisor, and `a // b == -a // -b`), so a constant divisor stays
    linear; otherwise the real quotient is floored (`ToInt` is floor). By zero the
    result is z3's unconstrained value: Python raised there, the path never ends."""
    if _is_int(left) and _is_int(right):
        if op == "//":
            up, down = left / right, (-left) / (-right)
        else:
            up, down = left % right, -((-left) % (-right))
        if z3.is_int_value(right):  # a constant divisor: its sign picks the form
            return up if right.as_long() > 0 else down
        return z3.If(right > 0, up, down)
    left, right = _real(left), _real(right)
    quotient = z3.ToReal(z3.ToInt(left / right))
    return quotient if op == "//" else left - right * quotient


def _too_long(number: int) -> bool:
    return abs(number) >= _TOO_LONG


def _is_int(value: Any) -> bool:
    return bool(z3.is_int(value))


def _real(value: Any) -> Any:
    return z3.ToReal(value) if _is_int(value) else value


def _comparable(left: Any, right: Any) -> bool:
    if z3.is_arith(left) and z3.is_arith(right):
        return True
    return bool(left.sort() == right.sort())
