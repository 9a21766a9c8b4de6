"""Messages people act on (issue 24 item 4, newuser2 §7): each diagnostic says what
is wrong where it is wrong, in the words and units the user wrote."""

from __future__ import annotations

from pathlib import Path

from robotfix.api import check_source
from robotfix.config import Config
from robotfix.diagnostics import Diagnostic
from robotfix.ros.catalog import MsgCatalog

CASES = Path(__file__).parent / "cases"


def _only(source: str, catalog: MsgCatalog | None = None) -> Diagnostic:
    """The one diagnostic of a check of `source`."""
    [found] = check_source(source, "node.py", Config(), catalog)
    return found


def test_rf301_caret_is_under_the_unbound_name_at_the_line_of_the_read() -> None:
    path = CASES / "paths" / "unbound_read_located.py"
    found = check_source(path.read_text(encoding="utf-8"), str(path), Config())
    spans = [(d.code, d.span.line, d.span.col, d.span.end_col) for d in found]
    assert spans == [
        ("RF301", 15, 57, 59),  # `dt` in `... % dt`, on the line of the read
        ("RF301", 23, 12, 18),  # `period`, the second argument's line
        ("RF301", 27, 14, 19),  # `speed` in `print(speed)`
    ]


def test_units_are_printed_as_people_write_them() -> None:
    from robotfix.annotations.units import named, resolve

    shown = {t: str(named(resolve(t))) for t in ("N", "kN", "kg", "g", "kg*m^2")}
    assert shown == {"N": "N", "kN": "kN", "kg": "kg", "g": "g", "kg*m^2": "kg*m^2"}
    shown = {t: str(named(resolve(t))) for t in ("Pa", "hPa", "W", "V", "J", "rpm")}
    assert shown == {
        "Pa": "Pa",
        "hPa": "hPa",
        "W": "W",
        "V": "V",
        "J": "N*m",
        "rpm": "rpm",
    }
    assert str(resolve("kg") * resolve("m/s^2")) == "N"  # arithmetic, then named


def test_a_force_computed_in_the_code_is_named_n_in_the_message() -> None:
    source = (
        "from typing import Annotated\n"
        "def f(mass: Annotated[float, \"Unit('kg')\"],"
        " acc: Annotated[float, \"Unit('m/s^2')\"]) -> None:\n"
        "    force = mass * acc\n"
        "    t: Annotated[float, \"Unit('s')\"] = force\n"
    )
    assert _only(source).message == (
        "`t = force` gives `t` a value in N, but `t` is in s"
    )


def test_a_unit_from_an_interface_comment_names_that_comment(tmp_path: Path) -> None:
    from robotfix.api import interface_files

    folder = tmp_path / "px4_msgs" / "msg"
    folder.mkdir(parents=True)
    (folder / "VehicleCommand.msg").write_text(
        "uint64 timestamp # time since system start [us]\n", encoding="utf-8"
    )
    catalog = MsgCatalog(interface_files([folder]))
    source = (
        "from px4_msgs.msg import VehicleCommand\n"
        "def stamp(node):\n"
        "    msg = VehicleCommand()\n"
        "    msg.timestamp = int(node.get_clock().now().nanoseconds / 1e6)\n"
    )
    [note] = _only(source, catalog).notes
    assert note.message == (
        "unit of px4_msgs/VehicleCommand: `us` in the comment of `timestamp`"
    )
    assert (note.path, note.line) == (str(folder / "VehicleCommand.msg"), 1)


def test_rf101_at_a_call_says_the_value_in_its_message() -> None:
    source = (
        "from typing import Annotated\n"
        "LOOK_TIME = 10000\n"
        "def spin(time_allowance: Annotated[int, 'time_allowance <= 600']) -> None:\n"
        "    pass\n"
        "spin(time_allowance=LOOK_TIME)\n"
    )
    assert _only(source).message == (
        "`spin(time_allowance=LOOK_TIME)` violates `time_allowance <= 600`: "
        "here `time_allowance` = 10000"
    )  # in the concise, GitHub and SARIF forms too, which show no notes


def test_a_unit_from_a_field_name_suffix_names_that_suffix(tmp_path: Path) -> None:
    from robotfix.api import interface_files

    folder = tmp_path / "drive_msgs" / "msg"
    folder.mkdir(parents=True)
    (folder / "Pulse.msg").write_text("float64 period_ms\n", encoding="utf-8")
    catalog = MsgCatalog(interface_files([folder]), unit_suffixes=True)
    source = (
        "from typing import Annotated\n"
        "from drive_msgs.msg import Pulse\n"
        "def send(period: Annotated[float, \"Unit('s')\"]):\n"
        "    msg = Pulse()\n"
        "    msg.period_ms = period\n"
    )
    [note] = _only(source, catalog).notes
    assert note.message == (
        "unit of drive_msgs/Pulse: `ms` from the suffix of `period_ms` (unit-suffixes)"
    )


def test_a_statement_over_several_lines_is_shown_on_one() -> None:
    from robotfix.source import SourceFile

    text = (
        "x = 1 + \\\n    2  # c\ny = f(\n  a,  # the first\n  b,\n)\nif x:\n    pass\n"
    )
    source = SourceFile.from_text("node.py", text)
    assert source.tree is not None
    shown = [source.statement_text(s) for s in source.tree.body]
    assert shown == ["x = 1 + 2", "y = f(a, b)", "if x:"]
