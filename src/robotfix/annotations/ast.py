"""Frozen dataclasses for refinement predicates and the terms the analysis builds.

The same nodes serve two purposes: they are what an annotation string parses to, and,
with `Sym` standing for a solver symbol, the language of verification conditions.
No lark types, no z3 types live here.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from fractions import Fraction

from robotfix.annotations.numbers import shown_as_infinity

# The nodes the analysis makes by the thousand (a symbol per unknown value, a sum
# or a test per operation, a literal) are slotted, and their `__init__` sets each
# slot through the slot's own setter: a frozen dataclass's generated one calls
# object.__setattr__ per field (a Sym 0.45 us, 0.27 us so). Frozen, compared and
# hashed as the others.


@dataclass(frozen=True, slots=True)
class Num:
    value: Fraction
    is_int: bool
    # the constant's name when a refinement travelled from another module with its
    # constants put in (`MAX_SPEED`, `math.pi`): shown in messages in place of the
    # number, as in the declaring module; not part of equality (a display only)
    label: str | None = field(default=None, compare=False, repr=False)

    def __init__(self, value: Fraction, is_int: bool, label: str | None = None) -> None:
        _NUM_VALUE(self, value)
        _NUM_IS_INT(self, is_int)
        _NUM_LABEL(self, label)


@dataclass(frozen=True)
class Bool:
    value: bool


@dataclass(frozen=True, slots=True)
class Str:
    value: str
    label: str | None = field(default=None, compare=False, repr=False)  # as Num's

    def __init__(self, value: str, label: str | None = None) -> None:
        _STR_VALUE(self, value)
        _STR_LABEL(self, label)


@dataclass(frozen=True)
class Name:
    """A variable, `_`, or a dotted message field path such as `linear.x`."""

    name: str
    pos: int = field(default=0, compare=False)


@dataclass(frozen=True, slots=True)
class Sym:
    """A solver symbol introduced by the analysis; `sort` is int, real, bool or str."""

    ident: int
    sort: str

    def __init__(self, ident: int, sort: str) -> None:
        SET_SYM_IDENT(self, ident)
        SET_SYM_SORT(self, sort)


@dataclass(frozen=True, slots=True)
class Unary:
    op: str  # "-" or "not"
    operand: Expr

    def __init__(self, op: str, operand: Expr) -> None:
        _UNARY_OP(self, op)
        _UNARY_OPERAND(self, operand)


@dataclass(frozen=True, slots=True)
class Binary:
    op: str  # + - * / // % and or == != < <= > >=  (`//`, `%`: Python's, floored)
    left: Expr
    right: Expr

    def __init__(self, op: str, left: Expr, right: Expr) -> None:
        _BINARY_OP(self, op)
        _BINARY_LEFT(self, left)
        _BINARY_RIGHT(self, right)


def slot_setter(cls: type, name: str) -> Callable[[object, object], None]:
    """The setter of `cls`'s slot `name`, which a frozen instance's setattr refuses:
    what the `__init__` of a frozen slotted dataclass made by the thousand calls."""
    return getattr(cls, name).__set__  # type: ignore[no-any-return]


_NUM_VALUE, _NUM_IS_INT = slot_setter(Num, "value"), slot_setter(Num, "is_int")
_NUM_LABEL = slot_setter(Num, "label")
_STR_VALUE, _STR_LABEL = slot_setter(Str, "value"), slot_setter(Str, "label")
# public: `analysis.values.unknown` makes symbols by the thousand without `__init__`
SET_SYM_IDENT, SET_SYM_SORT = slot_setter(Sym, "ident"), slot_setter(Sym, "sort")
_UNARY_OP, _UNARY_OPERAND = slot_setter(Unary, "op"), slot_setter(Unary, "operand")
_BINARY_OP, _BINARY_LEFT = slot_setter(Binary, "op"), slot_setter(Binary, "left")
_BINARY_RIGHT = slot_setter(Binary, "right")


@dataclass(frozen=True)
class Ite:
    cond: Expr
    then: Expr
    orelse: Expr


@dataclass(frozen=True)
class Func:
    name: str  # abs, min, max
    args: tuple[Expr, ...]


@dataclass(frozen=True)
class UnitIs:
    """`Unit('m/s')`, `Frame('map')`, `Tag('x')`, or `Unit(path) == "m/s"`.

    `kind` is unit, frame or tag; `target` is the field path, or None for the
    annotated value itself.
    """

    kind: str
    text: str
    target: str | None = None
    pos: int = field(default=0, compare=False)


Expr = Num | Bool | Str | Name | Sym | Unary | Binary | Ite | Func | UnitIs

ARITH_OPS = frozenset({"+", "-", "*", "/", "//", "%"})
COMPARE_OPS = frozenset({"==", "!=", "<", "<=", ">", ">="})
BOOL_OPS = frozenset({"and", "or"})
TRUE = Bool(True)


def conjuncts(expr: Expr) -> list[Expr]:
    """The top-level `and` operands of a predicate, left to right."""
    out: list[Expr] = []
    todo = [expr]
    while todo:
        node = todo.pop()
        if isinstance(node, Binary) and node.op == "and":
            todo += (node.right, node.left)
        else:
            out.append(node)
    return out


def conjoin(parts: list[Expr]) -> Expr:
    """`a and b and ...`, balanced: 500 conjuncts nest 9 levels deep, not 500."""
    return join("and", parts) if parts else TRUE


def join(op: str, parts: Sequence[Expr]) -> Expr:
    """`parts` joined by an associative `op` (and, or) as a balanced tree, in order.

    Up to three parts this is the left-leaning chain a parser builds."""
    if len(parts) == 1:
        return parts[0]
    middle = (len(parts) + 1) // 2
    return Binary(op, join(op, parts[:middle]), join(op, parts[middle:]))


def disjoin(parts: list[Expr]) -> Expr:
    result: Expr | None = None
    for part in parts:
        result = part if result is None else Binary("or", result, part)
    return Bool(False) if result is None else result


def children(expr: Expr) -> tuple[Expr, ...]:
    if isinstance(expr, Unary):
        return (expr.operand,)
    if isinstance(expr, Binary):
        return (expr.left, expr.right)
    if isinstance(expr, Ite):
        return (expr.cond, expr.then, expr.orelse)
    if isinstance(expr, Func):
        return expr.args
    return ()


def walk(expr: Expr) -> list[Expr]:
    """Every node of `expr`, parents before children, left to right."""
    out: list[Expr] = []
    todo = [expr]
    while todo:
        node = todo.pop()
        out.append(node)
        todo.extend(reversed(children(node)))
    return out


def deeper_than(expr: Expr, limit: int) -> bool:
    """Whether some path from the root has more than `limit` nodes."""
    todo = [(expr, 1)]
    while todo:
        node, depth = todo.pop()
        if depth > limit:
            return True
        todo.extend((child, depth + 1) for child in children(node))
    return False


def larger_than(expr: Expr, limit: int) -> bool:
    """Whether the term has more than `limit` nodes, counting shared ones each time,
    in at most `limit` steps (terms share subterms, so their trees can be huge)."""
    todo = [expr]
    count = 0
    while todo:
        count += 1
        if count > limit:
            return True
        todo.extend(children(todo.pop()))
    return False


def names(expr: Expr) -> list[Name]:
    return [n for n in walk(expr) if isinstance(n, Name)]


def syms(*exprs: Expr) -> set[Sym]:
    """The solver symbols in `exprs`, each sub-term they share read once (a VC's
    facts share the terms of a path: `x2 = x1 + 1` holds x1's whole term)."""
    found: set[Sym] = set()
    seen: set[int] = set()  # ids of nodes read; all held by `exprs` meanwhile
    todo = list(exprs)
    while todo:
        node = todo.pop()
        if id(node) in seen:
            continue
        seen.add(id(node))
        if type(node) is Sym:
            found.add(node)
        else:
            todo.extend(children(node))
    return found


def rebuild(expr: Expr, new_children: tuple[Expr, ...]) -> Expr:
    if isinstance(expr, Unary):
        return Unary(expr.op, new_children[0])
    if isinstance(expr, Binary):
        return Binary(expr.op, new_children[0], new_children[1])
    if isinstance(expr, Ite):
        return Ite(*new_children)
    if isinstance(expr, Func):
        return Func(expr.name, new_children)
    return expr


def labelled(term: Expr | None, name: str) -> Num | Str | None:
    """A constant's number or string put into a refinement, shown by `name` in
    messages (`Num.label`); None for any other term."""
    if isinstance(term, (Num, Str)):
        return replace(term, label=name)
    return None


def substitute(expr: Expr, mapping: dict[str, Expr]) -> Expr:
    """Replace names found in `mapping`; other nodes are rebuilt unchanged."""
    if isinstance(expr, Name):
        return mapping.get(expr.name, expr)
    kids = children(expr)
    if not kids:
        return expr
    return rebuild(expr, tuple(substitute(k, mapping) for k in kids))


_PRECEDENCE = {
    "or": 1,
    "and": 2,
    "not": 3,
    "==": 4,
    "!=": 4,
    "<": 4,
    "<=": 4,
    ">": 4,
    ">=": 4,
    "+": 5,
    "-": 5,
    "*": 6,
    "/": 6,
    "//": 6,
    "%": 6,
}


_LEFT_ONLY = frozenset({"-", "/", "//", "%"})  # not associative on the right


def arith(op: str, left: Fraction, right: Fraction) -> Fraction | None:
    """`left op right` exactly, as Python computes it on numbers (`//` floors and
    `%` takes the divisor's sign, for ints and floats alike); None for a division
    by zero or an operator that is not arithmetic."""
    if op in ("/", "//", "%") and right == 0:
        return None
    if op == "//":
        return Fraction(left // right)
    found = {
        "+": lambda: left + right,
        "-": lambda: left - right,
        "*": lambda: left * right,
        "/": lambda: left / right,
        "%": lambda: left % right,
    }.get(op)
    return None if found is None else found()


def show(expr: Expr) -> str:
    """Source-like text of an expression for messages, parenthesised only as needed."""
    if isinstance(expr, Num):
        return expr.label or _show_number(expr)
    if isinstance(expr, Bool):
        return "True" if expr.value else "False"
    if isinstance(expr, Str):
        return expr.label or repr(expr.value)
    if isinstance(expr, Name):
        return expr.name
    if isinstance(expr, Sym):
        return f"${expr.ident}"
    if isinstance(expr, Unary):
        if expr.op == "not":
            return f"not {_operand(expr.operand, 3)}"
        return f"-{_operand(expr.operand, 7)}"
    if isinstance(expr, Binary):
        level = _PRECEDENCE[expr.op]
        # comparisons do not chain here, and - and / are not associative on the right
        right_level = level + 1 if expr.op in _LEFT_ONLY or level == 4 else level
        left_level = level + 1 if level == 4 else level
        left = _operand(expr.left, left_level)
        return f"{left} {expr.op} {_operand(expr.right, right_level)}"
    if isinstance(expr, Ite):
        then, cond = _operand(expr.then, 1), _operand(expr.cond, 1)
        return f"{then} if {cond} else {show(expr.orelse)}"
    if isinstance(expr, Func):
        return f"{expr.name}({', '.join(show(a) for a in expr.args)})"
    if expr.target is None:
        return f"{expr.kind.capitalize()}({expr.text!r})"
    return f"{expr.kind.capitalize()}({expr.target}) == {expr.text!r}"


def _level(expr: Expr) -> int:
    if isinstance(expr, Binary):
        return _PRECEDENCE[expr.op]
    if isinstance(expr, Unary):
        return 3 if expr.op == "not" else 7
    if isinstance(expr, Ite):
        return 0
    if isinstance(expr, Num) and expr.value < 0 and expr.label is None:
        return 7
    return 9


def _operand(expr: Expr, minimum: int) -> str:
    text = show(expr)
    return f"({text})" if _level(expr) < minimum else text


def _show_number(num: Num) -> str:
    value = num.value
    infinite = None if num.is_int else shown_as_infinity(value)  # ints never overflow
    if infinite is not None:
        return infinite
    if max(value.numerator.bit_length(), value.denominator.bit_length()) > _EXACT_BITS:
        return _scientific(value)
    if value.denominator == 1:
        if num.is_int:
            return str(value.numerator)
        if value.numerator.bit_length() > _SHOWN_FLOAT_BITS:  # `1e308`, not 309 digits
            return _scientific(value)
        return f"{value.numerator}.0"
    if value.denominator > _FLOAT_DENOMINATOR and Fraction(float(value)) == value:
        # a float's binary value (math.pi): as Python shows it
        return repr(float(value))
    decimal = _exact_decimal(value)
    return decimal if decimal is not None else f"{float(value):g}"


def _exact_decimal(value: Fraction) -> str | None:
    """The finite decimal expansion of `value`, if it has one."""
    den = value.denominator
    twos = fives = 0
    while den % 2 == 0:
        den //= 2
        twos += 1
    while den % 5 == 0:
        den //= 5
        fives += 1
    if den != 1:
        return None
    digits = max(twos, fives)
    scaled = abs(value.numerator) * (10**digits // value.denominator)
    text = str(scaled).rjust(digits + 1, "0")
    sign = "-" if value < 0 else ""
    return f"{sign}{text[:-digits]}.{text[-digits:]}"


_EXACT_BITS = 3000  # about 900 digits: shown exactly below, approximately above
_SHOWN_FLOAT_BITS = 70  # a whole float beyond about 1e21 is shown as 1e+22, as Python
_FLOAT_DENOMINATOR = 1 << 20  # below it (0.5, 0.125...) the exact decimal is short


def _scientific(value: Fraction) -> str:
    """`1.5e5000`: a number too long to show (or to convert with `str`) exactly."""
    if value == 0:
        return "0"
    size = abs(value)
    exponent = math.floor(math.log10(size.numerator) - math.log10(size.denominator))
    scaled = size / Fraction(10) ** exponent  # within [0.1, 100) whatever the rounding
    mantissa = float(scaled)
    while mantissa >= 10:
        mantissa, exponent = mantissa / 10, exponent + 1
    while mantissa < 1:
        mantissa, exponent = mantissa * 10, exponent - 1
    sign = "-" if value < 0 else ""
    return f"{sign}{mantissa:.6g}e{exponent}"


def excerpt(text: str, limit: int = 40) -> str:
    """The start of `text` for a message: at most `limit` characters, then `…`.

    Diagnostics quote what they could not read by a short prefix, never whole: the
    line may be long, or not meant to be shown at all."""
    return text if len(text) <= limit else text[:limit].rstrip() + "…"
