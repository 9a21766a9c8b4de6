"""Abstract values: numbers and booleans as solver terms with a unit, and messages.

Values are immutable. A message is a reference into the state's heap, so that
aliases (`m = move`) see the same fields, as in Python. A tuple, list or dict display
keeps its elements (and keys), so a constant table can be looked up.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

from robotfix.annotations import ast as A
from robotfix.annotations.units import Unit
from robotfix.messages import Declared

NUMERIC = frozenset({"int", "float", "bool"})
CONTAINERS = frozenset({"tuple", "list", "dict"})
# Values whose elements a refinement speaks of: lists (also message array fields),
# tuples, and generators (`min(r for r in ranges)`).
SEQUENCES = frozenset({"list", "tuple", "generator"})


@dataclass(frozen=True)
class Items:
    """What holds of every element of a sequence, beyond the `elements` a display
    names: their kind, a predicate `each` over `_`, and a predicate `size` over `_`
    that the sequence's length satisfies."""

    kind: str = "unknown"
    each: A.Expr = A.TRUE
    size: A.Expr = A.TRUE
    kept: Kept | None = None  # the declaration every change must keep
    # a display's element nodes, where an element's diagnostic points
    sites: tuple[object, ...] | None = field(default=None, compare=False)


@dataclass(frozen=True)
class Kept:
    """A sequence's declaration (a refined variable or attribute, a message array
    field), which every change must keep, also one made through another name: its
    elements' base type, unit and predicate (over `_`), its length's predicate, how
    diagnostics name the sequence, and where it was declared."""

    item: str
    unit: Unit | None
    each: A.Expr
    size: A.Expr
    label: str
    declared: Declared
    unit_declared: Declared | None = None  # where the unit was, if elsewhere
    # a message array's fixed size or bound: its type's, not a refinement, so only
    # a length known to break it is reported
    shape: A.Expr = A.TRUE


@dataclass(frozen=True)
class Uninit:
    """A read of a name that holds nothing on this path."""

    name: str
    declared: bool  # declared with an annotation but never assigned, vs never bound


@dataclass(frozen=True)
class Value:
    kind: str  # int float bool str msg msgclass module none unknown tuple list dict
    term: A.Expr | None = None  # the solver term, for int/float/bool/str
    unit: Unit | None = None  # None: no unit known
    literal: bool = False  # a number literal: takes the unit of its context
    ref: int | None = None  # heap id, for messages
    name: str = ""  # msgclass: pkg/Name; module: dotted name
    elements: tuple[Value, ...] | None = None  # tuple, list, dict (its values)
    keys: tuple[Value, ...] | None = None  # dict
    uninit: Uninit | None = None
    # The product of the number literals this value was multiplied by since it got its
    # unit: `speed / 3.6` is km/h scaled by 1/3.6, which is a conversion to m/s.
    scale: float = 1.0
    default_of: tuple[int, str] | None = field(default=None, compare=False)
    items: Items | None = None  # a sequence: what holds of its elements

    @property
    def known_term(self) -> A.Expr:
        """The term of a value the caller knows has one (fresh unknowns always do)."""
        assert self.term is not None, self
        return self.term

    @property
    def is_number(self) -> bool:
        return self.kind in NUMERIC

    def with_unit(self, unit: Unit | None) -> Value:
        if self.unit == unit and not self.literal and self.scale == 1.0:
            return self
        return replace(self, unit=unit, literal=False, scale=1.0)

    def settled(self) -> Value:
        """The value as a name or field holds it: set, and not a default."""
        if self.uninit is None and self.default_of is None:
            return self  # (the common case: no copy)
        return replace(self, uninit=None, default_of=None)

    def fits_unit(self, expected: Unit) -> bool:
        """Same unit; or the same dimension after the literal factors it was scaled by
        (`speed / 3.6` fits m/s when speed is in km/h); or, once scaled by a literal,
        any other dimension (the literal may carry a unit)."""
        got = self.unit
        if got is None or got.same_as(expected):
            return True
        if not got.same_dimension(expected):
            # `v * 0.1` may be a speed times a literal time step: the literal can carry
            # the missing unit, so only an unscaled value is surely a mismatch.
            return self.scale != 1.0
        if got.offset or expected.offset:
            return False
        return math.isclose(got.factor / self.scale, expected.factor, rel_tol=1e-3)


NONE = Value("none")


def sort_of(kind: str) -> str:
    return {"int": "int", "bool": "bool", "str": "str"}.get(kind, "real")


@dataclass
class MsgObj:
    """A message instance. `fields` holds what was set (or, if received, read)."""

    type: str  # pkg/Name
    origin: str  # constructed | received | unknown
    fields: dict[str, Value] = field(default_factory=dict)
    owner: tuple[int, str] | None = None  # (parent ref, field name)
    reported: set[str] = field(default_factory=set)  # unset fields already reported

    def copy(self) -> MsgObj:
        return MsgObj(
            self.type, self.origin, dict(self.fields), self.owner, set(self.reported)
        )
