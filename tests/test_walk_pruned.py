"""Issue 25 target 1 (eighth session): walks that look for a few names skip the
statements whose source lines cannot hold them (`astwalk.Mentions`). The pruned
answer must equal the full walk's on every case file, and a line that is not
ASCII is always walked (the source may spell a name otherwise than the AST does:
a fullwidth letter in the source is a plain one in the name)."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from robotfix.analysis.constants import _only_read
from robotfix.analysis.containers import shared_names, shares
from robotfix.astwalk import Mentions, names_under
from robotfix.source import SourceFile

CASES = Path(__file__).parent / "cases"


def _sources() -> list[SourceFile]:
    found = []
    for path in sorted(CASES.rglob("*.py")):
        source = SourceFile.from_bytes(str(path), path.read_bytes())
        try:
            source.tree = ast.parse(source.text)
        except SyntaxError:
            continue
        found.append(source)
    return found


def _names(tree: ast.AST) -> list[str]:
    return sorted({n.id for n in ast.walk(tree) if isinstance(n, ast.Name)})


def test_the_pruned_walk_finds_every_use_a_full_walk_finds() -> None:
    sources = _sources()
    assert len(sources) > 20
    for source in sources:
        tree = source.tree
        assert tree is not None
        names = _names(tree)
        for words in [set(names), *({n} for n in names[::6])]:
            kept = Mentions(source.lines, words)
            pruned = [(p, n) for p, n in names_under(tree, kept) if n.id in words]
            full = [(p, n) for p, n in names_under(tree) if n.id in words]
            assert pruned == full, (source.path, words)
            assert _only_read(tree, words, source.lines) == _only_read(tree, words)


def test_a_line_that_is_not_ascii_is_walked() -> None:
    text = "TABLE = {'a': 1}\n\ndef f():\n    \uff34ABLE['b'] = 2\n"
    source = SourceFile.from_text("t.py", text)
    tree = ast.parse(text)
    assert _only_read(tree, {"TABLE"}, source.lines) == set()  # changed in f
    text = "TABLE = {'a': 1}\n\ndef f():\n    return TABLE['a']\n"
    assert _only_read(ast.parse(text), {"TABLE"}, text.split("\n")) == {"TABLE"}


@pytest.mark.parametrize("decorated", [True, False])
def test_a_decorator_line_belongs_to_its_definition(decorated: bool) -> None:
    text = "T = [1]\n\n@keep(T)\ndef f():\n    pass\n"
    if not decorated:
        text = text.replace("@keep(T)\n", "")
    tree = ast.parse(text)
    expected = set() if decorated else {"T"}
    assert _only_read(tree, {"T"}, text.split("\n")) == expected


def test_the_walk_skips_what_cannot_name_the_table() -> None:
    text = "T = [1]\n\ndef f():\n    x = 1\n    if x:\n        y = T[0]\n"
    tree = ast.parse(text)
    seen = {n.id for _, n in names_under(tree, Mentions(text.split("\n"), {"T"}))}
    assert seen == {"T", "x", "y"}  # `x = 1` skipped: its line does not name T
    assert {n.id for _, n in names_under(tree)} == {"T", "x", "y"}
    statements = [p for p, _ in names_under(tree, Mentions(text.split("\n"), {"T"}))]
    assert not any(isinstance(p, ast.Assign) and p.lineno == 4 for p in statements)


def _scopes(tree: ast.Module) -> list[ast.AST]:
    functions = (ast.FunctionDef, ast.AsyncFunctionDef)
    return [tree, *(n for n in ast.walk(tree) if isinstance(n, functions))]


def test_whether_a_list_is_shared_is_the_full_walks_answer() -> None:
    for source in _sources():
        assert source.tree is not None
        for scope in _scopes(source.tree):
            body = scope.body  # type: ignore[attr-defined]
            full = shared_names(body, lent=set())
            for name in _names(scope)[::4]:
                found = shares(scope, name, source.lines)
                assert found == (name in full), (source.path, name)


def test_a_list_named_in_a_decorator_or_a_nested_function_is_shared() -> None:
    text = (
        "def f():\n"
        "    xs = []\n"
        "    ys = []\n"
        "    zs = []\n"
        "    @keep(xs)\n"
        "    def g():\n"
        "        return len(ys)\n"
        "    for z in zs:\n"
        "        print(z)\n"
        "    ws = []\n"
        "    for w in ws:\n"
        "        print(w)\n"
        "    other = \uff57s\n"  # a fullwidth `w`: the name `ws`, on a line to walk
    )
    scope = ast.parse(text).body[0]
    lines = text.split("\n")
    assert shares(scope, "xs", lines)  # handed to a decorator
    assert shares(scope, "ys", lines)  # read in a nested function
    assert not shares(scope, "zs", lines)  # only iterated
    assert shares(scope, "ws", lines)  # bound to another name
    assert "ws" in shared_names(scope.body)  # type: ignore[attr-defined]
