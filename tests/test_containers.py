"""Issue 8, item 5: containers of numbers.

A refinement on a list, tuple or array field is on its elements (`len(_)` on its
length). The data-driven cases are in tests/cases/containers/; here: the language
and interface-file parts, and generated programs (elements checked one by one,
exact aggregates, and lists changed through other names, which must never give an
error on code that is correct).
"""

from __future__ import annotations

from fractions import Fraction
from functools import cache
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix import rules
from robotfix.api import catalog_problems, check_source, hover, interface_files
from robotfix.config import Config
from robotfix.diagnostics import Diagnostic
from robotfix.ros.catalog import MsgCatalog

HEADER = "from typing import Annotated\n\n"


def check(source: str, catalog: MsgCatalog | None = None) -> list[Diagnostic]:
    return check_source(HEADER + source, "node.py", Config(), catalog or _plain())


@cache
def _plain() -> MsgCatalog:
    return MsgCatalog([])


def codes(found: list[Diagnostic]) -> list[tuple[str, int]]:
    return sorted((d.code, d.span.line - 2) for d in found)  # lines of `source`


def catalog_with(tmp_path: Path, name: str, text: str) -> MsgCatalog:
    folder = tmp_path / "msg"
    folder.mkdir(exist_ok=True)
    (folder / name).write_text(text, encoding="utf-8")
    return MsgCatalog(interface_files([folder]))


# -- the report's reproducer (P3) ---------------------------------------------


def test_refined_list_reports_the_element_not_the_list() -> None:
    found = check(
        "def f() -> None:\n"
        "    ranges: Annotated[list[float], \"Unit('m') and 0 <= _ <= 10\"] = "
        "[1.0, 20.0]\n"
        "    ranges.append(-5.0)\n"
        "    first: Annotated[float, '_ >= 0'] = ranges[0]\n"
    )
    assert codes(found) == [("RF101", 2), ("RF101", 3)]
    element = next(d for d in found if d.span.line == 4)
    assert "`20.0` violates `ranges[1] <= 10`" in element.message
    written = "    ranges: Annotated[list[float], \"Unit('m') and 0 <= _ <= 10\"] = "
    assert element.span.col == len(written + "[1.0, ")  # 0-based: at the 20.0


# -- the annotation language ----------------------------------------------------


def test_container_annotations_and_len() -> None:
    found = check(
        "def f(\n"
        "    a: Annotated[tuple[float, float], '_ >= 0'],\n"
        "    b: Annotated[list[int], 'len(_) <= 2'],\n"
        ") -> None:\n"
        "    n: Annotated[int, '_ == 2'] = len(a)\n"
        "    m: Annotated[int, '_ <= 2'] = len(b)\n"
        "    x: Annotated[float, '_ >= 0'] = a[1]\n"
        "    k: Annotated[int, '_ == 3'] = len(b)\n"
    )
    assert codes(found) == [("RF101", 8)]  # b has at most 2 elements


def test_len_on_a_number_or_mixed_with_elements_is_rf501() -> None:
    found = check(
        "x: Annotated[float, 'len(_) > 0'] = 1.0\n"
        "ys: Annotated[list[float], 'len(_) > 0 or _ > 0'] = [1.0]\n"
        "zs: Annotated[list[float], 'len(_, _) > 0'] = [1.0]\n"
    )
    assert codes(found) == [("RF501", 1), ("RF501", 2), ("RF501", 3)]


def test_a_number_where_a_list_belongs_is_rf401() -> None:
    found = check("xs: Annotated[list[float], '_ >= 0'] = 1.5\n")
    assert codes(found) == [("RF401", 1)]


# -- interface files ------------------------------------------------------------


def test_array_field_annotations_are_on_elements_and_length(tmp_path: Path) -> None:
    catalog = catalog_with(
        tmp_path,
        "Ranges.msg",
        "robot_msgs/Ranges.msg\n"
        "float32[] ranges #RobotFix# Unit('m') and _ >= 0 and len(_) <= 4\n"
        "float64[3] gains #RobotFix# 0 < gains\n",
    )
    assert catalog_problems(catalog) == []
    found = check(
        "from robot_msgs.msg import Ranges\n"
        "def f(r: Ranges) -> None:\n"
        "    out = Ranges()\n"
        "    out.ranges = [0.5, 1.0]\n"
        "    out.ranges = [0.5, -1.0]\n"
        "    out.ranges = [0.5] * 5\n"
        "    out.gains = [1.0, 2.0]\n"
        "    smallest: Annotated[float, \"Unit('m') and _ >= 0\"] = min(r.ranges)\n"
        "    n: Annotated[int, '_ == 3'] = len(r.gains)\n"
        "    t: Annotated[float, \"Unit('s')\"] = r.ranges[0]\n",
        catalog,
    )
    assert codes(found) == [("RF101", 5), ("RF101", 6), ("RF101", 7), ("RF201", 10)]


def test_unset_array_default_breaks_a_length_refinement(tmp_path: Path) -> None:
    catalog = catalog_with(
        tmp_path,
        "Path.msg",
        "robot_msgs/Path.msg\nfloat64[] xs #RobotFix# len(xs) > 0\n",
    )
    found = check(
        "from robot_msgs.msg import Path\n"
        "def f(pub) -> None:\n"
        "    pub.publish(Path())\n"
        "    good = Path()\n"
        "    good.xs.append(1.0)\n"
        "    pub.publish(good)\n",
        catalog,
    )
    assert codes(found) == [("RF302", 3)]


def test_lengths_of_two_arrays_are_assumed_where_a_message_arrives(
    tmp_path: Path,
) -> None:
    catalog = catalog_with(
        tmp_path,
        "Scan.msg",
        "robot_msgs/Scan.msg\nfloat32[] ranges\nfloat32[] intensities\n"
        "#RobotFix# len(ranges) == len(intensities)\n",
    )
    assert catalog_problems(catalog) == []
    found = check(
        "from robot_msgs.msg import Scan\n"
        "def f(s: Scan) -> None:\n"
        "    a: Annotated[int, '_ == 0'] = len(s.ranges) - len(s.intensities)\n"
        "    b: Annotated[int, '_ == 1'] = len(s.ranges) - len(s.intensities)\n",
        catalog,
    )
    assert codes(found) == [("RF101", 4)]


def test_array_annotation_problems(tmp_path: Path) -> None:
    catalog = catalog_with(
        tmp_path,
        "Bad.msg",
        "robot_msgs/Bad.msg\n"
        "float64 x #RobotFix# len(x) > 0\n"
        "float64[] ys #RobotFix# ys <= x\n",
    )
    found = sorted((p.code, p.span.line) for p in catalog_problems(catalog))
    assert found == [("RF501", 2), ("RF505", 3)]


# -- generated programs -----------------------------------------------------------

SMALL = st.integers(min_value=-20, max_value=20)


@settings(max_examples=25, deadline=None)
@given(st.lists(SMALL, min_size=0, max_size=6), SMALL, SMALL)
def test_each_element_out_of_bounds_is_one_error_at_it(
    values: list[int], low: int, high: int
) -> None:
    shown = ", ".join(f"{v}.0" for v in values)
    line = f"xs: Annotated[list[float], '{low} <= _ <= {high}'] = [{shown}]\n"
    found = check(line)
    if low > high:  # a contradictory refinement: RF509 where declared, then absent
        assert [d.code for d in found] == ["RF509"]
        return
    bad = [i for i, v in enumerate(values) if not low <= v <= high]
    assert [d.code for d in found] == ["RF101"] * len(bad)
    start = line.index("[", line.index("=")) + 1
    columns = []
    for value in values:
        columns.append(start)
        start += len(f"{value}.0, ")
    assert sorted(d.span.col for d in found) == [columns[i] for i in bad]


@settings(max_examples=25, deadline=None)
@given(st.lists(SMALL, min_size=1, max_size=8))
def test_aggregates_of_known_elements_are_exact(values: list[int]) -> None:
    shown = ", ".join(str(v) for v in values)
    exact = (
        f"    low: Annotated[int, '_ == {min(values)}'] = min(xs)\n"
        f"    high: Annotated[int, '_ == {max(values)}'] = max(xs)\n"
        f"    total: Annotated[int, '_ == {sum(values)}'] = sum(xs)\n"
        f"    n: Annotated[int, '_ == {len(values)}'] = len(xs)\n"
    )
    assert check(f"def f() -> None:\n    xs = [{shown}]\n{exact}") == []
    wrong = f"    high: Annotated[int, '_ == {max(values) + 1}'] = max(xs)\n"
    found = check(f"def f() -> None:\n    xs = [{shown}]\n{wrong}")
    assert [d.code for d in found] == ["RF101"]


# Operations on a list `a` and a second name `b`, which may or may not be `a`
# itself: the test follows them in Python, RobotFix statically. Whatever RobotFix
# concludes, an error would claim that the true maximum and length are impossible.
OPS = st.lists(
    st.one_of(
        st.tuples(st.just("append"), st.sampled_from("ab"), SMALL),
        st.tuples(st.just("extend"), st.sampled_from("ab"), SMALL),
        st.tuples(st.just("set0"), st.sampled_from("ab"), SMALL),
        st.tuples(st.just("pop"), st.sampled_from("ab"), SMALL),
        st.tuples(st.just("alias"), st.just("b"), SMALL),
        st.tuples(st.just("copy"), st.just("b"), SMALL),
        st.tuples(st.just("loop"), st.sampled_from("ab"), SMALL),
        st.tuples(st.just("call"), st.sampled_from("ab"), SMALL),
        st.tuples(st.just("closure"), st.sampled_from("ab"), SMALL),
    ),
    max_size=6,
)


@settings(max_examples=40, deadline=None)
@given(st.lists(SMALL, min_size=1, max_size=3), OPS)
def test_lists_changed_through_other_names_never_give_an_error(
    start: list[int], ops: list[tuple[str, str, int]]
) -> None:
    lists = {"a": list(start), "b": [0]}
    lines = [f"    a = [{', '.join(str(v) for v in start)}]", "    b = [0]"]
    for op, name, value in ops:
        target = lists[name]
        if op == "append":
            target.append(value)
            lines.append(f"    {name}.append({value})")
        elif op == "extend":
            target.extend([value, value])
            lines.append(f"    {name}.extend([{value}, {value}])")
        elif op == "set0" and target:
            target[0] = value
            lines.append(f"    {name}[0] = {value}")
        elif op == "pop" and target:
            target.pop()
            lines.append(f"    {name}.pop()")
        elif op == "alias":
            lists["b"] = lists["a"]
            lines.append("    b = a")
        elif op == "copy":
            lists["b"] = list(lists["a"])
            lines.append("    b = list(a)")
        elif op == "loop":
            target.extend([value] * 2)
            lines += [
                "    for _ in range(2):",
                f"        {name}.append({value})",
            ]
        elif op == "call":
            target.append(value)
            lines.append(f"    grow({name}, {value})")
        elif op == "closure":
            target.append(value)
            lines += [
                "    def more() -> None:",
                f"        {name}.append({value})",
                "    more()",
            ]
    final = lists["a"]
    lines.append(f"    n: Annotated[int, '_ == {len(final)}'] = len(a)")
    if final:
        lines.append(f"    top: Annotated[int, '_ == {max(final)}'] = max(a)")
        lines.append(f"    low: Annotated[int, '_ == {min(final)}'] = min(a)")
        lines.append(f"    total: Annotated[int, '_ == {sum(final)}'] = sum(a)")
    source = (
        "def grow(xs: list, v: int) -> None:\n"
        "    xs.append(v)\n\n"
        "def f() -> None:\n" + "\n".join(lines) + "\n"
    )
    found = check(source)
    assert not [d for d in found if d.rule.severity.value == "error"], (
        source,
        found,
    )


@settings(max_examples=20, deadline=None)
@given(st.lists(st.integers(min_value=0, max_value=10), min_size=1, max_size=20))
def test_sum_of_refined_elements_is_bounded(values: list[int]) -> None:
    """The sum of n elements within [0, 10] is within [0, 10 n]; known lengths up
    to 16 sum element by element, longer ones through the bounds."""
    n = len(values)
    found = check(
        "def f(xs: Annotated[list[float], '0 <= _ <= 10']) -> None:\n"
        f"    if len(xs) == {n}:\n"
        f"        s: Annotated[float, '0 <= _ <= {10 * n}'] = sum(xs)\n"
        f"        t: Annotated[float, '_ <= {10 * n - 1}'] = sum(xs)\n"
    )
    assert codes(found) == [("RF102", 4)]


def test_fraction_bounds_are_kept_exact() -> None:
    assert Fraction("0.1") * 3 == Fraction(3, 10)  # the language's decimals
    found = check(
        "def f() -> None:\n"
        "    xs = [0.1, 0.1, 0.1]\n"
        "    s: Annotated[float, '_ == 0.3'] = sum(xs)\n"
    )
    assert found == []


def test_a_module_list_only_read_is_a_constant_table() -> None:
    found = check(
        "GAINS = [0.5, 1.0, 2.0]\n"
        "def f(i: int) -> None:\n"
        "    g: Annotated[float, '_ <= 2'] = GAINS[i]\n"
        "    h: Annotated[float, '_ == 2'] = max(GAINS)\n"
        "    k: Annotated[float, '_ < 2'] = GAINS[2]\n"
    )
    assert codes(found) == [("RF101", 5)]


def test_comprehensions_keep_what_they_compute() -> None:
    found = check(
        "def f(xs: Annotated[list[float], '_ >= 0']) -> None:\n"
        "    a: Annotated[list[float], '_ >= 0'] = [2 * x for x in xs]\n"
        "    b: Annotated[list[float], '_ > 1'] = [x for x in xs if x > 1]\n"
        "    c: Annotated[list[float], '_ > 0'] = [x - 1 for x in xs]\n"
        "    d: Annotated[float, '_ >= 1'] = min(x + 1 for x in xs)\n"
    )
    assert codes(found) == [("RF102", 4)]


def test_hover_shows_a_list_refinement_as_on_each_element() -> None:
    text = (
        HEADER
        + "ranges: Annotated[list[float], \"Unit('m') and _ >= 0 and len(_) <= 5\"]"
        " = [1.0]\n"
    )
    shown = hover(text, "node.py", 3, 1, _plain())
    assert shown is not None
    assert "`list[float]` of `m`" in shown
    assert "each element `_ >= 0`" in shown and "length `_ <= 5`" in shown


def test_rule_codes_used_exist() -> None:
    assert {"RF101", "RF102", "RF302", "RF401", "RF501", "RF505"} <= set(
        rules.ALL_RULES
    )
