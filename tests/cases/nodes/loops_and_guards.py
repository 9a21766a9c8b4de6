"""Loops keep refinements as invariants; guards make values safe."""
from typing import Annotated


def count_up(n: int) -> None:
    total: Annotated[int, "_ >= 0"] = 0
    for _ in range(n):
        total += 1
    steps: Annotated[int, "_ < 100"] = 0
    while steps < 100:
        steps += 1  # warning: RF102
    safe: Annotated[int, "_ < 100"] = 0
    while safe < 99:
        safe += 1


def limited(v: float, limit: Annotated[float, "_ > 0"]) -> None:
    if v > limit:
        v = limit
    elif v < -limit:
        v = -limit
    bounded: Annotated[float, "abs(_) <= limit"] = v
    clipped: Annotated[float, "_ <= limit"] = min(v, limit)


def handled(raw: str) -> None:
    try:
        value = float(raw)
    except ValueError:
        value = 0.0
    with open(raw) as stream:
        stream.read()
    ratio: Annotated[float, "_ >= 0"] = abs(value)
    items = [x * 2 for x in range(3)]
    doubled = lambda y: y * 2  # noqa: E731
