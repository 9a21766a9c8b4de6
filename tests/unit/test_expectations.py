"""The test-case assertion reader (robotfix.testing.expectations) never lets an
expectation vanish: a misspelt assertion or one that targets no line is an error of
the test, not a comment."""

from __future__ import annotations

from pathlib import Path

import pytest

from robotfix.diagnostics import Diagnostic, Span
from robotfix.rules import ALL_RULES
from robotfix.testing.expectations import (
    Expectation,
    compare_files,
    read_expectations,
    read_line_expectations,
)


def test_trailing_and_stacked_assertions() -> None:
    source = (
        "x = 1  # error: RF101\n"
        '# warning: RF201 "m/s"\n'
        "# note: RF510\n"
        "\n"
        "y = 2\n"
        "s = '# error: RF999'  # a string is not a comment\n"
    )
    assert read_expectations(source) == [
        Expectation(1, "error", "RF101"),
        Expectation(5, "warning", "RF201", "m/s"),
        Expectation(5, "note", "RF510"),
    ]


def test_an_assertion_on_the_last_line_of_code_is_read() -> None:
    assert read_expectations("x = 1  # error: RF101") == [
        Expectation(1, "error", "RF101")
    ]


@pytest.mark.parametrize(
    "source",
    ["x = 1\n# error: RF101\n", "x = 1\n# error: RF101", "# error: RF101\n"],
    ids=["after the code", "no final newline", "no code at all"],
)
def test_an_assertion_after_the_last_line_of_code_is_an_error(source: str) -> None:
    with pytest.raises(ValueError, match="after the last line of code"):
        read_expectations(source)


MALFORMED = [
    "# Error: RF101",
    "# ERROR: RF101",
    "# error RF101",
    "# errors: RF101",
    "# error: rf101",
    "# error: RF10",
    "# warning - RF201",
    "#error RF101",
    '# error: RF101 "unclosed',
    "# note: the default is 0",  # the strict prefix with no code
]


@pytest.mark.parametrize("comment", MALFORMED)
def test_a_misspelt_assertion_is_an_error(comment: str) -> None:
    with pytest.raises(ValueError, match="malformed assertion"):
        read_expectations(f"x = 1  {comment}\n")
    with pytest.raises(ValueError, match="malformed assertion"):
        read_expectations(f"{comment}\nx = 1\n")
    with pytest.raises(ValueError, match="malformed assertion"):
        read_line_expectations(f"max_speed: 3.0  {comment}\n")


@pytest.mark.parametrize(
    "comment",
    [
        "# Note: the default is 0",
        "# error handling below",
        "# an error here would be RF101",
        "# noqa: E501",
    ],
)
def test_prose_is_not_an_assertion(comment: str) -> None:
    assert read_expectations(f"x = 1  {comment}\n{comment}\ny = 2\n") == []
    assert read_line_expectations(f"max_speed: 3.0  {comment}\n") == []


def test_yaml_assertions_end_the_line_they_are_about() -> None:
    text = (
        "driver:\n"
        "  ros__parameters:\n"
        '    max_speed: 3.0  # error: RF101 "max_speed"\n'
        "    url: http://host/#error:RF101\n"  # no space before `#`: not a comment
    )
    assert read_line_expectations(text) == [
        Expectation(3, "error", "RF101", "max_speed")
    ]
    with pytest.raises(ValueError, match="end of the line it is about"):
        read_line_expectations("# error: RF101\nmax_speed: 3.0\n")


def test_compare_files_reports_a_diagnostic_in_any_other_file(tmp_path: Path) -> None:
    """The tree tests compare every diagnostic of the run: one in a file they do not
    list (a node of a parameter package, a YAML file of a package) is a mismatch."""
    node, params = tmp_path / "node.py", tmp_path / "params.yaml"
    node.write_text("x = 1  # error: RF101\n")
    params.write_text("max_speed: 3.0  # error: RF101\n")
    found = [_error(node, 1), _error(params, 1)]
    assert compare_files([node, params], found) == []
    assert compare_files([params], found) == [
        f"{node}:1: unexpected error RF101 violated"
    ]
    assert compare_files([node, params], found[:1]) == [
        f"{params}: line 1: expected error RF101, got none"
    ]


def _error(path: Path, line: int) -> Diagnostic:
    return Diagnostic(ALL_RULES["RF101"], str(path), Span.point(line), "violated")
