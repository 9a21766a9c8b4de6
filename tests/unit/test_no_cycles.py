"""What a cold check makes and drops is freed by reference counting: the run's
young collections (`robotfix.GC_THRESHOLDS`) are rare, so an object kept in a reference
cycle would stay until one runs, and with it all it holds. Each case failed before
its cycle was broken (the collector found the garbage)."""

from __future__ import annotations

import gc
from collections.abc import Callable, Iterator

import pytest

from robotfix.ros.launch.tree import LaunchSyntaxError, parse_xml
from robotfix.smt import propositional as P


@pytest.fixture
def no_collector() -> Iterator[None]:
    gc.collect()
    gc.disable()
    try:
        yield
    finally:
        gc.enable()


def _garbage(make: Callable[[], object]) -> int:
    """The objects `make` left that only the collector frees."""
    make()
    return gc.collect()


def _refused() -> None:
    with pytest.raises(LaunchSyntaxError):
        parse_xml('<!DOCTYPE x [<!ENTITY e "e">]><launch/>')


@pytest.mark.usefixtures("no_collector")
def test_a_launch_file_read_leaves_no_cycle() -> None:
    """The expat parser's handlers are closures over the parser (and its elements)."""
    text = '<launch>\n  <node pkg="a" exec="b" name="c"/>\n</launch>\n'
    assert parse_xml(text).children[0].attrs["pkg"] == "a"
    assert _garbage(lambda: parse_xml(text)) == 0
    assert _garbage(_refused) == 0  # also when a handler raised


@pytest.mark.usefixtures("no_collector")
def test_a_propositional_search_leaves_no_cycle() -> None:
    """The search's closure calls itself through its cell."""
    formulas = [("or", ("atom", 0), ("atom", 1)), ("not", ("atom", 0))]
    assert P._search(formulas, 2) is True
    assert _garbage(lambda: P._search(formulas, 2)) == 0
