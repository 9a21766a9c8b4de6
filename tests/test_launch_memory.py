"""A run holds no syntax tree for its launch files' reading (issue 25, target 4:
memory): the checks keep each file's import statements as plain data, not the
tree's nodes, and no Python launch file's tree outlives its check; the reading
parses each launch file itself and keeps only the entries it read."""

from __future__ import annotations

import ast
import gc
import shutil
from pathlib import Path
from typing import Any

import pytest

from robotfix import run
from robotfix.config import Config
from robotfix.launchcheck import LaunchRun

CASES = Path(__file__).parent / "cases" / "launch"


def _trees() -> list[ast.Module]:
    """The syntax trees the collector can see. A check freezes what was alive
    before it (`gc.freeze`), so those are not seen while it runs."""
    gc.collect()
    return [o for o in gc.get_objects() if isinstance(o, ast.Module)]


def _new(trees: list[ast.Module], before: list[ast.Module]) -> list[ast.Module]:
    """`trees` that are not in `before` (held there, so no id is reused)."""
    old = {id(t) for t in before}
    return [t for t in trees if id(t) not in old]


def _nodes(value: Any) -> bool:
    """Whether `value` (tuples, lists) holds a syntax tree's node."""
    if isinstance(value, ast.AST):
        return True
    if isinstance(value, (tuple, list)):
        return any(_nodes(v) for v in value)
    return False


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    """A package with a Python launch file and the node it starts."""
    root = tmp_path / "ws"
    shutil.copytree(CASES / "gym_bridge", root / "gym_bridge")
    return root


def test_no_tree_is_held_for_the_launch_reading(
    workspace: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    seen: dict[str, Any] = {}
    reading = run._launches

    def launches(*args: Any, **kwargs: Any) -> Any:
        seen["trees"] = _new(_trees(), before)  # the checks are done: trees gone
        seen["imports"] = dict(run._IMPORTS)
        return reading(*args, **kwargs)

    monkeypatch.setattr(run, "_launches", launches)
    before = _trees()  # what other tests left alive, if anything
    result = run.check_paths(
        [workspace], Config(root=workspace), jobs=1, use_cache=False
    )
    assert not result.internal_errors
    assert seen["trees"] == []
    assert seen["imports"]  # the node's code: its import statements kept
    assert not any(_nodes(kept) for kept in seen["imports"].values())


def test_the_reading_keeps_its_entries_not_its_trees(workspace: Path) -> None:
    launch = sorted(workspace.rglob("*_launch.py"))
    code = sorted(p for p in workspace.rglob("*.py") if p not in launch)
    before = _trees()
    read = LaunchRun(launch, code)
    assert read.started  # the entries were read
    assert _new(_trees(), before) == []
