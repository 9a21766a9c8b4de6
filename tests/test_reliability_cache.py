"""The result cache and the machine caches are safe and never stale (issue 12).

Built from the reliability report's reproducers: F5 (writes through planted
symlinks), H6 (FIFOs and devices as cache files), C6 (well-formed entries with wrong
types), W2 (stale after a .msg resolves a type or a duplicate changes), W3 (cached
note paths replayed), W11 (entries never dropped); and round 2's (reliability2.md):
N5 (an empty `.gitignore` after a full disk), N12 (lone surrogates in the cache),
N13 (stale after a rewrite that keeps the size and the mtime).
"""

from __future__ import annotations

import contextlib
import copy
import errno
import io
import json
import os
import shutil
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import robotfix
import robotfix.cache
import robotfix.discovery
import robotfix.project.modules
import robotfix.run
from robotfix import cli
from robotfix.api import InternalError, check_paths, interface_files
from robotfix.cache import GITIGNORE, ResultCache
from robotfix.config import Config
from robotfix.ros.catalog import MsgCatalog
from robotfix.run import FileResult

NODE = (
    "from pkg_a.msg import Outer\n"
    "\n"
    "def send(pub) -> None:\n"
    "    o = Outer()\n"
    "    o.inner.x = 5.0\n"
    "    pub.publish(o)\n"
)
CMD_NODE = (
    "from demo.msg import Cmd\n"
    "\n"
    "def send(pub) -> None:\n"
    "    c = Cmd()\n"
    "    c.speed = 3\n"
    "    pub.publish(c)\n"
)
UNIT_NODE = (
    "from typing import Annotated\n"
    "from demo.msg import Cmd\n"
    "\n"
    "def send(pub, v: Annotated[float, \"Unit('km/h')\"]) -> None:\n"
    "    c = Cmd()\n"
    "    c.speed = v\n"
    "    c.speed = 3.0\n"
    "    pub.publish(c)\n"
)
FORMATS = ("text", "concise", "json", "sarif", "github")


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


def package(root: Path, name: str) -> Path:
    return write(root / name / "package.xml", f"<package><name>{name}</name></package>")


def check(capsys: pytest.CaptureFixture[str], *args: str, fmt: str = "text") -> str:
    """The stdout of `robotfix check <args>`, in-process (cwd set by the caller)."""
    capsys.readouterr()
    cli.main(["check", *args, "--format", fmt, "-j", "1"])
    out = capsys.readouterr().out
    if fmt == "json":  # everything but the timing
        data = json.loads(out)
        del data["summary"]["seconds"]
        return json.dumps(data, sort_keys=True)
    return out


def same_cached_and_uncached(capsys: pytest.CaptureFixture[str], *args: str) -> str:
    """Runs uncached, cached (twice: filling, then reusing) in every format; asserts
    every output equals the uncached one and returns the text output."""
    for fmt in FORMATS:
        fresh = check(capsys, *args, "--no-cache", fmt=fmt)
        assert check(capsys, *args, fmt=fmt) == fresh, fmt
        assert check(capsys, *args, fmt=fmt) == fresh, fmt
    return check(capsys, *args, "--no-cache")


def entries(root: Path) -> dict[str, Any]:
    data = json.loads((root / ".robotfix_cache" / "results.json").read_text())
    found: dict[str, Any] = data["entries"]
    return found


@contextlib.contextmanager
def stamps_trusted() -> Iterator[None]:
    """Every stamp trusted at once (`fs.RACY_NS` 0 wherever it is read): a test's
    files are seconds old, and what the cache keeps must not depend on the clock
    (every edit below comes a whole run after the stamp it changes)."""
    with pytest.MonkeyPatch.context() as patch:
        for module in (
            robotfix.cache,
            robotfix.run,
            robotfix.discovery,
            robotfix.project.modules,
        ):
            patch.setattr(module, "RACY_NS", 0)
        yield


@pytest.fixture
def project(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    write(tmp_path / "pyproject.toml", "")
    monkeypatch.chdir(tmp_path)
    yield tmp_path


# -- W2: a cached result is keyed by resolved definitions ----------------------------
def test_a_msg_that_resolves_a_missing_field_type_rechecks_its_users(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    package(project, "pkg_a")
    package(project, "pkg_b")
    write(project / "pkg_a" / "msg" / "Outer.msg", "Inner inner\n")
    write(project / "pkg_a" / "node.py", NODE)
    assert "RF101" not in check(capsys, ".")
    write(project / "pkg_b" / "msg" / "Inner.msg", "float64 x #RobotFix# _ < 1\n")
    cached = check(capsys, ".")
    assert "pkg_a/node.py:5:5: error[RF101]" in cached
    assert cached == check(capsys, ".", "--no-cache")


def test_a_change_to_either_copy_of_a_duplicated_type_rechecks(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    write(project / "node.py", CMD_NODE)
    for side in ("a", "b"):
        write(project / side / "demo" / "msg" / "Cmd.msg", "int32 speed\n")
    flags = ("node.py", "--msg-path", "a", "--msg-path", "b")
    assert "RF101" not in check(capsys, *flags)
    write(project / "a" / "demo" / "msg" / "Cmd.msg", "int32 speed #RobotFix# _ < 1\n")
    cached = check(capsys, *flags)
    assert "node.py:5:5: error[RF101]" in cached
    assert cached == check(capsys, *flags, "--no-cache")


def test_fingerprint_covers_field_types_transitively_and_missing_types(
    tmp_path: Path,
) -> None:
    msgs = tmp_path / "msgs"
    write(msgs / "p" / "msg" / "Outer.msg", "Mid mid\n")
    write(msgs / "p" / "msg" / "Mid.msg", "Inner inner\n")

    def fingerprint(*names: str) -> str:
        return MsgCatalog(interface_files([msgs])).fingerprint_types(list(names))

    missing = fingerprint("p/Outer", "q/Absent")
    write(msgs / "p" / "msg" / "Inner.msg", "float64 x\n")
    plain = fingerprint("p/Outer", "q/Absent")
    assert plain != missing  # Mid's field now resolves
    write(msgs / "p" / "msg" / "Inner.msg", "float64 x #RobotFix# _ < 1\n")
    refined = fingerprint("p/Outer", "q/Absent")
    assert refined != plain  # two levels down
    write(msgs / "q" / "msg" / "Absent.msg", "int8 y\n")
    assert fingerprint("p/Outer", "q/Absent") != refined  # no longer missing
    assert fingerprint("p/Outer", "q/Absent") == fingerprint("q/Absent", "p/Outer")


def test_fingerprint_is_the_same_in_every_process(tmp_path: Path) -> None:
    msgs = tmp_path / "msgs"
    write(
        msgs / "p" / "msg" / "Pose.msg",
        'float64 x #RobotFix# Unit(x) == "m" and _ < 10\n'
        "float64 y #RobotFix# 0 <= _ + x <= x * 3\n",
    )
    code = (
        "import sys\nfrom pathlib import Path\n"
        "from robotfix.api import interface_files\n"
        "from robotfix.ros.catalog import MsgCatalog\n"
        "catalog = MsgCatalog(interface_files([Path(sys.argv[1])]))\n"
        "print(catalog.fingerprint_types(['p/Pose', 'geometry_msgs/Twist']))\n"
    )
    prints = {
        subprocess.run(
            [sys.executable, "-c", code, str(msgs)],
            env={**os.environ, "PYTHONHASHSEED": seed},
            capture_output=True,
            text=True,
            timeout=120,
            check=True,
        ).stdout
        for seed in ("0", "1", "4242")
    }
    assert len(prints) == 1


# -- W3: cached output is uncached output, byte for byte -----------------------------
def test_cached_notes_follow_the_msg_path_spelling_and_moves(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    write(project / "src" / "node.py", UNIT_NODE)
    write(
        project / "ifaces" / "demo" / "msg" / "Cmd.msg",
        'float64 speed #RobotFix# Unit(speed) == "m/s" and _ < 1\n',
    )
    relative = same_cached_and_uncached(capsys, "src/node.py", "--msg-path", "ifaces")
    assert "--> ifaces/demo/msg/Cmd.msg:1" in relative
    spelled = str(project / "ifaces")
    absolute = same_cached_and_uncached(capsys, "src/node.py", "--msg-path", spelled)
    assert f"--> {project}/ifaces/demo/msg/Cmd.msg:1" in absolute
    shutil.move(project / "ifaces", project / "interfaces")
    moved = same_cached_and_uncached(capsys, "src/node.py", "--msg-path", "interfaces")
    assert "ifaces/" not in moved and "--> interfaces/demo/msg/Cmd.msg:1" in moved


def test_cached_output_follows_the_spelling_of_the_checked_file(
    project: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    write(project / "src" / "node.py", UNIT_NODE)
    write(
        project / "ifaces" / "demo" / "msg" / "Cmd.msg",
        "float64 speed #RobotFix# _ < 1\n",
    )
    msg = ("--msg-path", str(project / "ifaces"))
    assert "src/node.py:7:5" in same_cached_and_uncached(capsys, "src/node.py", *msg)
    absolute = str(project / "src" / "node.py")
    assert f"{absolute}:7:5" in same_cached_and_uncached(capsys, absolute, *msg)
    monkeypatch.chdir(project / "src")
    inside = same_cached_and_uncached(capsys, "node.py", *msg)
    assert inside.startswith("node.py:") and "\nnode.py:7:5: error[RF101]" in inside
    assert list(entries(project)) == [absolute]  # one entry, whatever the spelling


# -- W11: entries of files that are gone are dropped ---------------------------------
def test_the_cache_forgets_files_that_are_gone(project: Path) -> None:
    config = Config(root=project)
    outside = write(project.parent / f"{project.name}-other.py", "y = 2\n")
    check_paths([outside], config, use_cache=True)
    for generation in range(3):
        for old in project.glob("gen*.py"):
            old.unlink()
        names = {f"gen{generation}_{i}.py" for i in range(5)}
        for name in names:
            write(project / name, "x = 1\n")
        result = check_paths([project], config, use_cache=True)
        assert result.from_cache == 0
        assert {Path(k).name for k in entries(project)} == names | {outside.name}
    excluded = Config(root=project, exclude=("gen2_0.py",))
    check_paths([project], excluded, use_cache=True)
    assert f"{project}/gen2_0.py" not in entries(project)  # not part of the run
    outside.unlink()  # outside the checked paths: dropped once it no longer exists
    check_paths([project / "gen2_1.py"], config, use_cache=True)
    assert sorted(Path(k).name for k in entries(project)) == sorted(
        names - {"gen2_0.py"}
    )


# -- C6: a well-formed cache with wrong types is ignored and rebuilt -----------------
def leaves(value: Any, at: tuple[Any, ...] = ()) -> Iterator[tuple[Any, ...]]:
    yield at
    if isinstance(value, dict):
        for key, item in value.items():
            yield from leaves(item, (*at, key))
    elif isinstance(value, list):
        for index, item in enumerate(value):
            yield from leaves(item, (*at, index))


WRONG = [None, 0, 7, -1, True, 1.5, "x", "RF999", [], [1, 2], {}, {"a": 1}]


def json_type(value: Any) -> str:
    return "bool" if isinstance(value, bool) else type(value).__name__


@pytest.fixture(scope="module")
def filled(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, dict[str, Any]]:
    root = tmp_path_factory.mktemp("c6")
    write(root / "pyproject.toml", "")
    write(root / "src" / "node.py", UNIT_NODE)
    write(
        root / "ifaces" / "demo" / "msg" / "Cmd.msg", "float64 speed #RobotFix# _ < 1\n"
    )
    config = Config(root=root, msg_paths=(root / "ifaces",))
    with stamps_trusted():
        for _ in range(2):  # the second after `.robotfix_cache/` changed the root
            check_paths([root / "src"], config, use_cache=True)
    data = json.loads((root / ".robotfix_cache" / "results.json").read_text())
    (entry,) = data["entries"].values()
    assert entry["diagnostics"] and entry["diagnostics"][0][4]  # some notes to break
    return root, data


@settings(
    max_examples=40,
    deadline=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture],
)
@given(st.data())
def test_an_entry_with_wrong_types_is_rebuilt_never_a_crash(
    filled: tuple[Path, dict[str, Any]], data: st.DataObject
) -> None:
    root, pristine = filled
    (name,) = pristine["entries"]
    paths = sorted(leaves(pristine["entries"][name]))[1:]  # not the entry itself
    at = data.draw(st.sampled_from(paths))
    broken = copy.deepcopy(pristine)
    parent = broken["entries"][name]
    for step in at[:-1]:
        parent = parent[step]
    old = parent[at[-1]]
    new = data.draw(
        st.sampled_from([w for w in WRONG if json_type(w) != json_type(old)])
    )
    parent[at[-1]] = new
    cache = root / ".robotfix_cache" / "results.json"
    cache.write_text(json.dumps(broken))
    config = Config(root=root, msg_paths=(root / "ifaces",))
    with stamps_trusted():  # no part kept or not by the clock: all compared
        result = check_paths([root / "src"], config, use_cache=True)
    assert result.from_cache == 0  # rebuilt
    for fmt in FORMATS:
        cli.render(result, fmt, 1, 0)  # every renderer copes
    assert json.loads(cache.read_text()) == pristine


@pytest.mark.parametrize(
    "content",
    [
        "[]",
        '{"key": 1}',
        '{"entries": [], "key": "%s"}',
        '{"entries": {"/x.py": 5}, "key": "%s"}',
        "[" * 100_000 + "]" * 100_000,
        '{"key": "%s", "entries": {"/x.py": {"file": ' + "9" * 5000 + "}}}",
    ],
)
def test_a_foreign_or_ill_shaped_results_file_is_ignored(
    project: Path, content: str
) -> None:
    from robotfix.cache import run_key

    config = Config(root=project)
    write(project / "a.py", "x = 1\n")
    cache = write(project / ".robotfix_cache" / "results.json", "")
    cache.write_text(
        content.replace("%s", run_key(config)) if "%s" in content else content
    )
    assert check_paths([project], config, use_cache=True).from_cache == 0
    assert check_paths([project], config, use_cache=True).from_cache == 1


# -- F5: never written through a symlink, temp files are exclusive -------------------
def test_planted_symlinks_in_the_cache_folder_are_never_written_through(
    project: Path,
) -> None:
    victim = write(project.parent / f"{project.name}-victim.txt", "precious\n")
    created = project.parent / f"{project.name}-created.txt"
    folder = project / ".robotfix_cache"
    folder.mkdir()
    (folder / ".gitignore").symlink_to(created)  # dangling
    (folder / "results.json").symlink_to(victim)
    pid = os.getpid()
    for guess in ["results", ".results.json", "results.json"]:
        for n in range(pid - 50, pid + 50):
            (folder / f"{guess}.{n}.tmp").symlink_to(victim)
    write(project / "a.py", "x = 1\n")
    config = Config(root=project)
    check_paths([project], config, use_cache=True)
    assert victim.read_text() == "precious\n"
    assert not created.exists()
    assert (folder / "results.json").is_file() and not (
        folder / "results.json"
    ).is_symlink()
    assert check_paths([project], config, use_cache=True).from_cache == 1


def test_the_cache_folder_gets_a_gitignore_and_no_leftover_temp_files(
    project: Path,
) -> None:
    write(project / "a.py", "x = 1\n")
    check_paths([project], Config(root=project), use_cache=True)
    folder = project / ".robotfix_cache"
    assert (folder / ".gitignore").read_text() == "# Created by robotfix\n*\n"
    assert sorted(p.name for p in folder.iterdir()) == [".gitignore", "results.json"]


def test_a_cache_folder_that_cannot_be_made_only_costs_speed(project: Path) -> None:
    write(project / ".robotfix_cache", "a file, not a folder\n")
    write(
        project / "a.py",
        'from typing import Annotated\nx: Annotated[int, "_ < 1"] = 1\n',
    )
    for _ in range(2):
        result = check_paths([project], Config(root=project), use_cache=True)
        assert result.from_cache == 0 and [d.code for d in result.diagnostics] == [
            "RF101"
        ]


def test_processes_sharing_one_cache_leave_it_whole(project: Path) -> None:
    config = Config(root=project)
    for i in range(4):
        write(project / f"f{i}.py", "x = 1\n")
    check_paths([project], config, use_cache=True)
    first = ResultCache(project / ".robotfix_cache", "k")
    second = ResultCache(project / ".robotfix_cache", "k")
    catalog = MsgCatalog([])
    for cache, name in ((first, "f0.py"), (second, "f1.py")):
        cache.put(
            project / name, b"x = 1\n", config, [], [], catalog.fingerprint_types([])
        )
    first.save()
    second.save()  # the last writer wins; entries lost only cost speed
    assert list(entries(project)) == [str(project / "f1.py")]
    assert check_paths([project], config, use_cache=True).from_cache == 0
    assert check_paths([project], config, use_cache=True).from_cache == 4


# -- H6: FIFOs and devices as cache files are ignored, never waited on --------------
@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs FIFOs")
def test_fifos_and_devices_as_cache_files_never_hang(tmp_path: Path) -> None:
    root = tmp_path / "proj"
    write(root / "pyproject.toml", "")
    write(root / "node.py", UNIT_NODE.replace("from demo.msg import Cmd\n", ""))
    folder = root / ".robotfix_cache"
    folder.mkdir()
    os.mkfifo(folder / "results.json")
    machine = tmp_path / "machine"
    machine.mkdir()
    os.mkfifo(machine / "units.json")
    (machine / "ros-messages-ros2.json").symlink_to("/dev/zero")
    env = {**os.environ, "ROBOTFIX_CACHE_DIR": str(machine)}
    env["PYTHONPATH"] = str(Path(robotfix.__file__).parent.parent)  # this robotfix
    run = subprocess.run(
        [sys.executable, "-m", "robotfix", "check", "."],
        cwd=root,
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert run.returncode in (0, 1), run.stderr
    assert "Traceback" not in run.stderr
    assert run.stdout.rstrip().endswith("in 1 file.")
    (folder / "results.json").unlink()
    (folder / "results.json").symlink_to("/dev/zero")
    again = subprocess.run(
        [sys.executable, "-m", "robotfix", "check", "."],
        cwd=root,
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert again.stdout == run.stdout


# -- N13: a rewrite that keeps the size and the mtime is seen (the ctime) ------------
HELPER = """\
from typing import Annotated


def h(v: Annotated[float, "_ < 1.9"]) -> None:
    pass
"""


def rewrite_keeping_mtime(path: Path, old: str, new: str) -> None:
    """`path` rewritten in place, same size, its mtime put back (as `cp -p`,
    `rsync --inplace -t` and archives with fixed mtimes leave a file)."""
    before = os.stat(path)
    text = path.read_text()
    assert len(old) == len(new) and old in text
    path.write_text(text.replace(old, new))
    os.utime(path, ns=(before.st_atime_ns, before.st_mtime_ns))
    after = os.stat(path)
    assert (after.st_size, after.st_mtime_ns, after.st_ino, after.st_dev) == (
        before.st_size,
        before.st_mtime_ns,
        before.st_ino,
        before.st_dev,
    )
    assert after.st_ctime_ns != before.st_ctime_ns  # a whole run came between


def test_a_rewrite_keeping_size_and_mtime_rechecks_the_file_and_importers(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    write(project / "pkg" / "helper.py", HELPER)
    user = write(project / "pkg" / "user.py", "from pkg.helper import h\n\nh(1.5)\n")
    with stamps_trusted():  # as a tree untouched for RACY_NS: its stats trusted
        assert check(capsys, ".") == check(capsys, ".", "--no-cache")
        assert "RF101" not in check(capsys, ".")
        rewrite_keeping_mtime(user, "h(1.5)", "h(9.5)")
        cached = check(capsys, ".")
        assert "user.py:3:1: error[RF101]: `h(9.5)` violates `v < 1.9`" in cached
        assert cached == check(capsys, ".", "--no-cache")
        rewrite_keeping_mtime(user, "h(9.5)", "h(1.5)")
        assert "RF101" not in check(capsys, ".")
        rewrite_keeping_mtime(project / "pkg" / "helper.py", "_ < 1.9", "_ < 1.4")
        cached = check(capsys, ".")  # the importer is checked again
        assert "user.py:3:1: error[RF101]: `h(1.5)` violates `v < 1.4`" in cached
        assert cached == check(capsys, ".", "--no-cache")


# -- N12: no string in the cache can fail a run ----------------------------------------
DRIVER = """\
from geometry_msgs.msg import Twist
from rclpy.node import Node

from demo.limits import clamp
from demo.msg import Cmd


class Driver(Node):
    def __init__(self) -> None:
        super().__init__("driver")
        self.declare_parameter("rate", 10.0)
        self.pub = self.create_publisher(Cmd, "cmd", 10)

    def tick(self) -> None:
        c = Cmd()
        c.speed = clamp(1.5)
        t = Twist()
        t.linear.x = 1.0
        self.pub.publish(c)
"""
LIMITS = """\
from typing import Annotated

MAX = 3.0


def clamp(x: float) -> Annotated[float, "_ <= MAX"]:
    return min(x, MAX)
"""


@pytest.fixture(scope="module")
def every_section(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A tree whose cache has every part: entries, summaries, stats, parameter
    files, the catalog (digests, problems, outline), discovery and resolution."""
    root = tmp_path_factory.mktemp("n12")
    write(root / "pyproject.toml", "")
    demo = root / "src" / "demo"
    package(root / "src", "demo")
    write(demo / "msg" / "Cmd.msg", "float64 speed  # [m/s]\n#RobotFix# speed <= 2.0\n")
    write(demo / "msg" / "Bad.msg", "float64 x\nnot a field line\n")
    write(demo / "demo" / "__init__.py", "")
    write(demo / "demo" / "limits.py", LIMITS)
    write(demo / "demo" / "driver.py", DRIVER)
    write(demo / "config" / "driver.yaml", "driver:\n  ros__parameters:\n    rate: x\n")
    return root


BYTE_FF = chr(0xDCFF)  # the byte 0xFF of a non-UTF-8 name, as os.fsdecode gives it
NEVER_A_NAME = chr(0xD800)  # a lone surrogate no file name decodes to


def report(root: Path, cache: bool = True) -> tuple[str, int]:
    """The concise report of a run over `root` (no internal error) and the number
    of results that came from the cache."""
    result = check_paths([root / "src"], Config(root=root), use_cache=cache)
    assert not result.internal_errors, result.internal_errors[0].detail
    return cli.render(result, "concise", 1, 0), result.from_cache


def strings(value: Any, at: tuple[Any, ...] = ()) -> Iterator[tuple[Any, ...]]:
    """Where each string is, a key of a dict too (its place ends with ("key", k))."""
    if isinstance(value, dict):
        for key, item in value.items():
            yield (*at, ("key", key))
            yield from strings(item, (*at, key))
    elif isinstance(value, list):
        for index, item in enumerate(value):
            yield from strings(item, (*at, index))
    elif isinstance(value, str):
        yield at


def put(data: Any, at: tuple[Any, ...], value: str) -> Any:
    """A copy of `data` with `value` at `at` (a key renamed when `at` is a key)."""
    changed = copy.deepcopy(data)
    parent = changed
    for step in at[:-1]:
        parent = parent[step]
    if isinstance(at[-1], tuple):
        parent[value] = parent.pop(at[-1][1])
    else:
        parent[at[-1]] = value
    return changed


def test_lone_surrogates_anywhere_in_the_cache_are_a_rebuild_never_a_crash(
    every_section: Path,
) -> None:
    """N12: each string of `results.json` in turn (keys too, a spread of each part)
    made a lone surrogate, valid JSON: the run is the uncached run. Text RobotFix
    makes (digests, fingerprints, type and module names, codes) takes "\\udcff",
    the report's; a path or a message, which may hold "\\udcff" as the byte 0xFF of
    a non-UTF-8 file name, takes "\\ud800", which no file name decodes to."""
    root = every_section
    with stamps_trusted():
        fresh, _ = report(root, cache=False)
        report(root)
        assert report(root) == (fresh, 3)  # every part of the cache in use
        results = root / ".robotfix_cache" / "results.json"
        pristine = json.loads(results.read_text())
        assert all(pristine[part] for part in ("params", "catalog", "discovery"))
        places = list(strings(pristine))
        spread = []
        for part in pristine:
            mine = [at for at in places if at[0] == part or at[0] == ("key", part)]
            step = max(1, len(mine) // 20)
            spread += mine[::step]
        spread.append(("catalog", "digests", "geometry_msgs/Twist", 0))  # the report's
        try:
            for at in spread:
                parent = pristine
                for step in at[:-1]:
                    parent = parent[step]
                old = at[-1][1] if isinstance(at[-1], tuple) else parent[at[-1]]
                quoted = old.startswith(str(root)) or " " in old  # path or message
                broken = put(pristine, at, NEVER_A_NAME if quoted else BYTE_FF)
                results.write_text(json.dumps(broken))
                assert report(root)[0] == fresh, at
        finally:  # the next test finds the cache whole
            results.write_text(json.dumps(pristine))


@pytest.mark.parametrize(
    "bad",
    [
        5,
        [],
        ["unit", [["meter", BYTE_FF], ["second", -1]], 0.2777777777777778, 0.0],
        ["unit", [["meter", 1], ["second", -1]], 0, 0.0],
        ["unit", [[BYTE_FF, 1], ["second", -1]], 0.2777777777777778, 0.0],
        ["error", BYTE_FF],
        ["tag", "x"],
        ["what"],
    ],
)
def test_a_bad_entry_of_the_units_cache_is_worked_out_again(
    bad: Any, monkeypatch: pytest.MonkeyPatch
) -> None:
    """N12 in the machine cache (`units-*.json`): an entry that is not what the
    resolution writes is ignored, never a failed check."""
    from robotfix.annotations import units

    monkeypatch.setattr(units._CACHE, "_entries", {})
    monkeypatch.setattr(units._CACHE, "_dirty", False)  # nothing saved from here
    right = units.resolve("km/h")
    units._CACHE.entries["km/h"] = bad
    assert units.resolve("km/h") == right


def test_a_check_that_fails_with_the_cache_is_done_again_without_it(
    every_section: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A state of the cache no validation foresaw that fails a check (here, any
    project that took summaries from the cache): the file is checked again with
    nothing of the cache, and the cache is dropped, then rebuilt."""
    root = every_section
    with stamps_trusted():
        fresh, _ = report(root, cache=False)
        report(root)
        limits = root / "src" / "demo" / "demo" / "limits.py"
        write(limits, LIMITS + "\n")  # checked again, with the cached summaries
        real = robotfix.run._check_one

        def fails_with_the_cache(
            path: Path, data: Any, catalog: Any, config: Any, project: Any
        ) -> Any:
            if project.known:  # as `_check_one` reports a fault of ours
                fault = "RuntimeError: a state of the cache no check foresaw"
                return FileResult(str(path), [], InternalError(str(path), fault, ""))
            return real(path, data, catalog, config, project)

        with monkeypatch.context() as patch:
            patch.setattr(robotfix.run, "_check_one", fails_with_the_cache)
            assert report(root) == (fresh, 2)
        assert entries(root) == {}  # dropped
        assert report(root) == (fresh, 0)
        assert report(root) == (fresh, 3)


def test_a_run_that_fails_reading_the_cache_is_done_again_without_it(
    every_section: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    root = every_section
    with stamps_trusted():
        fresh, _ = report(root, cache=False)
        report(root)
        real = ResultCache.resolution

        def fails_when_read(self: ResultCache) -> Any:
            if self._resolution is not None:  # read from the file
                raise RuntimeError("a state of the cache no check foresaw")
            return real(self)

        with monkeypatch.context() as patch:
            patch.setattr(ResultCache, "resolution", fails_when_read)
            assert report(root) == (fresh, 0)
        assert report(root) == (fresh, 3)


# -- N5: a full disk leaves no empty .gitignore ---------------------------------------
class FullFile(io.RawIOBase):
    """A file on a full disk: every write fails with ENOSPC."""

    def __init__(self, fd: int) -> None:
        self.fd = fd

    def writable(self) -> bool:
        return True

    def write(self, data: Any) -> int:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    def close(self) -> None:
        if not self.closed:
            os.close(self.fd)
        super().close()


def test_a_full_disk_leaves_no_empty_gitignore(
    project: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    write(project / "a.py", "x = 1\n")
    config = Config(root=project)
    gitignore = project / ".robotfix_cache" / ".gitignore"

    def full(fd: int, *args: Any, **kwargs: Any) -> Any:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    with monkeypatch.context() as disk:
        disk.setattr(os, "write", full)
        disk.setattr(os, "fdopen", lambda fd, *args, **kwargs: FullFile(fd))
        check_paths([project], config, use_cache=True)
    assert not gitignore.exists()  # neither empty nor cut
    check_paths([project], config, use_cache=True)  # space again
    assert gitignore.read_bytes() == GITIGNORE
    assert check_paths([project], config, use_cache=True).from_cache == 1
