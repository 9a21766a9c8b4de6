"""Issue 25 target 1 (sixth session): the escape scan keeps what it finds of a
node as long as the node lives (`writes._SYNTAX`), and the syntactic passes walk
only what can hold what they look for (`stmtsyntax.may_raise`,
`typesyntax.local_bindings` without `:=`, `relevance._binders`). A memo that
answered for another node or root, or that kept its tree alive, fails here; so
would a decision kept for a node (a memo of `decisions.decision` was measured
and dropped: +3.2 M instructions on the subset)."""

from __future__ import annotations

import ast
import gc
import weakref
from pathlib import Path

from robotfix.analysis import decisions, writes
from robotfix.analysis.stmtsyntax import may_raise

CASES = Path(__file__).parent / "cases"


def _test(source: str) -> ast.expr:
    statement = ast.parse(source).body[0]
    assert isinstance(statement, ast.If)
    return statement.test


def test_a_decision_reads_its_scope_and_values_at_each_call() -> None:
    test = _test("if a.size > b and f(c) and self.x:\n    pass\n")
    first = decisions.decision(test, {"a", "b"}, lambda n: n + "1", {})
    assert first[1] == {("b", "b1"), (".size", None), (".x", None)}
    # the same node, another scope and other values: nothing of the first call
    attribute = next(
        n for n in ast.walk(test) if isinstance(n, ast.Attribute) and n.attr == "x"
    )
    again = decisions.decision(test, {"c"}, lambda n: 7, {id(attribute): 3})
    assert again[1] == {("c", 7), (".size", None), (".x", 3)}
    plain = decisions.decision(test, {"b", "f"}, lambda n: None, {})
    assert plain[1] == {("b", None), (".size", None), (".x", None)}  # `f`: callee


def test_a_decision_of_a_new_node_is_its_own() -> None:
    """Nodes freed and made again may reuse an address: each answer is its own."""
    for round in range(50):
        name = f"v{round}"
        test = _test(f"if {name} > limit:\n    pass\n")
        found = decisions.decision(test, {name, "limit"}, lambda n: None, {})
        assert found[1] == {(name, None), ("limit", None)}
        del test
        gc.collect()


def test_the_escape_scan_of_a_function_answers_each_root() -> None:
    function = ast.parse(
        "def f(p, q, r):\n"
        "    q.header.stamp = now\n"
        "    keep(p)\n"
        "    m = r\n"
        "    m.data.append(1)\n"
        "    return len(q)\n"
    ).body[0]

    def never(root: str, path: tuple[str, ...]) -> bool:
        return False

    def reads(call: ast.Call, arg: ast.expr) -> bool:
        return isinstance(call.func, ast.Name) and call.func.id == "len"

    for _ in range(2):  # the second time from the memo
        found = writes.uses([function], {"p", "q", "r"}, never, reads)
        assert found == {
            "p": {writes.ESCAPE},
            "q": {("header", "stamp")},
            "r": {writes.CHANGE},
        }
        assert writes.uses([function], {"q"}, never, reads) == {
            "q": {("header", "stamp")}
        }


def test_the_escape_scan_of_one_statement_sees_its_own_parts() -> None:
    """The memo leaves out a root's edges to its children; they are made again
    (`m = p` as the only node: `p` is assigned, not escaped)."""
    statement = ast.parse("m = p\n").body[0]
    for _ in range(2):
        found = writes.uses([statement], {"p"}, lambda r, p: False, lambda c, a: True)
        assert found == {"p": set()}


def test_the_escape_memo_lets_its_tree_go() -> None:
    tree = ast.parse("def f(p):\n    g(p)\n")
    writes.uses([tree.body[0]], {"p"}, lambda r, p: False, lambda c, a: False)
    writes.uses([tree], {"p"}, lambda r, p: False, lambda c, a: False)
    gone = [weakref.ref(tree), weakref.ref(tree.body[0])]
    del tree
    gc.collect()
    assert [ref() for ref in gone] == [None, None]


def _may_raise_by_every_node(node: ast.AST) -> bool:
    """The definition `may_raise` had: a walk of every node of the body."""
    nested = (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)
    todo: list[ast.AST] = list(getattr(node, "body", []))
    while todo:
        child = todo.pop()
        if isinstance(child, (ast.Raise, ast.Assert)):
            return True
        if not isinstance(child, nested):
            todo.extend(ast.iter_child_nodes(child))
    return False


def test_may_raise_walks_statements_only() -> None:
    source = (
        "def a():\n    try:\n        pass\n    except E:\n        raise\n"
        "def b():\n    match x:\n        case 1:\n            assert y\n"
        "def c():\n    def inner():\n        raise E\n    class K:\n        assert 0\n"
        "def d():\n    with m:\n        for i in x:\n            pass\n"
        "        else:\n            raise E\n"
        "def e():\n    while x:\n        f(lambda: g())\n    try:\n        pass\n"
        "    finally:\n        assert z\n"
    )
    functions = ast.parse(source).body
    assert [may_raise(f) for f in functions] == [True, True, False, True, True]
    for path in sorted(CASES.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                assert may_raise(node) == _may_raise_by_every_node(node), path


def test_binders_of_a_scope_leave_out_what_nested_scopes_bind() -> None:
    from robotfix.analysis.relevance import _statements
    from robotfix.analysis.unbound import _binders

    function = ast.parse(
        "def f(a, *b, c=d0, **e):\n"
        "    global g\n"
        "    import os.path, numpy as np\n"
        "    from x import *\n"
        "    @dec(k := 1)\n"
        "    def inner(p=default, *, q=kw):\n"
        "        hidden = 1\n"
        "    class K(Base, metaclass=M):\n"
        "        inside = 2\n"
        "    h = lambda r=lam: (s := r)\n"
        "    t = [u for u in items if (w := u)]\n"
        "    try:\n"
        "        g = 1\n"
        "    except E as err:\n"
        "        del v\n"
        "    for (i, j) in pairs:\n"
        "        (y := i)\n"
        "    with open(n) as (fa, fb):\n"
        "        pass\n"
    ).body[0]
    bound, declared = _binders(function)
    assert declared == {"g"}
    assert bound == {
        "a", "b", "c", "e", "os", "np", "k", "inner", "K", "h", "t", "err",
        "v", "i", "j", "y", "fa", "fb",
    }  # fmt: skip
    kinds = [type(s).__name__ for s in _statements(function.body)]
    assert kinds == [
        "Global", "Import", "ImportFrom", "FunctionDef", "Assign", "ClassDef",
        "Assign", "Assign", "Assign", "Try", "Delete", "Assign", "For", "Expr",
        "With", "Pass",
    ]  # fmt: skip


def test_binders_without_walrus_find_what_the_walk_of_every_node_finds() -> None:
    from robotfix.analysis.unbound import _binders

    scopes = 0
    for path in sorted(CASES.rglob("*.py")):
        text = path.read_text(encoding="utf-8")
        if ":=" in text:
            continue
        for node in ast.walk(ast.parse(text)):
            if isinstance(
                node, (ast.Module, ast.FunctionDef, ast.ClassDef, ast.Lambda)
            ):
                assert _binders(node, walrus=False) == _binders(node), path
                scopes += 1
    assert scopes > 100
    # `a[...] =` reads `a`; a comprehension's target is its own; `:=` only when asked
    tree = ast.parse("a[[i for i in y]] = 1\nfor (b, *c) in d:\n    del e[f], g\n")
    assert _binders(tree, walrus=False) == (frozenset({"b", "c", "g"}), frozenset())
    walrus = ast.parse("if (n := 1):\n    pass\n")
    assert _binders(walrus)[0] == {"n"}
    assert _binders(walrus, walrus=False)[0] == frozenset()
