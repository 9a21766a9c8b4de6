"""What a `--no-cache` run holds through its checks (issue 25, target 4: memory):
the module index keeps no answer a folder's listing already gives, neither a
summary's fingerprints nor the message types' digests are made when no result
cache will ask for them, and the checked files' import statements go once the
launch files are read, before the C++ files are (the run's peak)."""

from __future__ import annotations

import os
import shutil
from pathlib import Path
from typing import Any

import pytest

from robotfix import run
from robotfix.api import make_project
from robotfix.config import Config
from robotfix.project.modules import ModuleIndex


def _workspace(root: Path) -> Path:
    """A package `a` (a node importing) and two library folders: `lib1` (a
    module `x`), `lib2` (a module `lone` and a package `b`)."""
    (root / "ws" / "a" / "a").mkdir(parents=True)
    (root / "ws" / "a" / "package.xml").write_text("<package><name>a</name></package>")
    (root / "ws" / "a" / "a" / "__init__.py").write_text("")
    (root / "ws" / "a" / "a" / "tool.py").write_text("SPEED = 1.0\n")
    (root / "lib1").mkdir()
    (root / "lib1" / "x.py").write_text("")
    (root / "lib2" / "b" / "sub").mkdir(parents=True)
    (root / "lib2" / "b" / "__init__.py").write_text("")
    (root / "lib2" / "b" / "tool.py").write_text("")
    (root / "lib2" / "b" / "sub" / "__init__.py").write_text("")
    (root / "lib2" / "lone.py").write_text("")
    node = root / "ws" / "a" / "a" / "node.py"
    node.write_text(
        "from a.tool import SPEED\nimport b.sub\nimport rclpy\n"
        "from std_msgs.msg import String\nmsg = String()\nmsg.data = 'go'\n"
    )
    return node


def test_the_index_keeps_no_answer_a_listing_gives(tmp_path: Path) -> None:
    node = _workspace(tmp_path)
    index = ModuleIndex([tmp_path / "ws"], [tmp_path / "lib1", tmp_path / "lib2"])
    assert len(index.search_path(node)) > 2  # several folders, most without a name
    names = ("a.tool", "b.tool", "b.sub", "b.nothing", "rclpy.node", "lone", "x")
    found = {name: index.find(name, node) for name in names}
    assert found == {
        "a.tool": tmp_path / "ws" / "a" / "a" / "tool.py",
        "b.tool": tmp_path / "lib2" / "b" / "tool.py",
        "b.sub": tmp_path / "lib2" / "b" / "sub" / "__init__.py",
        "b.nothing": None,
        "rclpy.node": None,
        "lone": tmp_path / "lib2" / "lone.py",
        "x": tmp_path / "lib1" / "x.py",
    }
    assert index._found  # answers kept: where a folder offers the name's top
    for root, name in index._found:
        top = name.partition(".")[0]
        listed = os.listdir(root)
        # a root whose listing lacks the name's top answers None without a memo
        assert top in listed or f"{top}.py" in listed, (root, name)
    # no set of top-level names per search path: the listings answer
    assert not any(
        isinstance(v, dict) and any(isinstance(x, frozenset) for x in v.values())
        for v in vars(index).values()
    )


def _project(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, cached: bool) -> Any:
    """The project of a run of the workspace, with the result cache or without."""
    _workspace(tmp_path)
    root = tmp_path / "ws"
    made: list[Any] = []

    def project(*args: Any, **kwargs: Any) -> Any:
        made.append(make_project(*args, **kwargs))
        return made[-1]

    monkeypatch.setattr(run, "make_project", project)
    config = Config(root=root, cache_dir=tmp_path / "cache")
    result = run.check_paths([root], config, jobs=1, use_cache=cached)
    assert not result.internal_errors
    (found,) = made
    return found


@pytest.mark.parametrize("cached", [False, True])
def test_summary_fingerprints_are_kept_only_for_the_cache(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, cached: bool
) -> None:
    built = _project(tmp_path, monkeypatch, cached).built
    if cached:  # the cache keeps them: a later run's check of an importer needs them
        assert str(tmp_path / "ws" / "a" / "a" / "tool.py") in built
    else:  # nothing would read them
        assert built == {}


@pytest.mark.parametrize("cached", [False, True])
def test_message_type_digests_are_made_only_for_the_cache(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, cached: bool
) -> None:
    catalog = _project(tmp_path, monkeypatch, cached).catalog
    if cached:  # a cached result holds while its types read the same
        assert "std_msgs/String" in catalog._resolved_digests
    else:
        assert not catalog._resolved_digests and not catalog._combined


def test_the_import_statements_go_once_the_launch_files_are_read(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    root = tmp_path / "ws"
    cases = Path(__file__).parent / "cases" / "launch"
    shutil.copytree(cases / "gym_bridge", root / "gym_bridge")
    seen: dict[str, int] = {}
    launches, cpp = run._launches, run._cpp_graphs

    def reading(*args: Any, **kwargs: Any) -> Any:
        seen["read"] = len(run._IMPORTS)
        return launches(*args, **kwargs)

    def graphs(*args: Any, **kwargs: Any) -> Any:
        seen["cpp"] = len(run._IMPORTS)
        return cpp(*args, **kwargs)

    monkeypatch.setattr(run, "_launches", reading)
    monkeypatch.setattr(run, "_cpp_graphs", graphs)
    result = run.check_paths([root], Config(root=root), jobs=1, use_cache=False)
    assert not result.internal_errors
    assert seen["read"] > 0  # the node's imports, for the launch reading
    assert seen["cpp"] == 0


def test_the_index_keeps_one_string_per_name(tmp_path: Path) -> None:
    node = _workspace(tmp_path)
    other = tmp_path / "lib2" / "b" / "tool.py"  # another search path
    index = ModuleIndex([tmp_path / "ws"], [tmp_path / "lib1", tmp_path / "lib2"])
    for importer in (node, other):
        for name in ("rclpy", "b.tool"):
            index.find("".join(name), importer)  # a new string each time
    keys = list(index._resolved)
    assert len({number for number, _ in keys}) == 2
    assert len({id(name) for _, name in keys}) == 2
