"""Issue 25 target 1 (eighth session): a declaration's default expression is found
in a map of the file's calls and `declare_parameters` tuples made once a file
(`param_eval._declarations`), not by walking every call of the file for each
declaration. Here the map is held to that walk, for every declaration of every
case file and of a file with nested and odd declarations."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from robotfix.analysis.index import index_of
from robotfix.analysis.param_eval import _declarations
from robotfix.analysis.parameters import summarize
from robotfix.analysis.paramwalk import called_name
from robotfix.analysis.program import call_argument
from robotfix.source import SourceFile

CASES = Path(__file__).parent / "cases"

ODD = """
from rclpy.node import Node

class N(Node):
    def __init__(self):
        super().__init__("n")
        self.declare_parameter("a", 1.5)
        self.declare_parameter(name="b", value=2)
        self.declare_parameter("c")
        self.declare_parameters("", [("d", 3), ("e",), ("f", f(("g", 4)))])
        self.declare_parameters(
            namespace="", parameters=[("h", self.declare_parameter("i", 5))]
        )
        self.get_parameter("a")
        x = self.get_parameter("d").value
"""


def _walked(calls: list[tuple[str | None, ast.Call]], node_id: int) -> ast.expr | None:
    """The walk the map replaced, as it was."""
    for _, call in calls:
        if id(call) == node_id:
            return call_argument(call, 1, "value")
        if called_name(call) == "declare_parameters":
            for item in ast.walk(call):
                if id(item) == node_id and isinstance(item, ast.Tuple):
                    return item.elts[1] if len(item.elts) > 1 else None
    return None


def _mapped(calls: list[tuple[str | None, ast.Call]], node_id: int) -> ast.expr | None:
    node = _declarations(calls).get(node_id)
    if isinstance(node, ast.Tuple):
        return node.elts[1] if len(node.elts) > 1 else None
    return None if node is None else call_argument(node, 1, "value")


def _sources() -> list[SourceFile]:
    files = [SourceFile.from_text("odd.py", ODD)]
    files += [
        SourceFile.from_bytes(str(p), p.read_bytes())
        for p in sorted(CASES.rglob("*.py"))
    ]
    return [f for f in files if f.tree is not None]


@pytest.mark.parametrize("source", _sources(), ids=lambda s: Path(s.path).name)
def test_the_map_finds_what_the_walk_found(source: SourceFile) -> None:
    assert source.tree is not None
    index = index_of(source.tree)
    summary = summarize(source, index)
    ids = [d.node_id for d in summary.decls]
    # and the calls and tuples no declaration is at
    ids += [
        id(n) for n in ast.walk(source.tree) if isinstance(n, (ast.Call, ast.Tuple))
    ]
    for node_id in ids:
        assert _mapped(index.calls, node_id) is _walked(index.calls, node_id)


def test_the_odd_file_has_declarations_of_every_kind() -> None:
    source = _sources()[0]
    assert source.tree is not None
    summary = summarize(source, index_of(source.tree))
    index = index_of(source.tree)
    found = {d.name: _mapped(index.calls, d.node_id) for d in summary.decls}
    assert {"a", "b", "c", "d", "e", "h", "i"} <= set(found)
    assert found["c"] is None and found["e"] is None
    assert isinstance(found["a"], ast.Constant) and found["a"].value == 1.5
    assert isinstance(found["d"], ast.Constant) and found["d"].value == 3
