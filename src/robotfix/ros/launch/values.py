"""A ROS 2 launch file's parameter value as the node gets it.

launch_ros reads a value written as text (an XML or YAML attribute, a Python
string) as YAML (`yaml.safe_load`, YAML 1.1), keeps a Python number or bool, and
hands the node every value in a parameter file it writes with `yaml.dump`, which
rcl reads. So a value is typed as rcl types what PyYAML writes of it
(`paramfile.ros2_value`), the same typing a parameter file gets: `1e999` is a
string to PyYAML, written plain, and a string to rcl too (strtod: ERANGE);
`100000000000000000000` is an integer to PyYAML, written as its digits, and a
double to rcl (beyond int64); `2.0` stays a double. A list of lists or of maps
never reaches rcl: launch refuses it (its values are bools, numbers, strings and
lists of them), so it is `paramfile.NESTED`, even `[[1.0]]`, which rcl would read
from a file as `[1.0]`.
"""

from __future__ import annotations

import dataclasses

from robotfix.ros import paramfile as P
from robotfix.ros import yamlfile as Y

LOADER = "launch"  # who cannot load a value PyYAML refuses (`paramfile.Unread`)
_KNOWN = (Y.Scalar, Y.Sequence, Y.Mapping)  # a written value (aliases resolved)
Written = Y.Scalar | Y.Sequence | Y.Mapping | P.Unread | None
REFUSED = (
    "launch refuses a list of lists or of maps as a parameter's value (a list "
    "holds bools, integers, doubles or strings)"
)


def from_yaml(node: Y.Node | None) -> P.Typed | P.Unread | None:
    """A value written as YAML (a YAML launch file's node, an XML attribute or a
    Python string read as YAML); a scalar keeps its text as written."""
    budget = [Y.WALK_BUDGET]
    written = _written_yaml(node, budget, 0)
    if not isinstance(written, _KNOWN):
        return written
    typed = _nested(written) or P.ros2_value(written, budget)
    shown = Y.resolve(node, budget)
    if typed is not None and isinstance(shown, Y.Scalar):
        return dataclasses.replace(typed, text=shown.text)
    return typed


def from_python(value: object) -> P.Typed | P.Unread | None:
    """A Python bool, number, string (as it is: a list's items) or list of them."""
    written = _written_python(value, 0)
    if not isinstance(written, _KNOWN):
        return written
    return _nested(written) or P.ros2_value(written, [Y.WALK_BUDGET])


def _nested(written: Y.Node) -> P.Typed | None:
    """A list holding a list or a map: what launch refuses."""
    if not isinstance(written, Y.Sequence):
        return None
    inner = [i for i in written.items if isinstance(i, (Y.Sequence, Y.Mapping))]
    if not inner:
        return None
    text = "[{...}, ...]" if isinstance(inner[0], Y.Mapping) else "[[...], ...]"
    return P.Typed(P.NESTED, [], text, REFUSED)


def _written_yaml(node: Y.Node | None, budget: list[int], depth: int) -> Written:
    """What `yaml.dump` writes of what PyYAML reads of `node` (None: a value of
    no type this checker follows, or one launch computes)."""
    node = Y.resolve(node, budget)
    if isinstance(node, Y.Scalar):
        loaded = P.ros1_value(node, budget, LOADER)
        return loaded if not isinstance(loaded, P.Typed) else _scalar(loaded.value)
    if isinstance(node, Y.Sequence) and depth < 50:
        return _sequence([_written_yaml(i, budget, depth + 1) for i in node.items])
    return node if isinstance(node, Y.Mapping) else None  # in a list: NESTED


def _written_python(value: object, depth: int) -> Written:
    if isinstance(value, list) and depth < 50:
        return _sequence([_written_python(v, depth + 1) for v in value])
    return _scalar(value)


def _sequence(items: list[Written]) -> Written:
    """A list whose items are all known, else its first unknown or unread one."""
    known: list[Y.Node] = []
    for item in items:
        if not isinstance(item, _KNOWN):
            return item
        known.append(item)
    return Y.Sequence(known)


def _scalar(value: object) -> Y.Scalar | P.Unread | None:
    """`yaml.dump`'s scalar for a bool, int, float or string."""
    if isinstance(value, bool):
        return _plain("true" if value else "false")
    if isinstance(value, int):
        try:
            return _plain(str(value))
        except ValueError:  # over Python's 4,300 digits: yaml.dump fails as well
            return P.Unread(
                "launch cannot write this integer: Python's str() refuses more "
                "than 4,300 digits"
            )
    if isinstance(value, float):
        if value != value:
            return _plain(".nan")
        if value in (float("inf"), float("-inf")):
            return _plain(".inf" if value > 0 else "-.inf")
        return _plain(repr(value))
    if isinstance(value, str):
        # written plain when PyYAML reads the plain text back as this string
        # (`1e999`, `y`), quoted when it would read another type (`'10'`)
        plain = Y.Scalar(value, True, None, 1, 0)
        return plain if value and plain.yaml11_tag() == Y.STR_TAG else _quoted(value)
    return None


def _plain(text: str) -> Y.Scalar:
    return Y.Scalar(text, True, None, 1, 0)


def _quoted(text: str) -> Y.Scalar:
    return Y.Scalar(text, False, None, 1, 0)
