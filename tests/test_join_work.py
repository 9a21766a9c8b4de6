"""Issue 25 target 1: paths split and join without work nobody uses. Work is
counted, not timed, so these fail on the code that did it: an `if` copied the
state for its `else` and dropped the original, a `try` copied its entry state for
handlers that never read it and each handler's state once more, and a join asked
what the merged value is (its None test, its truth) once per path."""

from __future__ import annotations

import ast
import textwrap

import pytest

from robotfix.analysis import decisions
from robotfix.analysis.paths import PathWalker
from robotfix.analysis.state import MAYBE, Binding, MaybeUnbound, State
from robotfix.analysis.stmtsyntax import excuse
from robotfix.analysis.values import Uninit, Value
from robotfix.api import check_source
from robotfix.astwalk import walk

# `Annotated` keeps the file from the skip rule: the analysis runs its bodies
HEADER = "from typing import Annotated\n\nMeters = Annotated[float, \"Unit('m')\"]\n"


def _forks(monkeypatch: pytest.MonkeyPatch, body: str) -> int:
    count = [0]
    fork = State.fork

    def counted(self: State) -> State:
        count[0] += 1
        return fork(self)

    monkeypatch.setattr(State, "fork", counted)
    check_source(HEADER + textwrap.dedent(body), "forks.py")
    return count[0]


def test_an_if_copies_the_state_once(monkeypatch: pytest.MonkeyPatch) -> None:
    """The `then` path is a copy; the `else` path goes on in the state itself."""
    forks = _forks(
        monkeypatch,
        """
        def pick(flag: bool, far: Meters) -> Meters:
            if flag:
                step = far
            else:
                step = 2 * far
            return step
        """,
    )
    assert forks == 1  # two on the old code


def test_a_try_copies_the_state_once_where_no_handler_reads_its_entry(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The state after an exception is a copy; the only handler (no `finally`)
    goes on in it, and the entry (read only where the body binds a name that may
    be unbound in a handler) is not copied."""
    forks = _forks(
        monkeypatch,
        """
        def stop(node: object, far: Meters) -> Meters:
            try:
                node.halt()
            except ValueError:
                pass
            return far
        """,
    )
    assert forks == 1  # three on the old code


def test_a_try_whose_body_binds_still_reads_its_entry() -> None:
    """Where a handler may run before the body bound a name, the entry is kept
    (copied): a read after the `try` is RF301; in a handler of what a loop's body
    raised, its target was bound (line 19), the body's name may not be (line 20)."""
    text = HEADER + textwrap.dedent(
        """
        def load(node: object) -> Meters:
            try:
                node.open()
                far: Meters = node.read()
            except ValueError:
                node.close()
            return far


        def each(items: list) -> Meters:
            try:
                for item in items:
                    far: Meters = item.read()
            except ValueError:
                print(item)
                return far
            return 0.0
        """
    )
    found = [(d.code, d.span.line) for d in check_source(text, "entry.py")]
    assert sorted(found) == [("RF301", 11), ("RF301", 20)]


def test_a_join_asks_what_its_merged_value_is_once(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """`ties` asked the merged value's None test and truth on each path; the
    answer is the same, so it is asked once (the paths' own values still are)."""
    asked: list[list[int]] = []
    ties, none_test = PathWalker.ties, PathWalker._none_test

    def counted_ties(self: PathWalker, *args: object) -> object:
        asked.append([])  # (on the old code: one call per path)
        return ties(self, *args)  # type: ignore[arg-type]

    def counted_none(self: PathWalker, value: Value) -> object:
        if asked:
            asked[-1].append(id(value))
        return none_test(self, value)

    monkeypatch.setattr(PathWalker, "ties", counted_ties)
    monkeypatch.setattr(PathWalker, "_none_test", counted_none)
    text = HEADER + textwrap.dedent(
        """
        def first(node: object, far: Meters) -> Meters:
            if far > 1.0:
                found = node.best()
            else:
                found = None
            if found:
                return far
            return 2 * far
        """
    )
    check_source(text, "ties.py")
    assert asked  # a value of unknown kind was merged
    for one in asked:
        assert len(one) == len(set(one)) == 3  # merged, then each path's value
    assert len(asked) == 1


def _walked(
    test: ast.expr, local_names: set[str], attributes: dict[int, int]
) -> decisions.Decision:
    """`decisions.decision` as it was written before: a walk of every node."""
    skipped: set[int] = set()
    found: set[tuple[str, object]] = set()
    for node in walk([test]):
        if isinstance(node, ast.Call):
            skipped.add(id(node.func))
        elif isinstance(node, ast.Attribute):
            skipped.add(id(node.value))
        elif isinstance(node, ast.Name) and (
            id(node) not in skipped
            and node.id in local_names
            and node.id not in decisions.RECEIVERS
        ):
            found.add((node.id, len(node.id)))
        if isinstance(node, ast.Attribute) and id(node) not in skipped:
            found.add(("." + node.attr, attributes.get(id(node))))
    return id(test), frozenset(found)  # type: ignore[arg-type]


def test_a_decision_reads_what_a_walk_of_its_test_reads() -> None:
    """The stack loop of `decision` finds the data of every branch test of the
    case files as a walk of every node does."""
    from pathlib import Path

    cases = Path(__file__).parent / "cases"
    tests = 0
    for path in sorted(cases.rglob("*.py")):
        try:
            tree = ast.parse(path.read_bytes())
        except SyntaxError:
            continue
        names = {n.id for n in walk(tree) if isinstance(n, ast.Name)}
        local = {n for n in names if hash(n) % 3}  # some names are locals
        attributes = {
            id(n): i for i, n in enumerate(walk(tree)) if isinstance(n, ast.Attribute)
        }
        for node in walk(tree):
            if isinstance(node, ast.If | ast.While | ast.IfExp | ast.Assert):
                test = node.test
                got = decisions.decision(test, local, len, attributes)
                assert got == _walked(test, local, attributes), ast.unparse(test)
                tests += 1
    assert tests > 100


def _excused_before(side: State, other: State) -> None:
    """`stmtsyntax.excuse` as it was written before: no identity shortcut."""
    for name, bound in other.env.items():
        if "." in name or not isinstance(bound, Value):
            continue
        mine = side.env.get(name)
        if not isinstance(mine, Value) or mine.uninit is not None:
            side.env[name] = MAYBE


def test_excuse_skips_only_a_binding_it_would_keep() -> None:
    """The same binding on both paths is skipped first, unless it is a value read
    uninitialised: every pair of bindings gives what the loop before gave."""
    from itertools import product

    shared = Value("float")
    bindings: list[Binding | None] = [
        None,
        shared,
        Value("float"),
        Value("unknown", uninit=Uninit("x", False)),
        MaybeUnbound(),
        MAYBE,
    ]
    for name, (mine, theirs) in product(["x", "self.x"], product(bindings, repeat=2)):
        if theirs is None:
            continue
        for excused in (excuse, _excused_before):
            side = State({name: mine} if mine is not None else {})
            other = State({name: theirs})
            excused(side, other)
            if excused is excuse:
                got = side.env
            else:
                assert got == side.env, (name, mine, theirs)
    uninit = bindings[3]
    side, other = State({"x": uninit}), State({"x": uninit})
    excuse(side, other)  # the same object, read uninitialised: excused
    assert side.env["x"] is MAYBE
