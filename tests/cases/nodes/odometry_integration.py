"""Plain Python dead reckoning: * and / compose units, + needs equal ones."""
from typing import Annotated


def integrate(
    x: Annotated[float, "Unit('m')"],
    v: Annotated[float, "Unit('m/s')"],
    dt: Annotated[float, "Unit('s') and 0 < _ < 1"],
) -> Annotated[float, "Unit('m')"]:
    x = x + v * dt
    x += v  # error: RF202
    return x


def average_speed(
    distance: Annotated[float, "Unit('m')"], duration: Annotated[float, "Unit('s') and _ > 0"]
) -> Annotated[float, "Unit('m/s')"]:
    return distance / duration


def wrong_speed(
    distance: Annotated[float, "Unit('m')"], duration: Annotated[float, "Unit('s') and _ > 0"]
) -> Annotated[float, "Unit('m/s')"]:
    return distance * duration  # error: RF201
