"""Run every program under tests/cases/ and compare with its inline assertions.

Interface files come from `tests/cases/msgs/` and from a `msg/` folder beside the case.
A `_xfail` suffix marks a known failure (it must fail, and fails the run once fixed).
Cases under `ros1/` are checked as `--ros-distro ros1` checks them.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

import pytest

from robotfix.api import catalog_problems, check_source, interface_files
from robotfix.config import Config
from robotfix.diagnostics import Diagnostic
from robotfix.ros.catalog import MsgCatalog
from robotfix.testing.expectations import compare, read_expectations

CASES = Path(__file__).parent / "cases"


@cache
def catalog_for(folder: Path) -> MsgCatalog:
    folders = [CASES / "msgs", folder / "msg"]
    catalog = MsgCatalog(
        interface_files([f for f in folders if f.is_dir()]), distro=_distro(folder)
    )
    problems = catalog_problems(catalog)
    assert not problems, f"the case's interface files have problems: {problems}"
    return catalog


def check_case(path: Path) -> list[Diagnostic]:
    """A case file checked as `test_case` checks it (its folder's interface files)."""
    text = path.read_text(encoding="utf-8")
    config = Config(ros_distro=_distro(path.parent))
    return check_source(text, str(path), config, catalog_for(path.parent))


def _distro(folder: Path) -> str:
    """ROS 1 for the cases under `ros1/`; ROS 2 elsewhere (also outside the cases)."""
    return "ros1" if folder.is_relative_to(CASES / "ros1") else "ros2"


# launch/, graph/, cpp_params/: whole workspaces, whose launch files' and graph's
# findings need the tree (tests/test_launch.py, test_graph.py and
# test_launch_cpp.py check every file of them)
SINGLE_FILES = sorted(
    p
    for p in CASES.rglob("*.py")
    if p.relative_to(CASES).parts[0] not in ("launch", "graph", "cpp_params")
)


@pytest.mark.parametrize("path", SINGLE_FILES, ids=lambda p: str(p.relative_to(CASES)))
def test_case(path: Path) -> None:
    source = path.read_text(encoding="utf-8")
    found = check_case(path)
    problems = compare(read_expectations(source), found)
    if path.stem.endswith("_xfail"):
        assert problems, "this case passes now: drop the _xfail suffix"
        pytest.xfail("\n".join(problems))
    assert not problems, "\n".join(problems)
