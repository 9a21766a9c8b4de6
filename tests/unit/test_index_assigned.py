"""The module index counts assigned attribute names as `frames.facts` did by
walking the whole file again (issue 13): same counts on every case file and on
RobotFix's own sources."""

from __future__ import annotations

import ast
from collections import Counter
from collections.abc import Callable
from pathlib import Path

import pytest

from robotfix.analysis.index import index_module

ROOT = Path(__file__).parents[2]


def _walked(tree: ast.Module) -> Counter[str]:
    """`frames.facts` before the index counted them."""
    counts: Counter[str] = Counter()
    for item in ast.walk(tree):
        targets: list[ast.expr] = []
        if isinstance(item, ast.Assign):
            targets = list(item.targets)
        elif isinstance(item, (ast.AugAssign, ast.AnnAssign)):
            targets = [item.target]
        for target in targets:
            for part in ast.walk(target):
                if isinstance(part, ast.Attribute):
                    counts[part.attr] += 1
    return counts


def test_nested_scopes_and_subscripts_count() -> None:
    text = (
        "class C:\n"
        "    def m(self, o):\n"
        "        self.a = 1\n"
        "        self.a += 1\n"
        "        o[self.i].b: int = 2\n"
        "        f = lambda: [x for x in o]\n"
        "        for k in o:\n"
        "            if k:\n"
        "                self.a, (o.c, _) = 1, (2, 3)\n"
    )
    found = index_module(ast.parse(text)).assigned
    assert found == Counter({"a": 3, "i": 1, "b": 1, "c": 1})


def _walked_none(tree: ast.Module) -> Counter[str]:
    """The attributes assigned `None`, which `frames.remember` sets aside."""
    counts: Counter[str] = Counter()
    for item in ast.walk(tree):
        if isinstance(item, (ast.Assign, ast.AnnAssign)):
            value = item.value
            if isinstance(value, ast.Constant) and value.value is None:
                targets = (
                    item.targets if isinstance(item, ast.Assign) else [item.target]
                )
                counts.update(t.attr for t in targets if isinstance(t, ast.Attribute))
    return counts


@pytest.mark.parametrize(
    ("field", "walked", "least"),
    [("assigned", _walked, 50), ("assigned_none", _walked_none, 20)],
)
def test_the_index_counts_as_a_walk_does(
    field: str, walked: Callable[[ast.Module], Counter[str]], least: int
) -> None:
    files = sorted((ROOT / "tests" / "cases").rglob("*.py"))
    files += sorted((ROOT / "src" / "robotfix").rglob("*.py"))
    compared = 0
    for path in files:
        try:
            tree = ast.parse(path.read_bytes())
        except (SyntaxError, ValueError):
            continue
        expected = walked(tree)
        assert +getattr(index_module(tree), field) == +expected, path
        compared += bool(expected)
    assert compared > least


def test_attributes_assigned_none_count() -> None:
    text = (
        "class C:\n"
        "    def m(self):\n"
        "        self.a = self.b = None\n"
        "        self.c: int | None = None\n"
        "        self.d = 0\n"
        "        x.e += None\n"
    )
    found = index_module(ast.parse(text)).assigned_none
    assert found == Counter({"a": 1, "b": 1, "c": 1})
