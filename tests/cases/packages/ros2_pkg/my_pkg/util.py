"""Helpers: refined parameters are checked where they are called."""
import math
from typing import Annotated

from .limits import MAX_SPEED
from .units import MetersPerSec, Radians


def clamp_speed(
    v: Annotated[float, "Unit('m/s') and -MAX_SPEED <= _ <= MAX_SPEED"],
) -> MetersPerSec:
    return v


def normalize(a: Radians) -> Annotated[float, "Unit('rad') and -4 <= _ <= 4"]:
    return math.atan2(math.sin(a), math.cos(a))


def ramp(step: Annotated[int, "0 <= _ < 10"], total: int) -> float:
    # the body may change freely: importers see only the signature
    return step / 10.0 * total


class Limiter:
    RATE = 10.0

    def __init__(self, limit: Annotated[float, "Unit('m/s') and 0 < _ <= 1"]) -> None:
        self.limit: Annotated[float, "Unit('m/s') and 0 < _ <= 1"] = limit

    def apply(self, v: MetersPerSec) -> MetersPerSec:
        return max(-self.limit, min(self.limit, v))
