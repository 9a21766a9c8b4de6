"""Imports speeds, which imports this module back: a cycle."""
import math
from typing import Annotated

from . import speeds


def wrap(a: Annotated[float, "Unit('rad')"]) -> Annotated[float, "Unit('rad')"]:
    return math.atan2(math.sin(a), math.cos(a))


def turn_rate(dt: Annotated[float, "Unit('s') and _ > 0"]) -> float:
    return speeds.LIMIT / dt
