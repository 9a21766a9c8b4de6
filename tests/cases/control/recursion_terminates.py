"""Recursion and mutually recursive callbacks terminate; refinements still hold."""
from typing import Annotated


def countdown(n: Annotated[int, "_ >= 0"]) -> Annotated[int, "_ >= 0"]:
    if n == 0:
        return 0
    return countdown(n - 1)


def ping(n: int) -> int:
    return pong(n + 1)


def pong(n: int) -> int:
    return ping(n - 1)


def wrong(n: Annotated[int, "_ >= 0"]) -> None:
    countdown(n - 1)  # warning: RF102
    countdown(-1)  # error: RF101
