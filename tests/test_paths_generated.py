"""Every path, on generated programs: nested `if`s (conditions drawn from three
parameters, so that tests repeat), `return`s and assignments. RF301 (a name read
after them) and RF302 (a field published after them) must appear exactly when some
assignment of the conditions reaches the read with nothing assigned: the analysis
is exact on this class, and an error is never reported for a path that cannot
happen."""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from functools import cache

from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix.api import check_source
from robotfix.config import Config
from robotfix.ros.catalog import MsgCatalog

CONDITIONS = ("c0", "c1", "c2")
INT32 = "[std_msgs/Int32]:\nint32 data #RobotFix# data in (1, 2, 3)\n"


@dataclass(frozen=True)
class Assign:
    pass


@dataclass(frozen=True)
class Return:
    pass


@dataclass(frozen=True)
class If:
    cond: int
    body: tuple[Stmt, ...]
    orelse: tuple[Stmt, ...]


Stmt = Assign | Return | If


def blocks(inner: st.SearchStrategy[Stmt]) -> st.SearchStrategy[tuple[Stmt, ...]]:
    return st.lists(inner, min_size=1, max_size=3).map(tuple)


STATEMENTS: st.SearchStrategy[Stmt] = st.recursive(
    st.sampled_from([Assign(), Assign(), Return()]),
    lambda inner: st.builds(
        If,
        st.integers(0, len(CONDITIONS) - 1),
        blocks(inner),
        st.one_of(st.just(()), blocks(inner)),
    ),
    max_leaves=8,
)


def render(body: tuple[Stmt, ...], assign: str, depth: int = 1) -> list[str]:
    pad = "    " * depth
    lines: list[str] = []
    for stmt in body:
        if isinstance(stmt, Assign):
            lines.append(pad + assign)
        elif isinstance(stmt, Return):
            lines.append(pad + "return")
        else:
            lines.append(f"{pad}if {CONDITIONS[stmt.cond]}:")
            lines += render(stmt.body, assign, depth + 1)
            if stmt.orelse:
                lines.append(pad + "else:")
                lines += render(stmt.orelse, assign, depth + 1)
    return lines


def run(body: tuple[Stmt, ...], values: tuple[bool, ...], bound: bool) -> str:
    """What a concrete run ends with: "returned", "bound" or "unbound"."""
    for stmt in body:
        if isinstance(stmt, Assign):
            bound = True
        elif isinstance(stmt, Return):
            return "returned"
        else:
            outcome = run(
                stmt.body if values[stmt.cond] else stmt.orelse, values, bound
            )
            if outcome == "returned":
                return outcome
            bound = outcome == "bound"
    return "bound" if bound else "unbound"


def unbound_on_some_run(body: tuple[Stmt, ...]) -> bool:
    runs = itertools.product((False, True), repeat=len(CONDITIONS))
    return any(run(body, values, False) == "unbound" for values in runs)


def assigns(body: tuple[Stmt, ...]) -> bool:
    return any(
        isinstance(s, Assign) or (isinstance(s, If) and assigns(s.body + s.orelse))
        for s in body
    )


@cache
def catalog(tmp: str) -> MsgCatalog:
    from pathlib import Path

    folder = Path(tmp)
    (folder / "Int32.msg").write_text(INT32)
    return MsgCatalog([folder / "Int32.msg"])


def codes(source: str, tmp: str | None = None) -> list[str]:
    found = check_source(source, "gen.py", Config(), catalog(tmp) if tmp else None)
    return [d.code for d in found]


@settings(max_examples=80, deadline=None)
@given(blocks(STATEMENTS))
def test_name_unbound_on_some_path(body: tuple[Stmt, ...]) -> None:
    lines = ["def node(c0, c1, c2):", *render(body, "x = 1"), "    print(x)"]
    expected = ["RF301"] if assigns(body) and unbound_on_some_run(body) else []
    assert codes("\n".join(lines) + "\n") == expected, "\n".join(lines)


@settings(max_examples=60, deadline=None)
@given(blocks(STATEMENTS))
def test_field_unset_on_some_path(
    tmp_path_factory: object, body: tuple[Stmt, ...]
) -> None:
    tmp = str(tmp_path_factory.getbasetemp())  # type: ignore[attr-defined]
    lines = [
        "from std_msgs.msg import Int32",
        "def node(pub, c0, c1, c2):",
        "    msg = Int32()",
        *render(body, "msg.data = 2"),
        "    pub.publish(msg)",
    ]
    expected = ["RF302"] if unbound_on_some_run(body) else []
    assert codes("\n".join(lines) + "\n", tmp) == expected, "\n".join(lines)
