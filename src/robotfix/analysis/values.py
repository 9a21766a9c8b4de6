"""Abstract values: numbers and booleans as solver terms with a unit, and messages.

Values are immutable. A message is a reference into the state's heap, so that
aliases (`m = move`) see the same fields, as in Python.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

from robotfix.annotations import ast as A
from robotfix.annotations.units import Unit

NUMERIC = frozenset({"int", "float", "bool"})


@dataclass(frozen=True)
class Uninit:
    """A read of a name that holds nothing on this path."""

    name: str
    declared: bool  # declared with an annotation but never assigned, vs never bound


Defs = tuple[tuple[int, A.Expr], ...]


@dataclass(frozen=True)
class MaybeDefault:
    """A message field set on some paths only: on the paths where `when` holds (a
    condition over join selectors) it still has its ROS default."""

    when: A.Expr
    default: A.Expr
    owner: tuple[int, str]  # (message ref, field name)


@dataclass(frozen=True)
class Value:
    kind: str  # int float bool str msg msgclass module none unknown
    term: A.Expr | None = None  # the solver term, for int/float/bool/str
    unit: Unit | None = None  # None: no unit known
    literal: bool = False  # a number literal: takes the unit of its context
    ref: int | None = None  # heap id, for messages
    name: str = ""  # msgclass: pkg/Name; module: dotted name
    uninit: Uninit | None = None
    # The product of the number literals this value was multiplied by since it got its
    # unit: `speed / 3.6` is km/h scaled by 1/3.6, which is a conversion to m/s.
    scale: float = 1.0
    default_of: tuple[int, str] | None = field(default=None, compare=False)

    @property
    def known_term(self) -> A.Expr:
        """The term of a value the caller knows has one (fresh unknowns always do)."""
        assert self.term is not None, self
        return self.term

    @property
    def is_number(self) -> bool:
        return self.kind in NUMERIC

    def with_unit(self, unit: Unit | None) -> Value:
        return replace(self, unit=unit, literal=False, scale=1.0)

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


@dataclass(frozen=True)
class ObjInvariant:
    """A refinement on one message value, from an annotation such as
    `Annotated[Twist, "abs(linear.x) <= 0.22"]`: paths are relative to the value."""

    predicate: A.Expr
    paths: frozenset[str]
    text: str
    what: str  # "annotation of `cmd`"
    path: str
    line: int


@dataclass
class MsgObj:
    """A message instance. `fields` holds what was set (or, if received, read)."""

    type: str  # pkg/Name
    origin: str  # constructed | received | unknown
    fields: dict[str, Value] = field(default_factory=dict)
    owner: tuple[int, str] | None = None  # (parent ref, field name)
    reported: set[str] = field(default_factory=set)  # unset fields already reported
    extra: tuple[ObjInvariant, ...] = ()  # refinements of the variables it reached
    # Fields set on some paths only, with when they still hold their default.
    unset: dict[str, MaybeDefault] | None = None

    def copy(self) -> MsgObj:
        return MsgObj(
            self.type,
            self.origin,
            dict(self.fields),
            self.owner,
            set(self.reported),
            self.extra,
            dict(self.unset) if self.unset else None,
        )

    def set_on_all_paths(self, name: str) -> None:
        if self.unset:
            self.unset.pop(name, None)
