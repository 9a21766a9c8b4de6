"""Constants and default values: interface files, the catalog, the analysis."""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import pytest

from robotfix import rules
from robotfix.ros.catalog import MsgCatalog
from robotfix.ros.msg import literal_of, read_interface

DRIVE = """\
uint8 MODE_MANUAL=1
uint8 MODE_AUTO = 2  # as mavros writes them
string NAME="drive"
float64 MAX_SPEED = 0.22
uint8 mode #RobotFix# _ == MODE_MANUAL or _ == MODE_AUTO
float64 speed 0.5 #RobotFix# 0 < speed <= MAX_SPEED
bool enabled true
string label "none"
int32[] ids [1, 2]
float64 heading #RobotFix# abs(heading) <= math.pi
"""


def test_constants_and_defaults_are_read_by_type() -> None:
    section = read_interface(Path("p/msg/Drive.msg"), DRIVE).sections[0]
    assert [(c.name, c.value) for c in section.constants] == [
        ("MODE_MANUAL", 1),
        ("MODE_AUTO", 2),
        ("NAME", "drive"),
        ("MAX_SPEED", Fraction(22, 100)),
    ]
    defaults = {f.name: f.default for f in section.fields}
    assert defaults == {
        "mode": None,
        "speed": Fraction(1, 2),
        "enabled": True,
        "label": "none",
        "ids": None,  # array defaults are not modelled
        "heading": None,
    }


@pytest.mark.parametrize(
    ("type_", "text", "value"),
    [
        ("uint8", "253", 253),
        ("int8", "-2", -2),
        ("uint16", "0x1F", 31),
        ("float64", "0.1", Fraction(1, 10)),  # exact, as in annotations
        ("float32", "1e-3", Fraction(1, 1000)),
        ("float64", "inf", None),  # valid, not modelled
        ("bool", "False", False),
        ("bool", "1", True),
        ("string", "'quoted'", "quoted"),
        ("string", "unquoted ROS 1 text", "unquoted ROS 1 text"),
        ("geometry_msgs/Point", "1", None),
    ],
)
def test_literal_of(type_: str, text: str, value: object) -> None:
    assert literal_of(type_, text) == value


def test_bad_values_are_interface_problems(tmp_path: Path) -> None:
    path = tmp_path / "p" / "msg" / "Bad.msg"
    path.parent.mkdir(parents=True)
    path.write_text("uint8 A=x\nfloat64 speed fast\n  bool b maybe\n")
    catalog = MsgCatalog([path])
    catalog.lookup("p/Bad")
    found = sorted((p.rule.code, p.line, p.col) for p in catalog.problems)
    code = rules.MALFORMED_INTERFACE.code
    assert found == [(code, 1, 0), (code, 2, 0), (code, 3, 2)]


def test_catalog_puts_constants_into_refinements(tmp_path: Path) -> None:
    path = tmp_path / "p" / "msg" / "Drive.msg"
    path.parent.mkdir(parents=True)
    path.write_text(DRIVE)
    catalog = MsgCatalog([path])
    spec = catalog.lookup("p/Drive")
    assert spec is not None and not catalog.problems
    assert spec.constants["MODE_AUTO"] == ("uint8", 2)
    assert spec.fields["speed"].default == Fraction(1, 2)
    texts = {inv.text: inv.paths for inv in spec.invariants}
    # the text keeps the names; the predicate holds the values
    assert texts == {
        "mode == MODE_MANUAL or mode == MODE_AUTO": {"mode"},
        "0 < speed": {"speed"},
        "speed <= MAX_SPEED": {"speed"},
        "abs(heading) <= math.pi": {"heading"},
    }


def test_standard_constants_and_ros2_defaults() -> None:
    catalog = MsgCatalog([])
    assert catalog.lookup("sensor_msgs/Range").constants["ULTRASOUND"] == ("uint8", 0)
    status = catalog.lookup("action_msgs/GoalStatus")
    assert status is not None and status.constants["STATUS_SUCCEEDED"][1] == 4
    w = catalog.lookup("geometry_msgs/Quaternion").fields["w"]
    assert (w.default, w.std_default) == (1, True)
    # NavSatStatus.status defaults to STATUS_UNKNOWN since Jazzy, not in Humble
    jazzy = catalog.lookup("sensor_msgs/NavSatStatus").fields["status"]
    humble = MsgCatalog([], distro="humble").lookup("sensor_msgs/NavSatStatus")
    assert jazzy.default == -2 and humble.fields["status"].default is None
    # ROS 1 has no default values
    noetic = MsgCatalog([], distro="noetic").lookup("geometry_msgs/Quaternion")
    assert noetic.fields["w"].default is None
