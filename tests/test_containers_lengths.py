"""Lengths that a slice's constant bounds and a comprehension state: `xs[0:360]` has
at most 360 elements, `[f(r) for r in xs]` as many as `xs`, with an `if` at most as
many. Each has a near miss one element short, which must stay a warning (never an
error: the source may be shorter)."""

from __future__ import annotations

from functools import cache

from robotfix.api import check_source
from robotfix.config import Config
from robotfix.ros.catalog import MsgCatalog

HEADER = (
    "from typing import Annotated\n\nfrom sensor_msgs.msg import LaserScan\n\n\n"
    "def on_scan(scan: LaserScan) -> None:\n"
)
SHIFT = HEADER.count("\n")


def check(body: str) -> list[tuple[str, int]]:
    found = check_source(HEADER + body, "node.py", Config(), _plain())
    return sorted((d.code, d.span.line - SHIFT) for d in found)


@cache
def _plain() -> MsgCatalog:
    return MsgCatalog([])


def test_constant_slice_bounds_give_a_length_bound() -> None:
    body = (
        '    a: Annotated[list[float], "len(_) <= 360"] = scan.ranges[0:360]\n'
        '    b: Annotated[list[float], "len(_) <= 90"] = scan.ranges[-90:]\n'
        '    c: Annotated[list[float], "len(_) <= 10"] = scan.ranges[5:15]\n'
        '    d: Annotated[list[float], "len(_) <= 10"] = scan.ranges[:10]\n'
        '    e: Annotated[list[float], "len(_) == 0"] = scan.ranges[5:3]\n'
        '    f: Annotated[list[float], "len(_) <= 9"] = scan.ranges[5:15]\n'
        '    g: Annotated[list[float], "len(_) <= 9"] = scan.ranges[-10:-1]\n'
        '    h: Annotated[list[float], "len(_) <= 9"] = scan.ranges[0:10:2]\n'
    )
    assert check(body) == [("RF102", 6), ("RF102", 7), ("RF102", 8)]


def test_a_comprehension_has_its_sources_length_or_less_with_an_if() -> None:
    body = (
        "    window = scan.ranges[0:360]\n"
        '    a: Annotated[list[float], "len(_) <= 360"] = [r * 2 for r in window]\n'
        '    b: Annotated[list[float], "len(_) <= 360"] = [\n'
        "        r for r in window if r > scan.range_min]\n"
        "    n = len(scan.ranges)\n"
        '    c: Annotated[int, "_ == n"] = len([0.0 for r in scan.ranges])\n'
        '    d: Annotated[list[float], "len(_) <= 359"] = [r for r in window]\n'
        '    e: Annotated[int, "_ == n"] = len([r for r in scan.ranges if r > 0])\n'
        '    f: Annotated[list[float], "len(_) <= 9"] = [\n'
        "        a * b for a in window for b in window]\n"
    )
    assert check(body) == [("RF102", 7), ("RF102", 8), ("RF102", 9)]
