"""What differs between the Pythons RobotFix supports (3.10 for ROS 2 Humble, 3.12
for Jazzy), tested on whichever runs the suite."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

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


WITHOUT_TRYSTAR = """
import ast, sys
del ast.TryStar  # as on Python 3.10
from robotfix import cli
sys.exit(cli.main(["check", sys.argv[1], "--no-cache", "-j", "1"]))
"""


def test_a_check_runs_where_ast_has_no_trystar() -> None:
    """3.10's `ast` has no `TryStar` (`except*` is 3.11's): three modules named
    it at import, and every run on Humble stopped with an AttributeError before
    checking anything. A process here takes it away first."""
    node = Path(__file__).parent / "cases" / "units" / "angle_is_not_frequency.py"
    done = subprocess.run(
        [sys.executable, "-c", WITHOUT_TRYSTAR, str(node)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert "AttributeError" not in done.stderr, done.stderr
    assert done.returncode == 1 and "RF201" in done.stdout, done.stdout
