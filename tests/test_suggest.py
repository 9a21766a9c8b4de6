"""`robotfix suggest`: proposals from flows, a diff, and a careful --apply."""

from __future__ import annotations

from pathlib import Path

from robotfix.ros.catalog import MsgCatalog
from robotfix.suggest import annotate
from tests.test_cli import run

NODE = '''"""Doc."""
from geometry_msgs.msg import Twist


def drive(pub, requested):
    speed = requested * 0.5
    turn = 0.2
    both = 1.0
    cmd = Twist()
    cmd.linear.x = speed
    cmd.angular.z = turn
    cmd.linear.y = both
    cmd.angular.x = both
    pub.publish(cmd)
'''


def test_units_from_flows_and_nothing_else_changes() -> None:
    changed = annotate(NODE, "node.py", MsgCatalog([]))
    assert "    speed: Annotated[float, \"Unit('m/s')\"] = requested * 0.5\n" in changed
    assert "    turn: Annotated[float, \"Unit('rad/s')\"] = 0.2\n" in changed
    assert "    both = 1.0\n" in changed  # flows into m/s and rad/s: no proposal
    assert changed.splitlines()[1] == "from typing import Annotated"
    assert len(changed.splitlines()) == len(NODE.splitlines()) + 1


def test_diff_then_apply(tmp_path: Path) -> None:
    node = tmp_path / "node.py"
    node.write_text(NODE)
    diff = run("suggest", "node.py", cwd=tmp_path)
    assert diff.returncode == 0
    assert diff.stdout.startswith("--- a/node.py\n+++ b/node.py\n")
    assert node.read_text() == NODE  # only printed
    assert run("suggest", "node.py", "--apply", cwd=tmp_path).returncode == 0
    assert "Unit('rad/s')" in node.read_text()
    assert run("check", "node.py", cwd=tmp_path).returncode == 0
    again = run("suggest", "node.py", cwd=tmp_path)
    assert again.stdout == "No suggestions in 1 file.\n"  # nothing left
