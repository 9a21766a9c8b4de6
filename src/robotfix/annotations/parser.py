"""Parse refinement text into `annotations.ast`. The only module that imports lark.

No lark object leaves this module: the LALR parser calls `_ToAst` as it reduces, so
no parse tree is built or walked recursively, and lark's errors become
`AnnotationSyntaxError` with a 0-based character offset.

Bounds, so that no annotation can hang or crash a later stage (`str()` of a huge
integer, z3, recursive walks): the text is at most MAX_CHARS long, a number has at
most MAX_DIGITS digits and an exponent within +-MAX_EXPONENT (every double fits,
and no literal is far beyond one), arithmetic on literals stays within
MAX_CONSTANT_DIGITS, and the expression
is at most MAX_DEPTH levels deep. `and`, `or` and
`in (...)` are built balanced, so hundreds of conjuncts or options stay shallow.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Callable
from dataclasses import fields, is_dataclass
from fractions import Fraction
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

from robotfix.annotations import ast as A

if TYPE_CHECKING:
    from lark import Lark, Token
    from lark.exceptions import UnexpectedInput

MAX_DIGITS = 100
MAX_EXPONENT = 400  # doubles reach 1.8e308 and 5e-324
MAX_DEPTH = 100
MAX_CHARS = 100_000  # parsing takes about 1 s per 100,000 characters
MAX_CONSTANT_DIGITS = 1000  # of a product of literals; Python's str(int) stops at 4300
_MAX_CONSTANT_BITS = 3322  # 1000 decimal digits
_LABEL_FUNCS = {"Unit": "unit", "Frame": "frame", "Tag": "tag"}
_MATH_FUNCS = {"abs": 1, "min": 2, "max": 2, "len": 1}


class AnnotationSyntaxError(Exception):
    def __init__(self, message: str, offset: int) -> None:
        super().__init__(message)
        self.message = message
        self.offset = offset


class _LabelOf:
    """`Unit(path)` before it is compared with a string; never leaves the parser."""

    def __init__(self, kind: str, target: str, pos: int) -> None:
        self.kind, self.target, self.pos = kind, target, pos


class _ToAst:
    """One method per grammar alias; each returns a node of our own AST. Lark calls
    them through `_Inline`, with a rule's children as the arguments."""

    def number(self, tok: Token) -> A.Num:
        text = str(tok)
        mantissa, _, exponent = text.lower().partition("e")
        digits = sum(c.isdigit() for c in mantissa)
        power = exponent.lstrip("+-").lstrip("0")
        if digits > MAX_DIGITS or len(power) > 3 or int(power or 0) > MAX_EXPONENT:
            raise AnnotationSyntaxError(
                f"the number `{A.excerpt(text, 20)}` is out of range: a number in an "
                f"annotation has at most {MAX_DIGITS} digits and an exponent from "
                f"-{MAX_EXPONENT} to {MAX_EXPONENT}",
                tok.start_pos or 0,
            )
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
        if (
            str(op) in ("/", "//", "%")
            and isinstance(right, A.Num)
            and right.value == 0
        ):
            raise AnnotationSyntaxError("division by zero", op.start_pos or 0)
        return A.Binary(str(op), _value(left), _value(right))

    def and_(self, *operands: A.Expr) -> A.Expr:
        return A.join("and", [_value(o) for o in operands])

    def or_(self, *operands: A.Expr) -> A.Expr:
        return A.join("or", [_value(o) for o in operands])

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
        equal = [A.Binary("==", subject, _value(o)) for o in options if o is not None]
        return A.join("or", equal)  # the grammar requires one option

    def call(self, name: Token, *args: A.Expr | None) -> Any:
        given = [a for a in args if a is not None]
        fname, pos = str(name), name.start_pos or 0
        if fname in _LABEL_FUNCS:
            return _label(_LABEL_FUNCS[fname], given, pos)
        if fname in _MATH_FUNCS:
            arity = _MATH_FUNCS[fname]
            fixed = fname in ("abs", "len")
            if len(given) != arity and not (not fixed and len(given) >= 2):
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


class _Inline:
    """What lark's LALR parser calls as it reduces: `_ToAst`'s method of the rule's
    alias, given the children as arguments (lark's `v_args(inline=True)`, without
    making `_ToAst` a lark class, so that lark is imported only when needed)."""

    def __init__(self, target: _ToAst) -> None:
        self._target = target

    def __getattr__(self, name: str) -> Callable[[list[Any]], Any]:
        method = getattr(type(self._target), name)  # AttributeError: lark's default
        target = self._target
        return lambda children: method(target, *children)


GRAMMAR = Path(__file__).parent / "grammar.lark"
# the parser's tables, written by tools/build_package_data.py (JSON: no pickle)
TABLES = Path(__file__).parent / "grammar.json"


@lru_cache(maxsize=1)
def _parser() -> Lark:
    """Made on the first annotation a process parses, not when the module is
    imported (most files have no annotation): loaded from the shipped tables (5 ms),
    or built from the grammar (35 ms) when they are not those of this grammar and
    lark version, or cannot be read."""
    from lark import Lark
    from lark.exceptions import LarkError

    try:
        shipped = json.loads(TABLES.read_text(encoding="utf-8"), object_hook=_untag)
        if shipped["format"] == tables_format():
            loaded: Lark = Lark._load_from_dict(  # type: ignore[no-untyped-call]
                shipped["data"], shipped["memo"], transformer=_Inline(_ToAst())
            )  # lark's own loader of serialized tables (its standalone parsers')
            return loaded
    except (OSError, ValueError, LookupError, TypeError, AttributeError, LarkError):
        pass  # built below
    return build_parser()


def build_parser() -> Lark:
    from lark import Lark

    return Lark(
        GRAMMAR.read_text(encoding="utf-8"),
        parser="lalr",
        propagate_positions=False,
        transformer=_Inline(_ToAst()),
    )


def tables_format() -> str:
    """What tables are valid for: lark's version and the grammar's digest."""
    import lark

    digest = hashlib.sha256(GRAMMAR.read_bytes()).hexdigest()[:16]
    return f"lark {lark.__version__}, grammar {digest}"


def tables_json() -> str:
    """A freshly built parser's tables, as `TABLES` holds them: lark's serialized
    form (its `Lark.save` without pickle), integer keys and tuples tagged."""
    from lark.grammar import Rule
    from lark.lexer import TerminalDef

    data, memo = build_parser().memo_serialize([TerminalDef, Rule])
    data["options"] = {k: v for k, v in data["options"].items() if k != "transformer"}
    tables = {"format": tables_format(), "data": data, "memo": memo}
    return json.dumps(_tag(tables), separators=(",", ":")) + "\n"


def _tag(value: Any) -> Any:
    if isinstance(value, dict):
        if all(isinstance(key, str) for key in value):
            return {key: _tag(item) for key, item in value.items()}
        return {"int-keys": [[key, _tag(item)] for key, item in value.items()]}
    if isinstance(value, tuple):
        return {"tuple": [_tag(item) for item in value]}
    if isinstance(value, list):
        return [_tag(item) for item in value]
    return value


def _untag(value: dict[str, Any]) -> Any:
    if len(value) == 1 and "int-keys" in value:
        return {int(key): item for key, item in value["int-keys"]}
    if len(value) == 1 and "tuple" in value:
        return tuple(value["tuple"])
    return value


_TOO_DEEP = (
    f"the annotation is nested more than {MAX_DEPTH} levels deep: split it into "
    "simpler parts"
)


def parse_predicate(text: str) -> A.Expr:
    """Parse one annotation. An empty or blank text means no refinement (`True`)."""
    result = _parse(text)
    if isinstance(result, tuple):
        raise AnnotationSyntaxError(*result)
    return result


@lru_cache(maxsize=4096)
def _parse(text: str) -> A.Expr | tuple[str, int]:
    """The expression, or the (message, offset) of the error: errors are cached too,
    since a bad annotation is met again in every file and run that reads it. A
    predicate the shipped stubs write comes parsed (`shipped`)."""
    found = shipped().get(text)
    if found is not None:
        return found
    try:
        return _parse_uncached(text)
    except AnnotationSyntaxError as err:
        return err.message, err.offset


# the predicates the shipped stubs write (`_ >= 0` of `math.sqrt`), parsed by
# tools/build_package_data.py: a run that meets no other annotation imports no
# lark (115 M instructions with the tables loaded)
SHIPPED = Path(__file__).parent / "stub_predicates.json"


@lru_cache(maxsize=1)
def shipped() -> dict[str, A.Expr]:
    """The shipped parses, when written by this parser from this grammar (else
    none: each is parsed)."""
    try:
        raw = json.loads(SHIPPED.read_text(encoding="utf-8"))
        if not isinstance(raw, dict) or raw.get("key") != parser_key():
            return {}
        return {text: _node(value) for text, value in raw["predicates"].items()}
    except Exception:  # of another shape: parsed as any other text
        return {}


def parser_key() -> str:
    """The grammar, this module and the nodes it builds, as text: what a parse
    depends on."""
    digest = hashlib.sha256()
    for path in (GRAMMAR, Path(__file__), Path(A.__file__)):
        digest.update(path.read_bytes())
    return digest.hexdigest()


def spelt_node(node: object) -> object:
    """An expression as JSON (`_node` reads it back): `[class, fields]`, a
    Fraction `["Fraction", n, d]`, a tuple `["tuple", items]`."""
    if isinstance(node, Fraction):
        return ["Fraction", node.numerator, node.denominator]
    if isinstance(node, tuple):
        return ["tuple", [spelt_node(n) for n in node]]
    if is_dataclass(node):
        values = {f.name: spelt_node(getattr(node, f.name)) for f in fields(node)}
        return [type(node).__name__, values]
    return node


def _node(raw: Any) -> Any:
    if not isinstance(raw, list):
        return raw
    kind, *rest = raw
    if kind == "Fraction":
        return Fraction(rest[0], rest[1])
    if kind == "tuple":
        return tuple(_node(n) for n in rest[0])
    node = _NODES[kind](**{k: _node(v) for k, v in rest[0].items()})
    return A.TRUE if node == A.TRUE else node


_NODES = {
    c.__name__: c
    for c in (A.Num, A.Bool, A.Str, A.Name, A.Unary, A.Binary, A.Ite, A.Func, A.UnitIs)
}


def _parse_uncached(text: str) -> A.Expr:
    if not text.strip():
        return A.TRUE
    if len(text) > MAX_CHARS:
        raise AnnotationSyntaxError(
            f"the annotation is longer than {MAX_CHARS:,} characters", 0
        )
    parser = _parser()
    from lark.exceptions import UnexpectedInput

    try:
        expr = _value(parser.parse(text))
    except UnexpectedInput as err:
        raise AnnotationSyntaxError(_describe(err, text), _offset(err, text)) from None
    except (RecursionError, MemoryError):
        raise AnnotationSyntaxError(_TOO_DEEP, 0) from None
    if A.deeper_than(expr, MAX_DEPTH):
        raise AnnotationSyntaxError(_TOO_DEEP, 0)
    _constant_bits(expr)
    return expr


def _constant_bits(expr: A.Expr) -> tuple[int, int] | None:
    """Bounds on the bits of numerator and denominator of a closed arithmetic term
    (None when it names something); AnnotationSyntaxError when a constant grows past
    MAX_CONSTANT_DIGITS, as `1e200 * 1e200 * ...` would. Recursive: depth is bounded."""
    kids = [_constant_bits(child) for child in A.children(expr)]
    size: tuple[int, int] | None = None
    if isinstance(expr, A.Num):
        size = expr.value.numerator.bit_length(), expr.value.denominator.bit_length()
    elif isinstance(expr, A.Unary) and expr.op == "-":
        size = kids[0]
    elif isinstance(expr, A.Binary) and expr.op in A.ARITH_OPS:
        left, right = kids
        if left is not None and right is not None:
            (na, da), (nb, db) = left, right
            size = {
                "*": (na + nb, da + db),
                "/": (na + db, da + nb),
            }.get(expr.op, (max(na + db, nb + da) + 1, da + db))
    if size is not None and max(size) > _MAX_CONSTANT_BITS:
        raise AnnotationSyntaxError(
            "a constant in the annotation has more than "
            f"{MAX_CONSTANT_DIGITS:,} digits",
            0,
        )
    return size


def _offset(err: UnexpectedInput, text: str) -> int:
    from lark.exceptions import UnexpectedEOF

    pos = getattr(err, "pos_in_stream", None)
    if isinstance(pos, int) and pos >= 0:
        return min(pos, len(text))
    if isinstance(err, UnexpectedEOF):
        return len(text.rstrip())
    return max(0, (err.column or 1) - 1)


def _describe(err: UnexpectedInput, text: str) -> str:
    from lark.exceptions import UnexpectedCharacters, UnexpectedEOF

    if isinstance(err, UnexpectedCharacters):
        at = err.pos_in_stream or 0
        return f"unexpected character {text[at : at + 1]!r}"
    if isinstance(err, UnexpectedEOF):
        return "the annotation ends too early"
    token = getattr(err, "token", None)
    if token is not None and token.type == "$END":
        return "the annotation ends too early"
    if token is None:
        return "syntax error"
    return f"unexpected {A.excerpt(str(token), 20)!r}"
