"""Every natural annotation form means what it says (issue 9 item 2, report P3)."""

from __future__ import annotations

import ast
import sys

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix.analysis.index import _aliases
from robotfix.annotations.extract import Alias, Names, extract
from robotfix.api import check_source

HEADER = "from typing import Annotated, Final, Optional, Union, TypeAlias\n"


def codes(text: str) -> list[str]:
    return [d.code for d in check_source(HEADER + text, "t.py")]


def test_p3_reproducer() -> None:
    """The report's program: every line that was ignored is now reported."""
    found = check_source(
        "from typing import Annotated, Optional\n"
        "from geometry_msgs.msg import Twist\n"
        "MetersPerSec = Annotated[float, \"Unit('m/s') and 0 <= _ <= 1\"]\n"
        "def read() -> tuple[Annotated[float, \"Unit('degree')\"], float]: ...\n"
        "def main():\n"
        "    t = Twist()\n"
        "    v: MetersPerSec = 5.0\n"
        '    o: Optional[Annotated[float, "_ > 0"]] = -1.0\n'
        "    yaw, _ = read()\n"
        "    t.angular.z = yaw\n"
        '    w: Annotated[float, "Unit(\'m\')", "_ > 0"] = -1.0\n',
        "p3.py",
    )
    assert [(d.span.line, d.code) for d in found] == [
        (7, "RF101"),
        (8, "RF101"),
        (10, "RF201"),
        (11, "RF101"),
    ]


def test_type_alias_annotation_and_rebound_name() -> None:
    assert codes('Speed: TypeAlias = Annotated[float, "_ <= 1"]\nv: Speed = 2.0\n') == [
        "RF101"
    ]
    # bound twice: not an alias, so nothing is read through it
    assert (
        codes('Speed = Annotated[float, "_ <= 1"]\nSpeed = float\nv: Speed = 2.0\n')
        == []
    )


def test_alias_cycles_and_bad_string_annotations_do_not_crash() -> None:
    # `B = Optional[B]` reads B before it is bound: a NameError, the only report
    assert codes("A = Optional['A']\nB = Optional[B]\nx: A = 1\ny: B = 2\n") == [
        "RF301"
    ]
    huge = "Annotated[float, '_ < 1']" + " " * 5000
    assert codes(f'x: "{huge}" = 5\ny: "Annotated[float," = 5\nz: "[" * 3 = 1\n') == []
    deep = "Optional[" * 300 + "float" + "]" * 300
    assert codes(f'x: "{deep}" = 1\n') == []


@pytest.mark.skipif(sys.version_info < (3, 12), reason="`type` needs Python 3.12")
def test_type_statement() -> None:  # pragma: no cover - runs on 3.12+
    assert codes('type Speed = Annotated[float, "_ <= 1"]\nv: Speed = 2.0\n') == [
        "RF101"
    ]


def test_type_statement_node() -> None:
    """On any Python: a `type X = ...` statement node is an alias of the module."""
    tree = ast.parse("v: Speed = 2.0\n")
    value = ast.parse('Annotated[float, "_ <= 1"]', mode="eval").body

    class TypeAlias(ast.stmt):  # the 3.12 node's name and fields
        _fields = ("name", "type_params", "value")

    statement = TypeAlias()
    statement.name = ast.Name("Speed", ast.Store())  # type: ignore[attr-defined]
    statement.value = value  # type: ignore[attr-defined]
    tree.body.insert(0, statement)
    aliases = _aliases(tree)
    assert aliases == {"Speed": value}
    names = Names(
        lambda n: "typing.Annotated" if isinstance(n, ast.Name) else None,
        lambda n: None,
        lambda n: None,
        lambda line, col: col,
        lambda n: (
            Alias(aliases[n.id], names)
            if isinstance(n, ast.Name) and n.id in aliases
            else None
        ),
    )
    found, problems = extract(
        ast.parse("Speed", mode="eval").body,
        "v",
        names.qualname,
        names.msg_type,
        names.source_segment,
        names.col_of,
        alias=names.alias,
    )
    assert problems == []
    assert found is not None and found.base == "float"


WRAPPERS = [
    ("Final[{}]", False),
    ("Optional[{}]", True),
    ("Union[{}, None]", True),
    ("Union[None, {}]", True),
    ("{} | None", True),
]


@settings(max_examples=30, deadline=None)
@given(
    wrappers=st.lists(st.sampled_from(WRAPPERS), max_size=2),
    via_alias=st.booleans(),
    quoted=st.booleans(),
    value=st.sampled_from(["None", "1.0", "5.0"]),
)
def test_wrapped_annotated_keeps_its_meaning(
    wrappers: list[tuple[str, bool]], via_alias: bool, quoted: bool, value: str
) -> None:
    form = 'Annotated[float, "Unit(\'m\')", "_ < 3"]'
    optional = False
    for template, makes_optional in wrappers:
        form = template.format(form)
        optional = optional or makes_optional
    lines = ""
    if via_alias:
        lines += f"Alias = {form}\n"
        form = "Alias"
    if quoted:
        form = repr(form)
    found = codes(
        f"{lines}x: {form} = {value}\n"
        f"def f(p: {form}) -> None:\n"
        '    y: Annotated[float, "_ < 3"] = p\n'
    )
    # a read of an optional value assumes nothing (it may be None): RF102
    expected = (["RF101"] if value == "5.0" else []) + (["RF102"] if optional else [])
    assert found == expected
