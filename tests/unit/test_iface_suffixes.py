"""Unit naming conventions (Autoware's message guidelines) as an opt-in setting:
`unit-suffixes = true` or `--unit-suffixes` gives interface fields named `*_ms`,
`*_deg`, `*_kmph`, ... those units (issue 10 item 1)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from robotfix.api import check_source
from robotfix.config import Config, ConfigError, load
from robotfix.ros.catalog import MsgCatalog, suffix_unit

MSG = (
    "float64 timeout_ms\n"
    "float64 heading_deg  # compass heading [rad]\n"  # the comment wins
    'float64 limit_kmph #RobotFix# Unit(limit_kmph) == "m/s"\n'  # and the annotation
    "float64 range_min\n"  # `_min` is a minimum, not minutes
    "float64 torque_nm\n"  # newton metres, not nanometres
    "string name_ms\n"  # not a number
    "float64 _ms\n"
)

NODE = """from typing import Annotated
from my_pkg.msg import Limits


def fill(wait: Annotated[float, "Unit('s')"], pub) -> None:
    msg = Limits()
    msg.timeout_ms = wait
    msg.timeout_ms = wait * 1000
    pub.publish(msg)
"""


@pytest.fixture
def msg_folder(tmp_path: Path) -> Path:
    folder = tmp_path / "my_pkg" / "msg"
    folder.mkdir(parents=True)
    (folder / "Limits.msg").write_text(MSG, encoding="utf-8")
    return folder


@pytest.mark.parametrize(
    ("name", "unit"),
    [
        ("timeout_ms", "ms"),
        ("angle_deg", "degree"),
        ("speed_kmph", "km/h"),
        ("wait_us", "us"),
        ("stamp_ns", "ns"),
        ("gap_mm", "mm"),
        ("route_km", "km"),
        ("drift_um", "um"),
        ("uptime_hour", "hour"),
        ("range_min", None),
        ("torque_nm", None),
        ("status", None),
        ("_ms", None),
        ("msgs", None),
    ],
)
def test_suffixes(name: str, unit: str | None) -> None:
    assert suffix_unit(name) == unit


def test_only_when_asked(msg_folder: Path) -> None:
    spec = MsgCatalog([msg_folder / "Limits.msg"]).lookup("my_pkg/Limits")
    assert spec is not None
    assert {k: u.text for k, u in spec.units.items()} == {
        "heading_deg": "rad",
        "limit_kmph": "m/s",
    }
    catalog = MsgCatalog([msg_folder / "Limits.msg"], unit_suffixes=True)
    spec = catalog.lookup("my_pkg/Limits")
    assert spec is not None
    assert {k: u.text for k, u in spec.units.items()} == {
        "timeout_ms": "ms",
        "heading_deg": "rad",
        "limit_kmph": "m/s",
    }
    assert catalog.problems == []


def test_a_check_uses_the_suffix_unit(msg_folder: Path) -> None:
    plain = check_source(NODE, "node.py", Config(msg_paths=(msg_folder,)))
    assert plain == []
    config = Config(msg_paths=(msg_folder,), unit_suffixes=True)
    found = check_source(NODE, "node.py", config)
    assert [(d.code, d.span.line) for d in found] == [("RF201", 7)]


def test_the_setting_and_the_flag(msg_folder: Path, tmp_path: Path) -> None:
    (tmp_path / "node.py").write_text(NODE, encoding="utf-8")
    args = [sys.executable, "-m", "robotfix", "check", "node.py"]
    args += ["--msg-path", str(msg_folder)]

    def run(*extra: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run(
            [*args, *extra], cwd=tmp_path, capture_output=True, text=True, timeout=120
        )

    assert run().returncode == 0
    flagged = run("--unit-suffixes")
    assert flagged.returncode == 1 and "RF201" in flagged.stdout
    (tmp_path / "pyproject.toml").write_text("[tool.robotfix]\nunit-suffixes = true\n")
    assert load(tmp_path / "node.py").unit_suffixes
    assert run().returncode == 1
    (tmp_path / "pyproject.toml").write_text('[tool.robotfix]\nunit-suffixes = "y"\n')
    with pytest.raises(ConfigError, match="unit-suffixes"):
        load(tmp_path / "node.py")


def test_parameter_names_follow_the_setting_too() -> None:
    node = (
        "from typing import Annotated\n"
        "from rclpy.node import Node\n\n\n"
        "class Stepper(Node):\n"
        "    def __init__(self) -> None:\n"
        "        super().__init__('stepper')\n"
        "        self.declare_parameter('period_ms', 100.0)\n"
        "        period = self.get_parameter('period_ms').value\n"
        "        wait: Annotated[float, \"Unit('s')\"] = period\n"
    )
    flagged = check_source(node, "stepper.py", Config(unit_suffixes=True))
    assert [(d.code, d.span.line) for d in flagged] == [("RF201", 10)]
    assert "ms" in flagged[0].message
    assert check_source(node, "stepper.py", Config()) == []
