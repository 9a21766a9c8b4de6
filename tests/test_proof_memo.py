"""Proofs kept across edits (`smt.memo`, the editor's per-document memo): the same
diagnostics as a check without it, byte for byte, and no question to z3 about a VC
an earlier check of the document answered."""

from __future__ import annotations

import ast
import re
from fractions import Fraction
from pathlib import Path

import pytest

from robotfix import api
from robotfix.smt import memo as memo_module
from robotfix.smt.memo import ProofMemo
from tests.test_cases import CASES, catalog_for

ANNOTATED = sorted(
    p for p in CASES.rglob("*.py") if "Annotated" in p.read_text(encoding="utf-8")
)

NODE = '''"""A node whose speed limit and timer period are refined."""
from typing import Annotated

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node

MAX_SPEED: Annotated[float, "Unit('m/s') and 0 < _ <= 2"] = 1.5


def clamp(
    v: Annotated[float, "Unit('m/s')"], limit: Annotated[float, "Unit('m/s') and _ > 0"]
) -> Annotated[float, "Unit('m/s') and abs(_) <= limit"]:
    if v > limit:
        return limit
    if v < -limit:
        return -limit
    return v


def scaled(v: Annotated[float, "_ >= 0"], gain: float) -> Annotated[float, "_ <= 1"]:
    return v * gain


def diagonal(side: Annotated[float, "_ > 0"]) -> Annotated[float, "_ * _ != 2"]:
    return side  # broken only at an irrational side: z3's to find


def root_three(side: Annotated[float, "_ > 0"]) -> Annotated[float, "_ * _ != 3"]:
    return side


class Driver(Node):
    def __init__(self) -> None:
        super().__init__("driver")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_timer(0.1, self.tick)

    def tick(self) -> None:
        cmd = Twist()
        cmd.linear.x = clamp(3.0, MAX_SPEED)
        cmd.linear.y = diagonal(MAX_SPEED)
        steps: Annotated[int, "_ < 10"] = 10
        self.pub.publish(cmd)
'''


def render(found: list[object]) -> list[str]:
    return [repr(d) for d in found]


def without_example_values(rendered: list[str]) -> list[str]:
    """The diagnostics with the values of their counterexamples blanked out."""
    return [re.sub(r"(`[^`]*`) = [^,`]+", r"\1 = ?", d) for d in rendered]


def check(text: str, path: Path, memo: ProofMemo | None = None) -> list[str]:
    found = api.check_source(
        text, str(path), catalog=catalog_for(path.parent), memo=memo
    )
    return render(found)


@pytest.fixture
def z3_questions(monkeypatch: pytest.MonkeyPatch) -> list[object]:
    """Every VC asked of a z3 session from now on."""
    from robotfix.smt.solver import Session

    asked: list[object] = []
    original = Session.check

    def counted(self: Session, vc: object) -> object:
        asked.append(vc)
        return original(self, vc)  # type: ignore[arg-type]

    monkeypatch.setattr(Session, "check", counted)
    return asked


def test_second_check_of_the_same_text_asks_z3_nothing(
    tmp_path: Path, z3_questions: list[object]
) -> None:
    path = tmp_path / "driver.py"
    memo = ProofMemo()
    fresh = check(NODE, path)
    asked_fresh = len(z3_questions)
    assert asked_fresh > 0, "the node must need z3, or this test proves nothing"
    first = check(NODE, path, memo)
    assert first == fresh
    assert len(z3_questions) == 2 * asked_fresh
    second = check(NODE, path, memo)
    assert second == fresh
    assert len(z3_questions) == 2 * asked_fresh  # nothing asked the second time
    assert memo.hits > 0
    assert any("RF101" in d or "RF1" in d for d in fresh)  # the seeded findings


def test_an_edit_in_one_function_asks_only_about_that_function(
    tmp_path: Path, z3_questions: list[object]
) -> None:
    path = tmp_path / "driver.py"
    memo = ProofMemo()
    check(NODE, path, memo)
    edited = NODE.replace("return side  #", "return side * 1.0  #")
    before = len(z3_questions)
    kept = check(edited, path, memo)
    middle = len(z3_questions)
    assert kept == check(edited, path)
    with_memo, without = middle - before, len(z3_questions) - middle
    assert 0 < with_memo < without  # the edited function's VCs, not the file's


def shifted(text: str) -> str | None:
    """The text with a refined function inserted before its first top-level
    function or class, so that every later fresh symbol is numbered differently."""
    tree = ast.parse(text)
    first = next(
        (
            n
            for n in tree.body
            if isinstance(n, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef)
        ),
        None,
    )
    if first is None or "from typing import Annotated" not in text:
        return None
    line = min([first.lineno, *(d.lineno for d in first.decorator_list)])
    lines = text.splitlines(keepends=True)
    extra = (
        "def _memo_shift(\n"
        '    x: Annotated[float, "_ > 0"], y: Annotated[float, "_ > 1"]\n'
        ') -> Annotated[float, "_ > 1"]:\n'
        "    return x * y + y\n\n\n"
    )
    return "".join([*lines[: line - 1], extra, *lines[line - 1 :]])


@pytest.mark.parametrize("path", ANNOTATED, ids=lambda p: str(p.relative_to(CASES)))
def test_cases_give_the_same_diagnostics_with_kept_proofs(path: Path) -> None:
    """Each case: a cold memo and a memo warmed by the same text give what a check
    without it gives, byte for byte. A memo warmed by the text with other symbols
    numbered first gives the same verdicts; the values of a counterexample may be
    another valid one, as z3's model depends on what its session was asked before
    (a check without the memo shows other values after such an edit too)."""
    text = path.read_text(encoding="utf-8")
    fresh = check(text, path)
    memo = ProofMemo()
    assert check(text, path, memo) == fresh
    assert check(text, path, memo) == fresh
    other = shifted(text)
    if other is not None:
        renumbered = ProofMemo()
        check(other, path, renumbered)
        kept = check(text, path, renumbered)
        assert without_example_values(kept) == without_example_values(fresh)


def test_key_renumbers_symbols_in_order_of_appearance() -> None:
    from robotfix.annotations import ast as A
    from robotfix.vc import VC

    def vc(a: int, b: int) -> VC:
        x, y = A.Sym(a, "real"), A.Sym(b, "real")
        fact = A.Binary(">", x, A.Num(Fraction(0), False))
        return VC((fact,), A.Binary("<", y, x), (x, y))

    first, second = memo_module.key(vc(7, 9)), memo_module.key(vc(107, 109))
    assert first is not None and second is not None
    assert first[0] == second[0]
    assert first[1] == [7, 9] and second[1] == [107, 109]
    swapped = memo_module.key(vc(9, 7))
    assert swapped is not None and swapped[0] == first[0]
    other = VC(vc(7, 9).facts, A.Binary("<", A.Sym(7, "real"), A.Sym(9, "real")))
    keyed = memo_module.key(other)
    assert keyed is not None and keyed[0] != first[0]


def test_unproven_counterexamples_are_given_in_the_new_symbols() -> None:
    from robotfix.vc import Unproven

    memo = ProofMemo()
    memo.put(("k",), [7, 9], Unproven(("1",), ((7, "2"), (9, "3"))), 5, True)
    got = memo.get(("k",), [109, 107])
    assert got == (Unproven(("1",), ((107, "3"), (109, "2"))), 5, True)


def test_the_memo_is_bounded() -> None:
    from robotfix.vc import Proved, Undecided

    memo = ProofMemo(max_entries=2)
    for i in range(3):
        memo.put((i,), [], Proved(), 0, False)
    memo.put((9,), [], Undecided("unknown"), 0, True)
    assert len(memo) == 2
    assert memo.get((0,), []) is None
    assert memo.get((9,), []) is None  # never kept: it depends on the budget left
