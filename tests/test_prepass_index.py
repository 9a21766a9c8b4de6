"""Issue 25 target 1 (seventh session): the module index is one stack walk that
keeps no tuple per node (a marker on the stack ends a nested scope) and reads
names, constants and attribute chains under their parent. Here it is held to a
plain recursive reading of the same facts, scope by scope, on every case file:
a name given to the wrong scope after a nested one ends, a call under an
attribute chain (`a().b()`) or a store in one (`x.a.b = 1`) missed, fails here.
The index also keeps the `setattr` calls that `frames.facts` and the constants'
scan read (they searched the file for them again)."""

from __future__ import annotations

import ast
from collections import Counter
from pathlib import Path

import pytest

from robotfix.analysis.index import COMPREHENSIONS, FUNCTIONS, index_module

CASES = Path(__file__).parent / "cases"
SCOPES = (*FUNCTIONS, ast.Lambda, ast.ClassDef, *COMPREHENSIONS)


class _Reference:
    """What the index records, read by recursion: each node's scope is passed
    down, so nothing depends on the order of a stack."""

    def __init__(self, tree: ast.Module) -> None:
        self.names: dict[int, set[str]] = {id(tree): set()}
        self.declared: dict[int, set[str]] = {id(tree): set()}
        self.calls: Counter[tuple[str | None, int]] = Counter()
        self.returns: dict[int, set[int]] = {}
        self.generators: set[int] = set()
        self.attributes: set[tuple[str, str, int]] = set()
        self.classes: set[int] = set()
        self.root = id(tree)
        for statement in tree.body:
            self.visit(statement, id(tree), None, None)

    def open(self, node: ast.AST) -> int:
        self.names[id(node)] = set()
        self.declared[id(node)] = set()
        return id(node)

    def visit(
        self, node: ast.AST, owner: int, cls: str | None, self_name: str | None
    ) -> None:
        if isinstance(node, (*FUNCTIONS, ast.Lambda)):
            for d in [*node.args.defaults, *node.args.kw_defaults]:
                if d is not None:
                    self.visit(d, owner, cls, self_name)
            inner = self.open(node)
            args = node.args
            every = [*args.posonlyargs, *args.args, *args.kwonlyargs]
            every += [a for a in (args.vararg, args.kwarg) if a is not None]
            self.names[inner] |= {a.arg for a in every}
            if isinstance(node, ast.Lambda):
                self.visit(node.body, inner, cls, None)
                return
            self.names[owner].add(node.name)
            for d in node.decorator_list:
                self.visit(d, owner, cls, self_name)
            method = owner in self.classes and args.args
            first = args.args[0].arg if method else None
            for statement in node.body:
                self.visit(statement, inner, cls, first)
            return
        if isinstance(node, ast.ClassDef):
            self.names[owner].add(node.name)
            for d in [*node.decorator_list, *node.bases, *node.keywords]:
                self.visit(d, owner, cls, self_name)
            inner = self.open(node)
            self.classes.add(inner)
            top = node.name if owner == self.root else cls
            for statement in node.body:
                self.visit(statement, inner, top, None)
            return
        if isinstance(node, COMPREHENSIONS):
            first, *rest = node.generators
            self.visit(first.iter, owner, cls, self_name)
            inner = self.open(node)
            parts = [first.target, *first.ifs, *rest]
            parts += [c for c in ast.iter_child_nodes(node) if c not in node.generators]
            for part in parts:
                self.visit(part, inner, cls, self_name)
            return
        if isinstance(node, ast.Name) and not isinstance(node.ctx, ast.Load):
            self.names[owner].add(node.id)
        elif isinstance(node, ast.Call):
            self.calls[(cls, id(node))] += 1
        elif isinstance(node, ast.Return):
            self.returns.setdefault(owner, set()).add(id(node))
        elif isinstance(node, (ast.Yield, ast.YieldFrom)):
            self.generators.add(owner)
        elif isinstance(node, (ast.Global, ast.Nonlocal)):
            self.declared[owner] |= set(node.names)
        elif isinstance(node, ast.ExceptHandler) and node.name:
            self.names[owner].add(node.name)
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            self.names[owner] |= {
                a.asname or a.name.split(".")[0] for a in node.names if a.name != "*"
            }
        elif isinstance(node, ast.AnnAssign):
            target = node.target
            if (
                isinstance(target, ast.Attribute)
                and isinstance(target.value, ast.Name)
                and target.value.id == self_name
                and cls is not None
            ):
                self.attributes.add((cls, target.attr, id(node.annotation)))
        for child in ast.iter_child_nodes(node):
            self.visit(child, owner, cls, self_name)


def _trees() -> list[tuple[str, ast.Module]]:
    found = []
    for path in sorted(CASES.rglob("*.py")):
        try:
            found.append((path.name, ast.parse(path.read_bytes())))
        except (SyntaxError, ValueError):
            continue
    return found


SNIPPETS = [
    "class A:\n    x = 1\n    def m(self, p=f()):\n        self.a.b = g().h()\n"
    "        q = [y for y in p if (z := y)]\n        return lambda k=q: k\n"
    "    y = [x for _ in range(3)]\n",
    "def f():\n    global G\n    G = 1\n    def g():\n        nonlocal_ = 2\n"
    "        yield from h()\n    return g\n",
    "try:\n    import a.b as c\nexcept E as e:\n    from m import *\n"
    "setattr(o, 'x', 1)\nk.setattr(o, 'y', 2)\n",
]


@pytest.mark.parametrize(
    "tree",
    [t for _, t in _trees()] + [ast.parse(s) for s in SNIPPETS],
)
def test_the_index_records_what_a_recursive_reading_finds(tree: ast.Module) -> None:
    index = index_module(tree)
    expected = _Reference(tree)
    for scope, names in expected.names.items():
        assert index.scopes[scope].local_names == names
        assert index.scopes[scope].global_names == expected.declared[scope]
    assert set(index.scopes) == set(expected.names)
    assert Counter((c, id(n)) for c, n in index.calls) == expected.calls
    assert {k: {id(r) for r in v} for k, v in index.returns.items()} == (
        expected.returns
    )
    assert index.generators == expected.generators
    assert {(c, a, id(n)) for c, a, n in index.attributes} == expected.attributes
    every = list(ast.walk(tree))
    assert index.stores == Counter(
        n.id
        for n in every
        if isinstance(n, ast.Name) and not isinstance(n.ctx, ast.Load)
    )
    assert index.attribute_stores == {
        n.attr
        for n in every
        if isinstance(n, ast.Attribute) and not isinstance(n.ctx, ast.Load)
    }
    assert [id(c) for c in index.setattrs] == [
        id(n)
        for _, n in index.calls
        if isinstance(n.func, ast.Name) and n.func.id == "setattr"
    ]
    assert len(index.setattrs) == sum(
        1
        for n in every
        if isinstance(n, ast.Call)
        and isinstance(n.func, ast.Name)
        and n.func.id == "setattr"
    )


SETATTR = """\
import rclpy
from rclpy.node import Node


class Looker(Node):
    def __init__(self, name):
        super().__init__('looker')
        self.frame = 'map'
        self.other = 'odom'
        setattr(self, name, 'base_link')
        if name:
            setattr(self, 'other', 'map')
"""


@pytest.mark.parametrize("text", [SETATTR, SETATTR.replace("setattr(", "keep(")])
def test_frame_facts_count_setattr_calls_as_a_walk_of_the_file_does(text: str) -> None:
    """`frames.facts` reads the `setattr` calls from the index now (it walked the
    whole file when its text said `setattr`): the same counts as that walk."""
    from robotfix import api
    from robotfix.analysis import frames
    from robotfix.analysis.index import FileIndex
    from robotfix.ros.catalog import MsgCatalog
    from robotfix.source import SourceFile

    ctx = api._analyze(SourceFile.from_text("node.py", text), MsgCatalog([]))
    ctx.frame_facts = None
    indexed = frames.facts(ctx).assigned
    ctx.frame_facts, ctx.index = None, FileIndex()  # no index: the walk
    assert frames.facts(ctx).assigned == indexed
    assert indexed["*"] == (4 if "setattr" in text else 0)
