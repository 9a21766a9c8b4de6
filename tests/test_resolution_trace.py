"""The module index's answers kept between cached runs (`ModuleIndex.keep` and
`restore`, issue 13 item 5): every change on disk that can alter which file a name
is - a module added earlier on the search path, one deleted, a package's
`__init__.py` added or removed, a folder renamed, the python paths changed -
gives the report of a run without the cache, byte for byte."""

from __future__ import annotations

import os
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

from robotfix import cli
from robotfix.config import Config
from robotfix.project import modules
from robotfix.project.modules import ModuleIndex
from robotfix.run import check_paths

CMD_MSG = "float64 speed  # [m/s]\n#RobotFix# speed <= 2.0\n"
NODE = """\
import rclpy
from rclpy.node import Node
from demo.msg import Cmd
from {module} import clamp


class Driver(Node):
    def __init__(self) -> None:
        super().__init__("driver")
        self.declare_parameter("rate", 10.0)
        self.pub = self.create_publisher(Cmd, "cmd", 10)
        self.create_timer(0.1, self.tick)

    def tick(self) -> None:
        c = Cmd()
        c.speed = clamp(1.5)
        self.pub.publish(c)
"""
LIMIT = """\
from typing import Annotated


def clamp(x: float) -> Annotated[float, "_ <= {bound}"]:
    return min(x, {bound})
"""
TOO_HIGH = LIMIT.format(bound="3.0")  # Cmd's speed is at most 2.0: a finding
WITHIN = LIMIT.format(bound="1.0")  # the near miss: silent
FINDING = "value of `clamp()`"  # the report's words for TOO_HIGH


def write(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)


@pytest.fixture(autouse=True)
def trusted(monkeypatch: pytest.MonkeyPatch) -> Iterator[list[bool]]:
    """Folder stamps are trusted however young (the tests change a tree within
    seconds; a run lasts longer than a clock tick), and whether each `restore` took
    over some answer is noted."""
    monkeypatch.setattr(modules, "RACY_NS", 0)
    restored: list[bool] = []
    real = ModuleIndex.restore

    def noted(self: ModuleIndex, raw: object) -> bool:
        found = real(self, raw)
        restored.append(found and bool(self._resolved))  # some answer taken over
        return found

    monkeypatch.setattr(ModuleIndex, "restore", noted)
    yield restored


def package(root: Path, module: str) -> Path:
    """A ROS 2 package `demo` under `root/src` whose node imports `module`."""
    demo = root / "src" / "demo"
    write(demo / "package.xml", "<package><name>demo</name></package>\n")
    write(demo / "msg" / "Cmd.msg", CMD_MSG)
    write(demo / "demo" / "__init__.py", "")
    write(demo / "demo" / "driver.py", NODE.format(module=module))
    return demo


def run(root: Path, cache: bool = True, python_paths: tuple[Path, ...] = ()) -> str:
    config = Config(root=root, python_paths=python_paths)
    result = check_paths([root / "src"], config, use_cache=cache)
    return cli.render(result, "concise", 1, 0)


def same_as_cold(root: Path, python_paths: tuple[Path, ...] = ()) -> str:
    text = run(root, python_paths=python_paths)
    assert text == run(root, cache=False, python_paths=python_paths)
    return text


def test_answers_are_kept_and_reused(tmp_path: Path, trusted: list[bool]) -> None:
    package(tmp_path, "helpers")
    write(tmp_path / "src" / "helpers.py", TOO_HIGH)
    cold = run(tmp_path)
    assert "driver.py" in cold and FINDING in cold
    assert run(tmp_path) == cold
    assert trusted == [False, True]  # the second run took the first one's answers


def test_young_stamps_are_not_kept(
    tmp_path: Path, trusted: list[bool], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(modules, "RACY_NS", 3_600 * 10**9)  # all are young
    package(tmp_path, "helpers")
    write(tmp_path / "src" / "helpers.py", TOO_HIGH)
    cold = run(tmp_path)
    assert run(tmp_path) == cold
    assert trusted == [False, False]  # each folder counts as changed


def test_a_young_folder_alone_is_listed_again(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    write(tmp_path / "a" / "b.py", "")
    write(tmp_path / "c.py", "")
    node = tmp_path / "node.py"
    index = ModuleIndex([tmp_path])
    index.find("c", node)  # lists the root only
    time.sleep(0.05)
    write(tmp_path / "a" / "x.py", "")  # young when listed below
    monkeypatch.setattr(modules, "RACY_NS", 3_600 * 10**9)  # a/ is young
    index.find("a.x", node)
    kept = index.keep()
    assert kept is not None and kept["stamps"][str(tmp_path / "a")][0] == -1
    again = ModuleIndex([tmp_path])
    assert again.restore(kept)
    assert set(again._resolved) == {(0, "c")}


def test_a_module_added_earlier_on_the_search_path(
    tmp_path: Path, trusted: list[bool]
) -> None:
    demo = package(tmp_path, "helpers")
    write(tmp_path / "src" / "helpers.py", TOO_HIGH)  # a checked root: searched last
    assert FINDING in run(tmp_path)
    write(demo / "helpers.py", WITHIN)  # the package's own folder: searched before
    assert FINDING not in same_as_cold(tmp_path)
    assert trusted[-1] is True  # the answers that did not list demo/ are kept


def test_a_module_file_deleted(tmp_path: Path) -> None:
    demo = package(tmp_path, "helpers")
    write(tmp_path / "src" / "helpers.py", TOO_HIGH)
    write(demo / "helpers.py", WITHIN)
    assert FINDING not in run(tmp_path)
    (demo / "helpers.py").unlink()  # the root's helpers.py is found now
    assert FINDING in same_as_cold(tmp_path)
    (tmp_path / "src" / "helpers.py").unlink()  # no helpers at all
    assert FINDING not in same_as_cold(tmp_path)


@pytest.mark.parametrize("present", [True, False])
def test_a_package_init_added_or_removed(tmp_path: Path, present: bool) -> None:
    """With `demo/demo/__init__.py`, `import helpers` from the node searches the
    folder above the package (and the roots); without it, the node's own folder."""
    demo = package(tmp_path, "helpers")
    write(demo / "demo" / "helpers.py", TOO_HIGH)
    write(tmp_path / "src" / "helpers.py", WITHIN)
    init = demo / "demo" / "__init__.py"
    if not present:
        init.unlink()
    before = run(tmp_path)
    assert (FINDING in before) is not present
    if present:
        init.unlink()
    else:
        init.write_text("")
    after = same_as_cold(tmp_path)
    assert (FINDING in after) is present


def test_an_init_file_in_a_folder_never_listed(tmp_path: Path) -> None:
    """An `__init__.py` probed, not listed: only the probe can see it."""
    demo = package(tmp_path, "helpers")
    write(tmp_path / "src" / "helpers.py", TOO_HIGH)
    write(demo / "helpers.py", WITHIN)
    assert FINDING not in run(tmp_path)
    # demo/ becomes a package: the node's top parent is src/ now, whose
    # helpers.py is the one too high
    write(demo / "__init__.py", "")
    assert FINDING in same_as_cold(tmp_path)


def test_a_folder_renamed(tmp_path: Path) -> None:
    package(tmp_path, "tools.limits")
    tools = tmp_path / "src" / "tools"
    write(tools / "limits.py", TOO_HIGH)
    assert FINDING in run(tmp_path)
    tools.rename(tmp_path / "src" / "tools_old")
    assert FINDING not in same_as_cold(tmp_path)
    (tmp_path / "src" / "tools_old").rename(tools)
    assert FINDING in same_as_cold(tmp_path)


def test_a_sub_folder_renamed_without_touching_the_root(tmp_path: Path) -> None:
    """Only a nested folder's listing changes: the root's stamp stays."""
    package(tmp_path, "tools.sub.limits")
    sub = tmp_path / "src" / "tools" / "sub"
    write(sub / "limits.py", TOO_HIGH)
    assert FINDING in run(tmp_path)
    sub.rename(sub.with_name("other"))
    assert FINDING not in same_as_cold(tmp_path)


def test_the_python_paths_changed(tmp_path: Path, trusted: list[bool]) -> None:
    package(tmp_path, "helpers")
    write(tmp_path / "src" / "helpers.py", TOO_HIGH)
    shared = tmp_path / "shared"
    write(shared / "helpers.py", WITHIN)  # searched first when a python path
    assert FINDING in run(tmp_path)
    assert FINDING not in same_as_cold(tmp_path, (shared,))
    assert trusted[-1] is False  # another key: nothing taken over
    assert FINDING in same_as_cold(tmp_path)


def test_a_module_added_in_a_python_path_folder(tmp_path: Path) -> None:
    package(tmp_path, "helpers")
    write(tmp_path / "src" / "helpers.py", TOO_HIGH)
    shared = tmp_path / "shared"
    shared.mkdir()
    assert FINDING in run(tmp_path, python_paths=(shared,))
    write(shared / "helpers.py", WITHIN)
    assert FINDING not in same_as_cold(tmp_path, (shared,))


def test_a_symlink_is_kept_with_what_it_reaches(
    tmp_path: Path, trusted: list[bool]
) -> None:
    """A listing that met a symlink is kept, with what the link is (a module, a
    folder, neither), checked when the answers are taken over (it was never
    kept: one link anywhere on a search path and the whole tree's answers were
    worked out again on every run). The link dangles: its folder's stamp is
    unchanged, the answers are not taken over."""
    demo = package(tmp_path, "helpers")
    target = tmp_path / "elsewhere" / "helpers.py"
    write(target, TOO_HIGH)
    os.symlink(target, demo / "helpers.py")
    assert FINDING in run(tmp_path)
    assert FINDING in same_as_cold(tmp_path)
    assert trusted[1] is True
    target.unlink()
    trusted.clear()
    assert FINDING not in same_as_cold(tmp_path)
    assert trusted[0] is False


def test_a_linked_folder_become_a_module_is_seen(
    tmp_path: Path, trusted: list[bool]
) -> None:
    """`helpers` is a link to a folder without `__init__.py` (no module), then
    a link on the way outside the tree points to a file of that name instead:
    `helpers.py` is a link too, a module now (no folder of the tree changed)."""
    demo = package(tmp_path, "helpers")
    outside = tmp_path / "outside"
    write(outside / "a" / "helpers.py" / "readme.txt", "a folder\n")
    write(outside / "b" / "helpers.py", TOO_HIGH)
    os.symlink(outside / "a", outside / "hop")
    os.symlink(outside / "hop" / "helpers.py", demo / "helpers.py")
    assert FINDING not in run(tmp_path)
    assert FINDING not in same_as_cold(tmp_path)
    assert trusted[1] is True
    os.unlink(outside / "hop")
    os.symlink(outside / "b", outside / "hop")
    trusted.clear()
    assert FINDING in same_as_cold(tmp_path)
    assert trusted[0] is False


def test_an_atomic_save_keeps_the_other_answers(tmp_path: Path) -> None:
    """An editor's save through a temporary file and a rename changes the
    folder's stamp: the answers that listed it are worked out again, the others
    are taken over, and the report is the uncached one."""
    demo = package(tmp_path, "helpers")
    write(demo / "helpers.py", TOO_HIGH)
    write(tmp_path / "src" / "other" / "tool.py", "import helpers\nimport os\n")
    assert FINDING in run(tmp_path)
    temporary = demo / ".helpers.py.swp"
    temporary.write_text(WITHIN)
    temporary.replace(demo / "helpers.py")
    assert FINDING not in same_as_cold(tmp_path)


def test_only_the_answers_under_a_changed_folder_are_dropped(tmp_path: Path) -> None:
    write(tmp_path / "a" / "b.py", "")
    write(tmp_path / "c.py", "")
    node = tmp_path / "node.py"
    index = ModuleIndex([tmp_path])
    for name in ("a.b", "a.x", "c", "rclpy"):
        index.find(name, node)
    kept = index.keep()
    time.sleep(0.05)  # past the clock's tick: the folder's stamp changes
    write(tmp_path / "a" / "x.py", "")
    again = ModuleIndex([tmp_path])
    assert again.restore(kept)
    assert set(again._resolved) == {(0, "c"), (0, "rclpy")}
    assert again.find("a.x", node) == tmp_path / "a" / "x.py"
    assert again.find("a.b", node) == tmp_path / "a" / "b.py"
    assert again.find("c", node) == tmp_path / "c.py"
    assert again.find("rclpy", node) is None
    assert "covered" in kept and kept["covered"] == []


def test_a_changed_root_drops_every_answer_of_its_search_paths(
    tmp_path: Path,
) -> None:
    write(tmp_path / "a" / "b.py", "")
    node = tmp_path / "node.py"
    index = ModuleIndex([tmp_path])
    index.find("a.b", node)
    index.find("numpy", node)
    kept = index.keep()
    time.sleep(0.05)
    write(tmp_path / "numpy.py", "")
    again = ModuleIndex([tmp_path])
    assert again.restore(kept)
    assert not again._resolved
    assert again.find("numpy", node) == tmp_path / "numpy.py"


def test_a_deleted_module_is_looked_up_again(tmp_path: Path) -> None:
    write(tmp_path / "a.py", "")
    index = ModuleIndex([tmp_path])
    assert index.find("a", tmp_path / "node.py") == tmp_path / "a.py"
    kept = index.keep()
    assert kept is not None
    fresh = ModuleIndex([tmp_path])
    assert fresh.restore(kept)
    assert fresh.find("a", tmp_path / "node.py") == tmp_path / "a.py"
    time.sleep(0.05)
    (tmp_path / "a.py").unlink()
    again = ModuleIndex([tmp_path])
    again.restore(kept)
    assert not again._resolved
    assert again.find("a", tmp_path / "node.py") is None


@pytest.mark.parametrize(
    "raw",
    [None, [], {"key": "x"}, {"key": None}, "text", {"stamps": {}}],
)
def test_a_foreign_record_is_ignored(tmp_path: Path, raw: object) -> None:
    index = ModuleIndex([tmp_path])
    assert not index.restore(raw)
    write(tmp_path / "a.py", "")
    assert index.find("a", tmp_path / "node.py") == tmp_path / "a.py"


def test_a_malformed_record_with_the_right_key_is_ignored(tmp_path: Path) -> None:
    write(tmp_path / "a.py", "")
    index = ModuleIndex([tmp_path])
    index.find("a", tmp_path / "node.py")
    kept = index.keep()
    assert kept is not None
    for field, bad in [
        ("resolved", [[99, ["a"], [1]]]),
        ("resolved", [[0, ["a"], [5]]]),
        ("resolved", [[0, ["a"], [-1]]]),
        ("resolved", [[0, ["a", "b"], [1]]]),
        ("resolved", [[0, [3], [1]]]),
        ("files", [3]),
        ("ids", {"x": 7}),
        ("probes", [["a"]]),
        ("paths", 3),
        ("stamps", []),
        ("covered", None),
    ]:
        assert not ModuleIndex([tmp_path]).restore({**kept, field: bad}), field


def test_a_probe_answered_by_a_changed_folder_is_checked(tmp_path: Path) -> None:
    """`ws/sub/__init__.py` is probed after `ws/sub` was listed, so its answer is
    kept as the folder's stamp; adding it changes what `y` is for `sub/x.py`."""
    ws = tmp_path / "ws"
    write(ws / "sub" / "y.py", "")
    write(ws / "node.py", "")
    index = ModuleIndex([ws])
    assert index.find("sub.y", ws / "node.py") == ws / "sub" / "y.py"  # lists sub/
    assert index.find("y", ws / "sub" / "x.py") == ws / "sub" / "y.py"
    kept = index.keep()
    assert (
        kept is not None
        and [str(ws / "sub" / "__init__.py"), False, False] in (kept["covered"])
    )
    time.sleep(0.05)
    write(ws / "sub" / "__init__.py", "")  # sub/ is a package: x.py searches ws/
    again = ModuleIndex([ws])
    again.restore(kept)
    cold = ModuleIndex([ws])
    for name, importer in [("y", ws / "sub" / "x.py"), ("sub.y", ws / "node.py")]:
        assert again.find(name, importer) == cold.find(name, importer)
    assert cold.find("y", ws / "sub" / "x.py") is None


# -- the workers' answers (a `-j N` run) --------------------------------------------


def test_the_workers_answers_are_kept(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A run whose files were checked by workers keeps what they resolved and the
    digests of the message types they looked up, so the next (cached) run resolves
    no name and reads no interface file again (the first run after a parallel one
    took 0.51 s on a 235k-line tree, against 0.31 s for the runs after it)."""
    from robotfix import run as run_module
    from robotfix.ros import msg as msg_module  # the catalog reads a file with it

    monkeypatch.setattr(run_module, "MIN_PARALLEL", 1)
    monkeypatch.setattr(run_module, "RACY_NS", 0)  # Cmd.msg is seconds old
    package(tmp_path, "helpers")
    write(tmp_path / "src" / "helpers.py", TOO_HIGH)
    for index in range(4):
        other = tmp_path / "src" / "demo" / "demo" / f"other{index}.py"
        write(other, "import helpers\n")
    config = Config(root=tmp_path)
    cold = check_paths([tmp_path / "src"], config, jobs=2, use_cache=True)
    assert FINDING in cli.render(cold, "concise", 1, 0)
    looked: list[str] = []
    real = ModuleIndex._lookup

    def counted(self: ModuleIndex, roots: tuple[Path, ...], name: str) -> Path | None:
        looked.append(name)
        return real(self, roots, name)

    monkeypatch.setattr(ModuleIndex, "_lookup", counted)
    read: list[object] = []
    real_read = msg_module.read_interface

    def reading(*args: object, **kwargs: object) -> object:
        read.append(args)
        return real_read(*args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(msg_module, "read_interface", reading)
    warm = check_paths([tmp_path / "src"], config, jobs=2, use_cache=True)
    assert warm.from_cache == 7 and looked == []  # driver, __init__, helpers, 4 more
    assert read == []  # the workers' digests of Cmd.msg were kept too
    assert warm.diagnostics == cold.diagnostics


def test_merged_answers_are_those_of_one_index(tmp_path: Path) -> None:
    """`merge` of another index's `fresh` answers gives what one index finding both
    would keep; an answer that differs (the disk changed during the run) keeps
    nothing."""
    write(tmp_path / "a.py", "")
    write(tmp_path / "pkg" / "__init__.py", "")
    write(tmp_path / "pkg" / "b.py", "")
    node = tmp_path / "node.py"
    both = ModuleIndex([tmp_path])
    for name in ("a", "pkg.b", "numpy"):
        both.find(name, node)
    main, worker = ModuleIndex([tmp_path]), ModuleIndex([tmp_path])
    main.find("a", node)
    worker.handed_out()
    worker.find("pkg.b", node)
    worker.find("numpy", node)
    fresh = worker.fresh()
    assert fresh is not None and worker.fresh() is None  # each answer handed once
    main.merge(fresh)
    assert main.keep() is not None and main._resolved == both._resolved

    wrong = dict(fresh, resolved=[(0, "pkg.b", str(tmp_path / "a.py"))])
    main.merge(wrong)
    assert main.keep() is None
