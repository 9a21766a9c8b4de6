"""The VS Code extension in editors/vscode/ (issue 11, item 5): `build.sh` packages it
as a .vsix with the npm registry's vscode-languageclient and @vscode/vsce, and the
command line the packaged client computes from its default settings starts a
language server that publishes diagnostics.

Skipped where node or npm is missing or the npm registry cannot be reached."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path
from typing import Any

import pytest

from tests.lsp_client import Client

EXTENSION = Path(__file__).parent.parent / "editors" / "vscode"
BUGGY = """from typing import Annotated
from geometry_msgs.msg import Twist

speed: Annotated[float, "Unit('km/h')"] = 3.0
cmd = Twist()
cmd.linear.x = speed
"""


def _npm_registry_reachable() -> bool:
    if shutil.which("node") is None or shutil.which("npm") is None:
        return False
    try:
        done = subprocess.run(
            ["npm", "ping"], capture_output=True, timeout=30, check=False
        )
    except (OSError, subprocess.TimeoutExpired):
        return False
    return done.returncode == 0


@pytest.fixture(scope="module")
def unpacked(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The extension built by its own script from a copy of the folder, unpacked."""
    if not _npm_registry_reachable():
        pytest.skip("needs node, npm and the npm registry")
    root = tmp_path_factory.mktemp("vscode")
    source = root / "vscode"
    shutil.copytree(
        EXTENSION, source, ignore=shutil.ignore_patterns("node_modules", "*.vsix")
    )
    vsix = root / "robotfix.vsix"
    env = {**os.environ, "npm_config_prefer_offline": "true"}
    done = subprocess.run(
        ["sh", str(source / "build.sh"), str(vsix)],
        capture_output=True,
        text=True,
        timeout=900,
        env=env,
        check=False,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    with zipfile.ZipFile(vsix) as archive:
        archive.extractall(root / "unpacked")
    return root / "unpacked" / "extension"


def test_the_vsix_holds_the_client_and_its_runtime_dependency(unpacked: Path) -> None:
    manifest = json.loads((unpacked / "package.json").read_text())
    assert manifest["main"] == "./extension.js"
    assert "onLanguage:python" in manifest["activationEvents"]
    assert {"onLanguage:ros-msg", "onLanguage:ros-srv"} <= set(
        manifest["activationEvents"]
    )
    settings = manifest["contributes"]["configuration"]["properties"]
    assert {"robotfix.path", "robotfix.args"} <= set(settings)
    client = (unpacked / "extension.js").read_text()
    assert 'require("vscode-languageclient/node")' in client
    assert "serverCommand(settings" in client
    assert "**/*.{msg,srv,action}" in client
    modules = unpacked / "node_modules"
    assert (modules / "vscode-languageclient" / "package.json").is_file()
    assert not (modules / "@vscode" / "vsce").exists()  # a build tool only
    assert (unpacked / "readme.md").is_file() or (unpacked / "README.md").is_file()


def command_line(unpacked: Path) -> list[str]:
    """What the packaged client runs with the settings' defaults (in node)."""
    script = (
        "const dir = process.argv[1];"
        "const props = require(dir + '/package.json').contributes.configuration"
        ".properties;"
        "const settings = { get: (key) => props['robotfix.' + key].default };"
        "const { serverCommand } = require(dir + '/server-command.js');"
        "console.log(JSON.stringify(serverCommand(settings)));"
    )
    done = subprocess.run(
        ["node", "-e", script, str(unpacked)],
        capture_output=True,
        text=True,
        timeout=60,
        check=True,
    )
    found = json.loads(done.stdout)
    return [found["command"], *found["args"]]


def diagnostics_through(command: list[str], folder: Path) -> dict[str, Any]:
    # `robotfix` is found on PATH, as VS Code finds it: here, this Python's scripts
    path = os.pathsep.join([str(Path(sys.executable).parent), os.environ["PATH"]])
    client = Client(command, env={**os.environ, "PATH": path})
    try:
        client.initialize(folder)
        node = folder / "node.py"
        node.write_text(BUGGY)
        client.open(node, BUGGY)
        found = client.diagnostics()
        assert client.stop() == 0
    finally:
        client.kill()
    return found


def test_the_extensions_command_line_starts_the_language_server(
    unpacked: Path, tmp_path: Path
) -> None:
    command = command_line(unpacked)
    assert command == ["robotfix", "lsp"]
    found = diagnostics_through(command, tmp_path)
    assert [d["code"] for d in found["diagnostics"]] == ["RF201"]
    assert found["diagnostics"][0]["range"]["start"]["line"] == 5
