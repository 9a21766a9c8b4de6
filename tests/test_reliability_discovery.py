"""Discovery, configuration and the run never hang, crash or skip silently
(issue 12: C3 C4 C5 H5 H6 H8 W1 W6 F6; issue 11 item 1, its discovery parts)."""

from __future__ import annotations

import concurrent.futures
import errno
import multiprocessing
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix import config as config_module
from robotfix import discovery, run
from robotfix.api import Result, check_paths
from robotfix.config import Config, ConfigError, matches
from robotfix.ros.msg import read_interface
from tests.test_cli import run as cli

BUGGY = 'from typing import Annotated\ntimeout: Annotated[int, "_ < 200"] = 200\n'
SECRET = "FAKE_CI_TOKEN=ghp_SECRET0123456789\n"
EXAMPLE = Path(__file__).parent.parent / "examples" / "safety_stop"
posix = pytest.mark.skipif(os.name != "posix", reason="symlinks and FIFOs")


def check(root: Path, *paths: Path, **overrides: Any) -> Result:
    return check_paths(list(paths or [root]), Config(root=root, **overrides))


def codes(result: Result) -> list[tuple[str, str]]:
    return [(d.path, d.code) for d in result.diagnostics]


# -- C3: pyproject.toml --------------------------------------------------------


@pytest.mark.parametrize("tool", ['"x"', "5", "[1, 2]", "true"])
def test_a_non_table_tool_is_a_clean_config_error(tmp_path: Path, tool: str) -> None:
    (tmp_path / "pyproject.toml").write_text(f"tool = {tool}\n")
    with pytest.raises(ConfigError, match="`tool` must be a table"):
        config_module.load(tmp_path)


def test_deeply_nested_toml_is_a_clean_config_error(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text("x = " + "[" * 5000 + "]" * 5000 + "\n")
    with pytest.raises(ConfigError, match="nested too deeply"):
        config_module.load(tmp_path)


def test_config_errors_exit_2_with_one_line(tmp_path: Path) -> None:
    (tmp_path / "a.py").write_text("x = 1\n")
    (tmp_path / "pyproject.toml").write_text('tool = "x"\n')
    result = cli("check", ".", "--no-cache", cwd=tmp_path)
    assert result.returncode == 2
    assert result.stderr.startswith("robotfix: error: ")
    assert "Traceback" not in result.stderr
    (tmp_path / "pyproject.toml").write_text("[tool.robotfix]\nmsg-paths = 7\n")
    result = cli("check", ".", "--no-cache", cwd=tmp_path)
    assert result.returncode == 2 and "Traceback" not in result.stderr


@posix
def test_a_fifo_pyproject_is_not_read(tmp_path: Path) -> None:
    os.mkfifo(tmp_path / "pyproject.toml")
    assert config_module.load(tmp_path) == Config()  # found no file: defaults


# -- H5: exclude / per-file-ignores matching ------------------------------------


def _regex_matches(pattern: str, relative: str) -> bool:
    """The former regex translation: the meaning realistic patterns keep."""
    import fnmatch

    pattern = pattern.strip()
    directory = pattern.endswith("/")
    pattern = pattern.strip("/")
    parts = relative.split("/")
    candidates = ["/".join(parts[: i + 1]) for i in range(len(parts))]
    if directory:
        candidates = candidates[:-1] if len(candidates) > 1 else []
    if "/" not in pattern:
        return any(
            fnmatch.fnmatchcase(c.rsplit("/", 1)[-1], pattern) for c in candidates
        )
    regex = re.escape(pattern).replace(r"\*\*/", "(?:.*/)?").replace(r"\*\*", ".*")
    regex = regex.replace(r"\*", "[^/]*").replace(r"\?", "[^/]")
    return any(re.fullmatch(regex, c) for c in candidates)


SEGMENT = st.sampled_from(["a", "b", "ab", "*", "a*", "?", "*b", "x?z"])
PATTERN_SEGMENT = st.one_of(SEGMENT, st.just("**"))


@settings(max_examples=300, deadline=None)
@given(
    pattern=st.lists(PATTERN_SEGMENT, min_size=1, max_size=4),
    trailing=st.booleans(),
    leading=st.booleans(),
    path=st.lists(
        st.sampled_from(["a", "b", "ab", "xyz", "a.py"]), min_size=1, max_size=5
    ),
)
def test_matching_keeps_the_meaning_of_realistic_patterns(
    pattern: list[str], trailing: bool, leading: bool, path: list[str]
) -> None:
    text = ("/" if leading else "") + "/".join(pattern) + ("/" if trailing else "")
    relative = "/".join(path)
    assert matches(text, relative) == _regex_matches(text, relative), (text, relative)


@pytest.mark.parametrize(
    ("pattern", "relative", "expected"),
    [
        ("gen/", "gen/c.py", True),
        ("gen/", "gen", False),
        ("build", "src/build/x.py", True),
        ("legacy_*.py", "a/legacy_x.py", True),
        ("tests/**", "tests/a/b.py", True),
        ("tests/**", "tests", False),
        ("**/test/**/fixtures/**/data/**/*.py", "x/test/y/fixtures/data/z/q.py", True),
        ("**/test/**/fixtures/**/data/**/*.py", "x/test/y/fixtures/z/q.py", False),
        ("/a/b", "a/b/c.py", True),
        ("a/**/b", "a/b", True),
        ("a/**/b", "a/x/y/b", True),
    ],
)
def test_matching_examples(pattern: str, relative: str, expected: bool) -> None:
    assert matches(pattern, relative) is expected


def test_repeated_double_stars_cannot_backtrack() -> None:
    deep = "/".join(["d"] * 40) + "/file.py"
    assert not matches("**/" * 30 + "zzz", deep)
    assert not matches("**/**/**/**/**/**/**/**/zzz", deep)
    assert not matches("a/" + "**a" * 30 + "b", "a/" + "a" * 60)
    assert matches("**/" * 30 + "file.py", deep)
    assert matches("**/" * 30 + "d/**/" * 10 + "*.py", deep)


def test_a_folder_pattern_matches_the_folder_itself() -> None:
    assert matches("gen/", "gen", folder=True)
    assert matches("gen", "a/gen", folder=True)
    assert not matches("gen/*.py", "gen", folder=True)


# -- W1 and issue 11: the package's name and resolved paths -----------------------


def test_a_package_is_named_by_package_xml(tmp_path: Path) -> None:
    folder = tmp_path / "checkout-2" / "msg"
    folder.mkdir(parents=True)
    (tmp_path / "checkout-2" / "package.xml").write_text(
        '<?xml version="1.0"?>\n<package format="3">\n  <name> real_pkg </name>\n'
        "</package>\n"
    )
    parsed = read_interface(folder / "Cmd.msg", "float64 speed\n")
    assert parsed.sections[0].name == "real_pkg/Cmd"


@pytest.mark.parametrize(
    "xml",
    [
        "this is not xml <",
        "<package><name>has space</name></package>",
        "<manifest><name>other</name></manifest>",
        "<package></package>",
        '<!DOCTYPE p [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;&a;">]>'
        "<package><name>&b;</name></package>",
    ],
)
def test_an_unusable_package_xml_falls_back_to_the_folder(
    tmp_path: Path, xml: str
) -> None:
    (tmp_path / "my_pkg" / "msg").mkdir(parents=True)
    (tmp_path / "my_pkg" / "package.xml").write_text(xml)
    parsed = read_interface(tmp_path / "my_pkg" / "msg" / "Cmd.msg", "float64 v\n")
    assert parsed.sections[0].name == "my_pkg/Cmd"


@pytest.fixture
def example(tmp_path: Path) -> Path:
    copy = tmp_path / "checkout"  # not the package's name
    shutil.copytree(EXAMPLE, copy)
    return copy


def test_checking_dot_inside_a_package_finds_its_bug(example: Path) -> None:
    result = cli("check", ".", "--no-cache", cwd=example)
    assert result.returncode == 1
    assert "safety_stop/node.py:26:13: error[RF201]" in result.stdout
    assert "unknown/" not in result.stdout


def test_one_file_inside_a_package_finds_its_interfaces(example: Path) -> None:
    result = cli("check", "node.py", "--no-cache", cwd=example / "safety_stop")
    assert result.returncode == 1
    assert "node.py:26:13: error[RF201]" in result.stdout
    assert "--> ../msg/DriveCommand.msg:3" in result.stdout
    inside = cli("check", ".", "--no-cache", cwd=example / "safety_stop")
    assert "node.py:26:13: error[RF201]" in inside.stdout


def test_a_missing_msg_path_is_a_usage_error(tmp_path: Path) -> None:
    (tmp_path / "a.py").write_text("x = 1\n")
    result = cli("check", "a.py", "--msg-path", "does/not/exist", cwd=tmp_path)
    assert result.returncode == 2
    assert result.stderr == (
        "robotfix: error: --msg-path does/not/exist: no such file or directory\n"
    )
    (tmp_path / "pyproject.toml").write_text('[tool.robotfix]\nmsg-paths = ["gone"]\n')
    result = cli("check", "a.py", cwd=tmp_path)
    assert result.returncode == 2 and "msg-paths" in result.stderr


def test_nothing_checked_is_said(tmp_path: Path) -> None:
    (tmp_path / "empty").mkdir()
    result = cli("check", "empty", "--no-cache", cwd=tmp_path)
    assert result.returncode == 0
    assert "No problems found in 0 files" not in result.stdout
    assert "No Python files were found to check." in result.stdout
    assert "no Python files found in empty" in result.stderr


# -- W6 / F6: symlinks, roots, each file once ------------------------------------------


def test_overlapping_paths_check_each_file_once(tmp_path: Path) -> None:
    folder = tmp_path / "dir"
    folder.mkdir()
    (folder / "x.py").write_text(BUGGY)
    result = cli(
        "check", str(folder), str(folder / "x.py"), "../dir", "--no-cache", cwd=folder
    )
    assert result.stdout.count("error[RF101]") == 1
    assert result.stdout.rstrip().endswith("in 1 file.")


@posix
def test_symlinks_inside_the_roots_are_followed_once(tmp_path: Path) -> None:
    real = tmp_path / "repos" / "pkg"
    real.mkdir(parents=True)
    (real / "node.py").write_text(BUGGY)
    (tmp_path / "src").mkdir()
    (tmp_path / "src" / "pkg").symlink_to(real, target_is_directory=True)
    (tmp_path / "src" / "again").symlink_to(tmp_path / "src", target_is_directory=True)
    result = check(tmp_path)
    assert codes(result) == [(str(real / "node.py"), "RF101")]
    assert result.files == 1
    linked = check(tmp_path, tmp_path / "src")  # the target is outside this root
    assert [d.code for d in linked.diagnostics] == ["RF004"]


@posix
def test_a_symlinked_package_outside_is_a_warning_not_silence(tmp_path: Path) -> None:
    repo = tmp_path / "repos" / "my_pkg"
    (repo / "msg").mkdir(parents=True)
    (repo / "package.xml").write_text("<package><name>my_pkg</name></package>")
    (repo / "node.py").write_text(BUGGY)
    (tmp_path / "ws" / "src").mkdir(parents=True)
    (tmp_path / "ws" / "src" / "my_pkg").symlink_to(repo, target_is_directory=True)
    result = cli("check", "ws/src", "--no-cache", cwd=tmp_path)
    assert result.returncode == 0
    assert result.stdout.startswith(
        f"ws/src/my_pkg:1:1: warning[RF004]: not checked: a symlink to `{repo}`"
    )
    assert "No problems found" not in result.stdout
    assert "timeout" not in result.stdout  # the target's content is not shown
    assert cli("check", "ws/src", "--strict", cwd=tmp_path).returncode == 1
    both = cli("check", "ws/src", str(repo), "--no-cache", cwd=tmp_path)
    assert both.returncode == 1 and "error[RF101]" in both.stdout


@posix
@pytest.mark.parametrize("fmt", ["text", "github", "json", "sarif", "concise"])
def test_links_leaving_the_roots_are_named_never_read(tmp_path: Path, fmt: str) -> None:
    secret = tmp_path / "home" / "id_ed25519"
    secret.parent.mkdir()
    secret.write_text(SECRET + "-----BEGIN OPENSSH PRIVATE KEY-----\n")
    package = tmp_path / "proj" / "p"
    (package / "msg").mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>p</name></package>")
    (package / "msg" / "Key.msg").symlink_to(secret)
    (package / "key.py").symlink_to(secret)
    (package / "ok.py").write_text(BUGGY)
    result = cli("check", ".", "--no-cache", "--format", fmt, cwd=tmp_path / "proj")
    assert "ghp_SECRET" not in result.stdout + result.stderr
    assert "OPENSSH" not in result.stdout + result.stderr
    assert "RF101" in result.stdout  # the run went on
    assert result.stdout.count("RF004") >= 2
    if fmt == "concise":
        assert (
            f"p/key.py:1:1: warning[RF004]: not checked: a symlink to `{secret}`"
            in (result.stdout)
        )
        assert "p/msg/Key.msg:1:1: warning[RF004]" in result.stdout


@posix
def test_a_msg_folder_linked_outside_is_named(tmp_path: Path) -> None:
    outside = tmp_path / "elsewhere"
    outside.mkdir()
    (outside / "Cmd.msg").write_text("float64 speed\nnot a field " + SECRET)
    package = tmp_path / "proj" / "p"
    package.mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>p</name></package>")
    (package / "msg").symlink_to(outside, target_is_directory=True)
    (package / "a.py").write_text("x = 1\n")
    result = check(tmp_path / "proj")
    assert codes(result) == [(str(package / "msg"), "RF004")]
    assert "ghp_SECRET" not in result.diagnostics[0].message


# -- H6: FIFOs and devices -------------------------------------------------------------


@posix
def test_fifos_and_devices_are_rf003_never_a_hang(tmp_path: Path) -> None:
    os.mkfifo(tmp_path / "fifo.py")
    named = cli("check", "fifo.py", "/dev/zero", "--no-cache", cwd=tmp_path)
    assert named.returncode == 2, named.stderr
    assert named.stdout.splitlines()[:2] == [
        "/dev/zero:1:1: error[RF003]: cannot read: not a regular file",
        "fifo.py:1:1: error[RF003]: cannot read: not a regular file",
    ]
    tree = tmp_path / "tree"
    tree.mkdir()
    os.mkfifo(tree / "pipe")
    (tree / "x.py").symlink_to(tree / "pipe")  # inside: followed, refused at open
    (tree / "zero.py").symlink_to("/dev/zero")  # outside: not followed
    (tree / "pipe.msg").symlink_to(tree / "pipe")
    (tree / "ok.py").write_text(BUGGY)
    result = cli("check", "tree", "--no-cache", "--format", "concise", cwd=tmp_path)
    assert result.returncode == 2, result.stderr
    assert result.stdout.splitlines() == [
        "tree/ok.py:2:1: error[RF101]: `timeout = 200` violates `timeout < 200`",
        "tree/x.py:1:1: error[RF003]: cannot read: not a regular file",
        "tree/zero.py:1:1: warning[RF004]: not checked: a symlink to `/dev/zero`, "
        "outside the checked paths",
        "Found 2 errors and 1 warning in 2 files.",
    ]


# -- C4 / C5: long paths, vanishing and unreadable folders ---------------------------


def _make_deep(top: Path, depth: int, name: str) -> None:
    fd = os.open(top, os.O_RDONLY)
    try:
        for _ in range(depth):
            os.mkdir(name, dir_fd=fd)
            child = os.open(name, os.O_RDONLY, dir_fd=fd)
            os.close(fd)
            fd = child
        os.close(os.open("deep.py", os.O_WRONLY | os.O_CREAT, 0o644, dir_fd=fd))
    finally:
        os.close(fd)


def _remove_deep(top: Path, depth: int, name: str) -> None:
    # rmtree works by descriptors, so it can remove what paths cannot reach
    shutil.rmtree(top / name)


def test_a_path_longer_than_the_system_allows_is_not_a_crash(tmp_path: Path) -> None:
    (tmp_path / "ok.py").write_text(BUGGY)
    name = "d" * 200
    _make_deep(tmp_path, 25, name)  # more than 4096 bytes
    try:
        result = check(tmp_path)
        assert (str(tmp_path / "ok.py"), "RF101") in codes(result)
        assert not result.internal_errors
        notices = [d for d in result.diagnostics if d.code == "RF004"]
        assert len(notices) == 1 and "File name too long" in notices[0].message
        (tmp_path / "pyproject.toml").write_text('[tool.robotfix]\nmsg-paths = ["."]\n')
        settings = config_module.load(tmp_path, Config(root=tmp_path))
        assert not check_paths([tmp_path / "ok.py"], settings).internal_errors
    finally:
        _remove_deep(tmp_path, 25, name)


class _Listing:
    """A directory listing taken at once; the folder is changed before iterating."""

    def __init__(self, entries: list[os.DirEntry[str]]) -> None:
        self.entries = entries

    def __enter__(self) -> Iterator[os.DirEntry[str]]:
        return iter(self.entries)

    def __exit__(self, *args: object) -> None:
        return None


def test_a_folder_that_vanishes_during_the_walk_is_skipped(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "a" / "b" / "c").mkdir(parents=True)
    (tmp_path / "a" / "b" / "c" / "x.py").write_text("x = 1\n")
    (tmp_path / "a" / "ok.py").write_text(BUGGY)
    real_scandir = os.scandir

    def scandir(path: Any) -> Any:
        if not isinstance(path, Path) or path != tmp_path / "a":
            return real_scandir(path)
        with real_scandir(path) as listing:
            entries = list(listing)
        shutil.rmtree(tmp_path / "a" / "b")  # listed, then removed by a build
        return _Listing(entries)

    monkeypatch.setattr(discovery.os, "scandir", scandir)
    result = check(tmp_path)
    assert codes(result) == [(str(tmp_path / "a" / "ok.py"), "RF101")]


def test_folders_churning_during_the_run_never_crash(tmp_path: Path) -> None:
    (tmp_path / "ok.py").write_text(BUGGY)
    stop = threading.Event()

    def churn() -> None:
        n = 0
        while not stop.is_set():
            top = tmp_path / f"gen{n % 3}"
            for i in range(20):
                (top / f"d{i}").mkdir(parents=True, exist_ok=True)
                (top / f"d{i}" / "m.py").write_text("x = 1\n")
            shutil.rmtree(top, ignore_errors=True)
            n += 1

    worker = threading.Thread(target=churn)
    worker.start()
    try:
        for _ in range(15):
            result = check(tmp_path)
            assert not result.internal_errors
            assert (str(tmp_path / "ok.py"), "RF101") in codes(result)
    finally:
        stop.set()
        worker.join()


def test_an_unreadable_folder_is_a_warning(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "locked").mkdir()
    (tmp_path / "locked" / "x.py").write_text(BUGGY)
    (tmp_path / "ok.py").write_text(BUGGY)
    real_scandir = os.scandir

    def scandir(path: Any) -> Any:
        if isinstance(path, Path) and path.name == "locked":  # chmod 000, not root
            raise PermissionError(errno.EACCES, "Permission denied", str(path))
        return real_scandir(path)

    monkeypatch.setattr(discovery.os, "scandir", scandir)
    result = check(tmp_path)
    assert codes(result) == [
        (str(tmp_path / "locked"), "RF004"),
        (str(tmp_path / "ok.py"), "RF101"),
    ]
    assert "cannot read it (Permission denied)" in result.diagnostics[0].message


# -- H8: the pool ----------------------------------------------------------------------


@pytest.fixture
def many(tmp_path: Path) -> Path:
    for i in range(40):
        (tmp_path / f"f{i:02}.py").write_text(BUGGY if i % 4 == 0 else "x = 1\n")
    return tmp_path


def test_jobs_are_clamped_and_a_failing_pool_falls_back(
    many: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    expected = codes(check(many))
    workers: list[int] = []

    class NoPool:
        def __init__(self, max_workers: int, **_: Any) -> None:
            workers.append(max_workers)
            raise OSError(errno.EMFILE, "Too many open files")

    # run.py imports the pool class when it starts one
    monkeypatch.setattr(concurrent.futures, "ProcessPoolExecutor", NoPool)
    result = check_paths([many], Config(root=many), jobs=500)
    assert codes(result) == expected and not result.internal_errors
    assert workers == [min(run.default_jobs(), 40)]


def test_a_pool_broken_after_its_first_chunk_loses_only_that_chunk(
    many: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A worker that dies while chunks are still being sent breaks the pool: the
    chunk it had is lost (an internal error of its files), the chunks not sent yet
    are checked here, and the run does not start over in this process (which would
    check again the file that killed the worker, and die with it)."""
    from concurrent.futures import Future
    from concurrent.futures.process import BrokenProcessPool

    expected = codes(check(many))
    sent: list[list[Path]] = []

    class BreaksAfterOne:
        def __init__(self, max_workers: int, **_: Any) -> None:
            pass

        def submit(self, fn: Any, chunk: list[tuple[Path, bytes | None]]) -> Any:
            if sent:
                raise BrokenProcessPool("a worker died")
            sent.append([path for path, _ in chunk])
            future: Future[Any] = Future()
            future.set_exception(BrokenProcessPool("a worker died"))
            return future

        def shutdown(self, wait: bool = True, **_: Any) -> None:
            pass

    monkeypatch.setattr(run, "default_jobs", lambda: 2)
    monkeypatch.setattr(concurrent.futures, "ProcessPoolExecutor", BreaksAfterOne)
    result = check_paths([many], Config(root=many), jobs=2)
    lost = sorted(Path(e.path).name for e in result.internal_errors)
    assert len(sent) == 1 and lost == sorted(p.name for p in sent[0])
    assert all("worker process" in e.summary for e in result.internal_errors)
    first = {p.name for p in sent[0]}
    assert sorted(codes(result)) == sorted(
        c for c in expected if Path(c[0]).name not in first
    )


@pytest.mark.skipif(
    "fork" not in multiprocessing.get_all_start_methods() or run.default_jobs() < 2,
    reason="a patched worker needs fork and two cores",
)
def test_a_worker_that_dies_is_an_internal_error_not_a_hang(
    many: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (many / "die.py").write_text("x = 1\n")
    parent = os.getpid()
    check_one = run._check_one

    def dying(path: Path, *args: Any) -> Any:
        if path.name == "die.py" and os.getpid() != parent:
            os._exit(9)  # as the OOM killer or a segfault would
        return check_one(path, *args)

    monkeypatch.setattr(run, "_check_one", dying)
    result = check_paths([many], Config(root=many), jobs=2)
    lost = {Path(e.path).name for e in result.internal_errors}
    assert "die.py" in lost
    assert all("worker process" in e.summary for e in result.internal_errors)


@pytest.mark.skipif(
    sys.platform != "linux" or (os.cpu_count() or 1) < 2, reason="rlimit, fork"
)
def test_j_beyond_the_descriptor_limit_finishes(many: Path) -> None:
    import resource

    # comments enough for a pool (run.MIN_PARALLEL_BYTES), which then runs out of
    # descriptors; without them the run stays in one process and opens no pool
    (many / "zz_filler.py").write_text(("# " + "x" * 76 + "\n") * 7000)

    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_NOFILE, (24, 24))

    result = subprocess.run(
        [sys.executable, "-m", "robotfix", "check", ".", "-j", "200", "--no-cache"],
        cwd=many,
        capture_output=True,
        text=True,
        timeout=120,
        preexec_fn=limit,
    )
    assert "Traceback" not in result.stderr
    assert result.returncode == 1 and result.stdout.count("error[RF101]") == 10


@pytest.mark.skipif(os.name != "posix", reason="signals")
def test_ctrl_c_with_j2_exits_130_without_a_traceback(tmp_path: Path) -> None:
    body = "".join(
        f'def f{i}(a: Annotated[float, "_ > 0 and _ < 3"], '
        f'b: Annotated[float, "_ > 1"]) -> None:\n'
        f'    x: Annotated[float, "_ * _ != {i + 4}"] = a * b + b * a * b\n'
        for i in range(12)
    )
    # a comment block, so that the files hold enough source for a pool
    # (run.MIN_PARALLEL_BYTES): with less, the run stays in one process, the wait
    # below for workers lasts its whole 60 s, and the run may end before the signal
    padding = ("# " + "x" * 76 + "\n") * 40
    for i in range(200):
        (tmp_path / f"m{i:03}.py").write_text(
            "from typing import Annotated\n" + padding + body
        )
    assert 200 * len(padding) > run.MIN_PARALLEL_BYTES
    process = subprocess.Popen(
        [sys.executable, "-m", "robotfix", "check", ".", "-j", "2", "--no-cache"],
        cwd=tmp_path,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,  # its own group: Ctrl-C reaches it and its workers
        # as a terminal starts it: a suite started in the background (`pytest &`)
        # ignores SIGINT, and a child would inherit that and never see the Ctrl-C
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
    )
    # wait until the workers run (where /proc can tell; else 3 s)
    children = Path(f"/proc/{process.pid}/task/{process.pid}/children")
    deadline = time.monotonic() + (60 if children.exists() else 3)
    while time.monotonic() < deadline:
        if process.poll() is not None:
            pytest.skip("the run ended before the interrupt")  # pragma: no cover
        if children.exists() and children.read_text().split():
            break
        time.sleep(0.05)
    time.sleep(0.5)  # into the first chunks
    os.killpg(process.pid, signal.SIGINT)
    _, err = process.communicate(timeout=60)
    assert process.returncode == 130, err
    assert "Traceback" not in err
