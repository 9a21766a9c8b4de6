"""After a loop its exit condition holds (unless a `break` left it)."""
import math
from typing import Annotated


def wrap(angle: float) -> Annotated[float, "_ <= 3.1416"]:
    while angle > math.pi:
        angle -= 2 * math.pi
    return angle


def wrap_below(angle: float) -> Annotated[float, "_ >= -3.1416"]:
    while angle < -math.pi:
        angle += 2 * math.pi
    return angle


def wrap_with_break(angle: float) -> Annotated[float, "_ <= 3.1416"]:
    while angle > math.pi:
        angle -= 2 * math.pi
        if angle < -100:
            break
    return angle  # warning: RF102


def countdown(n: Annotated[int, "_ >= 0"]) -> Annotated[int, "_ == 0"]:
    while n > 0:
        n -= 1
    return n
