"""Constants and default values: interface files, the catalog, the analysis."""

from __future__ import annotations

import ast
import textwrap
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix import rules
from robotfix.analysis.constants import ConstantNames, scan
from robotfix.analysis.index import index_module
from robotfix.api import check_source
from robotfix.config import Config
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


# -- constants in code ------------------------------------------------------------


def check(source: str) -> list[tuple[int, str]]:
    found = check_source(textwrap.dedent(source), "node.py", Config())
    return [(d.span.line, d.code) for d in found]


def names(source: str, walrus: bool = True) -> ConstantNames:
    tree = ast.parse(textwrap.dedent(source))
    index = index_module(tree)
    qualname = lambda node: index.imports.get(getattr(node, "id", ""))  # noqa: E731
    return scan(tree, index, qualname, walrus)


@pytest.mark.parametrize("walrus", [True, False])
def test_scan_keeps_names_bound_once_and_never_changed(walrus: bool) -> None:
    found = names(
        """
        from typing import Final
        A = 1
        B = 1
        B = 2
        C = 0
        D = {"k": 1}
        E = {"k": 1}
        F = [1, 2]
        G = {"k": 1}
        alias = G
        for i in range(3):
            H = i

        def bump():
            global C
            C += 1

        def change():
            E["k"] = 2
            F.append(3)

        def read(key):
            return D[key] + D.get(key, 0) + len(D) + (key in D)

        class Base:
            MAX = 1.0
            SHARED = 2.0
            STORED = 3.0
            LIMIT: Final = 4.0

            def __init__(self):
                self.STORED = 0.0

        class Sub(Base):
            SHARED = 5.0
            LIMIT: Final = 6.0

        try:
            import numpy as np
        except ImportError:
            np = None
        with open("f") as handle:
            K, (L, *M) = 1, (2, 3)
        """,
        walrus,
    )
    assert {"A", "D", "H", "handle", "K", "L", "M"} <= found.module
    assert "np" not in found.module
    assert not {"B", "C"} & found.module
    assert found.changed_globals == {"C"}
    assert found.read_only == {"D"}
    # SHARED is overridden, STORED is set on instances; Final forbids overriding
    assert found.classes["Base"] - {"__init__"} == {"MAX", "LIMIT"}
    assert found.classes["Sub"] == {"LIMIT"}


def test_a_walrus_rebinds() -> None:
    found = names("W = 1\nif (W := 2) > 1:\n    pass\n")
    assert "W" not in found.module


def test_setattr_with_a_computed_name_keeps_no_class_constant() -> None:
    found = names(
        """
        class Node:
            MAX = 1.0
            def load(self, name, value):
                setattr(self, name, value)
        """
    )
    assert found.classes == {}


@pytest.mark.parametrize(
    "limit",
    [
        "LIMIT",  # a constant
        "PARAM",  # a module name read from the parameter server
        "self.limit",  # an attribute
        "Node.MAX",  # a class constant
        "limit",  # a parameter
    ],
)
def test_min_of_a_limit_is_below_the_limit(limit: str) -> None:
    source = f"""
        from typing import Annotated
        import rospy
        LIMIT = 0.5
        PARAM = rospy.get_param("~limit", 0.5)

        class Node:
            MAX = 2.0
            def __init__(self, limit: float):
                self.limit = limit

            def go(self, x: float, limit: float):
                v: Annotated[float, "_ <= {limit}"] = min({limit}, x)
                w: Annotated[float, "_ <= {limit}"] = max(x, {limit})  # RF102
        """
    assert check(source) == [(14, "RF102")]


def test_a_local_shadows_a_constant_in_refinements() -> None:
    source = """
        from typing import Annotated
        LIMIT = 1.0

        def f():
            LIMIT = 5.0
            v: Annotated[float, "_ <= LIMIT"] = 4.0

        def g():
            v: Annotated[float, "_ <= LIMIT"] = 4.0
        """
    assert check(source) == [(10, "RF101")]


def test_infinity_is_above_every_float_and_shown_as_inf() -> None:
    source = """
        import math
        from typing import Annotated

        def f(x: Annotated[float, "abs(_) <= 1e300"]):
            finite: Annotated[float, "_ < math.inf"] = x
            low: Annotated[float, "_ > -math.inf"] = float("-inf")
            big: Annotated[float, "_ <= 1e308"] = math.inf
        """
    found = check_source(textwrap.dedent(source), "node.py", Config())
    assert [(d.span.line, d.code) for d in found] == [(7, "RF101"), (8, "RF101")]
    assert found[0].message.endswith(": here `low` = -inf")


def test_numbers_near_infinity_neither_crash_nor_print_400_digits() -> None:
    source = """
        import math
        from typing import Annotated

        def f(v: Annotated[float, "Unit('m')"], w: Annotated[float, "_ >= 1"]):
            scaled = v * math.inf
            third: Annotated[float, "_ <= 10"] = math.inf / 3
            above: Annotated[float, "_ <= 10"] = math.inf / w
        """
    found = check_source(textwrap.dedent(source), "node.py", Config())
    assert [(d.span.line, d.code) for d in found] == [(7, "RF101"), (8, "RF102")]
    assert found[0].message.endswith(": here `third` = inf")
    assert len(" ".join(d.message for d in found)) < 1000


ENTRY = st.fractions(min_value=-5, max_value=5, max_denominator=4)


@settings(max_examples=25, deadline=None)
@given(
    table=st.dictionaries(
        st.sampled_from("ijklm,."), st.tuples(ENTRY, ENTRY), min_size=1, max_size=5
    ),
    bounds=st.tuples(ENTRY, ENTRY).map(sorted),
    column=st.integers(0, 1),
)
def test_a_lookup_with_an_unknown_key_is_one_of_the_entries(
    table: dict[str, tuple[Fraction, Fraction]],
    bounds: list[Fraction],
    column: int,
) -> None:
    low, high = bounds
    shown = ", ".join(f"{k!r}: ({_dec(a)}, {_dec(b)})" for k, (a, b) in table.items())
    key = next(iter(table))
    refined = f'Annotated[float, "{_dec(low)} <= _ <= {_dec(high)}"]'
    source = f"""
        from typing import Annotated
        BINDINGS = {{{shown}}}

        def on_key(key: str):
            v: {refined} = BINDINGS[key][{column}]

        def on_known_key():
            w: {refined} = BINDINGS[{key!r}][{column}]
        """
    entries = [entry[column] for entry in table.values()]
    expected = [(6, code) for code in _verdict(entries, low, high)]
    expected += [(9, code) for code in _verdict([table[key][column]], low, high)]
    assert check(source) == expected


def _verdict(values: list[Fraction], low: Fraction, high: Fraction) -> list[str]:
    """What checking `low <= _ <= high` part by part reports for a value that may
    be any of `values`: an error for a part none keeps, a warning for one some keep."""
    for keeps in (lambda v: low <= v, lambda v: v <= high):
        kept = [keeps(v) for v in values]
        if not any(kept):
            return ["RF101"]
        if not all(kept):
            return ["RF102"]
    return []


def _dec(value: Fraction) -> str:
    """An exact decimal literal (denominators are powers of 2 here)."""
    return str(value.numerator) if value.denominator == 1 else repr(float(value))


DECIMAL = st.decimals(min_value=-100, max_value=100, places=2, allow_nan=False)


@settings(max_examples=25, deadline=None)
@given(
    first=DECIMAL,
    steps=st.lists(st.tuples(st.sampled_from("+-*"), DECIMAL), min_size=1, max_size=4),
)
def test_module_arithmetic_of_constants_is_exact_in_functions(
    first: object, steps: list[tuple[str, object]]
) -> None:
    lines = [f"C0 = {first}"]
    value = Fraction(str(first))
    for index, (op, operand) in enumerate(steps, start=1):
        lines.append(f"C{index} = C{index - 1} {op} {operand}")
        right = Fraction(str(operand))
        value = {"+": value + right, "-": value - right, "*": value * right}[op]
    last = f"C{len(steps)}"
    exact = f"{value.numerator} / {value.denominator}"
    source = "\n".join(
        [
            "from typing import Annotated",
            *lines,
            "def f():",
            f'    same: Annotated[float, "_ == {exact}"] = {last}',
            f'    other: Annotated[float, "_ != {exact}"] = {last}',
        ]
    )
    assert check(source) == [(len(lines) + 4, "RF101")]


def test_class_tables_are_not_looked_up() -> None:
    # `self.TABLE[k] = v` would change it, which the scan does not follow
    source = """
        from typing import Annotated

        class Teleop:
            TABLE = {"a": (1,), "b": (2,)}
            SPEEDS = (0.1, 0.2)

            def on_key(self, key: str, i: int):
                x: Annotated[int, "_ <= 2"] = self.TABLE[key][0]
                v: Annotated[float, "_ <= 0.2"] = self.SPEEDS[i]
        """
    assert check(source) == [(9, "RF102")]


def test_a_tuple_is_not_a_number_but_fills_an_array_field() -> None:
    source = """
        from typing import Annotated
        from sensor_msgs.msg import LaserScan

        def f():
            x: Annotated[float, "_ > 0"] = (1.0, 2.0)
            scan = LaserScan()
            scan.ranges = [1.0, 2.0]
            scan.intensities = (1.0,)
            scan.range_max = (5.0,)
        """
    assert check(source) == [(6, "RF401"), (10, "RF401")]
