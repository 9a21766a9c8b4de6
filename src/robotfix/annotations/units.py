"""Unit strings -> dimension vectors and scale factors. The only pint importer.

A `Unit` is a product of base dimensions with integer exponents plus a scale factor
relative to SI. Angle is a base dimension of its own (pint calls `radian` a
dimensionless base unit; we keep it), so `rad/s` is not `Hz` and `rad` is not a plain
number. Names that are not units (`ENU`, `quaternion`) and the labels of `Frame(...)`
and `Tag(...)` become opaque base dimensions of their own, compared by name.

Importing pint and building its registry costs about 0.3 s, more than a whole check of
a small file, so pint's answers are shipped (`units.json`) and cached on disk as JSON
data, keyed by pint's install (`disk_cache.JsonCache`), and pint is imported only when
a unit string is in neither. pint's own disk cache is never used: it is a pickle, and
loading one runs whatever code the file names.

pint evaluates arithmetic in a unit string (`9**9**9` never returns), so a string is
checked before pint sees it (`check_text`): at most MAX_UNIT_CHARS characters, no
control characters, no digits but ASCII ones and single superscripts (`m²`), every
`**`/`^` exponent a whole number from -MAX_UNIT_EXPONENT to MAX_UNIT_EXPONENT applied
to a unit (never to a number), and no number but `1` (`1/s`) outside exponents and
names (`utm-32N` stays a tag).
"""

from __future__ import annotations

import functools
import json
import math
import unicodedata
from dataclasses import dataclass, field
from fractions import Fraction
from importlib.util import find_spec
from pathlib import Path
from typing import Any

from robotfix.disk_cache import JsonCache, install_key, is_text
from robotfix.lazyre import lazy

_SYMBOLS = {
    "meter": "m",
    "second": "s",
    "radian": "rad",
    "gram": "g",
    "kelvin": "K",
    "ampere": "A",
    "mole": "mol",
    "candela": "cd",
}
_IDENTIFIER = lazy(r"[A-Za-z_][A-Za-z0-9_\-]*")
MAX_UNIT_CHARS = 100
MAX_UNIT_EXPONENT = 9
_MAX_DIMENSION = 99  # (m^9)^9 is allowed by the text check; m^81 is still a unit
_SUPERSCRIPTS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻", "0123456789-")
_SUPERSCRIPT_RUN = lazy("⁻?[⁰¹²³⁴⁵⁶⁷⁸⁹]+")
_POWER = lazy(r"\*\*|\^")
_DIGIT = r"\s*(?:\(\s*[+-]?\s*[0-9]\s*\)|[+-]?\s*[0-9])(?![\w.])"  # 2, -1, (-1)
_EXPONENT = lazy(_DIGIT)
_POWER_OF = lazy(r"(?:\*\*|\^)" + _DIGIT)
_NUMBER = lazy(r"(?<![\w.])[0-9.][\w.]*")


@dataclass(frozen=True)
class Unit:
    """A physical unit: its SI dimensions, its scale and its zero."""

    dims: tuple[tuple[str, int], ...]  # sorted; e.g. (("meter", 1), ("second", -1))
    factor: float = 1.0  # SI (root-unit) value of one of this unit
    offset: float = 0.0  # SI value of this unit's zero (degC: 273.15 K)
    text: str = field(default="", compare=False)

    def __mul__(self, other: Unit) -> Unit:
        return _compose(self, other, 1)

    def __truediv__(self, other: Unit) -> Unit:
        return _compose(self, other, -1)

    def same_dimension(self, other: Unit) -> bool:
        return self.dims == other.dims

    def same_as(self, other: Unit) -> bool:
        return (
            self.dims == other.dims
            and math.isclose(self.factor, other.factor, rel_tol=1e-9)
            and math.isclose(self.offset, other.offset, abs_tol=1e-9)
        )

    def power(self, exponent: int) -> Unit:
        dims = tuple(
            (d, e * exponent)
            for d, e in self.dims
            if e * exponent and (e * exponent == 1 or not is_frame(d))
        )
        factor = self.factor**exponent
        return Unit(dims, factor, text=_render(dims, factor))

    def raised(self, exponent: Fraction) -> Unit | None:
        """The unit to a rational power (`d ** 0.5` of m^2 is m), or None when a
        dimension's exponent would not be whole (`m ** 0.5`) or it has an offset."""
        if exponent.denominator == 1:
            return self.power(int(exponent))
        if self.offset or any(
            e * exponent.numerator % exponent.denominator for _, e in self.dims
        ):
            return None
        dims = tuple((d, int(e * exponent)) for d, e in self.dims)
        return named(Unit(dims, self.factor ** float(exponent)))

    @property
    def is_label(self) -> bool:
        return any(":" in d for d, _ in self.dims)

    def __str__(self) -> str:
        return self.text or _render(self.dims, self.factor)


DIMENSIONLESS = Unit((), text="1")
TWO_PI = 2 * math.pi
# The literal factors that convert between two units people use for one quantity
# (s and ms, m and cm, m/s and km/h, rad and degrees, rad/s and rpm), and the
# dimension each applies to (None: any physical one); their inverses convert back.
# Such a factor on a value already in its target's unit is a conversion done once
# too often (`p_s * 1000` into s is in ms, `current_pos * 180 / math.pi` into rad is
# in degrees), never a gain: RF201. Any other literal factor (`2 * MAX_SPEED`,
# `(left + right) / 2`) is a plain one. 2*pi, 10 and 360 are left out: they are
# gains and periods as often as conversions.
CONVERSIONS: tuple[tuple[float, str | None], ...] = (
    (1e3, None),
    (1e6, None),
    (1e9, None),
    (100.0, "meter"),
    (60.0, "second"),
    (3600.0, "second"),
    (3.6, "speed"),
    (180 / math.pi, "radian"),
    (30 / math.pi, "radian"),
)
Factors = tuple[float, ...]
_MAX_FACTORS = 6  # more literal factors than this are taken as one product


@dataclass(frozen=True)
class Fit:
    """How a value's unit meets the unit expected of it (`fit`).

    kind: "ok"; "time" (the dimensions differ by one power of seconds: an implicit
    gain or time step, RF203); "folded" (only the scale differs, and the literal
    factors may be the conversion and a gain folded into one number: RF203);
    "mismatch". `got` is the unit the value really has
    (its converting literal factors applied, frames the target does not name
    dropped); `aligned` is that unit over the expected dimensions when only the
    scale differs (for the conversion advice), else None.
    """

    kind: str
    got: Unit
    aligned: Unit | None = None
    seconds: int = 0  # "time": the power of s the value has in excess
    # "mismatch" of a value already in the expected unit before its literal factors:
    # the factor that converts it a second time (`p_s * 1000` into s: 1000)
    twice: float | None = None
    # "folded": the literal that may hold a conversion and a gain (`d_cm * 0.02`)
    scale: float = 1.0


def is_frame(dim: str) -> bool:
    return dim.startswith("frame:")


def product(factors: Factors) -> float:
    return math.prod(factors) if factors else 1.0


def effective(unit: Unit, scale: float) -> Unit:
    """`unit` after literal factors: `1000.0 / hz` is 1/Hz scaled by 1000, i.e. ms."""
    if math.isclose(scale, 1.0):
        return unit
    return named(Unit(unit.dims, unit.factor / scale, unit.offset))


def converts(unit: Unit, factor: float) -> bool:
    """Whether a literal `factor` converts between two common units of `unit`'s
    quantity (one of `CONVERSIONS`, or its inverse)."""
    dims = dict(unit.dims)
    physical = {d for d in dims if ":" not in d}
    if not physical or math.isclose(factor, 1.0):
        return False
    for value, applies in CONVERSIONS:
        if applies == "speed":
            if dims != {"meter": 1, "second": -1}:
                continue
        elif applies is not None and applies not in physical:
            continue
        if math.isclose(factor, value, rel_tol=1e-3) or math.isclose(
            factor * value, 1.0, rel_tol=1e-3
        ):
            return True
    return False


def _converting(unit: Unit, factors: Factors) -> set[int]:
    """The positions of the factors that lie in a run of adjacent ones whose
    product converts (`converts`): `x * 180 / math.pi` holds 180 and 1/pi, which
    convert only together; `t * 1000 * 1.5` holds 1000 and a plain 1.5."""
    found: set[int] = set()
    for start in range(len(factors)):
        run = 1.0
        for end in range(start, len(factors)):
            run *= factors[end]
            if converts(unit, run):
                found.update(range(start, end + 1))
    return found


def converted(unit: Unit, factors: Factors) -> Unit:
    """`unit` after the literal factors among `factors` that convert (plain gains
    such as `/ 2` leave a value in its unit): `t_ns / 1e9` is in s."""
    if len(factors) > _MAX_FACTORS:
        factors = (product(factors),)
    chosen = _converting(unit, factors)
    return effective(unit, product(tuple(factors[i] for i in sorted(chosen))))


def _accounted(factors: Factors, need: float, unit: Unit) -> bool:
    """Whether the literal factors hold the conversion `need` (a value in `unit`
    times `need` is in its target's unit) with nothing else that converts: some of
    them multiply to `need`, and no run of adjacent others converts. `(l + r) / 2 *
    2 * math.pi / 60` holds rpm -> rad/s and a plain 1/2; `2 * d_cm / 100` holds cm
    -> m and a gain of 2; `t_s * 1000 * 1.5` into s holds a conversion too many."""
    if len(factors) > _MAX_FACTORS:
        factors = (product(factors),)
    count = len(factors)
    for mask in range(1 << count):
        chosen = product(tuple(f for i, f in enumerate(factors) if mask >> i & 1))
        if not math.isclose(chosen, need, rel_tol=1e-3):
            continue
        rest = [f if not mask >> i & 1 else None for i, f in enumerate(factors)]
        if not any(_converting(unit, run) for run in _runs(rest)):
            return True
    return False


def _runs(factors: list[float | None]) -> list[Factors]:
    """The runs of adjacent factors left (None: taken out)."""
    runs: list[Factors] = []
    current: list[float] = []
    for f in [*factors, None]:
        if f is None:
            if current:
                runs.append(tuple(current))
            current = []
        else:
            current.append(f)
    return runs


def _unconverted(
    got: Unit, expected: Unit, factors: Factors, raw: Unit, need: float
) -> Fit:
    """Only the scale differs and the factors do not hold the conversion. No
    factor, or one that converts (a wrong conversion, or one applied twice): a
    mismatch. A plain literal nearer the conversion than 1 may be the conversion
    folded with a gain into one number (`d_cm * 0.02` into m is `d_cm / 100 * 2`):
    "folded", a warning. Plain literals farther from it than 1 (`2 * d_cm` into m,
    `speed_kmh * 2` into m/s, an average's 1/2) leave the value in its own unit."""
    if factors and not _converting(got, factors):
        near = [f for f in factors if _nearer(abs(f), need)]
        if near:
            return Fit("folded", raw, scale=near[0])
    return _mismatch(got, expected, factors, raw)


def _nearer(factor: float, need: float) -> bool:
    """Whether `factor` is nearer `need` than 1, by ratio."""
    if not 0 < factor < math.inf or not 0 < need < math.inf:
        return False
    return abs(math.log(factor / need)) < abs(math.log(factor))


def _frame_only(unit: Unit) -> bool:
    """A frame and no unit: where a number is, not in what."""
    return bool(unit.dims) and all(is_frame(d) for d, _ in unit.dims)


def _where(unit: Unit) -> Unit:
    """The frames of `unit` alone, named as `Frame(...)` names them."""
    dims = tuple(x for x in unit.dims if is_frame(x[0]))
    return Unit(dims, text=", ".join(f"frame {d.split(':', 1)[1]}" for d, _ in dims))


def fit(
    got: Unit, expected: Unit, factors: Factors = (), rad_free: bool = False
) -> Fit:
    """Does a value in `got` (scaled by the literal `factors`, each a folded chain
    of number literals) fit `expected`?

    The factors must hold the conversion from `got` to `expected`, if one is needed,
    and no other conversion (`converts`); the rest are plain gains. The radian is a
    ratio of lengths: a value computed by a product or quotient with a length
    (`rad_free`) may gain or lose one power of radian (`omega * r` is m/s, `v / r`
    is rad/s). A literal factor of 2*pi turns revolutions (Hz) into radians and
    back. A frame only one side names is not a mismatch (in ROS the frame of a
    message's numbers lives in its header), and a side that names a frame and no
    unit (`Frame('map')` alone) says nothing of the other's unit: only two frames
    can disagree then.
    """
    if _frame_only(expected) or _frame_only(got):
        where, wanted = _where(got), _where(expected)
        if not where.dims or not wanted.dims or where.dims == wanted.dims:
            return Fit("ok", got if got.text else named(got))
        got, expected, factors = where, wanted, ()
    has_frame = any(is_frame(d) for d, _ in expected.dims)
    got_frame = any(is_frame(d) for d, _ in got.dims)
    if has_frame != got_frame:
        got = Unit(
            tuple(x for x in got.dims if not is_frame(x[0])), got.factor, got.offset
        )
        expected = Unit(
            tuple(x for x in expected.dims if not is_frame(x[0])),
            expected.factor,
            expected.offset,
        )
    raw = got if got.text else named(got)
    scale = product(factors)
    need = got.factor / expected.factor
    if got.dims == expected.dims and not got.offset and not expected.offset:
        # `speed * 2` keeps m/s; `speed / 3.6` converts km/h to m/s
        if _accounted(factors, need, got):
            return Fit("ok", effective(got, scale) if scale != 1.0 else raw)
        return _unconverted(got, expected, factors, raw, need)
    if got.dims == expected.dims:
        same = got.same_as(expected) and math.isclose(scale, 1.0)
        return Fit("ok" if same else "mismatch", effective(got, scale))
    ours, theirs = dict(got.dims), dict(expected.dims)
    diff = {
        d: ours.get(d, 0) - theirs.get(d, 0)
        for d in ours.keys() | theirs.keys()
        if ours.get(d, 0) != theirs.get(d, 0)
    }
    angle = diff.get("radian", 0)
    if abs(angle) == 1 and (rad_free or not math.isclose(scale, 1.0)):
        if not rad_free:  # a revolution is 2*pi radians: `2 * math.pi * f`
            need = need * TWO_PI if angle < 0 else need / TWO_PI
            if not _accounted(factors, need, got):
                return _other(diff, raw, scale, got, expected)  # a plain factor
        del diff["radian"]
    if not diff:
        if got.offset or expected.offset:
            return Fit("mismatch", effective(got, scale))
        if _accounted(factors, need, got):
            return Fit("ok", effective(got, scale))
        return _unconverted(got, expected, factors, raw, need)
    return _other(diff, raw, scale, got, expected)


def _mismatch(got: Unit, expected: Unit, factors: Factors, raw: Unit) -> Fit:
    """Only the scale differs: the value is in `got` after the factors that
    convert (a plain `/ 2` leaves degrees in degrees)."""
    shown = converted(raw, factors)
    twice = raw.factor / shown.factor
    again = math.isclose(raw.factor, expected.factor, rel_tol=1e-3)
    return Fit(
        "mismatch",
        shown,
        Unit(expected.dims, shown.factor),
        twice=twice if again else None,
    )


def _other(
    diff: dict[str, int], raw: Unit, scale: float, got: Unit, expected: Unit
) -> Fit:
    """Dimensions differ. One power of s is an implicit gain (`angular.z = yaw_error`,
    unit gain P-control) or, with a literal factor, an implicit time step
    (`x += vx * 0.1`): RF203. A velocity given as a position with no factor at all
    has no step to hide in, and anything else is a mismatch: so is another scale of
    the same quantity (degrees into rad/s), whatever the gain."""
    seconds = diff.get("second", 0) if set(diff) == {"second"} else 0
    if not math.isclose(got.factor, expected.factor, rel_tol=1e-3):
        return Fit("mismatch", raw)
    if seconds == 1 or (seconds == -1 and not math.isclose(scale, 1.0)):
        return Fit("time", raw, seconds=seconds)
    return Fit("mismatch", raw)


class UnitError(Exception):
    """A unit string that is neither a unit nor an acceptable label."""

    def __init__(self, message: str, suggestion: str | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.suggestion = suggestion


def _compose(a: Unit, b: Unit, sign: int) -> Unit:
    exps: dict[str, int] = dict(a.dims)
    for dim, exp in b.dims:
        exps[dim] = exps.get(dim, 0) + sign * exp
    # A product of two values in a frame (`dx * dx`) is no longer a coordinate in it:
    # a squared or inverted frame is dropped (so are norms, `analysis/frames.py`).
    dims = tuple(
        sorted((d, e) for d, e in exps.items() if e and (e == 1 or not is_frame(d)))
    )
    factor = a.factor * (b.factor if sign > 0 else 1 / b.factor)
    return Unit(dims, factor, text=_render(dims, factor))


_PREFIXES = {1e3: "k", 1e-2: "c", 1e-3: "m", 1e-6: "u", 1e-9: "n"}
_NAMED = {("second", 60.0): "min", ("second", 3600.0): "h"}
# Derived SI units as people write them (pint's short symbols), by their dimensions
# in the registry's base units (mass in g: one N is 1000 g*m/s^2). A torque and an
# energy have one dimension: N*m, as geometry_msgs/Wrench writes it, not J.
_DERIVED = {
    (("gram", 1), ("meter", 1), ("second", -2)): "N",
    (("gram", 1), ("meter", 2), ("second", -2)): "N*m",
    (("gram", 1), ("meter", -1), ("second", -2)): "Pa",
    (("gram", 1), ("meter", 2), ("second", -3)): "W",
    (("ampere", -1), ("gram", 1), ("meter", 2), ("second", -3)): "V",
    (("ampere", -1), ("gram", 1), ("second", -2)): "T",
}


def _render(dims: tuple[tuple[str, int], ...], factor: float) -> str:
    """A unit as people write it: `km`, `ms`, `kg`, `N`, `kPa`, `km/h`, `degree`,
    else a product of base symbols with mass in kg (`kg*m^2`), a scale left only
    when no name has it (`0.5*m`)."""
    if len(dims) == 1 and dims[0][1] == 1 and dims[0][0] in ("meter", "second", "gram"):
        dim = dims[0][0]
        if dim == "gram" and math.isclose(factor, 1.0, rel_tol=1e-9):
            return "g"
        for value, prefix in _PREFIXES.items():
            if math.isclose(factor, value, rel_tol=1e-9):
                return prefix + _SYMBOLS[dim]
        for (d, value), name in _NAMED.items():
            if d == dim and math.isclose(factor, value, rel_tol=1e-9):
                return name

    if dims == (("meter", 1), ("second", -1)) and math.isclose(factor, 1 / 3.6):
        return "km/h"
    if dims == (("radian", 1), ("second", -1)) and math.isclose(factor, TWO_PI / 60):
        return "rpm"

    physical = [(d, e) for d, e in dims if ":" not in d]
    mass = dict(physical).get("gram", 0)
    derived = _DERIVED.get(tuple(physical))
    if mass:  # SI's mass unit is the kg: 1000 g*m/s^2 is kg*m/s^2, a N
        factor /= 1000.0**mass

    def part(dim: str, exp: int) -> str:
        name = "kg" if dim == "gram" else _SYMBOLS.get(dim, dim)
        return name if abs(exp) == 1 else f"{name}^{abs(exp)}"

    angle = dict(physical).get("radian")
    if angle and math.isclose(factor, (math.pi / 180) ** angle):
        factor, physical = (
            1.0,
            [("degree" if d == "radian" else d, e) for d, e in physical],
        )
    num = "*".join(part(d, e) for d, e in physical if e > 0) or "1"
    den = "*".join(part(d, e) for d, e in physical if e < 0)
    text = f"{num}/{den}" if den else num
    if derived is not None:
        prefixes = {**_PREFIXES, 1e6: "M", 100.0: "h"}  # MPa, hPa
        named_prefix = next(
            (p for v, p in prefixes.items() if math.isclose(factor, v, rel_tol=1e-9)),
            None,
        )
        if math.isclose(factor, 1.0, rel_tol=1e-9) or named_prefix is not None:
            text, factor = (named_prefix or "") + derived, 1.0
    if not math.isclose(factor, 1.0):
        text = f"{factor:.6g}*{text}"
    for dim, exp in dims:
        if ":" in dim:
            kind, name = dim.split(":", 1)
            power = "" if exp == 1 else f"^{exp}"
            text = (
                f"{name}{power}"
                if text == "1" and kind == "tag"
                else f"{text} in {kind} {name}{power}"
            )
    return text


def named(unit: Unit) -> Unit:
    """The same unit, its text rendered from its dimensions (after arithmetic)."""
    if not unit.dims and math.isclose(unit.factor, 1.0) and not unit.offset:
        return DIMENSIONLESS
    return Unit(unit.dims, unit.factor, unit.offset, _render(unit.dims, unit.factor))


def label(kind: str, text: str) -> Unit:
    """`Frame('map')` or `Tag('x')`: a dimension of its own, matched by name."""
    return Unit(
        ((f"{kind}:{text}", 1),), text=text if kind == "tag" else f"frame {text}"
    )


def resolve(text: str) -> Unit:
    """The unit `Unit(text)` denotes; a non-unit name becomes a tag.

    Raises UnitError for a typo of a unit (`meterz`) or text that is not a unit
    expression and not a name.
    """
    check_text(text)
    entry = _CACHE.entries.get(text)
    if entry is not None and not _is_resolution(entry):
        entry = None  # not what this module writes: worked out again
    if entry is None:
        entry = _shipped().get(text)
    if entry is None:
        entry = shipped_rejection(text) or _resolve_with_pint(text)
        _CACHE.put(text, entry)
    kind = entry[0]
    if kind == "unit":
        dims = tuple((str(d), int(e)) for d, e in entry[1])
        offset = float(entry[3]) if len(entry) > 3 else 0.0
        return Unit(dims, float(entry[2]), offset, text)
    if kind == "tag":
        return label("tag", text)
    raise UnitError(str(entry[1]), entry[2] if len(entry) > 2 else None)


def _is_resolution(entry: Any) -> bool:
    """Whether a machine cache's entry is exactly what `_resolve_with_pint` or
    `shipped_rejection` gives: a unit (dimensions, factor, offset), an error (a
    message, a suggestion) or a tag, with the types and strings `resolve` reads."""
    if not isinstance(entry, list) or not entry:
        return False
    kind, rest = entry[0], entry[1:]
    if kind == "tag":
        return not rest
    if kind == "error":
        return 1 <= len(rest) <= 2 and all(is_text(x) for x in rest)
    return (
        kind == "unit"
        and len(rest) in (2, 3)
        and isinstance(rest[0], list)
        and all(
            isinstance(d, list)
            and len(d) == 2
            and is_text(d[0])
            and type(d[1]) is int
            and abs(d[1]) <= _MAX_DIMENSION
            for d in rest[0]
        )
        and all(type(x) in (int, float) and math.isfinite(x) for x in rest[1:])
        and rest[1] != 0
    )


def check_text(text: str) -> None:
    """UnitError unless `text` is safe to give pint (see the module docstring)."""
    shown = _shown(text)
    if len(text) > MAX_UNIT_CHARS:
        raise UnitError(
            f"the unit `{shown}` is too long: a unit has at most {MAX_UNIT_CHARS} "
            "characters"
        )
    for char in text:
        if unicodedata.category(char)[0] == "C":
            raise UnitError(
                f"the unit `{shown}` contains the control character U+{ord(char):04X}"
            )
        if char.isdigit() and not char.isascii() and char not in "⁰¹²³⁴⁵⁶⁷⁸⁹":
            raise UnitError(
                f"the unit `{shown}` contains `{char}`, which is not an ASCII digit"
            )
    for run in _SUPERSCRIPT_RUN.findall(text):
        if len(run.lstrip("⁻")) > 1:
            raise UnitError(
                f"the unit `{shown}` has an exponent of more than one digit"
            )
    plain = _SUPERSCRIPT_RUN.sub(lambda m: "^" + m[0].translate(_SUPERSCRIPTS), text)
    for power in _POWER.finditer(plain):
        base = plain[: power.start()].rstrip()
        if not base or base[-1].isdigit() or base[-1] in ".*/^":
            raise UnitError(
                f"the unit `{shown}` raises a number to a power: only units take an "
                "exponent (`m/s^2`)"
            )
        if not _EXPONENT.match(plain, power.end()):
            raise UnitError(
                f"the unit `{shown}` has an exponent that is not a whole number from "
                f"-{MAX_UNIT_EXPONENT} to {MAX_UNIT_EXPONENT} (`m/s^2`, `m**-1`)"
            )
    bare = _POWER.sub(" ", _POWER_OF.sub(" ", plain))
    if not _IDENTIFIER.fullmatch(text) and any(
        number != "1" for number in _NUMBER.findall(bare)
    ):
        raise UnitError(
            f"the unit `{shown}` has a number in it: write a unit (`km`, not "
            "`1000*m`); numbers appear only as exponents and in `1/s`"
        )


def _shown(text: str) -> str:
    """The unit text for a message: short, with control characters escaped."""
    short = text if len(text) <= 40 else text[:40] + "…"
    return "".join(
        f"\\u{ord(c):04x}" if unicodedata.category(c)[0] == "C" else c for c in short
    )


@functools.cache
def _shipped() -> dict[str, Any]:
    """pint's reading of the units of REP 103 and the standard messages, shipped in
    the package (`units.json`, written by tools/build_package_data.py), so that a
    first run need not import pint for them."""
    try:
        data = json.loads(Path(__file__).with_name("units.json").read_text("utf-8"))
    except (OSError, ValueError):
        return {}
    if not isinstance(data, dict) or data.get("format") != units_format():
        return {}  # written by another version of the resolution
    entries = data.get("entries")
    return entries if isinstance(entries, dict) else {}


@functools.cache
def _shipped_names() -> tuple[frozenset[str], tuple[str, ...], tuple[str, ...]] | None:
    """pint's unit names (with symbols and aliases), prefixes and suffixes, as a
    fresh registry holds them, shipped in `units.json` next to the entries."""
    try:
        data = json.loads(Path(__file__).with_name("units.json").read_text("utf-8"))
        names = data["pint"]
        if (
            data.get("format") != units_format()
            or names.get("version") != _PINT_NAMES_VERSION
            or names.get("pint") != _installed_pint()
        ):
            return None  # another conversion, or another pint: ask pint
        return (
            frozenset(str(n) for n in names["units"]),
            tuple(str(n) for n in names["prefixes"]),
            tuple(str(n) for n in names["suffixes"]),
        )
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        return None


def _installed_pint() -> str | None:
    """The version of the installed pint, from its `.dist-info` folder (without
    importing it); None when that is not plain to see."""
    spec = find_spec("pint")
    if spec is None or not spec.origin:
        return None
    found = list(Path(spec.origin).parent.parent.glob("pint-*.dist-info"))
    if len(found) != 1:
        return None
    return found[0].name[len("pint-") : -len(".dist-info")]


_PINT_NAMES_VERSION = 1
# The shapes of text pint's parser (`string_preprocessor`, then the tokenizer and
# `ParserHelper.from_string`, then `get_name` for each name left) is known to reject
# without pint: words joined by single spaces (pint reads them as products), `*`, `/`
# and `-` (pint cannot subtract units: any `-` between two words fails), or one word
# with `[`/`]` in it (pint renames brackets before tokenizing, then looks the word up).
_WORD = r"[A-Za-z_][A-Za-z0-9_]*"
_WORDS = lazy(rf"{_WORD}(?:[ */-]{_WORD})*")
_WORD_OR_SEPARATOR = lazy(rf"{_WORD}|[ */-]")
_BRACKETED_WORD = lazy(r"[A-Za-z_\[\]][A-Za-z0-9_\[\]]*")
_DIGIT_AFTER_BRACKET = lazy(r"[\[\]][0-9]")
# Text pint's `string_preprocessor` rewrites (`m per s`, `square m`, `s squared`):
# such text goes to pint.
_REWRITTEN = (" per ", " squared", " cubed", "cubic ", "square ", "sq ")


def shipped_rejection(text: str) -> list[Any] | None:
    """pint's answer for a text that is NOT a unit pint reads, decided with the
    shipped names alone (None: it might be a unit, ask pint).

    Sound only where the answer is pint's: a word is a unit when pint's `get_name`
    finds it (a name, or prefix + name + suffix); pint looks up every word whose
    exponent is not zero, and fails on a `-` between words. Anything else (numbers,
    exponents, parentheses, `nan`, text pint rewrites) is left to pint.
    tests/test_units_shipped.py compares the two on the vocabulary, on real code's
    interface comments and on random text.
    """
    names = _shipped_names()
    if names is None or any(k in text for k in _REWRITTEN):
        return None
    if _WORDS.fullmatch(text):
        parts = _WORD_OR_SEPARATOR.findall(text)
        words, separators = parts[::2], parts[1::2]
        if any(word.lower() == "nan" for word in words):
            return None  # pint drops a `nan` name instead of looking it up
        if "-" not in separators:
            exponents: dict[str, int] = {}
            for separator, word in zip(["*", *separators], words, strict=True):
                exponents[word] = exponents.get(word, 0) + (
                    -1 if separator == "/" else 1
                )
            if all(e == 0 or _defined(w, names) for w, e in exponents.items()):
                return None  # a unit, or dimensionless: pint's own answer
    elif (
        not _BRACKETED_WORD.fullmatch(text)
        or _DIGIT_AFTER_BRACKET.search(text)
        or text.lower() == "nan"
        or _defined(text, names)
    ):
        return None
    return _not_a_unit(text, names[0])


def _defined(
    word: str, names: tuple[frozenset[str], tuple[str, ...], tuple[str, ...]]
) -> bool:
    """Whether pint's `get_name` finds `word` (its `_yield_unit_triplets`, case
    sensitive as RobotFix's registry is)."""
    units, prefixes, suffixes = names
    if word == "dimensionless" or word in units:
        return True
    for suffix in suffixes:
        for prefix in prefixes:
            if word.startswith(prefix) and word.endswith(suffix):
                name = word[len(prefix) :]
                if suffix:
                    name = name[: -len(suffix)]
                    if len(name) == 1:
                        continue
                if name in units:
                    return True
    return False


def pint_names() -> dict[str, Any]:
    """The names `shipped_rejection` needs, from a fresh pint registry (for
    tools/build_package_data.py)."""
    import pint

    registry: Any = pint.UnitRegistry()
    return {
        "version": _PINT_NAMES_VERSION,
        "pint": str(pint.__version__),
        "units": sorted(registry._units),
        "prefixes": sorted(registry._prefixes),
        "suffixes": sorted(registry._suffixes),
    }


def units_format() -> str:
    """The version of the resolution (`units-vN`): the machine cache's key without
    the install of pint."""
    return _CACHE.key.rsplit(":", 1)[-1]


def save_cache() -> None:
    _CACHE.save()


def _resolve_with_pint(text: str) -> list[Any]:
    registry = _registry()
    try:
        zero = registry.Quantity(0, text).to_root_units()
        one = registry.Quantity(1, text).to_root_units()
    except Exception:  # pint raises many kinds for text that is not a unit
        return _not_a_unit(text, _registry_names())
    exponents = [(str(name), exp) for name, exp in one.unit_items()]
    offset = float(zero.magnitude)
    factor = float(one.magnitude) - offset
    if (
        any(exp != int(exp) or abs(exp) > _MAX_DIMENSION for _, exp in exponents)
        or not all(math.isfinite(x) for x in (factor, offset))
        or factor == 0
    ):
        return ["error", f"`{_shown(text)}` is not a unit RobotFix can compare"]
    dims = sorted((name, int(exp)) for name, exp in exponents)
    return ["unit", dims, factor, offset]


def _not_a_unit(text: str, units: frozenset[str]) -> list[Any]:
    if not _IDENTIFIER.fullmatch(text):
        return ["error", f"`{_shown(text)}` is not a unit pint understands"]
    suggestion = _near_unit(text, units)
    if suggestion is not None:
        return [
            "error",
            f"unknown unit `{text}`; did you mean `{suggestion}`? "
            f"(write Tag('{text}') if a label was meant)",
            suggestion,
        ]
    return ["tag"]


def _near_unit(text: str, units: frozenset[str]) -> str | None:
    """A unit name (or its plural) one edit away from `text`.

    Only for names of five or more letters: shorter frame names (`rear`, `odom`,
    `base`) are one edit away from some unit far too often.
    """
    if len(text) < 5:
        return None
    lowered = text.lower()
    names = [n for n in units if len(n) >= 3]
    for name in sorted(names):
        if name.lower() == lowered:
            return str(name)
    candidates = sorted({n for n in names} | {n + "s" for n in names if n.isalpha()})
    for name in candidates:
        if abs(len(name) - len(text)) <= 1 and _one_edit(lowered, name.lower()):
            return str(name)
    return None


def _one_edit(a: str, b: str) -> bool:
    """True when a and b differ by one insertion, deletion, substitution or swap."""
    if a == b:
        return False
    if len(a) == len(b):
        diffs = [i for i in range(len(a)) if a[i] != b[i]]
        if len(diffs) == 1:
            return True
        i, j = diffs[0], diffs[-1]
        return len(diffs) == 2 and j == i + 1 and a[i] == b[j] and a[j] == b[i]
    short, long_ = (a, b) if len(a) < len(b) else (b, a)
    return any(long_[:i] + long_[i + 1 :] == short for i in range(len(long_)))


_REGISTRY: Any = None
_REGISTRY_NAMES: frozenset[str] = frozenset()


def _registry_names() -> frozenset[str]:
    """The unit names the advice on a typo (`_near_unit`) is chosen from: those of a
    freshly built registry, as shipped. A registry's own names vary: pint adds each
    prefixed unit it resolves (`millimeter`)."""
    shipped = _shipped_names()
    if shipped is not None:
        return shipped[0]
    _registry()
    return _REGISTRY_NAMES


def _registry() -> Any:
    global _REGISTRY, _REGISTRY_NAMES
    if _REGISTRY is None:
        import pint

        # never pint's `cache_folder`: its disk cache is a pickle, and unpickling a
        # file of a folder others can write (a CI cache restored from another
        # branch, a shared ROBOTFIX_CACHE_DIR) runs their code. What RobotFix needs
        # of pint is kept as JSON data instead (`_CACHE`, `units.json`), so the
        # registry is built (~0.1 s) only for a unit text no cache answers.
        _REGISTRY = pint.UnitRegistry()
        _REGISTRY_NAMES = frozenset(str(n) for n in _REGISTRY._units)
    return _REGISTRY


_CACHE = JsonCache("units", install_key("pint", "units-v2"))
