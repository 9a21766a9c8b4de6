"""The command line contract of SPEC §5: exit statuses, formats, order, bad input."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

BUGGY = 'from typing import Annotated\ntimeout: Annotated[int, "_ < 200"] = 200\n'
WARN = 'from typing import Annotated\ndef f(v):\n    x: Annotated[int, "_ < 2"] = v\n'


def run(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "robotfix", *args],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=120,
    )


def run_python(script: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-c", script],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=120,
    )


@pytest.fixture
def project(tmp_path: Path) -> Path:
    (tmp_path / "a.py").write_text(BUGGY)
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "b.py").write_text(WARN)
    (tmp_path / "sub" / "c.py").write_text("x = 1\n")
    return tmp_path


def test_text_output_and_exit_status(project: Path) -> None:
    result = run("check", ".", cwd=project)
    assert result.returncode == 1
    first = result.stdout.splitlines()[0]
    assert first.startswith(
        "a.py:2:1: error[RF101]: `timeout = 200` violates `timeout < 200`"
    )
    assert "sub/b.py:3:5: warning[RF102]" in result.stdout
    assert result.stdout.rstrip().endswith("Found 1 error and 1 warning in 3 files.")


def test_warnings_pass_unless_strict(project: Path) -> None:
    assert run("check", "sub", cwd=project).returncode == 0
    assert run("check", "sub", "--strict", cwd=project).returncode == 1
    assert run("check", "sub/c.py", cwd=project).returncode == 0


def test_json_has_the_spec_keys(project: Path) -> None:
    data = json.loads(run("check", "--format", "json", cwd=project).stdout)
    assert set(data) == {"diagnostics", "summary"}
    assert set(data["summary"]) == {"files", "errors", "warnings", "seconds"}
    first = data["diagnostics"][0]
    assert set(first) == {
        "path",
        "line",
        "column",
        "end_line",
        "end_column",
        "severity",
        "code",
        "message",
        "notes",
    }
    assert (first["path"], first["line"], first["column"], first["code"]) == (
        "a.py",
        2,
        1,
        "RF101",
    )
    assert set(first["notes"][0]) == {"path", "line", "message"}


def test_output_is_deterministic(project: Path) -> None:
    assert (
        run("check", ".", cwd=project).stdout == run("check", ".", cwd=project).stdout
    )


def test_missing_path_is_a_usage_error(project: Path) -> None:
    result = run("check", "nope.py", cwd=project)
    assert result.returncode == 2
    assert "nope.py: no such file or directory" in result.stderr


def test_bad_files_do_not_stop_the_run(project: Path) -> None:
    (project / "py2.py").write_text('print "hello"\n')
    result = run("check", ".", cwd=project)
    assert result.returncode == 1
    assert "py2.py:1:1: warning[RF002]" in result.stdout
    assert "a.py:2:1: error[RF101]" in result.stdout


def test_msg_path_and_pyproject(project: Path) -> None:
    (project / "interfaces").mkdir()
    (project / "interfaces" / "Int32.msg").write_text(
        "[std_msgs/Int32]:\nint32 data #RobotFix# data > 0\n"
    )
    (project / "d.py").write_text(
        "from std_msgs.msg import Int32\nm = Int32()\nm.data = -1\n"
    )
    assert (
        "d.py:3:1: error[RF101]"
        in run("check", "d.py", "--msg-path", "interfaces", cwd=project).stdout
    )
    (project / "pyproject.toml").write_text(
        '[tool.robotfix]\nmsg-paths = ["interfaces"]\n'
    )
    assert "d.py:3:1: error[RF101]" in run("check", "d.py", cwd=project).stdout
    (project / "pyproject.toml").write_text("[tool.robotfix]\nmsg-paths = [\n")
    broken = run("check", "d.py", cwd=project)
    assert broken.returncode == 2 and "pyproject.toml:" in broken.stderr


def test_suppression_comment(project: Path) -> None:
    (project / "a.py").write_text(
        BUGGY.replace("= 200\n", "= 200  # robotfix: ignore[RF101]\n")
    )
    assert run("check", "a.py", cwd=project).returncode == 0


def test_version_and_rules(project: Path) -> None:
    assert run("--version", cwd=project).stdout.startswith("robotfix ")
    assert "RF101  refinement-violated" in run("rules", cwd=project).stdout


def test_unreadable_file_is_reported_and_the_run_goes_on(project: Path) -> None:
    (project / "gone.py").symlink_to(project / "missing-target.py")
    (project / "latin.py").write_bytes(b"\xff\xfe\xfa = 1\n")
    result = run("check", ".", cwd=project)
    assert result.returncode == 2
    assert "gone.py:1:1: error[RF003]" in result.stdout
    assert "latin.py:1:1: error[RF003]" in result.stdout
    assert "a.py:2:1: error[RF101]" in result.stdout


def test_internal_error_names_the_file_without_a_traceback(project: Path) -> None:
    script = (
        "import sys, robotfix.analysis.interpreter as i\n"
        "def boom(ctx): raise RuntimeError('boom')\n"
        "i.analyze_module = boom\n"
        "from robotfix.cli import main\n"
        "sys.exit(main(['check', 'sub/c.py', 'a.py']))\n"
    )
    result = run_python(script, cwd=project)
    assert result.returncode == 2
    assert "internal error while checking a.py: RuntimeError: boom" in result.stderr
    assert "Traceback" not in result.stderr


def test_the_command_ends_without_tearing_down_its_heap(project: Path) -> None:
    """`robotfix` (`cli.run`) writes everything and runs the `atexit` handlers, then
    ends the process without freeing its objects one by one (a module's global
    is never finalized), with `main`'s exit status."""
    script = (
        "import atexit, sys\n"
        "atexit.register(lambda: print('atexit ran', file=sys.stderr))\n"
        "class Kept:\n"
        "    def __del__(self):\n"
        "        print('freed at exit', file=sys.stderr)\n"
        "kept = Kept()\n"
        "sys.argv = ['robotfix', 'check', 'a.py']\n"
        "from robotfix.cli import run\n"
        "run()\n"
    )
    result = run_python(script, cwd=project)
    assert result.returncode == 1
    assert result.stdout.endswith("Found 1 error and 0 warnings in 1 file.\n")
    assert "atexit ran" in result.stderr
    assert "freed at exit" not in result.stderr
