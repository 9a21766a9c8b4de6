"""Units in interface comments, by rosidl's rule (issue 10 item 1).

The cases are written from rosidl_adapter's documented behaviour: a field's comments
are the first-column comment lines since the previous element, its trailing comment
and the indented comment lines below it; the message's leading comment block is the
message's; exactly one `[...]` without a comma is the unit.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix import rules
from robotfix.annotations.units import resolve
from robotfix.ros.catalog import MsgCatalog
from robotfix.ros.comments import comment_units, unit_in
from robotfix.ros.msg import read_interface

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

ROS = Path(__file__).resolve().parents[2] / "src" / "robotfix" / "ros"


def units(text: str, suffix: str = ".msg") -> list[dict[str, str]]:
    parsed = read_interface(Path(f"pkg/msg/M{suffix}"), text)
    return [{u.field: u.text for u in s.units} for s in parsed.sections]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("float32 range_min  # minimum range value [m]\n", {"range_min": "m"}),
        ("int32 a\n# time since start [s]\nfloat64 t\n", {"t": "s"}),
        ("int32 a\n# speed [m/s]\n\n\nfloat64 v\n", {"v": "m/s"}),
        ("int32 a\n# [m]\nfloat64 d  # and [cm]\n", {}),  # two units: none
        ("float64 x  # in [0, 1]\n", {}),  # a comma: a range, not a unit
        ("float64 x  # in [0, 1] [m]\n", {"x": "m"}),  # only one without a comma
        ("float64 x  # [ m ]\n", {"x": "m"}),
        ("float64 x  # []\n", {}),
        ("int32 a\n#[rad]\nfloat64 yaw\n", {"yaw": "rad"}),
        ("float64 x  ## [Hz]\n", {"x": "Hz"}),
    ],
)
def test_one_field_one_unit(text: str, expected: dict[str, str]) -> None:
    assert units(text) == [expected]


def test_brackets_may_span_comment_lines() -> None:
    """As in rosidl, the comments are joined before the search; the catalog then
    drops such a `unit` (pint never sees a line break)."""
    assert units("float64 x  # the [deg\n  # rees]\n") == [{"x": "deg\n rees"}]


def test_the_leading_comment_block_is_the_messages() -> None:
    assert units("# Mass [kg]\nfloat64 m\n") == [{}]
    assert units("# About this message\n\n# Mass [kg]\nfloat64 m\n") == [{"m": "kg"}]
    # a first-column comment block ends at the first line that is not one
    assert units("#\n# [kg]\n\nfloat64 m\n") == [{}]


def test_indented_comments_continue_the_element_above() -> None:
    text = "float32 fov   # the size of the arc\n              # valid for [rad]\n"
    assert units(text) == [{"fov": "rad"}]
    text = "uint8 kind  # the kind\n            # [enum]\nfloat32 r  # [m]\n"
    assert units(text) == [{"kind": "enum", "r": "m"}]
    # before any field an indented comment belongs to nothing
    assert units("int32 a\n   # [s]\n") == [{"a": "s"}]
    assert units("\n   # [s]\nint32 a\n") == [{}]
    assert units("float64 x\n\t# [s]\n") == [{"x": "s"}]  # a tab counts as a blank


def test_comments_go_to_the_next_element_even_a_constant() -> None:
    assert units("int32 a\n# [m]\nuint8 MODE=1\nfloat64 x\n") == [{}]
    assert units("int32 a\nuint8 MODE=1  # [m]\nfloat64 x\n") == [{}]
    # comments after the last element belong to nothing
    assert units("float64 x\n# [m]\n") == [{}]


def test_each_part_of_a_service_has_its_own_leading_comment() -> None:
    text = "# [m]\nfloat64 a\n---\n# [s]\nfloat64 b\n\n# [s]\nfloat64 c\n"
    assert units(text, ".srv") == [{}, {"c": "s"}]
    action = "float64 a # [m]\n---\nfloat64 b # [s]\n---\nfloat64 c # [Hz]\n"
    assert units(action, ".action") == [{"a": "m"}, {"b": "s"}, {"c": "Hz"}]


def test_the_unit_is_found_on_its_line() -> None:
    text = "int32 a\n# distance\n# to the goal [m]\nfloat64 d\n"
    parsed = read_interface(Path("p/msg/M.msg"), text)
    assert [(u.field, u.line) for u in parsed.sections[0].units] == [("d", 3)]
    assert unit_in([(7, "a [m]"), (8, "b")]) == (7, "m")
    assert unit_in([(7, "a"), (8, "[m] [s]")]) is None


def test_optional_and_deprecated_fields_keep_their_units() -> None:
    text = "int32 a\n# @deprecated\nfloat64 old  # [s]\n@optional float64 t  # [ms]\n"
    assert units(text) == [{"old": "s", "t": "ms"}]


@settings(max_examples=30, deadline=None)
@given(
    unit=st.sampled_from(["m", "s", "rad", "m/s", "kg*m^2", "degC", "Hz"]),
    above=st.booleans(),
    blanks=st.integers(0, 2),
    words=st.text(st.sampled_from("abc xyz.-"), max_size=12),
)
def test_a_unit_is_read_wherever_its_comment_is(
    unit: str, above: bool, blanks: int, words: str
) -> None:
    if above:
        text = f"int32 first\n# {words} [{unit}]\n" + "\n" * blanks + "float64 v\n"
    else:
        text = f"int32 first\nfloat64 v  # {words} [{unit}] {words}\n"
    assert units(text) == [{"v": unit}]
    assert units(text.replace("float64 v", "float64 v  # and [x]")) == [{}]


@settings(max_examples=50, deadline=None)
@given(st.lists(st.text(max_size=40), max_size=8))
def test_random_lines_never_raise(lines: list[str]) -> None:
    comment_units(list(enumerate(lines, start=1)))


# -- the catalog ---------------------------------------------------------------


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / "my_pkg" / "msg" / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


def test_a_comment_unit_is_the_fields_unit(tmp_path: Path) -> None:
    path = write(
        tmp_path,
        "Sonar.msg",
        "std_msgs/Header header\n"
        "float32 distance  # measured distance [m]\n"
        "float32 rate  # [cells]\n"  # not a unit: ignored
        "uint8 kind  # [enum]\n"
        "string label  # [m]\n",  # not a number: ignored
    )
    catalog = MsgCatalog([path])
    spec = catalog.lookup("my_pkg/Sonar")
    assert spec is not None
    assert {k: u.text for k, u in spec.units.items()} == {"distance": "m"}
    assert spec.units["distance"].origin is not None
    assert spec.units["distance"].origin.line == 2
    assert catalog.problems == []


def test_a_robotfix_unit_overrides_a_comment_unit(tmp_path: Path) -> None:
    path = write(
        tmp_path,
        "Cmd.msg",
        "float64 speed  # wheel speed [rpm]\n"
        '#RobotFix# Unit(speed) == "rad/s"\n'
        'float64 angle #RobotFix# Unit(angle) == "degree"  # [deg]\n',
    )
    catalog = MsgCatalog([path])
    spec = catalog.lookup("my_pkg/Cmd")
    assert spec is not None
    assert spec.units["speed"].text == "rad/s"
    assert spec.units["angle"].text == "degree"
    assert catalog.problems == []


def test_two_robotfix_units_still_conflict_after_a_comment(tmp_path: Path) -> None:
    path = write(
        tmp_path,
        "Cmd.msg",
        "float64 speed  # [rpm]\n"
        '#RobotFix# Unit(speed) == "rad/s"\n'
        '#RobotFix# Unit(speed) == "m/s"\n',
    )
    catalog = MsgCatalog([path])
    catalog.lookup("my_pkg/Cmd")
    assert [p.rule for p in catalog.problems] == [rules.MISPLACED_UNIT]


def test_standard_messages_carry_their_comment_units() -> None:
    catalog = MsgCatalog([], rep103=False)
    scan = catalog.lookup("sensor_msgs/LaserScan")
    assert scan is not None
    assert scan.units["range_min"].text == "m"
    assert "LaserScan.msg comment" in scan.units["range_min"].source
    fix = catalog.lookup("sensor_msgs/NavSatFix")
    assert fix is not None and fix.units["latitude"].text == "degrees"
    range_ = catalog.lookup("sensor_msgs/Range")
    assert range_ is not None and range_.units["field_of_view"].text == "rad"
    assert "radiation_type" not in range_.units  # `[enum]` is not a unit


def test_rep103_agrees_with_the_comment_units() -> None:
    """Where REP 103's table and a standard message's comment both give a field a
    unit, they are the same unit (no disagreement exists today)."""
    table = tomllib.loads((ROS / "rep103.toml").read_text(encoding="utf-8"))
    comments = tomllib.loads((ROS / "comment_units.toml").read_text(encoding="utf-8"))
    by_type = {entry["type"]: entry["units"] for entry in comments["message"]}
    both = 0
    disagree = []
    for entry in table["message"]:
        for field, unit in entry["units"].items():
            other = by_type.get(entry["type"], {}).get(field)
            if other is None:
                continue
            both += 1
            if not resolve(unit).same_as(resolve(other)):
                disagree.append((entry["type"], field, unit, other))
    assert both >= 12
    assert disagree == []


def test_the_bundled_comment_units_are_units() -> None:
    comments = tomllib.loads((ROS / "comment_units.toml").read_text(encoding="utf-8"))
    for entry in comments["message"]:
        for unit in entry["units"].values():
            assert not resolve(unit).is_label
        assert set(entry["comments"]) == set(entry["units"])
