"""Issue 25 target 1: a loop's head is walked once. `havoc` returns the names the
loop sums (`accumulated`) with what it forgets, and the unit a sum takes after the
loop (`_loop_units`) is read from them, not from a second walk of the loop."""

from __future__ import annotations

import ast

import pytest

from robotfix.analysis.compound import CompoundWalker
from robotfix.analysis.stmtsyntax import accumulated
from robotfix.api import check_source

LOOPS = """\
from typing import Annotated

Meters = Annotated[float, "Unit('m')"]


def walked(n: int, limit: Meters) -> float:
    total = 0.0
    for _ in range(n):
        total += limit
        if total > limit:
            break
    else:
        total = 1.0  # the loop's else: `total` is no sum of the whole loop
    left = 0.0
    while n > 0:
        n -= 1
        left += limit
        for _ in range(n):
            left -= limit
    return total + left
"""


def test_a_loop_reads_its_sums_from_havoc_also_when_its_else_stores_one(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    met: list[tuple[str, set[str], set[str]]] = []  # loop, havoc's sums, read
    original = CompoundWalker._summed

    def checked(
        self: CompoundWalker, node: ast.stmt, iteration: ast.stmt, summed: set[str]
    ) -> set[str]:
        found = original(self, node, iteration, summed)
        assert found == accumulated([node])
        met.append((type(node).__name__, set(summed), found))
        return found

    monkeypatch.setattr(CompoundWalker, "_summed", checked)
    check_source(LOOPS, "loops.py")
    # havoc saw the `for` without its else, where `total` is a sum: after the
    # loop it is none (the else stores it); the other loops read havoc's names
    assert ("For", {"total"}, set()) in met
    assert ("While", {"n", "left"}, {"n", "left"}) in met
    assert ("For", {"left"}, {"left"}) in met
