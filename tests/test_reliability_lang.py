"""Issue 12, the annotation language and interface files: bounded and exact.

Regression tests for the reliability report's findings H2, H3, C1, C2, C9 (annotation
numbers), C11, K3, K4, W7, W10 and F6 (quoting), each from a small input of the same
class as the report's reproducer.
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix import rules
from robotfix.annotations import ast as A
from robotfix.annotations.parser import (
    MAX_DEPTH,
    MAX_DIGITS,
    MAX_EXPONENT,
    AnnotationSyntaxError,
    parse_predicate,
)
from robotfix.annotations.units import UnitError, check_text, resolve
from robotfix.api import catalog_problems, check_source, interface_files
from robotfix.config import Config
from robotfix.diagnostics import Diagnostic
from robotfix.ros import msg as msg_module
from robotfix.ros.catalog import MsgCatalog
from robotfix.ros.msg import read_interface

HEADER = "from typing import Annotated\n\n"


def annotated(predicate: str, value: str = "1", base: str = "float") -> str:
    return f"{HEADER}x: Annotated[{base}, {predicate!r}] = {value}\n"


def codes(found: list[Diagnostic]) -> list[tuple[str, int]]:
    return [(d.code, d.span.line) for d in found]


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


# -- H2, C2, C9: numbers ------------------------------------------------------

BIG_NUMBERS = [
    "1e999999999",
    "1" * 5000,
    "1e5000",
    "1e-5000",
    "1e4000 * 1e4000",
    "0." + "0" * 4999 + "1",
]


@pytest.mark.parametrize("number", BIG_NUMBERS, ids=lambda n: n[:12])
def test_a_number_out_of_range_is_rf501_at_its_column(number: str) -> None:
    with pytest.raises(AnnotationSyntaxError) as info:
        parse_predicate(f"_ < {number}")
    assert info.value.offset == 4
    assert "out of range" in info.value.message
    assert len(info.value.message) < 200  # quotes a prefix, not 5,000 digits


@pytest.mark.parametrize("number", BIG_NUMBERS, ids=lambda n: n[:12])
def test_a_big_number_never_raises_downstream(number: str, tmp_path: Path) -> None:
    source = (
        f"{HEADER}def f(y: float) -> None:\n"
        f'    x: Annotated[float, "_ < {number}"] = y\n'
        f'    z: Annotated[float, "_ > {number}"] = 5\n'
    )
    assert codes(check_source(source, "n.py")) == [("RF501", 4), ("RF501", 5)]
    msg = write(
        tmp_path / "p" / "msg" / "Big.msg", f"float64 x #RobotFix# _ > {number}\n"
    )
    found = catalog_problems(MsgCatalog([msg]))
    assert [(d.code, d.span.line, d.span.col) for d in found] == [("RF501", 1, 25)]


def test_products_of_literals_stay_small_enough_to_show_and_solve() -> None:
    with pytest.raises(AnnotationSyntaxError, match="1,000 digits"):
        parse_predicate("_ > " + " * ".join(["1e200"] * 24))
    with pytest.raises(AnnotationSyntaxError, match="1,000 digits"):
        parse_predicate("_ > 1 + " + " / ".join(["1e-200"] * 6))
    fine = "_ > " + " * ".join(["1e200"] * 4)
    source = (
        f"{HEADER}def f(y: float) -> None:\n    x: Annotated[float, {fine!r}] = y\n"
    )
    assert codes(check_source(source, "p.py")) == [("RF102", 4)]


@settings(max_examples=60, deadline=None)
@given(
    digits=st.integers(min_value=1, max_value=400),
    fraction=st.booleans(),
    exponent=st.one_of(st.none(), st.integers(min_value=-2000, max_value=2000)),
)
def test_every_number_is_a_value_or_rf501(
    digits: int, fraction: bool, exponent: int | None
) -> None:
    text = "7" * digits
    if fraction:
        text = text[: digits // 2] + "." + text[digits // 2 :]
    if exponent is not None:
        text += f"e{exponent}"
    in_range = digits <= MAX_DIGITS and abs(exponent or 0) <= MAX_EXPONENT
    try:
        predicate = parse_predicate(f"_ >= {text}")
    except AnnotationSyntaxError as err:
        assert not in_range and err.offset == 5
        return
    assert in_range
    assert A.show(predicate).startswith("_ >= ")


def test_show_never_calls_str_on_a_huge_integer() -> None:
    huge = A.Num(Fraction(10) ** 5000 * 3, True)
    assert A.show(huge) == "3e5000"
    assert A.show(A.Num(-Fraction(1, 7 * 10**6000), False)) == "-1.42857e-6001"


def test_fullwidth_digits_are_not_numbers() -> None:
    assert codes(check_source(annotated("_ > \uff11"), "k.py")) == [("RF501", 3)]
    with pytest.raises(AnnotationSyntaxError) as info:
        parse_predicate("_ > \uff11")
    assert info.value.offset == 4


def test_division_by_a_literal_zero_is_rf501_not_rf102() -> None:
    found = check_source(annotated("_ > 1/0"), "d.py")
    assert [(d.code, d.span.col) for d in found] == [("RF501", 26)]
    assert "division by zero" in found[0].message


# -- C1, C11: depth -------------------------------------------------------------

DEEP = {
    "500 and": " and ".join(f"_ != {i}" for i in range(500)),
    "500 in": "_ in (" + ", ".join(str(i) for i in range(500)) + ")",
    "50000 not": "not " * 50_000 + "_",
    "50000 !": "!" * 50_000 + "_",
    "50000 minus": "_ > " + "-" * 50_000 + "y",
    "100000-char sum": "_ < " + "+".join(["1"] * 49_990),
    "3000 ite": "if _ > 0 then " * 3000 + "1" + " else 2" * 3000,
    "3000 py ite": "_ if y else " * 3000 + "2",
}


@pytest.mark.parametrize("text", DEEP.values(), ids=list(DEEP))
def test_deep_annotations_work_or_are_rf501(text: str) -> None:
    try:
        predicate = parse_predicate(text)
    except AnnotationSyntaxError as err:
        assert err.offset == 0
        assert "nested" in err.message or "longer than" in err.message
        return
    assert not A.deeper_than(predicate, MAX_DEPTH)
    assert A.show(A.substitute(predicate, {"_": A.Name("x")}))
    assert len(A.walk(predicate)) > 500


def test_hundreds_of_conjuncts_and_options_parse() -> None:
    for text in (DEEP["500 and"], DEEP["500 in"]):
        assert len(A.conjuncts(parse_predicate(text))) >= 1
    assert len(A.conjuncts(parse_predicate(DEEP["500 and"]))) == 500


@pytest.mark.parametrize("name", list(DEEP))
def test_deep_annotations_never_crash_a_python_file(name: str) -> None:
    source = (
        f"{HEADER}def f(y: int) -> None:\n    x: Annotated[int, {DEEP[name]!r}] = 7\n"
    )
    for diag in check_source(source, "deep.py"):
        assert diag.code in ("RF501", "RF101", "RF102"), diag.message


@pytest.mark.parametrize("name", list(DEEP))
def test_deep_annotations_in_a_msg_never_stop_the_run(
    name: str, tmp_path: Path
) -> None:
    text = DEEP[name].replace("_ if y", "_ if mode > 1").replace("y", "mode")
    msg = write(tmp_path / "p" / "msg" / "Deep.msg", f"uint16 mode #RobotFix# {text}\n")
    other = write(tmp_path / "p" / "msg" / "Ok.msg", "float64 v #RobotFix# _ < 1\n")
    catalog = MsgCatalog([msg, other])
    for diag in catalog_problems(catalog):
        assert (diag.path, diag.span.line, diag.code) == (str(msg), 1, "RF501")
    spec = catalog.lookup("p/Ok")
    assert spec is not None and [i.text for i in spec.invariants] == ["v < 1"]


def test_an_enumeration_of_hundreds_of_values_is_checked(tmp_path: Path) -> None:
    options = ", ".join(str(i) for i in range(0, 1000, 2))
    write(
        tmp_path / "p" / "msg" / "Mode.msg",
        f"uint16 mode #RobotFix# _ in ({options})\n",
    )
    config = Config(msg_paths=(tmp_path,))
    node = (
        f"{HEADER}from p.msg import Mode\n\n\n"
        "def on_mode(msg: Mode) -> None:\n"
        '    below: Annotated[int, "_ < 1000"] = msg.mode\n'
        "    msg.mode = 3\n"
        "    msg.mode = 4\n"
    )
    assert codes(check_source(node, "node.py", config)) == [("RF101", 8)]
    odd = f"{HEADER}e: Annotated[int, '_ in ({options})'] = 999\n"
    assert codes(check_source(odd, "e.py")) == [("RF101", 3)]


# -- H3, K4: unit strings -------------------------------------------------------

BAD_UNITS = [
    "9**9**9",
    "2**2**2**2**2**2",
    "9**9**9*m",
    "m**99999999999999999999",
    "m**1e308",
    "m^2.5",
    "m\x00",
    "m\x1b[31m",
    "\uff11m",
    "m²²",
    "1000*m",
    "m" * 101,
]


@pytest.mark.parametrize("text", BAD_UNITS, ids=repr)
def test_unsafe_unit_strings_are_refused_before_pint(text: str) -> None:
    with pytest.raises(UnitError) as info:
        check_text(text)
    assert "\x00" not in info.value.message and len(info.value.message) < 200
    with pytest.raises(UnitError):
        resolve(text)


ORDINARY_UNITS = {
    "m/s^2": (("meter", 1), ("second", -2)),
    "m/s**2": (("meter", 1), ("second", -2)),
    "1/s": (("second", -1),),
    "m²": (("meter", 2),),
    "m⁻¹": (("meter", -1),),
    "(m/s)^2": (("meter", 2), ("second", -2)),
    "m**-1": (("meter", -1),),
    "utm-32N": (("tag:utm-32N", 1),),  # not a unit: a label, compared by name
}


@pytest.mark.parametrize("text", ORDINARY_UNITS)
def test_ordinary_unit_strings_still_resolve(text: str) -> None:
    """The safety check lets them through, and pint reads them as the units they
    are (a unit string it could not read would become a label, `tag:...`)."""
    check_text(text)
    unit = resolve(text)
    assert unit.dims == ORDINARY_UNITS[text]
    assert unit.factor == 1.0


def test_unsafe_units_are_rf502_in_python_and_in_a_msg(tmp_path: Path) -> None:
    found = check_source(annotated("Unit('9**9**9')"), "u.py")
    assert codes(found) == [("RF502", 3)]
    msg = write(
        tmp_path / "p" / "msg" / "U.msg",
        'float64 x #RobotFix# Unit(x) == "9**9**9*m"\n'
        'float64 y #RobotFix# Unit(y) == "m\\x00"\n',
    )
    msg.write_text(msg.read_text().replace("\\x00", "\x00"))
    found = catalog_problems(MsgCatalog([msg]))
    assert codes(found) == [("RF502", 1), ("RF502", 2)]


@settings(max_examples=50, deadline=None)
@given(st.text(alphabet="ms9(1)*^/-+. e²", max_size=24))
def test_unit_strings_resolve_or_are_refused(text: str) -> None:
    try:
        unit = resolve(text)
    except UnitError:
        return
    assert all(isinstance(e, int) and abs(e) < 100 for _, e in unit.dims)


def test_two_units_for_one_field_in_a_msg_is_rf507(tmp_path: Path) -> None:
    msg = write(
        tmp_path / "p" / "msg" / "R.msg",
        'float64 x #RobotFix# Unit(x) == "m" and Unit(x) == "s"\n'
        'float64 y #RobotFix# Unit(y) == "m"\n'
        '#RobotFix# Unit(y) == "meter"\n',
    )
    catalog = MsgCatalog([msg])
    found = catalog_problems(catalog)
    assert [(d.code, d.span.line, d.span.col) for d in found] == [("RF507", 1, 40)]
    assert "`m`" in found[0].message and "`s`" in found[0].message
    spec = catalog.lookup("p/R")
    assert spec is not None and spec.units["x"].text == "m"


# -- K3, F6: reading interface files ---------------------------------------------


def test_a_bom_is_not_part_of_the_first_line(tmp_path: Path) -> None:
    msg = tmp_path / "p" / "msg" / "B.msg"
    msg.parent.mkdir(parents=True)
    msg.write_bytes(b"\xef\xbb\xbffloat64 x #RobotFix# _ > 0\n")
    catalog = MsgCatalog([msg])
    assert catalog_problems(catalog) == []
    spec = catalog.lookup("p/B")
    assert spec is not None and [i.text for i in spec.invariants] == ["x > 0"]
    parsed = read_interface(Path("p/msg/B.msg"), "\ufeffp/B.msg\nint32 a\n")
    assert parsed.sections[0].name == "p/B" and parsed.problems == ()


def test_an_unparsable_line_is_quoted_by_a_short_prefix(tmp_path: Path) -> None:
    secret = "b3BlbnNzaC1rZXktdjEAAAAABG5vbmUAAAAEbm9uZQ" + "QUFBQUJHNXZibVV" * 20
    msg = write(tmp_path / "p" / "msg" / "Key.msg", f"{secret}\n")
    (diag,) = catalog_problems(MsgCatalog([msg]))
    assert diag.code == "RF506" and secret[:40] in diag.message
    assert secret[40:60] not in diag.message and len(diag.message) < 120


def test_an_unexpected_token_is_quoted_by_a_short_prefix() -> None:
    with pytest.raises(AnnotationSyntaxError) as info:
        parse_predicate("_ < 2 " + "x" * 10_000)
    assert len(info.value.message) < 60


# -- C1: one bad file or line never takes the run down ---------------------------


def test_a_failure_on_one_file_is_a_diagnostic_there(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    bad = write(tmp_path / "p" / "msg" / "Bad.msg", "float64 x\n")
    good = write(tmp_path / "p" / "msg" / "Good.msg", "float64 v #RobotFix# _ < 1\n")
    real = msg_module.read_interface

    def flaky(path: Path, text: str):  # type: ignore[no-untyped-def]
        if path.name == "Bad.msg":
            raise RecursionError("maximum recursion depth exceeded")
        return real(path, text)

    monkeypatch.setattr(msg_module, "read_interface", flaky)
    catalog = MsgCatalog([bad, good])
    found = catalog_problems(catalog)
    assert [(d.path, d.span.line, d.code) for d in found] == [(str(bad), 1, "RF506")]
    assert "RecursionError" in found[0].message
    assert catalog.lookup("p/Good") is not None


def test_a_failure_on_one_annotation_is_a_diagnostic_there(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    msg = write(
        tmp_path / "p" / "msg" / "M.msg",
        "float64 x #RobotFix# _ > 0\nfloat64 y #RobotFix# _ < 3\n",
    )
    real = MsgCatalog._add_predicate

    def flaky(self, spec, predicate, own, origin, note):  # type: ignore[no-untyped-def]
        if origin.line == 1:
            raise MemoryError
        real(self, spec, predicate, own, origin, note)

    monkeypatch.setattr(MsgCatalog, "_add_predicate", flaky)
    catalog = MsgCatalog([msg])
    found = catalog_problems(catalog)
    assert [(d.span.line, d.span.col, d.code) for d in found] == [(1, 21, "RF501")]
    spec = catalog.lookup("p/M")
    assert spec is not None and [i.text for i in spec.invariants] == ["y < 3"]


# -- W7: other libraries' strings in Annotated ----------------------------------

FOREIGN = [
    'b: Annotated[int, "const"] = 4',
    'title: Annotated[Annotated[str, "foobar"], "another level"] = "t"',
    'classvar: Annotated[int, "a decoration"] = 4',
    'const: Annotated[int, "Const"] = 4',
    'flag: Annotated[bool, "positive and small"] = True',
    'x: Annotated[float, "1.0"] = 2.5',
    'y: Annotated[int, "data", 5, "c"] = 1',
    'z: Annotated[str, "The name of the robot, e.g. turtle-1."] = "t"',
]


@pytest.mark.parametrize("line", FOREIGN)
def test_string_metadata_that_is_not_a_refinement_is_ignored(line: str) -> None:
    assert check_source(f"{HEADER}{line}\n", "typing_test.py") == []


@pytest.mark.parametrize(
    ("line", "code"),
    [
        ('speed: Annotated[float, "_ < < 2"] = 1', "RF501"),
        ('speed: Annotated[float, "speed ≤ 2"] = 1', "RF501"),
        ('speed: Annotated[float, "Unit(m/s)"] = 1', "RF501"),
        ("speed: Annotated[float, \"__import__('os').getcwd()\"] = 1", "RF501"),
        ('speed: Annotated[float, "_ < limit"] = 1', "RF503"),
        ('speed: Annotated[float, "meta", "_ < 1"] = 2', "RF101"),
        ('ready: Annotated[bool, "ready"] = False', "RF101"),
        ("speed: Annotated[int, \"Unit('meterz')\"] = 0", "RF502"),
    ],
)
def test_strings_that_are_or_look_like_refinements_still_count(
    line: str, code: str
) -> None:
    assert [d.code for d in check_source(f"{HEADER}{line}\n", "r.py")] == [code]


# -- W10: one type, two files ----------------------------------------------------


def duplicate_tree(root: Path) -> tuple[Path, Path]:
    first = write(
        root / "a" / "demo" / "msg" / "Cmd.msg", "float64 speed #RobotFix# _ < 1\n"
    )
    second = write(
        root / "b" / "demo" / "msg" / "Cmd.msg", "int32 speed #RobotFix# _ > 5\n"
    )
    return first, second


def test_a_type_defined_twice_is_rf510_at_the_second_file(tmp_path: Path) -> None:
    first, second = duplicate_tree(tmp_path)
    catalog = MsgCatalog(interface_files([tmp_path / "a", tmp_path / "b"]))
    (diag,) = catalog_problems(catalog)
    assert (diag.code, diag.path, diag.span.line) == ("RF510", str(second), 1)
    assert diag.rule is rules.DUPLICATE_INTERFACE and diag.severity.value == "warning"
    assert str(first) in diag.message and "demo/Cmd" in diag.message
    assert any(n.path == str(first) and n.line == 1 for n in diag.notes)
    spec = catalog.lookup("demo/Cmd")
    assert spec is not None and spec.fields["speed"].kind == "float"
    assert [i.text for i in spec.invariants] == ["speed < 1"]


def test_the_first_msg_path_wins_whatever_the_names(tmp_path: Path) -> None:
    first, _ = duplicate_tree(tmp_path)
    catalog = MsgCatalog(interface_files([tmp_path / "b", tmp_path / "a"]))
    assert [d.path for d in catalog_problems(catalog)] == [str(first)]
    spec = catalog.lookup("demo/Cmd")
    assert spec is not None and [i.text for i in spec.invariants] == ["speed > 5"]
    node = (
        f"{HEADER}from demo.msg import Cmd\n\n\ndef send(pub) -> None:\n"
        "    c = Cmd()\n    c.speed = 7\n    pub.publish(c)\n"
    )
    config = Config(msg_paths=(tmp_path / "b", tmp_path / "a"))
    assert codes(check_source(node, "node.py", config)) == []
    config = Config(msg_paths=(tmp_path / "a", tmp_path / "b"))
    assert codes(check_source(node, "node.py", config)) == [("RF101", 8)]


def test_copies_and_one_file_spelled_twice_are_one_definition(tmp_path: Path) -> None:
    first, _ = duplicate_tree(tmp_path)
    copy = write(tmp_path / "install" / "demo" / "msg" / "Cmd.msg", first.read_text())
    spelled = Path(str(tmp_path / "a")) / "demo" / ".." / "demo" / "msg" / "Cmd.msg"
    catalog = MsgCatalog([first, copy, spelled])
    assert catalog_problems(catalog) == []
