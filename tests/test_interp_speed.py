"""Issue 13 item 1, the interpreter's fast paths: each one equals the slow path it
replaced (the slow path is kept here as the reference)."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from robotfix.analysis.stmtsyntax import accumulated, note_sum
from robotfix.project.modules import import_names, imported_names

CASES = Path(__file__).parent / "cases"

NESTED = """\
import os, sys as system
from . import sibling
from ..pkg import helper as h, other
from .mod import *
try:
    import yaml
except ImportError as err:
    from json import loads
else:
    import a.b.c
finally:
    from x import y
class Node:
    import rclpy
    def run(self):
        if True:
            from geometry_msgs.msg import Twist
        with open("f") as f:
            import math
        while False:
            import time
        for _ in []:
            pass
        else:
            from std_msgs import msg
        f = lambda: __import__("not_an_import")
match command:
    case "go":
        import go_module
    case _:
        from stop import now
async def later():
    async with lock:
        import asyncio
"""


def _reference(tree: ast.Module, package: str | None) -> list[str]:
    """`imported_names` as it was: every node of the tree, through `ast.walk`."""
    return import_names(ast.walk(tree), package)


@pytest.mark.parametrize("package", [None, "pkg.sub.node"])
def test_imported_names_visits_every_nesting_in_walk_order(
    package: str | None,
) -> None:
    tree = ast.parse(NESTED)
    found = imported_names(tree, package)
    assert found == _reference(tree, package)
    assert "go_module" in found and "stop.now" in found and "asyncio" in found


def test_imported_names_equals_the_full_walk_on_every_case() -> None:
    files = sorted(CASES.rglob("*.py"))
    assert len(files) > 50
    for path in files:
        try:
            tree = ast.parse(path.read_bytes())
        except SyntaxError:
            continue
        assert imported_names(tree, "pkg.node") == _reference(tree, "pkg.node"), path


def _old_accumulated(nodes: list[ast.stmt]) -> set[str]:
    """`_accumulated` as it was: every node, through `ast.walk`."""
    summed: set[str] = set()
    targets: set[int] = set()
    stores: list[ast.Name] = []
    for child in ast.walk(ast.Module(body=nodes, type_ignores=[])):
        note_sum(child, summed, targets)
        if isinstance(child, ast.Name) and isinstance(child.ctx, ast.Store):
            stores.append(child)
    return summed - {n.id for n in stores if id(n) not in targets}


def test_accumulated_names_are_those_only_ever_summed() -> None:
    body = ast.parse(
        "total += d\nother -= d\nscaled *= 2\nreset += 1\nreset = 0\n"
        "[seen for seen in xs]\nseen += 1\n(walrus := 3)\nwalrus += 1\n"
    ).body
    assert accumulated(body) == {"total", "other"} == _old_accumulated(body)


def _shape(found: dict) -> dict:
    """A local's bindings, comparable across two calls (the wrappers are new)."""
    from robotfix.analysis.typesyntax import BoundAnnotation, BoundElement

    def one(b: object) -> object:
        if isinstance(b, (BoundAnnotation, BoundElement)):
            return (type(b).__name__, id(b.node))
        return None if b is None else id(b)

    return {name: [one(b) for b in bound] for name, bound in found.items()}


def test_local_bindings_without_walrus_skips_only_what_holds_nothing() -> None:
    """A file without `:=` has no binding inside an expression: walking only the
    statements gives the same bindings, in the same order, as walking every node
    (checked on every function of the test cases and of RobotFix's own source)."""
    from robotfix.analysis.typesyntax import local_bindings

    files = [*CASES.rglob("*.py"), *(Path(__file__).parents[1] / "src").rglob("*.py")]
    checked = 0
    for path in files:
        text = path.read_text(encoding="utf-8", errors="replace")
        if ":=" in text:
            continue
        try:
            tree = ast.parse(text)
        except SyntaxError:
            continue
        for node in ast.walk(tree):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                fast = local_bindings(node, walrus=False)
                assert _shape(fast) == _shape(local_bindings(node)), (path, node.name)
                assert list(fast) == list(local_bindings(node))
                checked += 1
    assert checked > 1000


def test_local_bindings_walks_expressions_when_the_file_has_a_walrus() -> None:
    from robotfix.analysis.typesyntax import local_bindings

    tree = ast.parse("def f(xs):\n    if (n := len(xs)) > 0:\n        return n\n")
    function = tree.body[0]
    assert "n" in local_bindings(function)
    assert "n" not in local_bindings(function, walrus=False)


def test_type_names_memo_keeps_messages_and_interfaces_apart_per_file(
    tmp_path: Path,
) -> None:
    """`FileContext`'s memo of `msg_type_named` and `interface_named` (issue 25
    target 1): each question keeps its own answer for the same dotted name, in
    either order, and a later file's check still records the types it looked up
    in the catalog's `touched` (which decides its cache entry)."""
    from robotfix.analysis.context import FileContext
    from robotfix.ros.catalog import MsgCatalog
    from robotfix.source import SourceFile

    srv = tmp_path / "pkg" / "srv" / "AddTwoInts.srv"
    srv.parent.mkdir(parents=True)
    srv.write_text("int64 a\n---\nint64 sum\n")
    catalog = MsgCatalog([srv])
    for interface_first in (False, True):
        catalog.touched = set()
        ctx = FileContext(SourceFile.from_bytes("n.py", b""), catalog, print)
        for _ in range(2):
            if interface_first:
                assert ctx.interface_named("pkg.srv.AddTwoInts") == "pkg/AddTwoInts"
            assert ctx.msg_type_named("pkg.srv.AddTwoInts") is None
            assert ctx.interface_named("pkg.srv.AddTwoInts") == "pkg/AddTwoInts"
            request = ctx.msg_type_named("pkg.srv.AddTwoInts.Request")
            assert request == "pkg/AddTwoInts_Request"
            assert ctx.interface_named("pkg.srv.AddTwoInts.Request") is None
        assert "pkg/AddTwoInts_Request" in catalog.touched


def test_int_literal_terms_are_made_once_per_value() -> None:
    """The int literal memo (issue 25 target 1) gives the term a literal had
    before it, and None (unknown) for one too large to model."""
    from fractions import Fraction

    from robotfix.analysis.literals import int_term
    from robotfix.annotations import ast as A

    for value in (0, 1, -7, 2**40):
        assert int_term(value) == A.Num(Fraction(value), True)
        assert int_term(value) is int_term(value)
    assert int_term(10**100) is None


def test_float_literal_terms_are_kept_per_text_and_value() -> None:
    """The float literal memo (issue 25 target 1) is keyed by the literal's text:
    two texts of one float are two exact numbers, and a text that is no plain
    decimal (or no text) falls back to the float's value."""
    from fractions import Fraction

    from robotfix.analysis.literals import float_term
    from robotfix.annotations import ast as A

    assert float_term("0.1", 0.1) == A.Num(Fraction(1, 10), False)
    long = "0.1000000000000000000001"
    assert float(long) == 0.1
    assert float_term(long, 0.1) == A.Num(Fraction(long), False)
    assert float_term("", 0.1) == A.Num(Fraction(0.1), False)
    assert float_term("1e-9999999", 0.0) == A.Num(Fraction(0), False)
    assert float_term("1e200", 1e200) is None  # too large to model
    assert float_term("0.1", 0.1) is float_term("0.1", 0.1)


def test_dispatch_tables_are_kept_per_evaluator_class() -> None:
    """`eval` and `exec_block` keep one method table per class (issue 25 target
    1): a subclass that overrides a method is dispatched to its own, also after
    its base class dispatched the same node class, and the base to its own after
    (a table keyed by the node class alone fails one or the other)."""
    from fractions import Fraction

    from robotfix.analysis.constants import scan
    from robotfix.analysis.context import FileContext, build_scope
    from robotfix.analysis.index import index_of
    from robotfix.analysis.interpreter import Interpreter
    from robotfix.analysis.program import collect
    from robotfix.analysis.state import State
    from robotfix.analysis.values import NONE, Value
    from robotfix.annotations import ast as A
    from robotfix.ros.catalog import MsgCatalog
    from robotfix.source import SourceFile

    source = SourceFile.from_bytes("n.py", b"x = 1\npass\n")
    assert source.tree is not None
    ctx = FileContext(source, MsgCatalog([]), print)
    ctx.record_imports(index_of(source.tree))
    ctx.constants = scan(source.tree, ctx.index, ctx.qualname, False)
    module = build_scope(ctx, "module", "<module>", source.tree, None)
    program = collect(ctx, source.tree, module)

    class Marked(Interpreter):
        def eval_Constant(self, node: ast.Constant, state: State) -> Value:  # noqa: N802
            return Value("str", A.Str("marked"))

        def visit_Pass(self, node: ast.stmt, state: State) -> State:  # noqa: N802
            state.env["passed"] = NONE
            return state

    def run(kind: type[Interpreter]) -> dict[str, object]:
        walker = kind(ctx, program, module, {})
        return dict(walker.exec_block(source.tree.body, State()).env)  # type: ignore[union-attr]

    one = Value("int", A.Num(Fraction(1), True), literal=True)
    for kind in (Interpreter, Marked, Interpreter, Marked):
        env = run(kind)
        marked = kind is Marked
        assert env["x"] == (Value("str", A.Str("marked")) if marked else one)
        assert ("passed" in env) == marked
