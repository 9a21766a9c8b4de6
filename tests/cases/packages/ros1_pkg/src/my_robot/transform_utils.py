"""Conversions, as rbx1_nav keeps them in transform_utils.py."""
import math
from typing import Annotated

Degrees = Annotated[float, "Unit('degree')"]
Radians = Annotated[float, "Unit('rad')"]
SCAN_RANGE_MAX: Annotated[float, "Unit('m')"] = 3.5


def normalize_angle(angle: Radians) -> Annotated[float, "Unit('rad') and -4 <= _ <= 4"]:
    return math.atan2(math.sin(angle), math.cos(angle))


def to_degrees(angle: Radians) -> Degrees:
    return math.degrees(angle)


def scaled(fraction: Annotated[float, "0 <= _ <= 1"]) -> Annotated[float, "Unit('m')"]:
    return fraction * SCAN_RANGE_MAX
