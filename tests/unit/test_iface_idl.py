"""`.idl` interface files (issue 10 item 2): the subset rosidl emits, its
annotations as units and refinements, discovery, and a `.idl` beside its `.msg`."""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix import rules
from robotfix.api import check_source, interface_files
from robotfix.config import Config
from robotfix.ros.catalog import MsgCatalog
from robotfix.ros.install import InstallSpace
from robotfix.ros.msg import read_interface

# the form rosidl_adapter writes for `float64 range_min  # minimum range [m]` & co.
GENERATED = """\
// generated from rosidl_adapter/resource/msg.idl.em
// with input from my_pkg/msg/Scan.msg
// generated code does not contain a copyright notice

#include "std_msgs/msg/Header.idl"

module my_pkg {
  module msg {
    module Scan_Constants {
      const uint8 MODE_A = 1;
      const int16 OFFSET = -3;
      const string LABEL = "scan \\"one\\"";
      const boolean ON = TRUE;
    };
    typedef double double__9[9];
    @verbatim (language="comment", text=
      "A scan." "\\n"
      "Second line.")
    struct Scan {
      std_msgs::msg::Header header;

      @verbatim (language="comment", text=
        "minimum range")
      @unit (value="m")
      float range_min;

      @default (value=0.5)
      @unit (value="s")
      float scan_time;

      double__9 covariance;

      sequence<float> ranges;

      sequence<string<8>, 4> names;

      @default (value="(1, 2)")
      sequence<int32> pair;

      @default (value=TRUE)
      boolean enabled;

      @default (value="hi")
      string<10> greeting;

      unsigned long long count;

      @key
      octet id;
    };
  };
};
"""


def read(text: str, name: str = "my_pkg/msg/Scan.idl"):  # type: ignore[no-untyped-def]
    return read_interface(Path(name), text)


def test_the_generated_form() -> None:
    parsed = read(GENERATED)
    assert parsed.problems == ()
    assert parsed.package == "my_pkg"
    (section,) = parsed.sections
    assert section.name == "my_pkg/Scan"
    assert [(f.name, f.type, f.array) for f in section.fields] == [
        ("header", "std_msgs/Header", False),
        ("range_min", "float32", False),
        ("scan_time", "float32", False),
        ("covariance", "float64", True),
        ("ranges", "float32", True),
        ("names", "string", True),
        ("pair", "int32", True),
        ("enabled", "bool", False),
        ("greeting", "string", False),
        ("count", "uint64", False),
        ("id", "byte", False),
    ]
    assert [(u.field, u.text, u.line) for u in section.units] == [
        ("range_min", "m", 24),
        ("scan_time", "s", 28),
    ]
    defaults = {f.name: f.default for f in section.fields if f.default is not None}
    # `pair`'s `[1, 2]` is an array default: arrays are not modelled (as in .msg)
    assert defaults == {"scan_time": Fraction(1, 2), "enabled": True, "greeting": "hi"}


def test_services_and_actions_are_one_struct_per_part() -> None:
    text = """module my_pkg { module srv {
      struct Add_Request { int64 a; int64 b; };
      struct Add_Response { int64 sum; };
    }; };"""
    parsed = read(text, "my_pkg/srv/Add.idl")
    assert [s.name for s in parsed.sections] == [
        "my_pkg/Add_Request",
        "my_pkg/Add_Response",
    ]
    text = """module my_pkg { module action {
      struct Go_Goal { float x; }; struct Go_Result { boolean ok; };
      struct Go_Feedback { float left; };
    }; };"""
    parsed = read(text, "my_pkg/action/Go.idl")
    assert [s.name for s in parsed.sections] == [
        "my_pkg/Go_Goal",
        "my_pkg/Go_Result",
        "my_pkg/Go_Feedback",
    ]


@pytest.mark.parametrize(
    ("note", "predicate"),
    [
        ("@range (min=0, max=10)", "v >= 0 and v <= 10"),
        ("@range (min=-1.5, max=.5)", "v >= -1.5 and v <= 0.5"),
        ("@min (0)", "v >= 0"),
        ("@min (value=1.)", "v >= 1.0"),
        ("@max (value=0x10)", "v <= 16"),
        ("@max ( value = 2.5d )", "v <= 2.5"),
    ],
)
def test_ranges_are_refinements(note: str, predicate: str) -> None:
    parsed = read(
        f"module p {{ module msg {{ struct S {{ {note}\n double v; }}; }}; }};"
    )
    assert parsed.problems == ()
    (line,) = parsed.sections[0].annotations
    assert (line.text, line.field) == (predicate, "v")


def test_verbatim_robotfix_lines_are_annotations() -> None:
    text = """module p { module msg {
      @verbatim (language="comment", text="doc" "\\n" "RobotFix# a <= b")
      struct S {
        @verbatim (language="comment", text="RobotFix# _ > 0")
        double a;
        @verbatim (language="comment", text="robotfix # Unit(b) == 'm'")
        double b;
        @verbatim (language="comment", text="not RobotFix# x")
        double c;
      };
    }; };"""
    parsed = read(text)
    assert [(a.text, a.field) for a in parsed.sections[0].annotations] == [
        ("a <= b", None),
        ("_ > 0", "a"),
        ("Unit(b) == 'm'", "b"),
    ]


def test_catalog_units_and_refinements(tmp_path: Path) -> None:
    path = tmp_path / "my_pkg" / "msg" / "Scan.idl"
    path.parent.mkdir(parents=True)
    path.write_text(
        GENERATED.replace("float scan_time;", "@range (min=0, max=1)\nfloat scan_time;")
    )
    catalog = MsgCatalog([path])
    spec = catalog.lookup("my_pkg/Scan")
    assert spec is not None
    assert catalog.problems == []
    assert {k: u.text for k, u in spec.units.items()} == {
        "range_min": "m",
        "scan_time": "s",
    }
    assert [i.text for i in spec.invariants] == ["scan_time >= 0", "scan_time <= 1"]


def test_a_unit_typo_is_rf502_and_a_word_is_ignored(tmp_path: Path) -> None:
    path = tmp_path / "p" / "msg" / "S.idl"
    path.parent.mkdir(parents=True)
    path.write_text(
        "module p { module msg { struct S {\n"
        '  @unit (value="meterz")\n  double a;\n'
        '  @unit (value="enum")\n  uint8 b;\n'
        "}; }; };\n"
    )
    catalog = MsgCatalog([path])
    spec = catalog.lookup("p/S")
    assert spec is not None and spec.units == {}
    assert [(p.rule, p.line, p.col) for p in catalog.problems] == [
        (rules.UNKNOWN_UNIT, 2, 2)
    ]


@pytest.mark.parametrize(
    ("text", "line", "col"),
    [
        ("module p { struct S { double; }; };", 1, 28),
        ("module p { struct S { double x }; };", 1, 31),
        ("module p { union U { }; };", 1, 11),
        ("module p { struct S { double x; };", 1, 34),
        ("module p {\n  struct S { double x; ? };\n};", 2, 23),
    ],
)
def test_problems_point_into_the_file(text: str, line: int, col: int) -> None:
    (problem,) = read(text).problems
    assert (problem.line, problem.col) == (line, col)


@settings(max_examples=100, deadline=None)
@given(
    st.text(
        alphabet=st.sampled_from(list('module p{}struct S;double x@()=<>,[]"/*\n 9')),
        max_size=120,
    )
)
def test_random_idl_never_raises(text: str) -> None:
    read(text)


def test_discovery_reads_idl_and_a_twin_idl_is_the_msg(tmp_path: Path) -> None:
    folder = tmp_path / "my_pkg" / "msg"
    folder.mkdir(parents=True)
    (folder / "Scan.msg").write_text("float32 range_min  # [m]\n")
    (folder / "Scan.idl").write_text(GENERATED)
    (folder / "Other.idl").write_text(
        "module my_pkg { module msg { struct Other { double x; }; }; };"
    )
    files = interface_files([folder])
    assert sorted(p.name for p in files) == ["Other.idl", "Scan.idl", "Scan.msg"]
    catalog = MsgCatalog(files)
    scan = catalog.lookup("my_pkg/Scan")
    assert scan is not None and list(scan.fields) == ["range_min"]  # from the .msg
    assert catalog.lookup("my_pkg/Other") is not None
    assert catalog.problems == []  # no RF510 for the twin


def test_an_installed_package_written_in_idl(tmp_path: Path) -> None:
    share = tmp_path / "install" / "share"
    folder = share / "my_pkg" / "msg"
    folder.mkdir(parents=True)
    (folder / "Scan.idl").write_text(GENERATED)
    catalog = MsgCatalog([], installed=InstallSpace([share]))
    scan = catalog.lookup("my_pkg/Scan")
    assert scan is not None and scan.units["range_min"].text == "m"
    (folder / "Scan.msg").write_text("float64 other\n")
    catalog = MsgCatalog([], installed=InstallSpace([share]))
    scan = catalog.lookup("my_pkg/Scan")
    assert scan is not None and list(scan.fields) == ["other"]  # the .msg first


def test_an_idl_default_is_the_value_of_a_field_never_set(tmp_path: Path) -> None:
    idl = tmp_path / "grip" / "msg" / "Grip.idl"
    idl.parent.mkdir(parents=True)
    idl.write_text(
        "module grip { module msg { struct Grip {\n"
        '  @verbatim (language="comment", text="RobotFix# _ > 0")\n'
        "  @default (value=0.5)\n"
        "  double force;\n"
        '  @verbatim (language="comment", text="RobotFix# _ > 0")\n'
        "  double width;\n"
        "}; }; };\n"
    )
    node = (
        "from grip.msg import Grip\n\n\ndef send(pub) -> None:\n"
        "    pub.publish(Grip())\n"
    )
    found = check_source(node, "node.py", Config(msg_paths=(tmp_path,)))
    # force's default 0.5 keeps `_ > 0`; width's 0.0 does not
    assert [(d.code, d.span.line) for d in found] == [("RF302", 5)]
    assert "width" in found[0].message and "force" not in found[0].message
