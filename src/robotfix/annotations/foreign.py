"""Metadata other libraries put in `Annotated`, read as RobotFix would write it.

- annotated-types constraints (`Gt(0)`, `Le(1.5)`, `Interval(ge=0, lt=MAX)`,
  `MinLen(1)`, `MaxLen(10)`, `Len(0, 10)`, `MultipleOf(5)`, `Unit('m')`), as pydantic
  users write them: each becomes the refinement text it means (`_ > 0`, `len(_) <=
  10`, `Unit('m')`), read from the AST only (annotated_types is never imported), and
  only when the call's name is annotated_types' own (`from annotated_types import Gt`,
  `at.Gt`). An argument is a number or a name (a constant, `math.pi`), as a string
  refinement would write it; anything else, and the constraints with no meaning for
  RobotFix (`Predicate`, `Timezone`), is `Unusable`: the caller notes it (RF511).
- a unit written as a bare string (`Annotated[float, "m"]`, `"unit:m/s"`), as other
  unit checkers write it: `unit_string` says how RobotFix spells it.
"""

from __future__ import annotations

import ast
from collections.abc import Callable
from dataclasses import dataclass

from robotfix.annotations.units import UnitError, resolve

MODULE = "annotated_types"
# constraint -> the comparison each keyword (in positional order) stands for
_BOUNDS = {
    "Gt": (("gt", "_ > {}"),),
    "Ge": (("ge", "_ >= {}"),),
    "Lt": (("lt", "_ < {}"),),
    "Le": (("le", "_ <= {}"),),
    "MinLen": (("min_length", "len(_) >= {}"),),
    "MaxLen": (("max_length", "len(_) <= {}"),),
    "Len": (("min_length", "len(_) >= {}"), ("max_length", "len(_) <= {}")),
    # annotated-types documents Python's meaning, `value % multiple_of == 0`
    "MultipleOf": (("multiple_of", "_ % {} == 0"),),
}
_KEYWORD_ONLY = {  # `Interval` takes keywords only
    "Interval": tuple(p for bound in ("Gt", "Ge", "Lt", "Le") for p in _BOUNDS[bound])
}
_WHY_NOT: dict[str, str] = {}
# dimensions a bare word may have by accident (`"count"`, `"byte"`, `"unit"` is a
# candela per square metre)
_NOT_PHYSICAL = frozenset({"count", "bit", "candela"})
MAX_UNIT_STRING = 40  # characters of a bare string worth asking the unit registry


@dataclass(frozen=True)
class Unusable:
    """An annotated-types constraint RobotFix cannot read: why, for the note."""

    why: str


def constraint(
    node: ast.expr, qualname: Callable[[ast.expr], str | None]
) -> str | Unusable | None:
    """The refinement text an annotated-types constraint means, `Unusable`, or None
    when `node` is no call of annotated_types."""
    if not isinstance(node, ast.Call):
        return None
    module, _, name = (qualname(node.func) or "").rpartition(".")
    if module != MODULE:
        return None
    if name == "Unit":
        return _unit(node)
    slots = _BOUNDS.get(name)
    positional = slots is not None
    slots = slots or _KEYWORD_ONLY.get(name)
    if slots is None:
        return Unusable(_WHY_NOT.get(name, f"`{name}` says nothing RobotFix checks"))
    if (node.args and not positional) or len(node.args) > len(slots):
        return Unusable(f"`{name}` takes {'fewer' if positional else 'keywords'}")
    keys = [key for key, _ in slots]
    given: dict[str, ast.expr] = dict(zip(keys, node.args, strict=False))
    forms = dict(slots)
    for keyword in node.keywords:
        if keyword.arg is None or keyword.arg not in forms or keyword.arg in given:
            return Unusable(f"`{name}` has no argument `{keyword.arg}` to read")
        given[keyword.arg] = keyword.value
    parts = []
    for key, form in slots:
        bound = given.get(key)
        if bound is None or (isinstance(bound, ast.Constant) and bound.value is None):
            continue
        if not _plain(bound):
            return Unusable(
                "its bound is not a number or a constant's name: "
                "write it as a string refinement"
            )
        parts.append(form.format(ast.unparse(bound)))
    return " and ".join(parts) if parts else Unusable(f"`{name}` gives no bound")


def _unit(node: ast.Call) -> str | Unusable:
    arg: ast.expr | None = None
    if len(node.args) == 1 and not node.keywords:
        arg = node.args[0]
    elif not node.args and len(node.keywords) == 1 and node.keywords[0].arg == "unit":
        arg = node.keywords[0].value
    if not (
        isinstance(arg, ast.Constant)
        and isinstance(arg.value, str)
        and '"' not in arg.value
        and not arg.value.startswith("[")
    ):
        return Unusable("its unit is not a unit string RobotFix reads (`'m/s'`)")
    return f'Unit("{arg.value}")'


def _plain(node: ast.expr) -> bool:
    """A number (signed), or a name or dotted name (`MAX_SPEED`, `math.pi`)."""
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        node = node.operand
    if isinstance(node, ast.Constant):
        value = node.value
        return isinstance(value, (int, float)) and not isinstance(value, bool)
    while isinstance(node, ast.Attribute):
        node = node.value
    return isinstance(node, ast.Name)


def unit_string(text: str) -> str | None:
    """`Unit('m')` for a string other unit checkers read as a unit (`"m"`,
    `"unit:m"`); None for any other string. A bare string counts only when it is a
    unit with a dimension (so `"count"` or `"percent"` stay silent); with `unit:`,
    any unit. Words that are no unit (`"const"`) are never a unit here."""
    spelled = text.strip()
    prefixed = spelled.startswith("unit:")
    if prefixed:
        spelled = spelled[len("unit:") :].strip()
    if not spelled or len(spelled) > MAX_UNIT_STRING or "'" in spelled:
        return None
    try:
        unit = resolve(spelled)
    except UnitError:
        return None
    dims = {d for d, _ in unit.dims}
    if any(d.startswith(("tag:", "frame:")) for d in dims):
        return None  # a word, no unit (`"const"`)
    if not prefixed and (not dims or dims & _NOT_PHYSICAL):
        return None  # `"percent"`, `"count"`, `"byte"`, `"unit"`: likely words
    return f"Unit('{spelled}')"
