"""Issue 24 item 1: the same tree gives the same findings from everywhere.

One workspace, as the second new-user trial built it: a third-party message package
cloned into `src/` (px4_msgs-like), a package whose own configuration adds an
overlay to one of its types, and a package whose configuration names its stubs and
extends the workspace's configuration (which silences one file). Checked from the
workspace root, from each package, file by file and through the language server, it
gives the same findings each way."""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

import pytest

import robotfix.cache
import robotfix.run
from robotfix import cli, discovery
from robotfix.lsp import server
from tests.test_workspace import no_ros_sourced as no_ros_sourced  # autouse
from tests.test_workspace import package, write

# every finding the workspace holds: (file, line, code)
EXPECTED = [
    ("src/drive/drive/node.py", 5, "RF101"),
    ("src/px4_ros_com/px4_ros_com/offboard.py", 6, "RF101"),
]


def workspace(ws: Path, extend: bool) -> list[Path]:
    """The workspace; its Python files. Without `extend`, the drive package does
    not extend the workspace's configuration and `quiet.py` is not silenced."""
    # the workspace's configuration: a default that reaches a package only
    # through `extend` (the package has a configuration of its own)
    write(
        ws / "robotfix.toml",
        'per-file-ignores = {"src/drive/drive/quiet.py" = ["RF101"]}\n',
    )
    msgs = package(ws / "src" / "px4_msgs", "px4_msgs")
    write(
        msgs / "msg" / "TrajectorySetpoint.msg",
        "uint64 timestamp # time since system start [us]\n"
        "float32[3] position # in meters\n"
        "float32 yaw # euler angle of desired attitude in radians -PI..+PI\n",
    )
    px4 = package(ws / "src" / "px4_ros_com", "px4_ros_com")
    write(
        px4 / "pyproject.toml",
        '[tool.robotfix]\nmsg-paths = ["interfaces", "../px4_msgs"]\n',
    )
    write(
        px4 / "interfaces" / "TrajectorySetpoint.msg",
        "[px4_msgs/TrajectorySetpoint]:\n"
        '#RobotFix# Unit(yaw) == "rad" and abs(yaw) <= 3.1416\n',
    )
    offboard = write(
        px4 / "px4_ros_com" / "offboard.py",
        "from px4_msgs.msg import TrajectorySetpoint\n"
        "\n\n"
        "def publish_setpoint(pub) -> None:\n"
        "    msg = TrajectorySetpoint()\n"
        "    msg.yaw = 90.0\n"
        "    pub.publish(msg)\n",
    )
    drive = package(ws / "src" / "drive", "drive")
    extends = 'extend = "../../robotfix.toml"\n' if extend else ""
    write(
        drive / "pyproject.toml", f'[tool.robotfix]\n{extends}stub-paths = ["stubs"]\n'
    )
    write(
        drive / "stubs" / "motor.pyi",
        "from typing import Annotated\n\n"
        'def set_duty(duty: Annotated[float, "0 <= _ <= 1"]) -> None: ...\n',
    )
    node = write(
        drive / "drive" / "node.py",
        "import motor\n\n\ndef run() -> None:\n    motor.set_duty(2.0)\n",
    )
    quiet = write(
        drive / "drive" / "quiet.py",
        "import motor\n\n\ndef run() -> None:\n    motor.set_duty(3.0)\n",
    )
    return [offboard, node, quiet]


def cli_findings(
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
    cwd: Path,
    ws: Path,
    *args: str,
) -> list[tuple[str, int, str]]:
    """`robotfix check ARGS --format json` run in `cwd` (in process)."""
    monkeypatch.chdir(cwd)
    capsys.readouterr()
    status = cli.main(["check", *args, "--format", "json"])
    printed = capsys.readouterr()
    assert status in (0, 1), printed.err
    out = json.loads(printed.out)
    return sorted(
        (
            Path(os.path.abspath(d["path"])).relative_to(ws).as_posix(),
            d["line"],
            d["code"],
        )
        for d in out["diagnostics"]
    )


class _Session(server.Session):
    def __init__(self) -> None:
        super().__init__()
        self.published: list[Any] = []

    def notify(self, method: str, params: object) -> None:
        if method == "textDocument/publishDiagnostics":
            self.published.append(params)


def lsp_findings(files: list[Path], ws: Path) -> list[tuple[str, int, str]]:
    """Each file as the language server checks it, in process (`_publish`)."""
    session = _Session()
    for file in files:
        server._publish(session, file.as_uri())
    found = []
    for params in session.published:
        path = Path(server.path_of(params["uri"])).relative_to(ws).as_posix()
        for d in params["diagnostics"]:
            found.append((path, d["range"]["start"]["line"] + 1, d["code"]))
    return sorted(found)


@pytest.mark.parametrize("extend", [True, False])
def test_one_workspace_gives_the_same_findings_every_way(
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
    extend: bool,
) -> None:
    ws = tmp_path / "ws"
    files = workspace(ws, extend)
    cache = ["--cache-dir", str(tmp_path / "cache")]
    ways = {
        "root": cli_findings(capsys, monkeypatch, ws, ws, ".", "--no-cache"),
        "root -j 2": cli_findings(capsys, monkeypatch, ws, ws, ".", "-j", "2"),
        "root, cache written": cli_findings(capsys, monkeypatch, ws, ws, ".", *cache),
        "root, from the cache": cli_findings(capsys, monkeypatch, ws, ws, ".", *cache),
        "src": cli_findings(capsys, monkeypatch, ws / "src", ws, "."),
        "packages": sorted(
            finding
            for name in ("px4_msgs", "px4_ros_com", "drive")
            for finding in cli_findings(capsys, monkeypatch, ws / "src" / name, ws, ".")
        ),
        "files from their folder": sorted(
            finding
            for file in files
            for finding in cli_findings(capsys, monkeypatch, file.parent, ws, file.name)
        ),
        "files from the root": sorted(
            finding
            for file in files
            for finding in cli_findings(
                capsys, monkeypatch, ws, ws, str(file.relative_to(ws))
            )
        ),
        "language server": lsp_findings(files, ws),
    }
    quiet = [] if extend else [("src/drive/drive/quiet.py", 5, "RF101")]
    assert ways == dict.fromkeys(ways, sorted(EXPECTED + quiet))


BUG = 'from typing import Annotated\n\nx: Annotated[int, "_ < 5"] = 9\n'


def test_a_pyproject_without_the_table_is_passed_over(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """A package's pyproject.toml for its build alone does not hide the
    workspace's configuration."""
    write(tmp_path / "robotfix.toml", 'per-file-ignores = {"**/node.py" = ["RF101"]}\n')
    write(tmp_path / "pkg" / "pyproject.toml", "[project]\nname = 'pkg'\n")
    write(tmp_path / "pkg" / "node.py", BUG)
    for cwd in (tmp_path, tmp_path / "pkg"):
        assert cli_findings(capsys, monkeypatch, cwd, tmp_path, ".", "--no-cache") == []


def test_a_package_exclude_holds_at_the_root_also_from_the_cache(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """The cached discovery (`discovery.Trace`) holds while the package's
    configuration does: its `exclude` decides what the walk finds."""
    for module in (discovery, robotfix.cache, robotfix.run):
        monkeypatch.setattr(module, "RACY_NS", 0)  # stamps count as old at once
    ws = tmp_path / "ws"
    write(ws / "top.py", BUG)
    config = write(ws / "pkg" / "robotfix.toml", 'exclude = ["gen/"]\n')
    write(ws / "pkg" / "gen" / "made.py", BUG)
    cache = ["--cache-dir", str(tmp_path / "cache")]
    want = [("top.py", 3, "RF101")]
    for _ in range(2):
        assert cli_findings(capsys, monkeypatch, ws, ws, ".", *cache) == want
    config.write_text("exclude = []\n")
    os.utime(config, ns=(1, 1))  # an old mtime: only the ctime and size changed
    want.insert(0, ("pkg/gen/made.py", 3, "RF101"))
    assert cli_findings(capsys, monkeypatch, ws, ws, ".", *cache) == want


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ('extend = "robotfix.toml"\n', "makes a cycle"),
        ('extend = "nowhere.toml"\n', "no such file"),
        ("strict = 3\n", "must be true or false"),
    ],
)
def test_a_package_configuration_error_is_one_line_and_exit_2(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], text: str, message: str
) -> None:
    write(tmp_path / "top.py", "x = 1\n")
    write(tmp_path / "pkg" / "robotfix.toml", text)
    write(tmp_path / "pkg" / "node.py", "x = 1\n")
    capsys.readouterr()
    assert cli.main(["check", str(tmp_path), "--no-cache"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("robotfix: error: ") and message in err
    assert err.count("\n") == 1
