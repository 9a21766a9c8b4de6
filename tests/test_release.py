"""Installable and releasable (issue 11, item 4), marked slow: `python -m build` makes
an sdist and a wheel that `twine check` accepts; the wheel, installed alone into a
fresh venv from the package index, checks the bundled example, explains rules from
the pages it carries, serves the language server and brings `ament_robotfix` with its
pytest plugin; the pre-commit hook works from a local checkout and runs when only an
interface file changes."""

from __future__ import annotations

import json
import os
import select
import shutil
import subprocess
import tarfile
import time
import zipfile
from pathlib import Path
from typing import Any

import pytest

from tests.release_env import ROOT, Release, release, run

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def built(tmp_path_factory: pytest.TempPathFactory) -> Release:
    return release(tmp_path_factory)


def test_twine_accepts_the_sdist_and_the_wheel(built: Release, tmp_path: Path) -> None:
    checked = run(
        [built.tools / "twine", "check", "--strict", built.sdist, built.wheel],
        built.env(built.tools),
        tmp_path,
    )
    assert checked.returncode == 0, checked.stdout + checked.stderr
    assert checked.stdout.count("PASSED") == 2


def test_the_sdist_holds_what_a_release_needs(built: Release) -> None:
    with tarfile.open(built.sdist) as sdist:
        names = {n.split("/", 1)[1] for n in sdist.getnames() if "/" in n}
    for needed in (
        "pyproject.toml",
        "README.md",
        ".pre-commit-hooks.yaml",
        "docs/rules/RF101.md",
        "docs/ros.md",
        "examples/safety_stop/msg/DriveCommand.msg",
        "ament/ament_cmake_robotfix/cmake/ament_robotfix.cmake",
        "src/robotfix/ament/data/test_robotfix.py",
        "tests/test_ament.py",
    ):
        assert needed in names, needed
    assert not [n for n in names if n.startswith((".venv/", ".git/", "build/"))]


def test_the_wheel_carries_data_and_entry_points(built: Release) -> None:
    with zipfile.ZipFile(built.wheel) as wheel:
        names = set(wheel.namelist())
        (entry_points,) = [n for n in names if n.endswith("entry_points.txt")]
        declared = wheel.read(entry_points).decode()
    for needed in (
        "robotfix/rule_docs/RF101.md",
        "robotfix/ros/rep103.toml",
        "robotfix/annotations/grammar.lark",
        "robotfix/ament/data/test_robotfix.py",
        "robotfix/ament/pytest_marker.py",
        "robotfix/stubs/data/rospy.pyi",
        "robotfix/stubs/data/rclpy/node.pyi",
        "robotfix/stubs/data/tf/transformations.pyi",
    ):
        assert needed in names, needed
    assert "ament_robotfix = robotfix.ament:main" in declared
    assert "robotfix = robotfix.ament.pytest_marker" in declared


def test_fresh_install_checks_the_example_and_explains(
    built: Release, tmp_path: Path
) -> None:
    env = built.env(built.fresh)
    shutil.copytree(ROOT / "examples", tmp_path / "examples")
    checked = run([built.fresh / "robotfix", "check", "examples/"], env, tmp_path)
    assert checked.returncode == 1, checked.stdout + checked.stderr
    assert "error[RF201]" in checked.stdout
    assert "divide by 3.6 to convert km/h to m/s" in checked.stdout
    # explained from the pages inside the wheel (there is no docs/ here)
    explained = run([built.fresh / "robotfix", "explain", "RF101"], env, tmp_path)
    assert explained.returncode == 0
    assert explained.stdout.startswith("# RF101 ")
    assert "## Use instead" in explained.stdout
    template = run([built.fresh / "ament_robotfix", "--template"], env, tmp_path)
    assert "from robotfix.ament import main_with_errors" in template.stdout
    markers = run([built.fresh / "python", "-m", "pytest", "--markers"], env, tmp_path)
    # pytest is not a dependency: the plugin only matters where pytest is installed
    if markers.returncode == 0:
        assert "@pytest.mark.robotfix" in markers.stdout
    tools_markers = run(
        [built.tools / "python", "-m", "pytest", "--markers"],
        built.env(built.tools),
        tmp_path,
    )
    assert "@pytest.mark.robotfix:" in tools_markers.stdout
    assert "@pytest.mark.linter:" in tools_markers.stdout


def test_fresh_install_serves_the_language_server(
    built: Release, tmp_path: Path
) -> None:
    source = tmp_path / "node.py"
    source.write_text('from typing import Annotated\nx: Annotated[int, "_ < 2"] = 5\n')
    server = subprocess.Popen(
        [str(built.fresh / "robotfix"), "lsp"],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        env=built.env(built.fresh),
        cwd=tmp_path,
    )
    try:
        lsp = RawClient(server)
        lsp.send(
            "initialize",
            {"processId": None, "rootUri": tmp_path.as_uri(), "capabilities": {}},
            1,
        )
        assert "capabilities" in lsp.wait(lambda m: m.get("id") == 1)["result"]
        lsp.send("initialized", {})
        document = {
            "uri": source.as_uri(),
            "languageId": "python",
            "version": 1,
            "text": source.read_text(),
        }
        lsp.send("textDocument/didOpen", {"textDocument": document})
        published = lsp.wait(
            lambda m: m.get("method") == "textDocument/publishDiagnostics"
        )
        codes = [d.get("code") for d in published["params"]["diagnostics"]]
        assert codes == ["RF101"]
        lsp.send("shutdown", None, 2)
        lsp.wait(lambda m: m.get("id") == 2)
        lsp.send("exit", None)
        assert server.wait(timeout=60) == 0
    finally:
        if server.poll() is None:
            server.kill()
            server.wait()


class RawClient:
    """JSON-RPC over stdio with Content-Length headers, with a deadline per wait."""

    def __init__(self, process: subprocess.Popen[bytes]) -> None:
        assert process.stdin is not None and process.stdout is not None
        self.stdin, self.fd = process.stdin, process.stdout.fileno()
        self.buffer = b""

    def send(self, method: str, params: Any, ident: int | None = None) -> None:
        message: dict[str, Any] = {"jsonrpc": "2.0", "method": method}
        if params is not None:
            message["params"] = params
        if ident is not None:
            message["id"] = ident
        body = json.dumps(message).encode()
        self.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.stdin.flush()

    def wait(self, wanted: Any, seconds: float = 120) -> dict[str, Any]:
        deadline = time.monotonic() + seconds
        while True:
            message = self._next(deadline)
            if wanted(message):
                return message

    def _next(self, deadline: float) -> dict[str, Any]:
        while True:
            header, sep, rest = self.buffer.partition(b"\r\n\r\n")
            if sep:
                length = int(header.split(b"Content-Length:")[1].split(b"\r\n")[0])
                if len(rest) >= length:
                    self.buffer = rest[length:]
                    found: dict[str, Any] = json.loads(rest[:length])
                    return found
            left = deadline - time.monotonic()
            ready, _, _ = select.select([self.fd], [], [], max(0.0, left))
            if not ready:
                raise TimeoutError("the language server did not answer")
            chunk = os.read(self.fd, 65536)
            if not chunk:
                raise EOFError("the language server stopped")
            self.buffer += chunk


GIT_ENV = {
    "GIT_AUTHOR_NAME": "t",
    "GIT_AUTHOR_EMAIL": "t@example.com",
    "GIT_COMMITTER_NAME": "t",
    "GIT_COMMITTER_EMAIL": "t@example.com",
    "GIT_CONFIG_NOSYSTEM": "1",
}


def test_pre_commit_hook_runs_when_only_a_msg_file_changes(
    built: Release, tmp_path: Path
) -> None:
    """The hook from this checkout (`pre-commit try-repo`, as a local `repo:` path
    works): a commit that only tightens a .msg refinement breaks a node using it."""
    if shutil.which("git") is None:
        pytest.skip("git is not installed")
    env = built.env(built.tools, HOME=str(built.home), **GIT_ENV)
    repo = tmp_path / "repo"
    (repo / "pkg" / "msg").mkdir(parents=True)
    (repo / "pkg" / "pkg").mkdir()
    (repo / "pkg" / "package.xml").write_text(
        "<package format='3'><name>pkg</name></package>\n"
    )
    (repo / "pkg" / "msg" / "Cmd.msg").write_text("float64 speed\n")
    (repo / "pkg" / "pkg" / "node.py").write_text(
        "from pkg.msg import Cmd\n\n\ndef go() -> Cmd:\n"
        "    c = Cmd()\n    c.speed = 5.0\n    return c\n"
    )

    def git(*args: str) -> None:
        done = run(["git", *args], env, repo)
        assert done.returncode == 0, done.stderr

    git("init", "-q")
    git("add", "-A")
    git("commit", "-qm", "a node")
    (repo / "pkg" / "msg" / "Cmd.msg").write_text(
        "float64 speed  #RobotFix# 0 <= _ <= 1.5\n"
    )
    git("add", "pkg/msg/Cmd.msg")
    hook = run([built.tools / "pre-commit", "try-repo", ROOT, "robotfix"], env, repo)
    assert hook.returncode == 1, hook.stdout + hook.stderr
    assert "robotfix" in hook.stdout and "Failed" in hook.stdout
    assert "pkg/pkg/node.py:6:5: error[RF101]" in hook.stdout
    git("commit", "-qm", "tighten the speed", "--no-verify")
    (repo / "notes.md").write_text("nothing to check\n")
    git("add", "notes.md")
    skipped = run([built.tools / "pre-commit", "try-repo", ROOT, "robotfix"], env, repo)
    assert skipped.returncode == 0, skipped.stdout
    assert "(no files to check)Skipped" in skipped.stdout
