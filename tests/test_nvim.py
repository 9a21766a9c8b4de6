"""`robotfix lsp` driven by a real editor client: headless Neovim (its built-in LSP
client, `tests/nvim_session.lua`) opens a node, gets its diagnostics, edits a
line, asks for a hover and for the code actions at the edited line, and applies
none of them (issue 24 item 2). Marked slow; skipped when `nvim` is not on PATH
(CI has none: `apt install neovim` gives 0.7.2 on Debian 12, which is enough)."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import robotfix

pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(
        shutil.which("nvim") is None, reason="needs Neovim (`nvim` is not on PATH)"
    ),
]

SESSION = Path(__file__).parent / "nvim_session.lua"
NODE = """from typing import Annotated

from geometry_msgs.msg import Twist

speed: Annotated[float, "Unit('km/h')"] = 3.0
cmd = Twist()
cmd.linear.y = 0.0
"""


def test_neovim_opens_edits_hovers_and_gets_a_quick_fix(tmp_path: Path) -> None:
    node = tmp_path / "node.py"
    node.write_text(NODE)
    out = tmp_path / "session.json"
    env = dict(
        os.environ,
        RF_FILE=str(node),
        RF_OUT=str(out),
        RF_CMD=json.dumps([sys.executable, "-m", "robotfix", "lsp"]),
        RF_EDIT_LINE="7",
        RF_EDIT_TEXT="cmd.linear.x = speed",
        RF_AT_LINE="6",  # 0-based: the edited line
        RF_AT_COL="15",  # `speed`
        XDG_CACHE_HOME=str(tmp_path / "cache"),
        XDG_CONFIG_HOME=str(tmp_path / "config"),  # no user init.lua
        XDG_STATE_HOME=str(tmp_path / "state"),
        # the robotfix under test, wherever the server process starts
        PYTHONPATH=os.pathsep.join(
            [str(Path(robotfix.__file__).parents[1]), os.environ.get("PYTHONPATH", "")]
        ),
    )
    subprocess.run(
        [
            "nvim",
            "--headless",
            "-u",
            "NONE",
            "-i",
            "NONE",
            "-n",
            "-c",
            f"luafile {SESSION}",
        ],
        env=env,
        cwd=tmp_path,
        stdin=subprocess.DEVNULL,
        capture_output=True,
        timeout=180,
        check=False,
    )
    seen = json.loads(out.read_text())
    assert seen["opened"] == []  # vim.json_encode writes an empty list as []
    (mismatch,) = seen["edited"]
    assert mismatch["code"] == "RF201" and "divide by 3.6" in mismatch["message"]
    assert mismatch["range"]["start"]["line"] == 6
    assert "km/h" in seen["hover"]["contents"]["value"]
    titles = [action["title"] for action in seen["actions"]]
    assert titles[:2] == [
        "RobotFix: Convert with `/ 3.6`",
        "RobotFix: Silence RF201 on this line",
    ]
    (edit,) = seen["actions"][0]["edit"]["changes"][node.as_uri()]
    assert edit["newText"] == "speed / 3.6"
    times = seen["times"]
    assert times["lua"] <= times["opened"] <= times["edited"] <= times["acted"]
