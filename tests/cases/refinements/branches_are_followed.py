"""Guards make values safe; an error needs the violation on every execution of a path."""
from typing import Annotated


def clamp(v: float) -> None:
    if v > 2:
        v = 2
    limited: Annotated[float, "_ <= 2"] = v


def maybe(v: float) -> None:
    x = 5 if v > 0 else 1  # two paths: on the one with v > 0, x is 5
    small: Annotated[int, "_ < 3"] = x  # error: RF101


def always(flag: bool) -> None:
    if flag:
        x = 5
    else:
        x = 7
    small: Annotated[int, "_ < 3"] = x  # error: RF101
