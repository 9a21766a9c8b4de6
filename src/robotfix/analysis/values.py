"""Abstract values: numbers and booleans as solver terms with a unit, and messages.

Values are immutable. A message is a reference into the state's heap, so that
aliases (`m = move`) see the same fields, as in Python. A tuple, list or dict display
keeps its elements (and keys), so a constant table can be looked up.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from dataclasses import replace as _replace
from typing import TYPE_CHECKING, Any, TypeVar

from robotfix.annotations import ast as A
from robotfix.annotations.units import Factors, Fit, Unit, fit, product
from robotfix.messages import Declared

if TYPE_CHECKING:
    from robotfix.analysis.typeterms import Type

NUMERIC = frozenset({"int", "float", "bool"})
CONTAINERS = frozenset({"tuple", "list", "dict"})
# Kinds of objects code may change in place (`xs.append(v)`, `d[k] = v`).
MUTABLE = frozenset({"unknown", "list", "dict"})
# Values whose elements a refinement speaks of: lists (also message array fields),
# tuples, and generators (`min(r for r in ranges)`).
SEQUENCES = frozenset({"list", "tuple", "generator"})
# Kinds of value a message may be: one on the heap, or (without a ref) one the
# analysis does not follow (two messages joined at an `if`, a library's object)
MESSAGE_LIKE = frozenset({"msg", "unknown", "object"})
_T = TypeVar("_T", bound=Any)


@dataclass(frozen=True, slots=True)  # made by the thousand: see A.slot_setter
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
    # a message array field's (element type, origin of the message that holds it)
    message: tuple[str, str] | None = None
    # the elements' type, when the type model gives one (`list[Driver]`,
    # `dict[str, Driver]`: `analysis/types.py`) and they are not messages
    of: Type | None = None

    def __init__(
        self,
        kind: str = "unknown",
        each: A.Expr = A.TRUE,
        size: A.Expr = A.TRUE,
        kept: Kept | None = None,
        sites: tuple[object, ...] | None = None,
        message: tuple[str, str] | None = None,
        of: Type | None = None,
    ) -> None:
        _SET_KIND(self, kind)
        _SET_EACH(self, each)
        _SET_SIZE(self, size)
        _SET_KEPT(self, kept)
        _SET_SITES(self, sites)
        _SET_MESSAGE(self, message)
        _SET_OF(self, of)


_SET_KIND, _SET_EACH, _SET_SIZE, _SET_KEPT, _SET_SITES, _SET_MESSAGE, _SET_OF = (
    A.slot_setter(Items, name) for name in Items.__slots__
)


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
class Conversion:
    """The last change of a value's unit, when a conversion call made it: `call`
    (the callee as written, `math.degrees`) of an argument in `argument`. `twice`:
    the argument was in the result's unit already, and the report of that waits
    under this key (`FileContext.defer`) for a better one at the same statement."""

    call: str
    argument: Unit
    twice: tuple[object, ...] | None = None


@dataclass(frozen=True)
class Uninit:
    """A read of a name that holds nothing on this path."""

    name: str
    declared: bool  # declared with an annotation but never assigned, vs never bound


Defs = tuple[tuple[int, A.Expr], ...]


@dataclass(frozen=True)
class Choice:
    """What a number merged at a join (`if flag: v = KMH else: v = MS`) is on the
    paths where `when` (over join selectors, defined by `defs`) holds: `value`,
    with the unit the merged number no longer has."""

    value: Value
    when: A.Expr
    defs: Defs


@dataclass(frozen=True)
class Choices:
    """The units a merged number had on the paths it was merged from, while it is
    that number (its solver symbol `ident`): arithmetic on it makes another."""

    ident: int
    options: tuple[Choice, ...]


@dataclass(frozen=True)
class MaybeDefault:
    """A message field set on some paths only: on the paths where `when` holds (a
    condition over join selectors) it still has its ROS default."""

    when: A.Expr
    default: A.Expr
    owner: tuple[int, str]  # (message ref, field name)


# Slotted, not frozen: a frozen dataclass's __init__ sets each of these 15 fields
# through object.__setattr__ (about 10x slower), and unknown values are made by the
# hundred thousand (issue 13). Still treated as immutable: change one with `replace`.
@dataclass(slots=True, unsafe_hash=True)
class Value:
    """An abstract value: kind, solver term, unit, and what else is known of it."""

    kind: str  # int float bool str msg msgclass module none unknown tuple list dict
    term: A.Expr | None = None  # the solver term, for int/float/bool/str
    unit: Unit | None = None  # None: no unit known
    literal: bool = False  # a number literal: takes the unit of its context
    ref: int | None = None  # heap id, for messages
    name: str = ""  # msgclass: pkg/Name; module: dotted name
    elements: tuple[Value, ...] | None = None  # tuple, list, dict (its values)
    keys: tuple[Value, ...] | None = None  # dict
    uninit: Uninit | None = None
    # The number literals this value was multiplied by since it got its unit, each
    # literal of a chain a factor of its own: `speed / 3.6` is km/h scaled by 1/3.6,
    # a conversion to m/s; `avg * 2 * math.pi / 60` with `avg = (l + r) / 2` holds
    # 1/2, 2, pi and 1/60 (`units.fit` tells conversions and gains apart).
    factors: Factors = ()
    default_of: tuple[int, str] | None = field(default=None, compare=False)
    # Computed by a product or quotient with a length: one power of radian may cancel
    # or appear, as the radian is a ratio of lengths (`omega * r` is m/s).
    rad_free: bool = False
    items: Items | None = None  # a sequence: what holds of its elements
    # A string the analysis does not know exactly but knows the frame name of (a
    # parameter's default, `analysis/frames.py`); None: no frame known.
    frame: str | None = None
    # a conversion call that gave the unit, kept through literal factors
    # (`-math.degrees(x) / 2.`): a unit message's advice comes from it
    conversion: Conversion | None = field(default=None, compare=False)
    # a number merged at a join from ones in different units: what it is per path
    choices: Choices | None = field(default=None, compare=False)

    def options(self) -> tuple[Choice, ...]:
        """The units this number has on the paths it was merged from (none, unless
        it is a merged number as it was merged: no unit, factor or radian since)."""
        chosen, term = self.choices, self.term
        if chosen is None or self.unit is not None or self.factors or self.rad_free:
            return ()
        return (
            chosen.options if type(term) is A.Sym and term.ident == chosen.ident else ()
        )

    @property
    def known_term(self) -> A.Expr:
        """The term of a value the caller knows has one (fresh unknowns always do)."""
        assert self.term is not None, self
        return self.term

    @property
    def is_number(self) -> bool:
        return self.kind in NUMERIC

    def with_unit(self, unit: Unit | None) -> Value:
        if (
            self.unit == unit
            and not self.literal
            and not self.factors
            and not self.rad_free
        ):
            return self
        return replace(
            self, unit=unit, literal=False, factors=(), rad_free=False, conversion=None
        )

    @property
    def scale(self) -> float:
        """The product of the literal factors."""
        return product(self.factors)

    def settled(self) -> Value:
        """The value as a name or field holds it: set, and not a default."""
        if self.uninit is None and self.default_of is None:
            return self  # (the common case: no copy)
        return replace(self, uninit=None, default_of=None)

    def fits_unit(self, expected: Unit) -> bool:
        """Same unit, after the literal factors it was scaled by (`speed / 3.6` fits
        m/s when speed is in km/h) and the radian cancelling (see `units.fit`)."""
        found = self.fit(expected)
        return found is None or found.kind == "ok"

    def fit(self, expected: Unit) -> Fit | None:
        """How this value's unit meets `expected`; None when there is nothing to
        compare (no unit known, or a literal, which takes the unit of its context)."""
        if self.unit is None:
            return None
        if self.literal:
            return self._converted_literal(expected)
        return fit(self.unit, expected, self.factors, self.rad_free)

    def _converted_literal(self, expected: Unit) -> Fit | None:
        """`math.radians(90.0)`: the literal took the unit of the call's parameter
        (degree) and was converted, so the result is in rad, times whatever else
        the literal stands for (deg/s gives rad/s). Into a unit that differs from
        that only by the scale (degree, degree/s) the conversion was one too many:
        a mismatch. Any other literal takes the unit of its context."""
        unit = self.unit
        if self.conversion is None or unit is None:
            return None
        ours, theirs = dict(unit.dims), dict(expected.dims)
        every = ours.keys() | theirs.keys()
        rest = {d for d in every if ours.get(d, 0) != theirs.get(d, 0)}
        if rest & ours.keys() or math.isclose(expected.factor, unit.factor):
            return None
        return Fit("mismatch", unit)


NONE = Value("none")
_new = object.__new__
_SYM = A.Sym
_SYM_IDENT, _SYM_SORT = A.SET_SYM_IDENT, A.SET_SYM_SORT


def unknown(kind: str, ident: int, unit: Unit | None) -> Value:
    """`Value(kind, A.Sym(ident, sort_of(kind)), unit)`, the symbol and the value
    made without the calls through their types to `__init__` (a fresh unknown per
    symbol, 135k on corpus25: `FileContext.fresh` took 7,770 instructions with
    `A.Sym(...)` made there, 7,210 so). Every other slot gets `__init__`'s
    default; a test checks that the two agree."""
    term = _new(_SYM)
    _SYM_IDENT(term, ident)
    _SYM_SORT(term, SORTS.get(kind, "real"))
    v = _new(Value)
    v.kind = kind
    v.term = term
    v.unit = unit
    v.literal = False
    v.ref = None
    v.name = ""
    v.elements = None
    v.keys = None
    v.uninit = None
    v.factors = ()
    v.default_of = None
    v.rad_free = False
    v.items = None
    v.frame = None
    v.conversion = None
    v.choices = None
    return v


def replace(obj: _T, /, **changes: object) -> _T:
    """`dataclasses.replace`, about 9x faster for a Value (its fields read one by
    one, passed to `__init__` in order; Value has no `__post_init__` and every
    field is an `__init__` argument). The fields are read as attributes written
    out, not with an `attrgetter` of the slots' names, which looks each name up
    (7,000 instructions a copy, 4,900 so); tests/unit/test_value_replace.py
    checks that every slot is read."""
    if obj.__class__ is not Value:  # (one class, most often: cheaper than a call)
        return _replace(obj, **changes)
    o: Value = obj
    new = Value(
        o.kind,
        o.term,
        o.unit,
        o.literal,
        o.ref,
        o.name,
        o.elements,
        o.keys,
        o.uninit,
        o.factors,
        o.default_of,
        o.rad_free,
        o.items,
        o.frame,
        o.conversion,
        o.choices,
    )
    for name, value in changes.items():
        setattr(new, name, value)
    return new  # type: ignore[return-value]


def sort_of(kind: str) -> str:
    return SORTS.get(kind, "real")


SORTS = {"int": "int", "bool": "bool", "str": "str"}  # every other kind: real


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
    unit: str | None = None  # `Unit(field) == "u"`: the field's unit (predicate TRUE)


@dataclass
class MsgObj:
    """A message instance. `fields` holds what was set (or, if received, read)."""

    type: str  # pkg/Name
    origin: str  # constructed | received | unknown
    fields: dict[str, Value] = field(default_factory=dict)
    owner: tuple[int, str] | None = None  # (parent ref, field name)
    reported: set[str] = field(default_factory=set)  # unset fields already reported
    # received, and its type's invariants not assumed yet: they are, when the code
    # first reads or writes one of its fields (`heap.settle`)
    pending: bool = False
    label: str = ""  # how counterexamples name it: `msg`, `msg.linear`
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
            self.pending,
            self.label,
            self.extra,
            dict(self.unset) if self.unset else None,
        )

    def set_on_all_paths(self, name: str) -> None:
        if self.unset:
            self.unset.pop(name, None)
