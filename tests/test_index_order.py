"""Issue 25 target 1 (ninth session): the module index's walk reads a call's
keywords, an expression statement's value and an assignment's targets without
stacking the node that holds them. What it records in order (the calls, each
function's returns, the import statements: the graph reads endpoints and the
parameter summaries declarations in that order) must stay the order of one
plain stack walk, and the attributes assigned (`frames.facts`) a walk's count.
`tests/test_prepass_index.py` holds the same facts to a recursive reading, but
as sets."""

from __future__ import annotations

import ast
from collections import Counter
from pathlib import Path

import pytest

from robotfix.analysis.index import COMPREHENSIONS, FUNCTIONS, index_module
from robotfix.astwalk import children, walk

CASES = Path(__file__).parent / "cases"


def _stacked(node: ast.AST) -> list[ast.AST]:
    """What a stack walk pushes under `node`: a nested scope's parts as Python
    evaluates them, the enclosing scope's first (defaults, decorators, bases, a
    comprehension's first iterable), then its own; any other node's children."""
    if isinstance(node, ast.ClassDef):
        return [*node.decorator_list, *node.bases, *node.keywords, *node.body]
    if isinstance(node, COMPREHENSIONS):
        first = node.generators[0]
        rest = [c for c in children(node) if not isinstance(c, ast.comprehension)]
        return [first.iter, first.target, *first.ifs, *node.generators[1:], *rest]
    if isinstance(node, (*FUNCTIONS, ast.Lambda)):
        args = node.args
        found = [*args.defaults, *[d for d in args.kw_defaults if d is not None]]
        if isinstance(node, ast.Lambda):
            return [*found, node.body]
        return [*found, *node.decorator_list, *node.body]
    if isinstance(node, (ast.Import, ast.ImportFrom)):
        return []
    return children(node)


def _in_order(tree: ast.Module) -> list[ast.AST]:
    order: list[ast.AST] = []
    todo: list[ast.AST] = list(tree.body)
    while todo:
        node = todo.pop()
        order.append(node)
        todo += _stacked(node)
    return order


def _trees() -> list[tuple[str, ast.Module]]:
    found = []
    for path in sorted(CASES.rglob("*.py")):
        try:
            found.append((str(path), ast.parse(path.read_bytes())))
        except (SyntaxError, ValueError):
            continue
    return found


SNIPPETS = [
    "f(a(), *b(), k=g(x), m=h(y=i()), **n())\n"
    "c.d(e=lambda q=r(): s(), t=[u() for v in w()])\n",
    "class A(B(), metaclass=M(k=j())):\n    def f(self, p=d(), *, q=e()):\n"
    "        return g(h=1)\n    def h(self):\n        yield k(l=m())\n"
    "        return n()\n",
    "x.a.b, y[z.c] = p.q = f(k=1)\n(x.d).e += 1\nz.f: int = 3\nimport os\n"
    "from . import a\ndef g():\n    import sys\n    return sys.f(k=os.g())\n",
]


@pytest.mark.parametrize(
    "tree",
    [t for _, t in _trees()] + [ast.parse(s) for s in SNIPPETS],
)
def test_the_index_records_calls_returns_and_imports_in_a_stack_walks_order(
    tree: ast.Module,
) -> None:
    index = index_module(tree)
    order = _in_order(tree)
    assert [id(c) for _, c in index.calls] == [
        id(n) for n in order if isinstance(n, ast.Call)
    ]
    assert [id(s) for s in index.import_statements] == [
        id(n) for n in order if isinstance(n, (ast.Import, ast.ImportFrom))
    ]
    returns = [id(n) for n in order if isinstance(n, ast.Return)]
    for found in index.returns.values():
        kept = [id(r) for r in found]
        assert kept == [r for r in returns if r in set(kept)]
    assert sum(len(v) for v in index.returns.values()) == len(returns)
    targets = [
        target
        for node in walk(tree)
        for target in (
            node.targets
            if isinstance(node, ast.Assign)
            else [node.target]
            if isinstance(node, (ast.AugAssign, ast.AnnAssign))
            else []
        )
    ]
    assert index.assigned == Counter(
        n.attr for n in walk(targets) if isinstance(n, ast.Attribute)
    )
