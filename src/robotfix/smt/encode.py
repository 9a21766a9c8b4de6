"""Terms of `annotations.ast` -> z3 expressions.

Total by design: a term used at a sort it does not have (an unknown value used as a
condition, a string compared with a number) becomes a fresh constant of the needed
sort, which can only weaken what is known, never invent a violation.
"""

from __future__ import annotations

from typing import Any

import z3

from robotfix.annotations import ast as A


class Encoder:
    def __init__(self) -> None:
        self.syms: dict[int, Any] = {}
        self._fresh = 0

    def sym(self, node: A.Sym) -> Any:
        if node.ident not in self.syms:
            name = f"s{node.ident}"
            make = {"int": z3.Int, "bool": z3.Bool, "str": z3.String}.get(
                node.sort, z3.Real
            )
            self.syms[node.ident] = make(name)
        return self.syms[node.ident]

    def fresh(self, sort: str) -> Any:
        self._fresh += 1
        make = {"bool": z3.Bool, "real": z3.Real, "int": z3.Int}[sort]
        return make(f"_f{self._fresh}")

    def encode(self, node: A.Expr) -> Any:
        if isinstance(node, A.Num):
            if node.is_int and node.value.denominator == 1:
                return z3.IntVal(node.value.numerator)
            return z3.Q(node.value.numerator, node.value.denominator)
        if isinstance(node, A.Bool):
            return z3.BoolVal(node.value)
        if isinstance(node, A.Str):
            return z3.StringVal(node.value)
        if isinstance(node, A.Sym):
            return self.sym(node)
        if isinstance(node, A.Name):  # an unresolved name: nothing is known of it
            return self.fresh("real")
        if isinstance(node, A.UnitIs):
            return z3.BoolVal(True)  # units are checked by the analysis, not here
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
        left, right = self.arith(node.left), self.arith(node.right)
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


def _is_int(value: Any) -> bool:
    return bool(z3.is_int(value))


def _real(value: Any) -> Any:
    return z3.ToReal(value) if _is_int(value) else value


def _comparable(left: Any, right: Any) -> bool:
    if z3.is_arith(left) and z3.is_arith(right):
        return True
    return bool(left.sort() == right.sort())
