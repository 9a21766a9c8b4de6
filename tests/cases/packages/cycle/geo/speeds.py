"""The other half of the cycle."""
from typing import Annotated

from .angles import wrap

LIMIT: Annotated[float, "Unit('m/s')"] = 0.5


def limited(v: Annotated[float, "Unit('m/s') and abs(_) <= 0.5"]) -> float:
    return v


def heading_of(a: Annotated[float, "Unit('rad')"]) -> float:
    return wrap(a)
