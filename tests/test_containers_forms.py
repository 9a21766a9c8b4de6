"""Issue 8, item 5 on main's annotation forms: a container refinement written behind
an alias, in `Optional`/`| None`, across several strings, nested `Annotated`, and
read from a parameter, is on the elements (`len(_)` on the length) as it is when
written plainly. Each form has a near miss that must stay silent."""

from __future__ import annotations

from functools import cache

from robotfix.api import check_source
from robotfix.config import Config
from robotfix.diagnostics import Diagnostic
from robotfix.ros.catalog import MsgCatalog

HEADER = "from typing import Annotated, Optional\n\nfrom rclpy.node import Node\n\n"
SHIFT = HEADER.count("\n")


def check(source: str) -> list[tuple[str, int]]:
    found: list[Diagnostic] = check_source(
        HEADER + source, "node.py", Config(), _plain()
    )
    return sorted((d.code, d.span.line - SHIFT) for d in found)


@cache
def _plain() -> MsgCatalog:
    return MsgCatalog([])


def test_alias_of_a_refined_list_is_on_its_elements() -> None:
    source = (
        "Ranges = Annotated[list[float], \"Unit('m') and 0 <= _ <= 10\"]\n"
        "bad: Ranges = [1.0, 20.0]\n"
        "good: Ranges = [1.0, 10.0]\n"
    )
    assert check(source) == [("RF101", 2)]


def test_optional_refined_list_may_be_none_and_is_checked_when_not() -> None:
    source = (
        'a: Optional[Annotated[list[float], "0 <= _ <= 10"]] = None\n'
        'b: Annotated[list[float], "0 <= _ <= 10"] | None = None\n'
        'c: Annotated[list[float], "0 <= _ <= 10"] | None = [1.0, 20.0]\n'
        'd: Optional[Annotated[list[float], "0 <= _ <= 10"]] = [0.0, 10.0]\n'
    )
    assert check(source) == [("RF101", 3)]


def test_several_strings_split_into_elements_and_length() -> None:
    source = (
        'a: Annotated[list[float], "_ >= 0", "len(_) <= 2"] = [1.0, 2.0, 3.0]\n'
        'b: Annotated[list[float], "_ >= 0", "len(_) <= 2"] = [-1.0]\n'
        'c: Annotated[list[float], "_ >= 0", "len(_) <= 2"] = [1.0, 2.0]\n'
    )
    assert check(source) == [("RF101", 1), ("RF101", 2)]


def test_nested_annotated_keeps_the_inner_container() -> None:
    source = (
        'a: Annotated[Annotated[list[float], "_ >= 0"], "len(_) <= 1"] = [1.0, 2.0]\n'
        'b: Annotated[Annotated[list[float], "_ >= 0"], "len(_) <= 1"] = [-1.0]\n'
        'c: Annotated[Annotated[list[float], "_ >= 0"], "len(_) <= 1"] = [1.0]\n'
    )
    assert check(source) == [("RF101", 1), ("RF101", 2)]


def test_len_of_a_scalar_is_rf501_and_a_mixed_part_too() -> None:
    source = (
        'a: Annotated[float, "len(_) <= 2"] = 1.0\n'
        'b: Annotated[list[float], "len(_) <= _"] = [1.0]\n'
        'c: Annotated[list[float], "len(_) <= 2 and _ <= 2"] = [1.0]\n'
    )
    assert check(source) == [("RF501", 1), ("RF501", 2)]


def test_tuple_of_refinements_and_refined_tuple_both_hold() -> None:
    source = (
        'a: tuple[Annotated[float, "_ > 0"], Annotated[float, "_ < 0"]] = (1.0, 1.0)\n'
        'b: Annotated[tuple[float, float], "_ >= 0"] = (1.0, -2.0)\n'
        'c: Annotated[tuple[float, float], "_ >= 0"] = (1.0, 2.0, 3.0)\n'
        'd: tuple[Annotated[float, "_ > 0"], Annotated[float, "_ < 0"]] = (1.0, -1.0)\n'
        'e: Annotated[tuple[float, float], "_ >= 0"] = (1.0, 2.0)\n'
    )
    assert check(source) == [("RF101", 1), ("RF101", 2), ("RF101", 3)]


def test_parameter_default_elements_are_checked_and_the_read_assumed() -> None:
    source = (
        "class Scanner(Node):\n"
        "    def __init__(self) -> None:\n"
        '        super().__init__("scanner")\n'
        '        bad: Annotated[list[float], "0 <= _ <= 10"] = (\n'
        '            self.declare_parameter("bad", [1.0, 20.0]).value)\n'
        '        good: Annotated[list[float], "0 <= _ <= 10"] = (\n'
        '            self.declare_parameter("good", [1.0, 2.0]).value)\n'
        '        top: Annotated[float, "_ <= 10"] = max(good)\n'
        '        low: Annotated[float, "_ >= 0"] = min(bad)\n'
    )
    assert check(source) == [("RF101", 5)]  # at the default's 20.0
