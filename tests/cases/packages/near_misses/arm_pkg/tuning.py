"""A limit that a function changes: not a constant, so importers may not assume it."""
from typing import Annotated

GAIN = 1.0
JOINT_LIMIT = 2.5


def retune(value: float) -> None:
    global GAIN
    GAIN = value


def scale(x: Annotated[float, "0 <= _ <= 1"]) -> float:
    return x * GAIN
