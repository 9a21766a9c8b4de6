"""The interface file reader and the catalog built on rosbags' standard messages."""

from __future__ import annotations

from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix import rules
from robotfix.ros.catalog import MsgCatalog
from robotfix.ros.msg import read_interface


def test_both_header_forms_and_the_path() -> None:
    assert (
        read_interface(Path("x/T.msg"), "geometry_msgs/Twist.msg\n").sections[0].name
        == "geometry_msgs/Twist"
    )
    assert (
        read_interface(Path("x/T.msg"), "[std_msgs/Int32]:\nint32 data\n")
        .sections[0]
        .name
        == "std_msgs/Int32"
    )
    assert (
        read_interface(Path("my_pkg/msg/Cmd.msg"), "float64 v\n").sections[0].name
        == "my_pkg/Cmd"
    )


def test_annotations_standalone_and_end_of_line() -> None:
    text = "[p/M]:\nfloat64 a #RobotFix# a > 0\n#RobotFix# Unit(a) == 'm'\nint32 K=3\n"
    section = read_interface(Path("M.msg"), text).sections[0]
    assert [f.name for f in section.fields] == ["a"]
    assert [(a.text, a.line) for a in section.annotations] == [
        ("a > 0", 2),
        ("Unit(a) == 'm'", 3),
    ]


def test_service_and_action_sections() -> None:
    srv = read_interface(Path("p/srv/Add.srv"), "int64 a\n---\nint64 sum\n")
    assert [s.name for s in srv.sections] == ["p/Add_Request", "p/Add_Response"]
    action = read_interface(
        Path("p/action/Go.action"), "int32 g\n---\nint32 r\n---\nint32 f\n"
    )
    assert [s.name for s in action.sections] == [
        "p/Go_Goal",
        "p/Go_Result",
        "p/Go_Feedback",
    ]


def test_standard_messages_without_ros(tmp_path: Path) -> None:
    catalog = MsgCatalog([])
    twist = catalog.lookup("geometry_msgs/msg/Twist")
    assert twist is not None and twist.units["linear.x"].text == "m/s"
    assert catalog.field_at("nav_msgs/Odometry", "twist.twist.linear.x") is not None
    assert catalog.lookup("std_msgs/Int32") is not None
    assert MsgCatalog([], rep103=False).lookup("geometry_msgs/Twist").units == {}


def test_annotation_problems_point_into_the_file(tmp_path: Path) -> None:
    path = tmp_path / "Twist.msg"
    path.write_text(
        "geometry_msgs/Twist.msg\nVector3 linear\n#RobotFix# linear.q > 0\n"
        '#RobotFix# Unit(linear.x) == "meterz"\n#RobotFix# linear.x > > 0\n'
    )
    catalog = MsgCatalog([path])
    catalog.lookup("geometry_msgs/Twist")
    found = sorted((p.rule.code, p.line, p.col) for p in catalog.problems)
    assert found == [
        (rules.ANNOTATION_SYNTAX.code, 5, 22),
        (rules.UNKNOWN_UNIT.code, 4, 11),
        (rules.UNKNOWN_FIELD.code, 3, 11),
    ]


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=200))
def test_random_text_never_raises(text: str) -> None:
    read_interface(Path("p/msg/R.msg"), text)


def test_underscore_is_the_field_of_its_line_only(tmp_path: Path) -> None:
    path = tmp_path / "Cmd.msg"
    path.write_text(
        "pkg/Cmd.msg\n"
        'float64 speed #RobotFix# Unit(_) == "m/s" and _ <= 1.5\n'
        'geometry_msgs/Vector3 accel #RobotFix# Unit(_.x) == "m/s^2" and _.x < 3\n'
        "#RobotFix# _ > 0\n"
    )
    catalog = MsgCatalog([path])
    spec = catalog.lookup("pkg/Cmd")
    assert spec.units["speed"].text == "m/s"
    assert spec.units["accel.x"].text == "m/s^2"
    assert sorted(i.text for i in spec.invariants) == ["accel.x < 3", "speed <= 1.5"]
    found = [(p.rule.code, p.line, p.message) for p in catalog.problems]
    assert found == [(rules.UNKNOWN_FIELD.code, 4, "`_` is not a field of pkg/Cmd")]
