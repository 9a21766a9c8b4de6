"""The annotation language: every thesis form parses; errors carry a column."""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix.annotations import ast as A
from robotfix.annotations.parser import AnnotationSyntaxError, parse_predicate

THESIS = [
    "Unit('m/s') and x < 20 and x > -20",
    "Unit('km/h') and x < 20 and x > -20",
    'Unit(linear.x) == "m/s"',
    "linear.x < 20 and linear.x > -20",
    'Unit(linear.x) == "m/s" and linear.x > 0 and linear.x < 20',
    "data == 1 or data == 2 or data == 3",
    "_ >= 3.141592653589793238 ",
    'Unit(data) == "seconds" and data >= 0',
    "x >= 0 and x <= 3.14",
    "Unit('NED')",
    "",
    "Unit('m/s') and y == x",
    "x != 1",
    "timeout < 200",
    "_ < 10",
    "Unit('rad/s') and _ > 0 and _ < 3 ",
    "if x > 0 then y else z",
]


@pytest.mark.parametrize("text", THESIS)
def test_every_thesis_annotation_parses(text: str) -> None:
    parse_predicate(text)


def test_decimals_stay_exact() -> None:
    pred = parse_predicate("_ >= 3.141592653589793238")
    assert isinstance(pred, A.Binary) and isinstance(pred.right, A.Num)
    assert pred.right.value == Fraction("3.141592653589793238")
    assert pred.right.value != Fraction(3.141592653589793238)


def test_chains_membership_and_labels() -> None:
    assert A.show(parse_predicate("0 <= _ < 20")) == "0 <= _ and _ < 20"
    assert A.show(parse_predicate("_ in (1, 2)")) == "_ == 1 or _ == 2"
    unit = parse_predicate('Unit(linear.x) == "m/s"')
    assert unit == A.UnitIs("unit", "m/s", "linear.x")
    assert parse_predicate("Frame('map')") == A.UnitIs("frame", "map")
    assert A.show(parse_predicate("a if c else b")) == "a if c else b"
    assert A.show(parse_predicate("!x")) == "not x"


def test_floored_division_and_remainder() -> None:
    """`//` and `%` bind as `*` and `/` do, and are shown as written."""
    pred = parse_predicate("x - y // 2 % 3 > 0")
    assert isinstance(pred, A.Binary) and isinstance(pred.left, A.Binary)
    remainder = pred.left.right
    assert isinstance(remainder, A.Binary) and remainder.op == "%"
    assert isinstance(remainder.left, A.Binary) and remainder.left.op == "//"
    for text in ("x - y // 2 % 3 > 0", "a // (b // c) == a % (b % c)", "_ % 2 == 0"):
        assert A.show(parse_predicate(text)) == text
    for text in ("_ // 0 == 1", "_ % 0 == 1"):
        with pytest.raises(AnnotationSyntaxError, match="division by zero"):
            parse_predicate(text)


@pytest.mark.parametrize(
    ("text", "offset"),
    [
        ("x < < 3", 4),
        ("x $ 3", 2),
        ("Foo(x)", 0),
        ("_ < 2 and Unit(x) < 3", 10),
        ("x <", 2),
    ],
)
def test_errors_point_at_the_problem(text: str, offset: int) -> None:
    with pytest.raises(AnnotationSyntaxError) as info:
        parse_predicate(text)
    assert info.value.offset == offset


def test_annotations_are_parsed_never_evaluated() -> None:
    with pytest.raises(AnnotationSyntaxError):
        parse_predicate("__import__('os').system('touch /tmp/robotfix-pwned')")


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet=st.characters(codec="utf-8"), max_size=40))
def test_random_text_is_a_result_or_a_syntax_error(text: str) -> None:
    try:
        parse_predicate(text)
    except AnnotationSyntaxError as err:
        assert 0 <= err.offset <= len(text)
