"""Dependable runs: the cache, -j, determinism, and never running the checked code."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from robotfix import api
from robotfix.api import check_paths
from robotfix.config import Config

USES_CMD = """from typing import Annotated
from my_pkg.msg import Cmd

def send(pub, v: Annotated[float, "0 <= _ <= 1"]) -> None:
    cmd = Cmd()
    cmd.speed = v
    pub.publish(cmd)
"""
PLAIN = 'from typing import Annotated\nlimit: Annotated[int, "_ < 10"] = 3\n'


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    package = tmp_path / "my_pkg"
    (package / "msg").mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>my_pkg</name></package>")
    (package / "msg" / "Cmd.msg").write_text("float64 speed #RobotFix# speed <= 2\n")
    (package / "node.py").write_text(USES_CMD)
    (package / "other.py").write_text(PLAIN)
    return tmp_path


def run_cached(root: Path) -> tuple[int, list[str]]:
    config = Config(root=root)
    result = check_paths([root], config, use_cache=True)
    return result.from_cache, [
        f"{d.path}:{d.span.line}:{d.code}" for d in result.diagnostics
    ]


def test_changing_a_msg_rechecks_exactly_its_users(workspace: Path) -> None:
    cached, first = run_cached(workspace)
    assert cached == 0 and first == []
    cached, again = run_cached(workspace)
    assert cached == 2 and again == first
    (workspace / "my_pkg" / "msg" / "Cmd.msg").write_text(
        "float64 speed #RobotFix# speed <= 0.5\n"
    )
    cached, after = run_cached(workspace)
    assert cached == 1  # other.py reused; node.py checked again
    assert after == [f"{workspace / 'my_pkg' / 'node.py'}:6:RF102"]


def test_a_corrupt_cache_is_ignored_and_rebuilt(workspace: Path) -> None:
    run_cached(workspace)
    (workspace / ".robotfix_cache" / "results.json").write_text("{not json")
    cached, found = run_cached(workspace)
    assert cached == 0 and found == []
    assert run_cached(workspace)[0] == 2


def robotfix(*args: str, cwd: Path, env: dict[str, str] | None = None) -> str:
    return subprocess.run(
        [sys.executable, "-m", "robotfix", *args],
        cwd=cwd,
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
    ).stdout


def test_output_is_byte_identical_across_runs_hash_seeds_and_jobs(
    tmp_path: Path,
) -> None:
    cases = tmp_path / "cases"
    shutil.copytree(Path(__file__).parent / "cases", cases)
    # comments enough for `-j 2` to start its workers (run.MIN_PARALLEL_BYTES):
    # the cases alone are checked in one process whatever `-j` says
    (cases / "zz_filler.py").write_text(("# " + "x" * 76 + "\n") * 7000)
    outputs = set()
    for seed, jobs in (("0", "1"), ("1", "2"), ("12345", "1"), ("random", "2")):
        env = {**os.environ, "PYTHONHASHSEED": seed}
        out = robotfix(
            "check",
            str(cases),
            "--msg-path",
            str(cases / "nodes" / "msg"),
            "-j",
            jobs,
            "--no-cache",
            cwd=tmp_path,
            env=env,
        )
        outputs.add(out)
    assert len(outputs) == 1
    assert "error[RF101]" in outputs.pop()


MARKER_PROGRAM = """import pathlib
pathlib.Path({marker!r}).write_text("module ran")


def callback(msg):
    pathlib.Path({marker!r}).write_text("function ran")


class Node:
    def __init__(self):
        pathlib.Path({marker!r}).write_text("method ran")

    def on_msg(self, msg):
        pathlib.Path({marker!r}).write_text("callback ran")


callback(None)
Node().on_msg(None)
limit: "typing.Annotated[int, __import__('os').system('touch {marker}')]" = 1
"""


def test_checked_code_and_annotations_never_run(tmp_path: Path) -> None:
    marker = tmp_path / "marker"
    program = tmp_path / "evil.py"
    program.write_text(MARKER_PROGRAM.format(marker=str(marker)))
    annotation = tmp_path / "annotation.py"
    annotation.write_text(
        "from typing import Annotated\n"
        f"x: Annotated[int, \"__import__('os').system('touch {marker}')\"] = 1\n"
    )
    out = robotfix("check", ".", cwd=tmp_path)
    assert not marker.exists()
    assert "annotation.py:2:" in out and "error[RF501]" in out


class _Planted:
    """A pickle that creates `marker` when it is loaded (N6 of reliability2.md)."""

    def __init__(self, marker: Path) -> None:
        self.marker = str(marker)

    def __reduce__(self) -> tuple[object, tuple[str, str]]:
        return (open, (self.marker, "w"))


def test_nothing_in_the_machine_cache_is_unpickled(tmp_path: Path) -> None:
    """pint's registry cache is a pickle: RobotFix never points pint at its cache
    folder, so a pickle planted where pint would look for one (a CI cache restored
    from another branch, a shared ROBOTFIX_CACHE_DIR) is never loaded."""
    import pickle

    import pint

    machine = tmp_path / "machine"
    pint.UnitRegistry(cache_folder=machine / "pint")  # the files pint would read
    planted = sorted((machine / "pint").glob("*.pickle"))
    assert planted
    marker = tmp_path / "PWNED"
    for path in planted:
        path.write_bytes(pickle.dumps(_Planted(marker)))
    (tmp_path / "u.py").write_text(
        "from typing import Annotated\n"
        "x: Annotated[float, \"Unit('furlong/fortnight')\"] = 1\n"  # not shipped
    )
    env = {
        **os.environ,
        "ROBOTFIX_CACHE_DIR": str(machine),
        "PYTHONPATH": str(Path(api.__file__).parents[1]),  # this robotfix
    }
    out = robotfix("check", "u.py", "--no-cache", cwd=tmp_path, env=env)
    assert not marker.exists()
    assert out == "No problems found in 1 file.\n"
    (units,) = machine.glob("units-*.json")  # pint was asked, its answer kept
    assert "furlong/fortnight" in units.read_text()
