"""Parse refinement text into `annotations.ast`. The only module that imports lark.

No lark object leaves this module: the parse tree is converted at once, and lark's
errors become `AnnotationSyntaxError` with a 0-based character offset.
"""

from __future__ import annotations

from fractions import Fraction
from functools import lru_cache
from typing import Any

from lark import Lark, Token, Transformer, v_args
from lark.exceptions import (
    UnexpectedCharacters,
    UnexpectedEOF,
    UnexpectedInput,
    VisitError,
)

from robotfix.annotations import ast as A

_PARSER = Lark.open(
    "grammar.lark", rel_to=__file__, parser="lalr", propagate_positions=False
)
_LABEL_FUNCS = {"Unit": "unit", "Frame": "frame", "Tag": "tag"}
_MATH_FUNCS = {"abs": 1, "min": 2, "max": 2}


class AnnotationSyntaxError(Exception):
    def __init__(self, message: str, offset: int) -> None:
        super().__init__(message)
        self.message = message
        self.offset = offset


class _LabelOf:
    """`Unit(path)` before it is compared with a string; never leaves the parser."""

    def __init__(self, kind: str, target: str, pos: int) -> None:
        self.kind, self.target, self.pos = kind, target, pos


@v_args(inline=True)
class _ToAst(Transformer[Token, Any]):
    """One method per grammar alias; each returns a node of our own AST."""

    def number(self, tok: Token) -> A.Num:
        text = str(tok)
        return A.Num(Fraction(text), not any(c in text for c in ".eE"))

    def string(self, tok: Token) -> A.Str:
        return A.Str(str(tok)[1:-1])

    def true(self) -> A.Bool:
        return A.Bool(True)

    def false(self) -> A.Bool:
        return A.Bool(False)

    def path(self, *parts: Token) -> A.Name:
        return A.Name(".".join(str(p) for p in parts), parts[0].start_pos or 0)

    def neg(self, operand: A.Expr) -> A.Expr:
        if isinstance(operand, A.Num):
            return A.Num(-operand.value, operand.is_int)
        return A.Unary("-", _value(operand))

    def not_(self, operand: A.Expr) -> A.Expr:
        return A.Unary("not", _value(operand))

    def arith(self, left: A.Expr, op: Token, right: A.Expr) -> A.Expr:
        return A.Binary(str(op), _value(left), _value(right))

    def and_(self, left: A.Expr, right: A.Expr) -> A.Expr:
        return A.Binary("and", _value(left), _value(right))

    def or_(self, left: A.Expr, right: A.Expr) -> A.Expr:
        return A.Binary("or", _value(left), _value(right))

    def ite(self, cond: A.Expr, then: A.Expr, orelse: A.Expr) -> A.Expr:
        return A.Ite(_value(cond), _value(then), _value(orelse))

    def py_ite(self, then: A.Expr, cond: A.Expr, orelse: A.Expr) -> A.Expr:
        return A.Ite(_value(cond), _value(then), _value(orelse))

    def chain(self, *items: Any) -> A.Expr:
        operands = items[0::2]
        ops = [str(op) for op in items[1::2]]
        parts = [
            _compare(op, a, b)
            for op, a, b in zip(ops, operands, operands[1:], strict=False)
        ]
        return A.conjoin(parts)

    def in_(self, item: A.Expr, *options: A.Expr | None) -> A.Expr:
        subject = _value(item)
        result: A.Expr | None = None
        for option in options:
            if option is None:
                continue
            eq = A.Binary("==", subject, _value(option))
            result = eq if result is None else A.Binary("or", result, eq)
        assert result is not None  # the grammar requires one option
        return result

    def call(self, name: Token, *args: A.Expr | None) -> Any:
        given = [a for a in args if a is not None]
        fname, pos = str(name), name.start_pos or 0
        if fname in _LABEL_FUNCS:
            return _label(_LABEL_FUNCS[fname], given, pos)
        if fname in _MATH_FUNCS:
            arity = _MATH_FUNCS[fname]
            if len(given) != arity and not (fname != "abs" and len(given) >= 2):
                raise AnnotationSyntaxError(
                    f"{fname}() takes {arity} argument{'s' * (arity > 1)}", pos
                )
            return A.Func(fname, tuple(_value(a) for a in given))
        known = ", ".join([*_LABEL_FUNCS, *_MATH_FUNCS])
        raise AnnotationSyntaxError(f"unknown function `{fname}` (known: {known})", pos)


def _label(kind: str, args: list[Any], pos: int) -> Any:
    if len(args) == 1 and isinstance(args[0], A.Str):
        return A.UnitIs(kind, args[0].value, None, pos)
    if len(args) == 1 and isinstance(args[0], A.Name):
        return _LabelOf(kind, args[0].name, pos)
    fname = kind.capitalize()
    raise AnnotationSyntaxError(
        f"{fname}() takes a string such as {fname}('m/s'), or a field path compared "
        f'with a string such as {fname}(linear.x) == "m/s"',
        pos,
    )


def _compare(op: str, left: Any, right: Any) -> A.Expr:
    if isinstance(left, _LabelOf) or isinstance(right, _LabelOf):
        label, other = (left, right) if isinstance(left, _LabelOf) else (right, left)
        if op == "==" and isinstance(other, A.Str):
            return A.UnitIs(label.kind, other.value, label.target, label.pos)
        raise AnnotationSyntaxError(
            f"{label.kind.capitalize()}({label.target}) can only be compared with == "
            "to a string",
            label.pos,
        )
    return A.Binary(op, _value(left), _value(right))


def _value(node: Any) -> A.Expr:
    if isinstance(node, _LabelOf):
        raise AnnotationSyntaxError(
            f"{node.kind.capitalize()}({node.target}) must be compared with a string",
            node.pos,
        )
    return node  # type: ignore[no-any-return]


@lru_cache(maxsize=4096)
def parse_predicate(text: str) -> A.Expr:
    """Parse one annotation. An empty or blank text means no refinement (`True`)."""
    if not text.strip():
        return A.TRUE
    try:
        tree = _PARSER.parse(text)
    except UnexpectedInput as err:
        raise AnnotationSyntaxError(_describe(err, text), _offset(err, text)) from None
    try:
        return _value(_ToAst().transform(tree))
    except VisitError as err:
        if isinstance(err.orig_exc, AnnotationSyntaxError):
            raise err.orig_exc from None
        raise


def _offset(err: UnexpectedInput, text: str) -> int:
    pos = getattr(err, "pos_in_stream", None)
    if isinstance(pos, int) and pos >= 0:
        return min(pos, len(text))
    if isinstance(err, UnexpectedEOF):
        return len(text.rstrip())
    return max(0, (err.column or 1) - 1)


def _describe(err: UnexpectedInput, text: str) -> str:
    if isinstance(err, UnexpectedCharacters):
        at = err.pos_in_stream or 0
        return f"unexpected character {text[at : at + 1]!r}"
    if isinstance(err, UnexpectedEOF):
        return "the annotation ends too early"
    token = getattr(err, "token", None)
    if token is not None and token.type == "$END":
        return "the annotation ends too early"
    return f"unexpected {str(token)!r}" if token is not None else "syntax error"
