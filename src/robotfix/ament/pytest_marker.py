"""A pytest plugin (entry point `pytest11`), loaded by every pytest run where RobotFix
is installed, so it imports nothing: it registers the `robotfix` marker of
`test_robotfix.py`, and the `linter` marker that ament_lint registers too, so the
template also runs under `--strict-markers` where ament_lint is not installed
(`colcon test --pytest-args -m "not linter"` then deselects it like the others)."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import pytest


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line(
        "markers", "robotfix: checks units, frames and refinements with RobotFix"
    )
    config.addinivalue_line("markers", "linter: marks tests as linter checks")
