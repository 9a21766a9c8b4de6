"""Parameter files and what ROS makes of them: pure data and ROS's own rules.

- ROS 2 parameter files (`node: ros__parameters: {...}`, also under namespaces and
  `/**`): scalars are typed as rcl_yaml_param_parser types them (quoted: string;
  `true`/`yes`/`on`...: bool; what `strtoll(.., 0)` reads whole without ERANGE:
  integer; what `strtod` reads whole without ERANGE: double; else string), nested
  maps give dotted names. A number is never converted whole when it is long: its
  digits are counted (Python refuses `int()` of over 4,300 digits, and rcl only
  needs to know it is beyond int64), and its exact value is taken only within the
  annotation grammar's bounds (`annotations/parser.py`), else the double ROS reads.
- ROS 1 parameter files (the flat layout `rosparam load` reads): YAML 1.1 types
  (PyYAML), nested maps give `/`-joined names.
- generate_parameter_library definitions (`ns: {param: {type: double,
  default_value: 0.5, validation: {bounds<>: [0, 1]}}}`).
- rclpy's acceptance of a value for a declared range (`Node._apply_integer_range`,
  `_apply_floating_point_range`: bounds in either order, a relative tolerance of
  1e-6 at the bounds, `step`) and generate_parameter_library's validators.

Mappings are read as PyYAML reads them (`yamlfile.pairs`: merge keys applied, alias
keys resolved): rosparam and generate_parameter_library load files so, and rcl,
which refuses aliases and knows no merge key, reads a ROS 2 file that has neither
exactly so too; a ROS 2 file with either keeps the first in `ParamFile.reference`.
"""

from __future__ import annotations

import math
import re
import sys
from dataclasses import dataclass, field
from fractions import Fraction

from robotfix.annotations.ast import excerpt
from robotfix.annotations.parser import MAX_DIGITS, MAX_EXPONENT
from robotfix.ros import yamlfile as Y
from robotfix.ros.rclpy_params import Range, python_type  # noqa: F401 (re-exported)

PARAMS_KEY = "ros__parameters"
_TRUE = {"Y", "y", "yes", "Yes", "YES", "true", "True", "TRUE", "on", "On", "ON"}
_FALSE = {"N", "n", "no", "No", "NO", "false", "False", "FALSE", "off", "Off", "OFF"}
_SPECIAL_FLOATS = {
    f"{sign}.{word}": float(f"{sign or '+'}{word}")
    for sign in ("", "+", "-")
    for word in ("inf", "Inf", "INF")
} | {".nan": math.nan, ".NaN": math.nan, ".NAN": math.nan}
_STRTOLL = re.compile(r"[+-]?(?:0[xX][0-9a-fA-F]+|0[0-7]*|[1-9][0-9]*)")
# Each alternative reads a run of digits one way only, so a long text that does
# not match fails in one pass (`[0-9]+\.?[0-9]*` backtracked: 50 s on 40,000 digits).
_DECIMAL = r"(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?"
_HEX = r"0[xX](?:[0-9a-fA-F]+(?:\.[0-9a-fA-F]*)?|\.[0-9a-fA-F]+)(?:[pP][+-]?[0-9]+)?"
_NUMBER = re.compile(rf"[+-]?(?:{_DECIMAL}|{_HEX})")
_STRTOD = re.compile(
    rf"[+-]?(?:{_DECIMAL}|{_HEX}|[iI][nN][fF](?:[iI][nN][iI][tT][yY])?|[nN][aA][nN])"
)
# significant digits beyond which strtoll's number is out of int64, by base
_INT64_DIGITS = {10: 19, 16: 16, 8: 22}
INT64 = (-(2**63), 2**63 - 1)
GPL_TYPE = re.compile(r"(?:string|double|int|bool)(?:_array)?(?:_fixed_[0-9]+)?|none")
# ROS 2 parameter types, by rclpy's Parameter.Type name
SCALAR_TYPES = ("bool", "integer", "double", "string")
GPL_TO_ROS = {"int": "integer", "double": "double", "bool": "bool", "string": "string"}
NESTED = "nested list"  # what no ROS 2 parameter type is: a list of lists or maps

Value = bool | int | float | str | list[object]


@dataclass(frozen=True)
class Typed:
    """A YAML value as ROS reads it: its ROS 2 type name and its Python value."""

    type: str  # bool integer double string *_array, or NESTED
    value: Value
    text: str  # as written (for messages)
    how: str = ""  # how ROS came to read it so, when the text does not say


@dataclass(frozen=True)
class Unread:
    """A value the loader cannot read (rosparam: PyYAML refuses it)."""

    why: str


def ros2_scalar(node: Y.Scalar) -> Typed | None:
    """rcl_yaml_param_parser's `get_value`; None for an empty or null scalar."""
    text = node.text
    if node.tag == Y.STR_TAG or not node.plain:
        return Typed("string", text, text)
    if node.tag is not None:
        return None  # another explicit tag: rcl's reading of it is not modelled
    if text in ("", "~", "null", "Null", "NULL"):
        return None
    if text in _TRUE or text in _FALSE:
        return Typed("bool", text in _TRUE, text)
    beyond = False  # an integer beyond int64: strtod reads it
    if _STRTOLL.fullmatch(text):
        number = _strtoll(text)
        if number is not None:
            return Typed("integer", number, text)
        beyond = True
    if text in _SPECIAL_FLOATS:
        return Typed("double", _SPECIAL_FLOATS[text], text)
    if _STRTOD.fullmatch(text):
        return _double(text, beyond)
    return Typed("string", text, text)


def _double(text: str, beyond: bool) -> Typed:
    """What rcl makes of a text strtod reads whole: a double, or a string when
    strtod sets ERANGE; `how` says why when the text does not show it."""
    shown = f"`{excerpt(text, 20)}`"
    number = _strtod(text)
    if number is None:
        why = "overflows" if _overflows(text) else "underflows"
        how = f"rcl reads {shown} as a string: it {why} a double (strtod: ERANGE)"
        return Typed("string", text, text, how)
    if beyond:
        how = (
            f"rcl reads {shown} as the double {number!r}: it is beyond a 64-bit "
            "integer (strtoll: ERANGE)"
        )
        return Typed("double", number, text, how)
    return Typed("double", number, text, _far(text, number))


def _far(text: str, number: float) -> str:
    """A note for a number past the bounds `exact` reads, else ""."""
    if not _NUMBER.fullmatch(text) or exact(text) is not None:
        return ""
    return (
        f"`{excerpt(text, 20)}` is compared as the double ROS reads, {number!r}: it "
        f"has more than {MAX_DIGITS} significant digits or is beyond 1e±{MAX_EXPONENT}"
    )


def _strtoll(text: str) -> int | None:
    """strtoll(text, 0) of a text _STRTOLL matches whole; None when it is out of
    int64 (ERANGE), known by the digits' count before any conversion."""
    sign = -1 if text.startswith("-") else 1
    body = text.lstrip("+-")
    if body[:2] in ("0x", "0X"):
        digits, base = body[2:], 16
    elif body.startswith("0") and len(body) > 1:
        digits, base = body[1:], 8
    else:
        digits, base = body, 10
    digits = digits.lstrip("0") or "0"
    if len(digits) > _INT64_DIGITS[base]:
        return None
    number = sign * int(digits, base)
    return number if INT64[0] <= number <= INT64[1] else None


def _strtod(text: str) -> float | None:
    """strtod of a text _STRTOD matches whole; None when it sets ERANGE (rcl then
    reads a string): the double overflows, or a nonzero number comes out zero or
    subnormal and inexact (glibc)."""
    body = text.lstrip("+-")
    try:
        number = float.fromhex(body) if body[:2] in ("0x", "0X") else float(body)
    except (ValueError, OverflowError):
        return None
    if not body[:1].isalpha():
        if math.isinf(number):
            return None
        tiny = abs(number) < sys.float_info.min and _mantissa(body).strip("0.") != ""
        # (an exact subnormal has at most 751 significant decimal digits)
        if tiny and exact(body, 800, 1200) != Fraction(number):
            return None
    return -number if text.startswith("-") else number


def _mantissa(body: str) -> str:
    if body[:2] in ("0x", "0X"):
        return body[2:].lower().partition("p")[0]
    return body.lower().partition("e")[0]


def _overflows(text: str) -> bool:
    """Of a number strtod refuses: is it too large (not too small)?"""
    body = text.lstrip("+-")
    try:
        number = float.fromhex(body) if body[:2] in ("0x", "0X") else float(body)
    except OverflowError:
        return True
    return math.isinf(number)


def exact(
    text: str, digits: int = MAX_DIGITS, exponent: int = MAX_EXPONENT
) -> Fraction | None:
    """The exact value of a number as written (decimal, or hexadecimal as strtod
    reads it) when it has at most `digits` significant digits and is a power of
    ten within +-`exponent` of them (a hexadecimal one: of two, within
    +-4*`exponent`); the defaults are the annotation grammar's bounds. None beyond,
    or for another text (the double ROS reads is what can be compared then)."""
    if not _NUMBER.fullmatch(text):
        return None
    sign = -1 if text.startswith("-") else 1
    body = text.lstrip("+-")
    hexadecimal = body[:2] in ("0x", "0X")
    whole, _, fraction = _mantissa(body).partition(".")
    power = body.lower().partition("p" if hexadecimal else "e")[2]
    significant = (whole + fraction).lstrip("0")
    kept = significant.rstrip("0")
    if not kept:
        return Fraction(0)
    scale = len(fraction) - (len(significant) - len(kept))  # digits after the point
    written = power.lstrip("+-").lstrip("0")  # `1e0…05`: no int() of the zeros
    if len(kept) > digits or len(written) > 6:
        return None
    base, radix, limit = (2, 16, 4 * exponent) if hexadecimal else (10, 10, exponent)
    signed = -int(written or 0) if power.startswith("-") else int(written or 0)
    shift = signed - scale * (4 if hexadecimal else 1)
    if abs(shift) > limit:
        return None
    return sign * int(kept, radix) * Fraction(base) ** shift


def ros2_value(node: Y.Node | None, budget: list[int]) -> Typed | None:
    """A parameter's value as rcl reads it: a scalar, or a sequence of scalars of
    one type (rcl refuses mixed sequences: those and empty ones are None here).
    No ROS 2 parameter holds a list of lists or of maps: rcl reads `[[1.0, 2.0]]`
    as its one inner list, and refuses any other such list ("Sequences cannot be
    key") or reads another value from it: NESTED."""
    node = Y.resolve(node, budget)
    if isinstance(node, Y.Scalar):
        return ros2_scalar(node)
    if not isinstance(node, Y.Sequence) or not node.items:
        return None
    items = [Y.resolve(item, budget) for item in node.items]
    flat = _array(items)
    if flat is not None:
        return flat
    inner = Y.resolve(items[0], budget) if len(items) == 1 else None
    if isinstance(inner, Y.Sequence) and inner.items:
        flat = _array([Y.resolve(item, budget) for item in inner.items])
        if flat is not None:
            text = f"[{flat.text}]"
            how = f"rcl reads the list of lists `{excerpt(text, 20)}` as its one list"
            return Typed(flat.type, flat.value, text, how)
    nested = [i for i in items if isinstance(i, (Y.Sequence, Y.Mapping))]
    if not nested:
        return None
    how = (
        "a ROS 2 parameter holds no list of lists or of maps: rcl refuses the file "
        '("Sequences cannot be key") or reads another value'
    )
    text = "[{...}, ...]" if isinstance(nested[0], Y.Mapping) else "[[...], ...]"
    return Typed(NESTED, [], text, how)


def _array(items: list[Y.Node | None]) -> Typed | None:
    """A sequence of scalars of one type as rcl reads it; None for another."""
    typed = [ros2_scalar(i) if isinstance(i, Y.Scalar) else None for i in items]
    kinds = {t.type for t in typed if t is not None}
    if None in typed or len(kinds) != 1:
        return None
    values: list[object] = [t.value for t in typed if t is not None]
    text = "[" + ", ".join(t.text for t in typed if t is not None) + "]"
    how = next((t.how for t in typed if t is not None and t.how), "")
    return Typed(f"{kinds.pop()}_array", values, text, how)


def ros1_value(
    node: Y.Node | None, budget: list[int], loader: str = "rosparam"
) -> Typed | Unread | None:
    """A value as rosparam reads it (YAML 1.1); None where rosparam's own
    conversions (`rad(...)`, `deg(...)`, `!degrees`) or other types apply;
    Unread for an integer PyYAML cannot make (`loader`: who then fails)."""
    node = Y.resolve(node, budget)
    if not isinstance(node, Y.Scalar):
        return None
    tag = node.yaml11_tag()
    if tag == Y.STR_TAG:
        if node.plain and re.match(r"\s*(rad|deg)\s*\(", node.text):
            return None
        return Typed("string", node.text, node.text)
    value = Y.yaml11_value(node, tag)
    if isinstance(value, bool):
        return Typed("bool", value, node.text)
    if isinstance(value, int):
        return Typed("integer", value, node.text)
    if isinstance(value, float):
        return Typed("double", value, node.text, _far(node.text, value))
    if value is None and tag == Y.INT_TAG:
        return Unread(
            f"PyYAML cannot read the integer `{excerpt(node.text, 20)}`: Python's "
            "int() refuses more than 4,300 digits (3.11, and security releases "
            f"since 3.7), so {loader} cannot load this file"
        )
    return None


# -- layouts -------------------------------------------------------------------


@dataclass(frozen=True)
class Entry:
    """One parameter value in a parameter file."""

    node: str  # ROS 2: the key path above ros__parameters (`/ns/node`, `/**`);
    # ROS 1: "" (the flat layout names no node)
    name: str  # ROS 2: `group.param`; ROS 1: `group/param`
    value: Y.Node
    line: int
    col: int

    @property
    def node_name(self) -> str:
        """The last token of a ROS 2 node key: `/ns/node` -> `node`."""
        return self.node.rstrip("/").rsplit("/", 1)[-1]


@dataclass(frozen=True)
class Definition:
    """One parameter of a generate_parameter_library definitions file."""

    namespace: str  # the root key
    name: str  # dotted; `__map_<key>` segments stand for any name
    type: str  # as written: double, int_array, string_fixed_10, ...
    default: Y.Node | None
    validations: tuple[tuple[str, Y.Node | None, int, int], ...]  # (name, args, l, c)
    line: int
    col: int

    @property
    def ros_type(self) -> str | None:
        base = re.sub(r"_fixed_[0-9]+$", "", self.type)
        array = base.endswith("_array")
        scalar = GPL_TO_ROS.get(base.removesuffix("_array"))
        if scalar is None:
            return None
        return f"{scalar}_array" if array else scalar

    def matches(self, name: str) -> bool:
        mine, theirs = self.name.split("."), name.split(".")
        return len(mine) == len(theirs) and all(
            a == b or a.startswith("__map_") for a, b in zip(mine, theirs, strict=True)
        )


@dataclass
class ParamFile:
    """A parameter file's entries, node sections and definitions."""

    layout: str  # ros2, ros1, definitions
    entries: list[Entry] = field(default_factory=list)
    # ROS 2: each node key path above a `ros__parameters` (`/ns/node`), and where
    # its last key is (line, col)
    sections: dict[str, tuple[int, int]] = field(default_factory=dict)
    definitions: list[Definition] = field(default_factory=list)
    # what PyYAML refuses, left out (a merge of a scalar, ...)
    problems: list[Y.YamlProblem] = field(default_factory=list)
    # ROS 2: the first alias or merge key, which rcl does not read
    reference: Y.Node | None = None


def classify(root: Y.Node | None, references: bool = True) -> ParamFile | None:
    """What a YAML file is to ROS: None when it is none of the three layouts.
    `references` False: the text has no `*` and no `<<`, so no alias and no merge
    key (not looked for)."""
    budget = [Y.WALK_BUDGET]
    root = Y.resolve(root, budget)
    if not isinstance(root, Y.Mapping) or not root.items:
        return None
    ros2 = _Reader(budget)
    if ros2.sections(root, [], 0):
        found = ParamFile(
            "ros2", ros2.entries, sections=ros2.places, problems=ros2.problems
        )
        found.reference = Y.first_reference(root) if references else None
        return found
    definitions = _Reader(budget)
    if definitions.definitions(root):
        return ParamFile(
            "definitions",
            definitions=definitions.found,
            problems=definitions.problems,
        )
    ros1 = _Reader(budget)
    ros1.flat(root, [], 0)
    return ParamFile("ros1", ros1.entries, problems=ros1.problems)


class _Reader:
    """One layout's reading of a file: mappings as PyYAML reads them."""

    def __init__(self, budget: list[int]) -> None:
        self.budget = budget
        self.problems: list[Y.YamlProblem] = []
        self.entries: list[Entry] = []
        self.found: list[Definition] = []
        # ROS 2: where each node section's last key is (`ParamFile.sections`)
        self.places: dict[str, tuple[int, int]] = {}

    def pairs(self, node: Y.Mapping) -> list[Y.Pair]:
        return Y.pairs(node, self.budget, self.problems)

    def sections(
        self,
        node: Y.Mapping,
        path: list[str],
        depth: int,
        where: tuple[int, int] = (1, 0),
    ) -> bool:
        """Collect every `ros__parameters` section (and in `places`, where its
        node key is); True if there was one."""
        seen = False
        for pair in self.pairs(node):
            value = pair.value
            if pair.key is None or not isinstance(value, Y.Mapping) or depth > 50:
                continue
            if pair.key == PARAMS_KEY:
                seen = True
                self.places.setdefault("/".join(path), where)
                self.params(value, "/".join(path), [], depth)
            else:
                at = (pair.where.line, pair.where.col)
                seen = self.sections(value, [*path, pair.key], depth + 1, at) or seen
        return seen

    def params(
        self, node: Y.Mapping, owner: str, prefix: list[str], depth: int
    ) -> None:
        for pair in self.pairs(node):
            if pair.key is None or pair.value is None or depth > 50:
                continue
            if isinstance(pair.value, Y.Mapping):
                self.params(pair.value, owner, [*prefix, pair.key], depth + 1)
            else:
                name = ".".join([*prefix, pair.key])
                self.entries.append(_entry(owner, name, pair))

    def flat(self, node: Y.Mapping, prefix: list[str], depth: int) -> None:
        for pair in self.pairs(node):
            if pair.key is None or pair.value is None or depth > 50:
                continue
            if isinstance(pair.value, Y.Mapping):
                self.flat(pair.value, [*prefix, pair.key], depth + 1)
            else:
                self.entries.append(_entry("", "/".join([*prefix, pair.key]), pair))

    def definitions(self, root: Y.Mapping) -> bool:
        top = self.pairs(root)
        if len(top) != 1:
            return False
        namespace, body = top[0].key, top[0].value
        if namespace is None or not isinstance(body, Y.Mapping):
            return False
        return self.leaves(body, namespace, [], 0) and bool(self.found)

    def leaves(
        self, node: Y.Mapping, namespace: str, prefix: list[str], depth: int
    ) -> bool:
        """Collect the parameters; False if the tree is not a definitions file."""
        pairs = self.pairs(node)
        fields = {p.key: p for p in pairs if p.key is not None}
        type_node = fields["type"].value if "type" in fields else None
        if prefix and isinstance(type_node, Y.Scalar):
            if not GPL_TYPE.fullmatch(type_node.text):
                return False
            self.found.append(
                self.definition(node, fields, namespace, prefix, type_node.text)
            )
            return True
        for pair in pairs:
            if pair.key is None or not isinstance(pair.value, Y.Mapping) or depth > 50:
                return False
            if not self.leaves(pair.value, namespace, [*prefix, pair.key], depth + 1):
                return False
        return True

    def definition(
        self,
        node: Y.Mapping,
        fields: dict[str, Y.Pair],
        namespace: str,
        prefix: list[str],
        type_: str,
    ) -> Definition:
        validations: list[tuple[str, Y.Node | None, int, int]] = []
        checks = fields["validation"].value if "validation" in fields else None
        if isinstance(checks, Y.Mapping):
            for pair in self.pairs(checks):
                if pair.key is not None:
                    where = pair.where
                    validations.append(
                        (pair.key.removesuffix("<>"), pair.value, where.line, where.col)
                    )
        default = fields["default_value"].value if "default_value" in fields else None
        return Definition(
            namespace,
            ".".join(prefix),
            type_,
            default,
            tuple(validations),
            node.line,
            node.col,
        )


def _entry(owner: str, name: str, pair: Y.Pair) -> Entry:
    assert pair.value is not None
    return Entry(owner, name, pair.value, pair.where.line, pair.where.col)


# -- what ROS accepts ----------------------------------------------------------


def type_words(type_: str) -> str:
    """`double` -> `a double`, `integer_array` -> `an integer array`."""
    words = type_.replace("_", " ")
    return ("an " if words[:1] in "aeiou" else "a ") + words


def gpl_violation(
    name: str, args: Y.Node | None, value: Typed, budget: list[int]
) -> str | None:
    """What a generate_parameter_library validator says of `value`: None when it
    holds or is not one this checker models; else the rule, in words."""
    values = _arguments(args, budget)
    if values is None:
        return None
    number = value.value if isinstance(value.value, (int, float)) else None
    if isinstance(value.value, bool):
        number = None
    items = value.value if isinstance(value.value, list) else None
    if name == "bounds" and number is not None and len(values) == 2:
        low, high = values
        if _num(low) and _num(high) and not low <= number <= high:  # type: ignore[operator]
            return f"bounds<> [{_show(low)}, {_show(high)}]"
    elif name in ("lt", "gt", "lt_eq", "gt_eq") and number is not None and values:
        limit = values[0]
        ops = {"lt": "<", "gt": ">", "lt_eq": "<=", "gt_eq": ">="}
        if _num(limit) and not _compare(number, ops[name], limit):  # type: ignore[arg-type]
            return f"{name}<> [{_show(limit)}]"
    elif name == "one_of" and values and isinstance(values[0], list):
        options = values[0]
        if items is None and not _member(value.value, options):
            return f"one_of<> {_show(options)}"
    elif items is not None:
        return _array_violation(name, values, items)
    return None


def _array_violation(
    name: str, values: list[object], items: list[object]
) -> str | None:
    numbers = [v for v in items if _num(v)]
    if name == "element_bounds" and len(values) == 2 and all(map(_num, values)):
        low, high = values
        if any(not low <= v <= high for v in numbers):  # type: ignore[operator]
            return f"element_bounds<> [{_show(low)}, {_show(high)}]"
    elif name in ("lower_element_bounds", "upper_element_bounds") and values:
        limit = values[0]
        op = ">=" if name.startswith("lower") else "<="
        if _num(limit) and any(not _compare(v, op, limit) for v in numbers):  # type: ignore[arg-type]
            return f"{name}<> [{_show(limit)}]"
    elif name in ("fixed_size", "size_gt", "size_lt") and values and _num(values[0]):
        op = {"fixed_size": "==", "size_gt": ">", "size_lt": "<"}[name]
        if not _compare(len(items), op, values[0]):  # type: ignore[arg-type]
            return f"{name}<> [{_show(values[0])}]"
    elif name == "not_empty" and not items:
        return "not_empty<>"
    elif name == "subset_of" and values and isinstance(values[0], list):
        if any(not _member(v, values[0]) for v in items):
            return f"subset_of<> {_show(values[0])}"
    elif name == "unique" and len({repr(v) for v in items}) != len(items):
        return "unique<>"
    return None


def _arguments(args: Y.Node | None, budget: list[int]) -> list[object] | None:
    """A validator's arguments: a list, or one scalar written without brackets."""
    node = Y.resolve(args, budget)
    if node is None or (isinstance(node, Y.Scalar) and node.text in ("", "null")):
        return []
    if isinstance(node, Y.Scalar):
        single = _plain_value(node, budget)
        return None if single is None else [single]
    if not isinstance(node, Y.Sequence):
        return None
    out: list[object] = []
    for item in node.items:
        found = _plain_value(item, budget)
        if found is None:
            return None
        out.append(found)
    return out


def _plain_value(node: Y.Node | None, budget: list[int]) -> object | None:
    node = Y.resolve(node, budget)
    if isinstance(node, Y.Scalar):
        typed = ros2_scalar(node)
        return None if typed is None else typed.value
    if isinstance(node, Y.Sequence):
        inner = [_plain_value(i, budget) for i in node.items]
        return None if any(v is None for v in inner) else inner
    return None


def _num(value: object) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _compare(left: float, op: str, right: float) -> bool:
    return {
        "<": left < right,
        ">": left > right,
        "<=": left <= right,
        ">=": left >= right,
        "==": left == right,
    }[op]


def _member(value: object, options: list[object]) -> bool:
    return any(
        value == option and type(value) is type(option) for option in options
    ) or (_num(value) and any(_num(o) and o == value for o in options))


def _show(value: object) -> str:
    if isinstance(value, list):
        return "[" + ", ".join(_show(v) for v in value) + "]"
    if isinstance(value, str):
        return f'"{value}"'
    return str(value)
