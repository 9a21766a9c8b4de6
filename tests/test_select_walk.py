"""`astwalk.select` reads attribute chains in place (`a.b().c` is not stacked
node by node): its answer, order included (`paramwalk.unit` sorts it stably by
place, so nodes at one place keep it), must be the plain stack walk's on every
case file, for kinds with and without attributes."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from robotfix.astwalk import children, select

CASES = Path(__file__).parent / "cases"
KINDS = [
    (frozenset({ast.Call, ast.Assign, ast.AnnAssign}), frozenset()),
    (
        frozenset({ast.Call, ast.Assign, ast.AnnAssign}),
        frozenset({ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda}),
    ),
    (frozenset({ast.Attribute, ast.Call}), frozenset()),
    (frozenset({ast.Call}), frozenset({ast.Attribute})),
]


def _stack_walk(
    roots: list[ast.AST], kinds: frozenset[type], skip: frozenset[type]
) -> list[ast.AST]:
    """Every node stacked, in `select`'s order (names and constants never)."""
    found = []
    todo = list(roots)
    while todo:
        node = todo.pop()
        if type(node) in skip:
            continue
        if type(node) in kinds:
            found.append(node)
        todo += [c for c in children(node) if type(c) not in (ast.Name, ast.Constant)]
    return found


def _trees() -> list[ast.Module]:
    found = []
    for path in sorted(CASES.rglob("*.py")):
        try:
            found.append(ast.parse(path.read_text(encoding="utf-8")))
        except (SyntaxError, UnicodeDecodeError):
            continue
    return found


@pytest.mark.parametrize(("kinds", "skip"), KINDS)
def test_select_meets_the_nodes_of_the_stack_walk_in_its_order(
    kinds: frozenset[type], skip: frozenset[type]
) -> None:
    trees = _trees()
    assert len(trees) > 20
    met = 0
    for tree in trees:
        expected = _stack_walk(tree.body, kinds, skip)
        assert select(tree.body, kinds, skip) == expected
        met += len(expected)
    assert met > 100


def test_a_call_at_the_end_of_a_chain_is_found_in_order() -> None:
    tree = ast.parse("x = f(a).g(b).h.i(c)\nd.e.k = j()\n")
    kinds = frozenset({ast.Call, ast.Assign})
    found = select(tree.body, kinds)
    assert found == _stack_walk(tree.body, kinds, frozenset())
    assert [ast.unparse(n) for n in found if isinstance(n, ast.Call)] == [
        "j()",  # the last statement first: a stack
        "f(a).g(b).h.i(c)",
        "f(a).g(b)",
        "f(a)",
    ]
