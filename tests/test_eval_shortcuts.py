"""Issue 25 target 1: the evaluator's shortcuts for the most frequent nodes (a
local's value read, an unknown's or a module's attribute, a fresh unknown made
without `__init__`) answer what the general path answers."""

from __future__ import annotations

import ast
from fractions import Fraction
from pathlib import Path
from typing import Any

import pytest

from robotfix import api
from robotfix.analysis import binder, calls, context, expressions, interpreter, values
from robotfix.analysis.context import FileContext
from robotfix.analysis.state import State
from robotfix.analysis.values import Value
from robotfix.annotations import ast as A
from robotfix.annotations.units import resolve
from robotfix.ros.catalog import MsgCatalog
from robotfix.source import SourceFile
from tests.test_eval_costs import _interpreters

CASES = Path(__file__).parent / "cases"
# single-file cases whose bodies read and bind many locals, lists, messages
DIRS = ("paths", "containers", "control", "nodes")

NODE = """\
import math
import sys
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist


class Driver(Node):
    def __init__(self):
        super().__init__('driver')
        self.pub = self.create_publisher(Twist, 'cmd_vel', 10)

    def cb(self, args):
        speed = args.speed
        turn = math.pi / 4
        if args.verbose:
            print(sys.argv, args.verbose)
        msg = Twist()
        msg.linear.x = speed
        msg.angular.z = turn
        self.pub.publish(msg)
"""


def _shown(diags: list[Any]) -> list[str]:
    return [f"{d.span.line}:{d.span.col} {d.rule.code} {d.message}" for d in diags]


def test_a_fresh_unknown_is_made_as_value_makes_it() -> None:
    """`FileContext.fresh` makes its value with `values.unknown`, which fills a
    Value's slots in place (no call through the type to `__init__`): every slot
    as `Value(kind, sym, unit)` has it."""
    ctx = FileContext(SourceFile.from_bytes("n.py", b""), MsgCatalog([]), print)
    for kind, unit in (("float", resolve("m")), ("int", None), ("unknown", None)):
        made = ctx.fresh(kind, "x", unit)
        assert type(made) is Value
        sym = made.term
        assert isinstance(sym, A.Sym) and sym.ident == ctx.last_id()
        plain = Value(kind, A.Sym(sym.ident, "int" if kind == "int" else "real"), unit)
        assert [getattr(made, n) for n in Value.__slots__] == [
            getattr(plain, n) for n in Value.__slots__
        ]
    # the symbol too is made in place, from its number: as `A.Sym` makes it
    for kind in ("int", "bool", "str", "float", "unknown", "msg"):
        made = values.unknown(kind, 41, None)
        sym = made.term
        assert type(sym) is A.Sym and sym == A.Sym(41, values.sort_of(kind))
        assert hash(sym) == hash(A.Sym(41, values.sort_of(kind)))
        assert [getattr(sym, n) for n in A.Sym.__slots__] == [41, values.sort_of(kind)]


def _cases() -> list[Path]:
    return sorted(p for d in DIRS for p in (CASES / d).glob("*.py"))


def test_a_local_read_by_the_shortcut_is_what_lookup_name_gives(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """`Binder.eval_Name` answers a local holding a value itself; through
    `lookup_name` alone (the general path) every case checks the same."""
    cases = _cases()
    assert len(cases) > 30
    fast = [_shown(api.check_source(p.read_text(), str(p))) for p in cases]
    monkeypatch.setattr(
        binder.Binder, "eval_Name", expressions.ExpressionEvaluator.eval_Name
    )
    monkeypatch.setattr(expressions, "_EVAL", {})  # the dispatch tables anew
    general = [_shown(api.check_source(p.read_text(), str(p))) for p in cases]
    assert fast == general
    assert any(fast)


def test_unknowns_and_modules_have_the_members_the_shortcuts_assume(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """`eval_Attribute` answers an unknown's attribute without asking `member`
    (it has none) and a module's from `module_attribute` alone: what `member`
    answers for them."""
    made = _interpreters(monkeypatch)
    api.check_source(NODE, str(tmp_path / "a.py"))
    walker = made[-1]
    state = State()
    unknown = walker.ctx.fresh("unknown", "args")
    for attr in ("speed", "verbose", "pi", "__class__"):
        assert walker.member(unknown, attr, state) is None
        assert walker.member(Value("unknown"), attr, state) is None
    for module, attr in (("math", "pi"), ("sys", "argv"), ("rclpy", "init")):
        base = Value("module", name=module)
        assert walker.member(base, attr, state) == (
            walker.lookups.module_attribute(module, attr)
        )
    pi = walker.member(Value("module", name="math"), "pi", state)
    assert pi is not None and pi.kind == "float"


def test_a_derived_value_skips_first_version_only_where_it_is_its_own() -> None:
    """`_first_version` answers a key that reads a first version of an unchanged
    object with the key itself, and `derived` ties a later version (or a read of a
    later read) to the first read."""
    sym = A.Sym(9, "real")
    own = [
        ("attribute", 5, "x", 0),
        ("truthy", 5, 0),
        ("len", 3, 0),
        ("isinstance", 4, "int", 0),
        ("is None", 7),
        ("is None", sym),
        ("==", sym, A.Str("slow")),
        ("truthy", "math.TYPE_CHECKING"),
    ]
    for key in own:
        assert context._first_version(key, {})[0] is key
    ctx = FileContext(SourceFile.from_bytes("n.py", b""), MsgCatalog([]), print)
    first = ctx.derived(("attribute", 5, "x", 0), "unknown", "x")
    assert not ctx.unchanged
    later = ctx.derived(("attribute", 5, "x", 2), "unknown", "x")
    assert isinstance(later.term, A.Sym) and ctx.unchanged == {
        later.term.ident: (first.term, 5)
    }
    again = ctx.derived(("truthy", 11, 0), "bool", "t")  # now something changed
    assert again.term != first.term and len(ctx.unchanged) == 1
    # a first read of an object that is itself a later read: tied to the first's
    assert isinstance(first.term, A.Sym)
    inner = ctx.derived(("attribute", later.term.ident, "y", 0), "unknown", "x.y")
    origin = ctx.derived(("attribute", first.term.ident, "y", 0), "unknown", "x.y")
    assert isinstance(inner.term, A.Sym)
    assert ctx.unchanged[inner.term.ident] == (origin.term, 5)


def test_a_section_type_is_found_under_its_nested_names(tmp_path: Path) -> None:
    """`msg_type_named` tries a name's section spellings only when it ends in one
    (`MoveRequest`, `Move_Request`): others are looked up as written."""
    srv = tmp_path / "pkg" / "srv" / "Move.srv"
    srv.parent.mkdir(parents=True)
    srv.write_text("float64 x\n---\nbool ok\n")
    ctx = FileContext(SourceFile.from_bytes("n.py", b""), MsgCatalog([srv]), print)
    assert ctx.msg_type_named("pkg.srv.MoveRequest") == "pkg/Move_Request"
    assert ctx.msg_type_named("pkg.srv.Move_Request") == "pkg/Move_Request"
    assert ctx.msg_type_named("pkg.srv.MoveResponse") == "pkg/Move_Response"
    assert ctx.msg_type_named("pkg.srv.Move.Response") == "pkg/Move_Response"
    assert ctx.msg_type_named("pkg.srv.Move") is None
    assert ctx.msg_type_named("rospy.loginfo") is None


def test_only_a_bool_is_compared_with_true() -> None:
    """`State.assume` and `under` compare a fact with TRUE only when it is a
    Bool: no other term equals it (a `Binary` asked two `__eq__`s to say so)."""
    sym = A.Sym(1, "real")
    others = [
        sym,
        A.Num(Fraction(1), True),
        A.Str("True"),
        A.Unary("not", A.Bool(False)),
        A.Binary("and", A.TRUE, A.TRUE),
        A.Name("True"),
    ]
    for term in others:
        assert term != A.TRUE
    assert A.Bool(True) == A.TRUE and A.Bool(False) != A.TRUE
    state = State()
    for fact in [A.TRUE, A.Bool(True), *others, A.Bool(False), None]:
        state.assume(fact)
    assert state.facts == [*others, A.Bool(False)]


def _all_cases() -> list[Path]:
    return sorted(p for p in CASES.rglob("*.py"))


def test_a_call_statement_makes_no_value_and_checks_the_same(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """A call whose statement drops its value (`self.get_logger().info(...)`)
    gives no fresh unknown; its symbol's number is taken all the same. Every case
    file checks the same when such calls make their unknown (the old path), and
    the file's symbols are as many."""
    cases = _all_cases()
    assert len(cases) > 100
    made: list[int] = []
    contexts: list[FileContext] = []
    fresh, numbered = FileContext.fresh, FileContext.fresh_id

    def counting(self: FileContext, *args: Any, **kwargs: Any) -> Value:
        made.append(1)
        contexts.append(self)
        return fresh(self, *args, **kwargs)

    def noting(self: FileContext) -> int:
        contexts.append(self)
        return numbered(self)

    monkeypatch.setattr(FileContext, "fresh", counting)
    monkeypatch.setattr(FileContext, "fresh_id", noting)
    lasts: list[int] = []

    def check(path: Path) -> list[str]:
        contexts.clear()
        shown = _shown(api.check_source(path.read_text(), str(path)))
        lasts.append(sum(c.last_id() for c in {id(c): c for c in contexts}.values()))
        return shown

    fast = [check(p) for p in cases]
    fast_made, fast_lasts = len(made), lasts[:]
    made.clear()
    lasts.clear()
    monkeypatch.setattr(calls, "_DROPPING", type(None))  # no statement drops
    general = [check(p) for p in cases]
    assert fast == general
    assert fast_lasts == lasts
    assert fast_made < len(made)
    assert any(fast)


def test_a_call_hands_on_the_method_name_its_node_has(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """`eval_Call` reads the callee's node once and hands its method name on:
    `_dispatch`, `_forget_after_call` and `library_call` are given what
    `node.func.attr` is (None for a callee that is no attribute), and the
    callee's node `node.func` and the argument nodes `node.args` are."""
    seen: list[str | None] = []
    dispatch = calls.CallEvaluator._dispatch
    forget = calls.CallEvaluator._forget_after_call

    def _attr(node: Any) -> str | None:
        func = node.func
        return func.attr if isinstance(func, ast.Attribute) else None

    def checked_dispatch(self: Any, callee: Any, node: Any, *rest: Any) -> Any:
        assert rest[-1] == _attr(node)
        seen.append(rest[-1])
        return dispatch(self, callee, node, *rest)

    def checked_forget(self: Any, node: Any, func: Any, given: Any, *rest: Any) -> Any:
        assert func is node.func and given is node.args and rest[-1] == _attr(node)
        return forget(self, node, func, given, *rest)

    monkeypatch.setattr(calls.CallEvaluator, "_dispatch", checked_dispatch)
    monkeypatch.setattr(calls.CallEvaluator, "_forget_after_call", checked_forget)
    for path in sorted((CASES / "nodes").glob("*.py")):
        api.check_source(path.read_text(), str(path))
    assert None in seen and any(seen)


def test_the_site_before_the_first_statement_is_shared_and_never_changed() -> None:
    """Every evaluator starts at one shared `ast.Pass()` (not one made per body
    run): checking the cases writes nothing into it."""
    fresh = vars(ast.Pass())
    for path in sorted((CASES / "nodes").glob("*.py")):
        api.check_source(path.read_text(), str(path))
    assert vars(expressions._NO_SITE) == fresh


def test_the_hot_evaluator_functions_make_no_cell_per_call() -> None:
    """A local that a lambda, comprehension or generator captures is a cell made
    at every call of its function (3.11), the lambda made or not: the most called
    evaluator functions capture nothing (their hovers are `partial`s)."""
    from robotfix.analysis.lookups import Lookups

    hot = [
        binder.Binder.bind,
        binder.Binder.bind_parameters,
        expressions.ExpressionEvaluator.eval,
        expressions.ExpressionEvaluator.eval_Attribute,
        expressions.ExpressionEvaluator.instance_attribute,
        calls.CallEvaluator.eval_Call,
        calls.CallEvaluator._dispatch,
        calls.CallEvaluator._forget_after_call,
        Lookups.typed,
        interpreter.Interpreter.visit_Assign,
    ]
    assert [f.__name__ for f in hot if f.__code__.co_cellvars] == []


def test_a_derived_term_makes_no_value_and_checks_the_same(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """`FileContext.derived_term` (a derived symbol read for its term alone: `x is
    None`, `if x:`, a join's ties) makes no value, only the symbol. Every case
    file checks the same, with the same symbols, names and ties of later reads to
    first ones, as when it takes the term of the value `derived` makes."""
    cases = _all_cases()
    assert len(cases) > 100
    contexts: list[FileContext] = []
    init = FileContext.__init__

    def noting(self: FileContext, *args: Any, **kwargs: Any) -> None:
        init(self, *args, **kwargs)
        contexts.append(self)

    monkeypatch.setattr(FileContext, "__init__", noting)

    def named(found: object) -> object:
        return found if isinstance(found, str) else ast.dump(found)  # type: ignore[arg-type]

    def run() -> tuple[list[object], int]:
        seen: list[object] = []
        alone = 0  # entries of `_derived` made for their term alone
        for path in cases:
            contexts.clear()
            seen.append(_shown(api.check_source(path.read_text(), str(path))))
            for ctx in contexts:
                names = {k: named(v) for k, v in ctx.sym_names.items()}
                seen.append((ctx.last_id(), sorted(ctx.unchanged.items()), names))
                alone += sum(isinstance(v, A.Sym) for v in ctx._derived.values())
        return seen, alone

    fast, alone = run()
    assert alone > 0
    monkeypatch.setattr(
        FileContext,
        "derived_term",
        lambda self, key, kind, description: self.derived(key, kind, description).term,
    )
    general, none = run()
    assert none == 0
    assert fast == general
