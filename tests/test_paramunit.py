"""Issue 25 (tenth session): the parameter walk of a function (`paramwalk.Walker.
unit`) walked every node of it for its calls and assignments; now the calls are
the check's index's within the function's positions, and only its statements
are walked. What it reads, and in which order, must be what the walk of every
node found, on every function of tests/cases."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from robotfix.analysis import paramunit
from robotfix.analysis.index import index_of
from robotfix.analysis.parameters import summarize
from robotfix.analysis.paramunit import PLACE, UNIT_KINDS, Placed, unit_nodes
from robotfix.astwalk import select
from robotfix.source import SourceFile

CASES = Path(__file__).parent / "cases"
FILES = sorted(CASES.rglob("*.py"))


def _functions(tree: ast.AST) -> list[ast.FunctionDef | ast.AsyncFunctionDef]:
    return [
        n
        for n in ast.walk(tree)
        if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))
    ]


@pytest.mark.parametrize("path", FILES, ids=lambda p: str(p.relative_to(CASES)))
def test_a_functions_calls_and_assignments_are_those_of_a_walk(path: Path) -> None:
    source = SourceFile.from_bytes(str(path), path.read_bytes())
    if source.tree is None:
        return
    placed = Placed(index_of(source.tree).calls)
    for function in _functions(source.tree):
        walked = sorted(select(function.body, UNIT_KINDS), key=PLACE)
        assert unit_nodes(function.body, True, placed) == walked, function.name


def test_the_places_that_a_walk_of_the_index_leaves_out() -> None:
    """Calls in a nested function's annotations (the index does not enter them),
    in a decorator of the first statement, calls that start at one place (the
    outer first) and an assignment that starts where its target's call does."""
    text = (
        "def f(node):\n"
        "    @deco(node.declare_parameter('a', 1))\n"
        "    def g(x: Annotated[int, node.declare_parameter('b', 2)]) -> h():\n"
        "        pass\n"
        "    node.get().declare_parameter('c', 3)\n"
        "    node.get().x = node.declare_parameter('d', 4).value\n"
    )
    tree = ast.parse(text)
    function = tree.body[0]
    assert isinstance(function, ast.FunctionDef)
    walked = sorted(select(function.body, UNIT_KINDS), key=PLACE)
    found = unit_nodes(function.body, True, Placed(index_of(tree).calls))
    assert found == walked
    assert len([n for n in found if isinstance(n, ast.Call)]) == 8


def test_a_function_is_not_walked_node_by_node(monkeypatch: pytest.MonkeyPatch) -> None:
    """With the index of the file's own tree, no function is walked by `select`
    (the module's statements are); a summary is what it was."""
    text = (
        "import rclpy\nfrom rclpy.node import Node\n"
        "class A(Node):\n    def __init__(self):\n"
        "        super().__init__('a')\n"
        "        self.declare_parameter('speed', 0.5)\n"
        "        x = [self.get_parameter(n) for n in ('speed',)]\n"
        "def main():\n    rclpy.init()\n    A()\n"
    )
    source = SourceFile.from_bytes("a.py", text.encode())
    walked: list[int] = []
    real = paramunit.select
    monkeypatch.setattr(
        paramunit, "select", lambda *a: walked.append(len(a[0])) or real(*a)
    )
    found = summarize(source)
    assert walked == [2]  # the module's statements: two imports (not its defs)
    assert [(d.owner, d.name) for d in found.decls] == [("A", "speed")]
    assert found.node_names == {"A": ["a"]}
