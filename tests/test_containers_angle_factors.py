"""A literal 180/pi or 30/pi converts an angle; on a value already in its target's
unit it is a conversion done by mistake (RF201), never a gain: found in a planted
bug of an annotated rbx1 joint state publisher (`current_pos * 180 / math.pi` into a
position in rad), alone and on a list's elements. Near misses: the same factors into
the other unit, and ordinary gains, stay silent."""

from __future__ import annotations

from functools import cache

import pytest

from robotfix.annotations.units import fit, resolve
from robotfix.api import check_source
from robotfix.config import Config
from robotfix.ros.catalog import MsgCatalog

HEADER = (
    "import math\nfrom typing import Annotated\n\n"
    "RadS = Annotated[float, \"Unit('rad/s')\"]\n"
    "Rad = Annotated[float, \"Unit('rad')\"]\n"
    "Deg = Annotated[float, \"Unit('degree')\"]\n"
    "MS = Annotated[float, \"Unit('m/s')\"]\n"
    "Rads = Annotated[list[float], \"Unit('rad')\"]\n"
    "Degs = Annotated[list[float], \"Unit('degree')\"]\n\n\n"
    "def f(w: RadS, a: Rad, d: Deg, v: MS, xs: Rads) -> None:\n"
)
SHIFT = HEADER.count("\n")


def check(body: str) -> list[tuple[str, int]]:
    found = check_source(HEADER + body, "node.py", Config(), _plain())
    return sorted((d.code, d.span.line - SHIFT) for d in found)


@cache
def _plain() -> MsgCatalog:
    return MsgCatalog([])


def test_angle_factors_on_a_value_in_the_target_unit_are_rf201() -> None:
    body = (
        "    p: Annotated[float, \"Unit('rad/s')\"] = w * 60 / (2 * math.pi)\n"
        "    q: Annotated[float, \"Unit('rad')\"] = a * 180 / math.pi\n"
        "    r: Annotated[float, \"Unit('rad')\"] = a * 57.2958\n"
        "    s: Annotated[float, \"Unit('degree')\"] = d * math.pi / 180\n"
        "    t: Rads = [x * 180 / math.pi for x in xs]\n"
    )
    assert check(body) == [("RF201", n) for n in (1, 2, 3, 4, 5)]


def test_the_same_factors_converting_and_plain_gains_stay_silent() -> None:
    body = (
        "    p: Annotated[float, \"Unit('degree')\"] = a * 180 / math.pi\n"
        "    q: Annotated[float, \"Unit('rad')\"] = d * math.pi / 180\n"
        "    r: Annotated[float, \"Unit('rad/s')\"] = 2 * w\n"
        "    s: Annotated[float, \"Unit('rad')\"] = a / 2\n"
        "    t: Annotated[float, \"Unit('m/s')\"] = v * 57.3\n"
        "    u: Degs = [x * 180 / math.pi for x in xs]\n"
    )
    assert check(body) == []


@pytest.mark.parametrize(
    ("unit", "scale", "ok"),
    [
        ("rad", 180 / 3.141592653589793, False),
        ("rad", 3.141592653589793 / 180, False),
        ("rad/s", 30 / 3.141592653589793, False),
        ("rad", 2.0, True),
        ("m", 180 / 3.141592653589793, True),  # no angle: a plain factor
        ("rad", 1.0, True),
        ("s", 1000.0, False),  # a time's conversions: issue 22
        ("ns", 1e-9, False),
        ("m/s", 3.6, False),
        ("m", 100.0, False),
        ("s", 2.0, True),
        ("1", 1000.0, True),  # a count has no unit to convert
    ],
)
def test_fit_of_angle_factors(unit: str, scale: float, ok: bool) -> None:
    found = fit(resolve(unit), resolve(unit), (scale,))
    assert (found.kind == "ok") is ok
