"""Parameter files and what ROS makes of them: pure data and ROS's own rules.

- ROS 2 parameter files (`node: ros__parameters: {...}`, also under namespaces and
  `/**`): scalars are typed as rcl_yaml_param_parser types them (quoted: string;
  `true`/`yes`/`on`...: bool; what `strtoll(.., 0)` reads whole: integer; what
  `strtod` reads whole: double; else string), nested maps give dotted names.
- ROS 1 parameter files (the flat layout `rosparam load` reads): YAML 1.1 types
  (PyYAML), nested maps give `/`-joined names.
- generate_parameter_library definitions (`ns: {param: {type: double,
  default_value: 0.5, validation: {bounds<>: [0, 1]}}}`).
- rclpy's acceptance of a value for a declared range (`Node._apply_integer_range`,
  `_apply_floating_point_range`: bounds in either order, a relative tolerance of
  1e-6 at the bounds, `step`) and generate_parameter_library's validators.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

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
_STRTOD = re.compile(
    r"[+-]?(?:(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?"
    r"|0[xX](?:[0-9a-fA-F]+\.?[0-9a-fA-F]*|\.[0-9a-fA-F]+)(?:[pP][+-]?[0-9]+)?"
    r"|[iI][nN][fF](?:[iI][nN][iI][tT][yY])?|[nN][aA][nN])"
)
INT64 = (-(2**63), 2**63 - 1)
GPL_TYPE = re.compile(r"(?:string|double|int|bool)(?:_array)?(?:_fixed_[0-9]+)?|none")
# ROS 2 parameter types, by rclpy's Parameter.Type name
SCALAR_TYPES = ("bool", "integer", "double", "string")
GPL_TO_ROS = {"int": "integer", "double": "double", "bool": "bool", "string": "string"}

Value = bool | int | float | str | list[object]


@dataclass(frozen=True)
class Typed:
    """A YAML value as ROS reads it: its ROS 2 type name and its Python value."""

    type: str  # bool integer double string *_array
    value: Value
    text: str  # as written (for messages)


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
    if _STRTOLL.fullmatch(text):
        number = _strtoll(text)
        if INT64[0] <= number <= INT64[1]:
            return Typed("integer", number, text)
    if text in _SPECIAL_FLOATS:
        return Typed("double", _SPECIAL_FLOATS[text], text)
    if _STRTOD.fullmatch(text):
        number_f = _strtod(text)
        if number_f is not None:
            return Typed("double", number_f, text)
    return Typed("string", text, text)


def _strtoll(text: str) -> int:
    sign = -1 if text.startswith("-") else 1
    body = text.lstrip("+-")
    if body[:2] in ("0x", "0X"):
        return sign * int(body[2:], 16)
    if body.startswith("0") and len(body) > 1:
        return sign * int(body[1:], 8)
    return sign * int(body)


def _strtod(text: str) -> float | None:
    body = text.lstrip("+-")
    try:
        number = float.fromhex(body) if body[:2] in ("0x", "0X") else float(body)
    except (ValueError, OverflowError):
        return None
    if math.isinf(number) and not body[:1].isalpha():
        return None  # strtod sets ERANGE: rcl reads a string
    return -number if text.startswith("-") else number


def ros2_value(node: Y.Node | None, budget: list[int]) -> Typed | None:
    """A parameter's value: a scalar, or a sequence of scalars of one type (rcl
    refuses mixed sequences: those, empty and nested ones are None here)."""
    node = Y.resolve(node, budget)
    if isinstance(node, Y.Scalar):
        return ros2_scalar(node)
    if not isinstance(node, Y.Sequence) or not node.items:
        return None
    items = [Y.resolve(item, budget) for item in node.items]
    return array([ros2_scalar(i) if isinstance(i, Y.Scalar) else None for i in items])


def array(typed: list[Typed | None]) -> Typed | None:
    """A list of values of one type as an array parameter; None when empty,
    mixed, or holding a value of no type."""
    kinds = {t.type for t in typed if t is not None}
    if None in typed or len(kinds) != 1:
        return None
    values: list[object] = [t.value for t in typed if t is not None]
    text = "[" + ", ".join(t.text for t in typed if t is not None) + "]"
    return Typed(f"{kinds.pop()}_array", values, text)


def ros1_value(node: Y.Node | None, budget: list[int]) -> Typed | None:
    """A value as rosparam reads it (YAML 1.1); None where rosparam's own
    conversions (`rad(...)`, `deg(...)`, `!degrees`) or other types apply."""
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
        return Typed("double", value, node.text)
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
    layout: str  # ros2, ros1, definitions
    entries: list[Entry] = field(default_factory=list)
    # ROS 2: each node key path above a `ros__parameters` (`/ns/node`), and where
    # its last key is (line, col)
    sections: dict[str, tuple[int, int]] = field(default_factory=dict)
    definitions: list[Definition] = field(default_factory=list)


def classify(root: Y.Node | None) -> ParamFile | None:
    """What a YAML file is to ROS: None when it is none of the three layouts."""
    budget = [Y.WALK_BUDGET]
    root = Y.resolve(root, budget)
    if not isinstance(root, Y.Mapping) or not root.items:
        return None
    found: list[Entry] = []
    sections: dict[str, tuple[int, int]] = {}
    if _ros2_sections(root, [], found, budget, 0, sections):
        return ParamFile("ros2", found, sections=sections)
    definitions = _definitions(root, budget)
    if definitions:
        return ParamFile("definitions", definitions=definitions)
    flat: list[Entry] = []
    _flat(root, [], flat, budget, 0)
    return ParamFile("ros1", flat)


def _key(node: Y.Node) -> str | None:
    return node.text if isinstance(node, Y.Scalar) else None


def _ros2_sections(
    node: Y.Mapping,
    path: list[str],
    out: list[Entry],
    budget: list[int],
    depth: int,
    places: dict[str, tuple[int, int]],
    where: tuple[int, int] = (1, 0),
) -> bool:
    """Collect every `ros__parameters` section (and in `places`, where its node
    key is); True if there was one."""
    seen = False
    for key_node, raw in node.items:
        key = _key(key_node)
        value = Y.resolve(raw, budget)
        if key is None or not isinstance(value, Y.Mapping) or depth > 50:
            continue
        if key == PARAMS_KEY:
            seen = True
            places.setdefault("/".join(path), where)
            _params(value, "/".join(path), [], out, budget, depth)
        else:
            at = (
                (key_node.line, key_node.col)
                if isinstance(key_node, Y.Scalar)
                else where
            )
            seen = (
                _ros2_sections(value, [*path, key], out, budget, depth + 1, places, at)
                or seen
            )
    return seen


def _params(
    node: Y.Mapping,
    owner: str,
    prefix: list[str],
    out: list[Entry],
    budget: list[int],
    depth: int,
) -> None:
    for key_node, raw in node.items:
        key = _key(key_node)
        value = Y.resolve(raw, budget)
        if key is None or value is None or depth > 50:
            continue
        if isinstance(value, Y.Mapping):
            _params(value, owner, [*prefix, key], out, budget, depth + 1)
        else:
            name = ".".join([*prefix, key])
            assert isinstance(key_node, Y.Scalar)
            out.append(Entry(owner, name, value, key_node.line, key_node.col))


def _flat(
    node: Y.Mapping, prefix: list[str], out: list[Entry], budget: list[int], depth: int
) -> None:
    for key_node, raw in node.items:
        key = _key(key_node)
        value = Y.resolve(raw, budget)
        if key is None or value is None or key == "<<" or depth > 50:
            continue
        if isinstance(value, Y.Mapping):
            _flat(value, [*prefix, key], out, budget, depth + 1)
        else:
            name = "/".join([*prefix, key])
            assert isinstance(key_node, Y.Scalar)
            out.append(Entry("", name, value, key_node.line, key_node.col))


def _definitions(root: Y.Mapping, budget: list[int]) -> list[Definition]:
    if len(root.items) != 1:
        return []
    namespace = _key(root.items[0][0])
    body = Y.resolve(root.items[0][1], budget)
    if namespace is None or not isinstance(body, Y.Mapping):
        return []
    found: list[Definition] = []
    if not _leaves(body, namespace, [], found, budget, 0):
        return []
    return found


def _leaves(
    node: Y.Mapping,
    namespace: str,
    prefix: list[str],
    out: list[Definition],
    budget: list[int],
    depth: int,
) -> bool:
    """Collect the parameters; False if the tree is not a definitions file."""
    type_node = Y.resolve(node.get("type"), budget)
    if prefix and isinstance(type_node, Y.Scalar):
        if not GPL_TYPE.fullmatch(type_node.text):
            return False
        out.append(_definition(node, namespace, prefix, type_node.text, budget))
        return True
    for key_node, raw in node.items:
        key = _key(key_node)
        value = Y.resolve(raw, budget)
        if key is None or not isinstance(value, Y.Mapping) or depth > 50:
            return False
        if not _leaves(value, namespace, [*prefix, key], out, budget, depth + 1):
            return False
    return True


def _definition(
    node: Y.Mapping, namespace: str, prefix: list[str], type_: str, budget: list[int]
) -> Definition:
    validations: list[tuple[str, Y.Node | None, int, int]] = []
    checks = Y.resolve(node.get("validation"), budget)
    if isinstance(checks, Y.Mapping):
        for key_node, args in checks.items:
            key = _key(key_node)
            if key is not None and isinstance(key_node, Y.Scalar):
                validations.append(
                    (key.removesuffix("<>"), args, key_node.line, key_node.col)
                )
    default = node.get("default_value")
    return Definition(
        namespace,
        ".".join(prefix),
        type_,
        default,
        tuple(validations),
        node.line,
        node.col,
    )


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
