"""A cached run over an unchanged tree stats what the last discovery looked at
instead of walking it again (`discovery.Trace`, issue 13 item 5); every change a
walk could see makes it walk again, and the report is always the uncached one."""

from __future__ import annotations

import os
import shutil
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

import robotfix.cache
from robotfix import cli, discovery
from robotfix.cache import ResultCache, run_key
from robotfix.config import Config
from robotfix.discovery import Trace, discover
from robotfix.run import check_paths

NODE = """\
import rclpy
from rclpy.node import Node
from demo.limits import clamp


class Driver(Node):
    def __init__(self) -> None:
        super().__init__("driver")
        self.declare_parameter("max_speed", 1.0)
        self.create_timer(0.1, self.tick)

    def tick(self) -> None:
        self.speed = clamp(1.5)
"""
LIMITS = """\
def clamp(x: float) -> float:
    return min(x, 3.0)
"""
BOUNDED = """\
from typing import Annotated


def clamp(x: float) -> Annotated[float, "_ <= {}"]:
    return x
"""
USE = """\
from typing import Annotated

from limits import clamp


def speed() -> Annotated[float, "_ <= 2.0"]:
    return clamp(1.5)
"""
SCRIPT = "#!/usr/bin/env python3\nimport rospy\nrospy.init_node('talker')\n"
CMAKE_GPL = "generate_parameter_library(driver_parameters src/driver_parameters.yaml)\n"
GPL_YAML = "driver:\n  max_speed:\n    type: double\n    default_value: 1.0\n"


def write(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)


@pytest.fixture
def tree(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A workspace; stamps count as old at once (the racy rule is its own test),
    and `later` waits out one clock tick before each change, as a user would."""
    monkeypatch.setattr(discovery, "RACY_NS", 0)
    root = tmp_path / "ws"
    write(root / "pyproject.toml", "")
    demo = root / "src" / "demo"
    write(demo / "package.xml", "<package><name>demo</name></package>\n")
    write(demo / "CMakeLists.txt", "project(demo)\n")
    write(demo / "demo" / "__init__.py", "")
    write(demo / "demo" / "driver.py", NODE)
    write(demo / "demo" / "limits.py", LIMITS)
    write(demo / "scripts" / "talker", SCRIPT)
    write(demo / "scripts" / "README", "not python\n")
    write(demo / "build" / "stale.py", "x = 1\n")  # output: skipped
    return root


def later() -> None:
    time.sleep(0.05)  # file systems stamp with a coarse clock (a few ms)


def run(root: Path, cache: bool = True) -> tuple[str, int]:
    result = check_paths([root / "src"], Config(root=root), use_cache=cache)
    return cli.render(result, "concise", 1, 0), len(result.checked)


def walks(root: Path, monkeypatch: pytest.MonkeyPatch) -> tuple[str, int, int]:
    """A cached run: its report, files checked, folders the discovery walked."""
    walked: list[Path] = []
    real = discovery._Walker.walk

    def counting(self: Any, *args: Any) -> Iterator[Any]:
        for item in real(self, *args):
            walked.append(item[0])
            yield item

    with monkeypatch.context() as patch:
        patch.setattr(discovery._Walker, "walk", counting)
        text, files = run(root)
    return text, files, len(walked)


def kept(root: Path) -> dict[str, Any] | None:
    """The discovery (with its trace) the cache holds for the next run."""
    config = Config(root=root)
    return ResultCache(root / ".robotfix_cache", run_key(config))._discovery


def same_as_uncached(root: Path, monkeypatch: pytest.MonkeyPatch) -> int:
    """Folders the cached run listed; its report must be the uncached one."""
    text, files, listed = walks(root, monkeypatch)
    assert (text, files) == run(root, cache=False)
    return listed


def test_an_unchanged_tree_is_not_walked_again(
    tree: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    cold = run(tree)
    assert cold[1] == 4  # driver, limits, __init__, the talker script
    assert kept(tree)
    text, files, listed = walks(tree, monkeypatch)
    assert (text, files) == cold and listed == 0


def test_a_file_added_in_a_known_folder_is_found(
    tree: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    run(tree)
    later()
    write(tree / "src" / "demo" / "demo" / "extra.py", "y = 2\n")
    assert same_as_uncached(tree, monkeypatch) > 0
    assert run(tree)[1] == 5


def test_deleted_and_renamed_files(tree: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    run(tree)
    later()
    (tree / "src" / "demo" / "demo" / "limits.py").unlink()
    assert same_as_uncached(tree, monkeypatch) > 0
    assert run(tree)[1] == 3
    later()
    talker = tree / "src" / "demo" / "scripts" / "talker"
    talker.rename(talker.with_name("speaker"))
    assert same_as_uncached(tree, monkeypatch) > 0
    assert same_as_uncached(tree, monkeypatch) == 0  # and kept again


def test_a_new_folder_deep_down_is_found(
    tree: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    run(tree)
    later()
    write(tree / "src" / "demo" / "demo" / "sub" / "deep.py", "z = 3\n")
    same_as_uncached(tree, monkeypatch)
    assert run(tree)[1] == 5


def test_a_script_whose_first_line_changes(
    tree: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """An extensionless file is a script by its content, not its folder's stamp."""
    run(tree)
    later()
    (tree / "src" / "demo" / "scripts" / "README").write_text(SCRIPT)
    assert same_as_uncached(tree, monkeypatch) > 0
    assert run(tree)[1] == 5


def test_an_ignore_marker_and_an_output_folder_that_becomes_a_package(
    tree: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    run(tree)
    later()
    write(tree / "src" / "demo" / "build" / "__init__.py", "")  # a package now
    same_as_uncached(tree, monkeypatch)
    assert run(tree)[1] == 6  # build/__init__.py, build/stale.py
    later()
    write(tree / "src" / "demo" / "scripts" / "COLCON_IGNORE", "")
    same_as_uncached(tree, monkeypatch)
    assert run(tree)[1] == 5


def test_a_build_file_naming_a_parameter_definition(
    tree: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """CMakeLists.txt is read for generate_parameter_library: its bytes count."""
    demo = tree / "src" / "demo"
    write(demo / "src" / "driver_parameters.yaml", GPL_YAML)
    run(tree)
    config = Config(root=tree)
    assert discover([tree / "src"], config).parameter_definitions == []
    later()
    (demo / "CMakeLists.txt").write_text(CMAKE_GPL)  # its folder's stamp stays
    same_as_uncached(tree, monkeypatch)
    assert kept(tree)["found"]["parameter_definitions"] == [
        str(demo / "src" / "driver_parameters.yaml")
    ]


def test_a_module_appearing_earlier_on_the_search_path(
    tree: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A new `limits.py` beside a script shadows the package's for that script."""
    write(tree / "src" / "demo" / "scripts" / "use.py", USE)
    write(tree / "src" / "demo" / "limits.py", BOUNDED.format(3.0))
    assert "use.py" in run(tree)[0]  # clamp's 3.0 against the 2.0 promised
    later()
    write(tree / "src" / "demo" / "scripts" / "limits.py", BOUNDED.format(1.0))
    same_as_uncached(tree, monkeypatch)
    assert "use.py" not in run(tree)[0]


@pytest.mark.skipif(
    not hasattr(os, "geteuid") or os.geteuid() == 0, reason="root reads anything"
)
def test_a_folder_made_unreadable(tree: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    scripts = tree / "src" / "demo" / "scripts"
    run(tree)
    later()
    scripts.chmod(0)  # the folder's ctime changes, not its mtime
    try:
        same_as_uncached(tree, monkeypatch)
        assert "RF004" in run(tree)[0]
    finally:
        scripts.chmod(0o755)


def test_a_mode_change_alone_is_seen(tree: Path) -> None:
    """What `test_a_folder_made_unreadable` relies on, whoever runs the tests."""
    scripts = tree / "src" / "demo" / "scripts"
    trace = Trace()
    trace.stamp(scripts)
    assert trace.holds()
    later()
    scripts.chmod(0o700)
    assert not trace.holds()


def test_a_file_rewritten_with_its_old_mtime_is_seen(tree: Path) -> None:
    """Same size, mtime set back (`touch -d`, an archive's extraction): the ctime
    still moves."""
    script = tree / "src" / "demo" / "scripts" / "talker"
    before = os.stat(script)
    trace = Trace()
    trace.stamp(script)
    later()
    script.write_text(SCRIPT.replace("talker", "walker"))
    os.utime(script, ns=(before.st_atime_ns, before.st_mtime_ns))
    assert os.stat(script).st_size == before.st_size
    assert not trace.holds()


def links(tree: Path) -> None:
    """A folder and a file of the tree reached through links as well."""
    shared = tree / "src" / "shared"
    write(shared / "helper.py", "h = 1\n")
    try:
        (tree / "src" / "demo" / "demo" / "linked").symlink_to(shared)
        (tree / "src" / "demo" / "scripts" / "speaker").symlink_to("talker")
    except OSError:
        pytest.skip("no symlinks here")


def repoint(link: Path, target: Path) -> None:
    """The symlink `link` made again, to `target`, a clock tick later."""
    later()
    link.unlink()
    link.symlink_to(target)


def test_a_tree_with_symlinks_is_not_walked_again(
    tree: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A link is noted by what it reaches (its real path and that one's stamp):
    an unchanged tree with links is kept like any other (it was walked on every
    run: 0.13 s of a cached run over the corpus, whose ros_tutorials has four)."""
    links(tree)
    cold = run(tree)
    assert kept(tree)
    assert same_as_uncached(tree, monkeypatch) == 0
    assert run(tree) == cold


def test_what_a_link_reaches_outside_the_walk_is_seen(
    tree: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Changes no folder the walk lists sees: the file a link reaches, outside
    the tree, becomes a folder (a link to a folder outside is RF004); a link on
    the way is pointed elsewhere (the real path is in the notice)."""
    outside = tmp_path / "outside"
    write(outside / "a" / "data", "x\n")
    write(outside / "b" / "data" / "x.py", "x = 1\n")
    try:
        (outside / "hop").symlink_to(outside / "a")
        (tree / "src" / "demo" / "data").symlink_to(outside / "hop" / "data")
    except OSError:
        pytest.skip("no symlinks here")
    links(tree)
    run(tree)
    assert kept(tree)
    assert "RF004" not in run(tree)[0]
    later()
    (outside / "a" / "data").unlink()
    (outside / "a" / "data").mkdir()
    assert same_as_uncached(tree, monkeypatch) > 0
    assert f"a symlink to `{outside / 'a' / 'data'}`" in run(tree)[0]
    repoint(outside / "hop", outside / "b")
    assert same_as_uncached(tree, monkeypatch) > 0
    assert f"a symlink to `{outside / 'b' / 'data'}`" in run(tree)[0]
    assert same_as_uncached(tree, monkeypatch) == 0
    later()
    shutil.rmtree(outside / "b")  # a broken link is no folder: no notice
    assert same_as_uncached(tree, monkeypatch) > 0
    assert "RF004" not in run(tree)[0]


def test_a_link_to_the_same_file_by_another_way_is_seen(
    tree: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Two names of one file outside the tree (hard links: one stamp): the link
    on the way pointed from one to the other changes only the real path."""
    outside = tmp_path / "outside"
    write(outside / "c" / "e.py", "e = 1\n")
    (outside / "d").mkdir()
    try:
        os.link(outside / "c" / "e.py", outside / "d" / "e.py")
        (outside / "hop").symlink_to(outside / "c")
        (tree / "src" / "demo" / "ext.py").symlink_to(outside / "hop" / "e.py")
    except OSError:
        pytest.skip("no links here")
    run(tree)
    assert f"a symlink to `{outside / 'c' / 'e.py'}`" in run(tree)[0]
    repoint(outside / "hop", outside / "d")
    assert same_as_uncached(tree, monkeypatch) > 0
    assert f"a symlink to `{outside / 'd' / 'e.py'}`" in run(tree)[0]


def test_a_touched_tree_is_not_walked_again(
    tree: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Every file given new stamps, same bytes (a checkout, a CI cache restored
    onto a fresh clone): the files the walk read (the script's first line) hold
    by their bytes (`ResultCache.same_bytes`), so the tree is not walked; the
    trace is kept with the new stamps. A script whose first line changes with
    its size and mtime kept is walked again (its own test, above)."""
    monkeypatch.setattr(robotfix.cache, "RACY_NS", 0)
    cold = run(tree)
    earlier = time.time() - 5
    for path in (tree / "src").rglob("*"):
        if path.is_file():
            os.utime(path, (earlier, earlier))
    text, files, listed = walks(tree, monkeypatch)
    assert (text, files) == cold and listed == 0
    assert same_as_uncached(tree, monkeypatch) == 0


def test_the_hashes_of_files_the_walk_read_outlive_a_run_that_did_not_ask(
    tree: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """scripts/README is read only by the walk (its first line): its hash,
    taken when the trace was kept, stays through a saving run that walked
    nothing (one module touched), so a later touch of the tree still holds."""
    monkeypatch.setattr(robotfix.cache, "RACY_NS", 0)
    cold = run(tree)
    earlier = time.time() - 10
    os.utime(tree / "src" / "demo" / "demo" / "limits.py", (earlier, earlier))
    assert walks(tree, monkeypatch) == (*cold, 0)
    earlier = time.time() - 5
    for path in (tree / "src").rglob("*"):
        if path.is_file():
            os.utime(path, (earlier, earlier))
    assert walks(tree, monkeypatch) == (*cold, 0)


def test_a_recently_changed_tree_is_not_kept(
    tree: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The racy rule: a stamp younger than RACY_NS could miss a change made in the
    same clock tick, so the discovery is walked again next time."""
    monkeypatch.setattr(discovery, "RACY_NS", 3600 * 10**9)
    run(tree)
    assert not kept(tree)
    assert same_as_uncached(tree, monkeypatch) > 0


def test_a_corrupt_trace_is_ignored(
    tree: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    run(tree)
    config = Config(root=tree)
    cache = ResultCache(tree / ".robotfix_cache", run_key(config))
    assert cache._discovery is not None
    cache._discovery["trace"]["stamps"] = {"x": "not a stamp"}
    cache._dirty = True
    cache.save()
    assert same_as_uncached(tree, monkeypatch) > 0
    assert Trace.from_json({"stamps": {}, "probes": [["rm -rf", "/", True]]}) is None


def test_another_cwd_or_setting_is_another_discovery(
    tree: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    run(tree)
    monkeypatch.chdir(tree)
    relative = check_paths([Path("src")], Config(root=tree), use_cache=True)
    cold = check_paths([Path("src")], Config(root=tree), use_cache=False)
    assert relative.checked == cold.checked
    excluded = Config(root=tree, exclude=("scripts/",))
    assert len(check_paths([tree / "src"], excluded, use_cache=True).checked) == 3


def test_the_fixture_tree_can_be_copied(tree: Path, tmp_path: Path) -> None:
    """A copy has new inodes: nothing of the original's trace holds there."""
    run(tree)
    copy = tmp_path / "copy"
    shutil.copytree(tree, copy)
    assert run(copy)[1] == run(copy, cache=False)[1] == 4


def test_absolute_paths_do_not_depend_on_the_current_folder(
    tree: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """An editor runs from anywhere: with every path absolute, the cwd is no key."""
    cold = run(tree)
    monkeypatch.chdir(tmp_path)
    text, files, listed = walks(tree, monkeypatch)
    assert (text, files) == cold and listed == 0
