"""What differs between the Pythons RobotFix supports (3.10 for ROS 2 Humble, 3.12
for Jazzy), tested on whichever runs the suite."""

from __future__ import annotations

import pytest

from robotfix.source import _is_python2


@pytest.mark.parametrize(
    ("line", "column", "python2"),
    [
        ("def draw_str(dst, (x, y), s):", 19, True),
        ("key = lambda (k, v): v", 14, True),
        ("f = lambda a, (k, v): v", 15, True),
        ("def f((a, b)):", 7, True),
        ("def f(a=(1, 2) b):", 16, False),
        ("def f(a=g (1)):", 11, False),
        ("x = lambda: (1 2)", 13, False),
    ],
)
def test_tuple_parameters_as_python_3_10_reports_them(
    line: str, column: int, python2: bool
) -> None:
    """3.10 says only "invalid syntax" at the `(` of a tuple parameter, where 3.11
    and later say "parameters cannot be parenthesized"."""
    err = SyntaxError("invalid syntax", ("a.py", 1, column, line))
    assert _is_python2(line + "\n", err) is python2
