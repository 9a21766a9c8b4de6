"""Path questions answered without z3 (issue 13 item 7): "possible" only with a
witness checked by exact evaluation, "impossible" only from the boolean skeleton;
z3 gives the same verdict on every question so answered."""

from __future__ import annotations

import os
from fractions import Fraction
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix import api, run
from robotfix.annotations import ast as A
from robotfix.annotations.parser import parse_predicate
from robotfix.annotations.witness import example, holds_somewhere
from robotfix.budget import Budget
from robotfix.config import Config
from robotfix.rules import UNREADABLE_FILE
from robotfix.smt.propositional import components, satisfiable
from robotfix.smt.solver import check
from robotfix.vc import VC, Proved, Undecided, Unproven, Verdict, Violated
from tests.test_cases import CASES, check_case

X, Y, N, B = A.Sym(1, "real"), A.Sym(2, "real"), A.Sym(3, "int"), A.Sym(4, "bool")
S = A.Sym(5, "str")


def term(text: str) -> A.Expr:
    return A.substitute(parse_predicate(text), {"x": X, "y": Y, "n": N, "b": B})


def question(*parts: str) -> VC:
    """Can every part hold? (the condition is the last part)"""
    *facts, condition = (term(p) for p in parts)
    return VC(tuple(facts), A.Unary("not", condition), question=True)


def same_class(fast: Verdict, slow: Verdict) -> bool:
    if isinstance(slow, Undecided):
        return True  # z3 gave up where an exact answer was found
    possible = (Violated, Unproven)
    return isinstance(fast, Proved) == isinstance(slow, Proved) and (
        isinstance(fast, possible) == isinstance(slow, possible)
    )


POSSIBLE = [
    ("x > 0", "x < 1"),
    ("x == y + 3", "y > 7"),
    ("n >= 2", "n * 3 == 6"),
    ("b", "x > 2 or b == False"),
    ("abs(x) <= 1", "min(x, y) == y", "y < -1 or y > 0"),
    ("n == 4", "x == n / 2", "x > 1.5"),
]

IMPOSSIBLE_BY_SKELETON = [
    ("b", "not b and x > 0"),
    ("b and 10 <= 0",),  # a closed comparison is a constant
    ("n == -1 or b", "not b", "n == 1"),  # one symbol, two constants
    ("x > 0", "not (x > 0)"),
    ("x > 2", "x < 1"),  # two bounds of one symbol no number meets
    ("n == -111 or b", "not b", "not (n <= 0)"),
]

LEFT_TO_Z3 = [
    ("n > 0", "n < 1"),  # impossible only by the integers
    ("x > y", "y > x"),  # two symbols
    ("x * x == 2",),  # possible, but not at any candidate
]


@pytest.mark.parametrize("parts", POSSIBLE, ids=" ; ".join)
def test_a_witnessed_question_is_possible_and_z3_agrees(parts: tuple[str, ...]) -> None:
    vc = question(*parts)
    assert holds_somewhere([*vc.facts, A.Unary("not", vc.goal)])
    assert api._without_solver(vc) == Unproven((), ())
    assert isinstance(check(vc), (Violated, Unproven))


@pytest.mark.parametrize("parts", IMPOSSIBLE_BY_SKELETON, ids=" ; ".join)
def test_the_skeleton_rules_out_and_z3_agrees(parts: tuple[str, ...]) -> None:
    vc = question(*parts)
    assert api._without_solver(vc) == Proved()
    assert check(vc) == Proved()


@pytest.mark.parametrize("parts", LEFT_TO_Z3, ids=" ; ".join)
def test_what_is_neither_witnessed_nor_ruled_out_goes_to_z3(
    parts: tuple[str, ...],
) -> None:
    assert api._without_solver(question(*parts)) is None


def test_a_check_with_witnesses_either_way_needs_no_z3() -> None:
    """A check (not a question) is Unproven without z3 when exact values break the
    goal and others keep it, with the counterexample z3's session shows; Violated
    when the skeleton rules out keeping it; with a probe that has no exact value
    there, a string or a long number to show, it is z3's."""
    int64 = "-9223372036854775808 <= {0} and {0} <= 9223372036854775807"
    facts = (term(int64.format("n")), term(int64.format("y")))
    plain = VC(facts, term("-9223372036854775808 <= n + y"))
    assert api._without_solver(plain) == check(plain)
    assert isinstance(check(plain), Unproven) and check(plain).sym_values
    broken = VC((term("b"), term("x > 2")), term("x < 1"))
    assert api._without_solver(broken) == check(broken) == Violated(())
    half = VC((term("x > 0"),), term("x > 0.5"))
    assert api._without_solver(half) == check(half)
    probed = VC(facts, plain.goal, probes=(N, term("n + y"), term("x / 2")))
    assert api._without_solver(probed) is None  # x has no value in the example
    probed = VC(facts, plain.goal, probes=(N, term("n + y"), term("n / 3 > 1")))
    assert api._without_solver(probed) == check(probed)
    assert None not in check(probed).probe_values
    speed = VC((term("x >= 0"),), term("x * 2 <= 1"), probes=(term("x * 2"),))
    assert api._without_solver(speed) == check(speed)
    text = VC((), A.Binary("==", S, A.Str("a")))
    assert api._without_solver(text) is None
    long = VC(
        (), term("n < 1000000000000000000000000000000000000000000000"), probes=(N,)
    )
    assert api._without_solver(long) is None  # shown rounded: z3's to show


def test_a_check_z3_proves_costs_little_witness_search_first() -> None:
    """A check the pre-pass cannot prove and no value breaks: the witness search
    tried before z3 stops at `api.CHECK_WORK` nodes (unbounded, this one walks
    25,884), and z3 proves it as before."""
    syms = [A.Sym(20 + i, "real") for i in range(6)]
    zero = A.Num(Fraction(0), True)
    facts = tuple(A.Binary(">", sym, zero) for sym in syms)
    goal: A.Expr = A.Binary(">", A.Binary("*", syms[0], syms[1]), zero)
    for sym in syms[2:]:
        product = A.Binary(">", A.Binary("*", sym, syms[0]), zero)
        goal = A.Binary("and", goal, product)
    vc = VC(facts, goal)
    spent = Budget()
    assert api._without_solver(vc, spent) is None
    assert spent.used <= api.CHECK_WORK + 200
    assert check(vc) == Proved()


def test_strings_compared_for_equality_have_witnesses() -> None:
    """A string symbol tries the strings it is compared with and one other (frame
    names: `frame_id == "map"`); other string terms have no value here."""
    a, b = A.Str("a"), A.Str("b")
    assert holds_somewhere([A.Binary("==", S, a)])
    assert holds_somewhere([A.Binary("!=", S, a), A.Binary("!=", S, b)])
    assert not holds_somewhere([A.Binary("==", S, a), A.Binary("==", S, b)])
    assert not holds_somewhere([A.Binary("==", A.Binary("+", S, a), b)])


def test_terms_without_a_value_here_have_no_witness() -> None:
    speed = A.Name("speed")
    assert not holds_somewhere([A.Binary("<", speed, A.Num(Fraction(1), True))])
    assert not holds_somewhere([term("x / (y - y) > 1")])
    huge = A.Num(Fraction(10**200), True)
    assert not holds_somewhere([A.Binary("<", X, huge)])


def test_groups_that_share_no_symbol_are_searched_apart() -> None:
    parts = [term("x > 0"), term("b"), term("y == x"), term("10 > 1"), term("n < 2")]
    assert components(parts) == [
        [parts[0], parts[2]],
        [parts[1]],
        [parts[3]],
        [parts[4]],
    ]
    # 80 unrelated booleans (more than the skeleton searches) and a contradiction
    noise = [
        A.Binary("or", A.Sym(10 + i, "bool"), A.Sym(60 + i, "bool")) for i in range(40)
    ]
    contradiction = [term("b"), term("not b")]
    vc = VC(tuple(noise + contradiction[:1]), term("b"), question=True)
    assert satisfiable([*noise, *contradiction]) is None
    assert api._without_solver(vc) == Proved()


def _questions(paths: list[Path], monkeypatch: pytest.MonkeyPatch) -> Any:
    asked: list[VC] = []
    original = api.Discharger._decide

    def decide(self: api.Discharger, vc: VC) -> Verdict:
        if vc.question:
            asked.append(vc)
        return original(self, vc)

    with monkeypatch.context() as patch:
        patch.setattr(api.Discharger, "_decide", decide)
        found = [repr(d) for path in paths for d in check_case(path)]
    return found, asked


def test_every_question_of_the_cases_gets_z3s_verdict(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    paths = sorted(CASES.rglob("*.py"))
    _, asked = _questions(paths, monkeypatch)
    answered = [(vc, api._without_solver(vc)) for vc in asked]
    witnessed = [vc for vc, verdict in answered if isinstance(verdict, Unproven)]
    assert witnessed, "the cases exercise the witnesses"
    for vc, verdict in answered:
        if verdict is not None:
            assert same_class(verdict, check(vc)), vc


def test_the_cases_give_the_diagnostics_of_z3_alone(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    paths = sorted(CASES.rglob("*.py"))
    fast, _ = _questions(paths, monkeypatch)
    with monkeypatch.context() as patch:
        patch.setattr(api, "_without_solver", lambda vc, budget=None: None)
        patch.setattr(api.Discharger, "prepass", False)
        slow, _ = _questions(paths, monkeypatch)
    assert fast == slow


def _conditions() -> st.SearchStrategy[A.Expr]:
    leaves = st.one_of(
        st.sampled_from([X, Y, N]),
        st.integers(-2, 2).map(lambda v: A.Num(Fraction(v), True)),
        st.just(A.Num(Fraction(1, 2), False)),
    )
    terms = st.recursive(
        leaves,
        lambda inner: st.one_of(
            st.builds(A.Binary, st.sampled_from(["+", "-", "*"]), inner, inner),
            inner.map(lambda t: A.Func("abs", (t,))),
        ),
        max_leaves=3,
    )
    compare = st.builds(
        A.Binary, st.sampled_from(["<", "<=", ">", ">=", "==", "!="]), terms, terms
    )
    atoms = st.one_of(compare, st.just(B))
    return st.recursive(
        atoms,
        lambda inner: st.one_of(
            st.builds(A.Binary, st.sampled_from(["and", "or"]), inner, inner),
            st.builds(A.Unary, st.just("not"), inner),
        ),
        max_leaves=3,
    )


@settings(max_examples=300, deadline=None)
@given(facts=st.lists(_conditions(), max_size=3), condition=_conditions())
def test_z3_agrees_with_every_answer_without_it(
    facts: list[A.Expr], condition: A.Expr
) -> None:
    vc = VC(tuple(facts), A.Unary("not", condition), question=True)
    verdict = api._without_solver(vc)
    if verdict is not None:
        assert same_class(verdict, check(vc)), (vc, verdict)


def _terms() -> st.SearchStrategy[A.Expr]:
    leaves = st.one_of(
        st.sampled_from([X, Y, N]),
        st.integers(-2, 2).map(lambda v: A.Num(Fraction(v), True)),
    )
    return st.recursive(
        leaves,
        lambda inner: st.builds(
            A.Binary, st.sampled_from(["+", "-", "*"]), inner, inner
        ),
        max_leaves=3,
    )


@settings(max_examples=300, deadline=None)
@given(
    facts=st.lists(_conditions(), max_size=3),
    goal=_conditions(),
    probes=st.lists(_terms(), max_size=2),
)
def test_z3_gives_every_check_answered_without_it(
    facts: list[A.Expr], goal: A.Expr, probes: list[A.Expr]
) -> None:
    """Verdict, probes' values and counterexample: byte for byte z3's."""
    vc = VC(tuple(facts), goal, probes=tuple(probes))
    verdict = api._without_solver(vc)
    if verdict is not None and not isinstance(slow := check(vc), Undecided):
        assert verdict == slow, (vc, verdict, slow)


@settings(max_examples=200, deadline=None)
@given(parts=st.lists(_conditions(), min_size=1, max_size=4), most=st.integers(1, 400))
def test_a_search_stopped_sooner_finds_what_a_longer_one_finds_first(
    parts: list[A.Expr], most: int
) -> None:
    sooner = example(parts, most=most)
    assert sooner is None or sooner == example(parts)


# Item 7's other half: a run without the cache reads each file when it checks it.

NODE = """import rclpy
from rclpy.node import Node


class Talker(Node):
    def __init__(self) -> None:
        super().__init__("talker")
        self.count = 0
"""


def test_a_file_is_read_when_it_is_checked(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    for index in range(4):
        (tmp_path / f"node{index}.py").write_text(NODE, encoding="utf-8")
    events: list[tuple[str, str]] = []
    read, check_file = run.read_regular, run.check_file

    def reading(path: Any, *args: Any, **kwargs: Any) -> bytes:
        events.append(("read", Path(path).name))
        return read(path, *args, **kwargs)

    def checking(path: str, *args: Any, **kwargs: Any) -> Any:
        events.append(("check", Path(path).name))
        return check_file(path, *args, **kwargs)

    monkeypatch.setattr(run, "read_regular", reading)
    monkeypatch.setattr(run, "check_file", checking)
    result = run.check_paths([tmp_path], Config(root=tmp_path), None, 1, False)
    assert not result.internal_errors
    names = [f"node{index}.py" for index in range(4)]
    assert events == [(kind, name) for name in names for kind in ("read", "check")]


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs FIFOs")
@pytest.mark.parametrize("jobs", [1, 2])
def test_an_unreadable_file_read_late_still_says_so(tmp_path: Path, jobs: int) -> None:
    for index in range(3):
        (tmp_path / f"node{index}.py").write_text(NODE, encoding="utf-8")
    fifo = tmp_path / "pipe.py"
    os.mkfifo(fifo)
    paths = sorted(tmp_path.glob("*.py"))
    result = run.check_paths(paths, Config(root=tmp_path), None, jobs, False)
    unreadable = [d.path for d in result.diagnostics if d.rule is UNREADABLE_FILE]
    assert unreadable == [str(fifo)]
    assert not result.internal_errors


def test_a_symbol_tries_one_past_its_bounds() -> None:
    """`v > limit`: no constant of its own fits `v`, one past `limit` does (a
    counterexample `smt.solver` then shows without asking z3 again)."""
    v, limit = A.Sym(40, "real"), A.Sym(41, "real")
    parts = [
        A.Binary(">", limit, A.Num(Fraction(0), False)),
        A.Binary(">", v, limit),
        A.Unary("not", A.Binary("<=", A.Func("abs", (v,)), limit)),
    ]
    found = example(parts)
    assert found is not None and found[v] > found[limit] > 0


def test_a_symbol_tries_past_where_a_comparison_turns() -> None:
    """`abs(x * 0.0175) > 3.1416` (degrees for radians): no constant of its own
    and no bound fits `x`; one past where the two sides meet (x = 180) does."""
    x = A.Sym(42, "real")
    scale, pi = Fraction(7, 400), Fraction(31416, 10000)
    scaled = A.Func("abs", (A.Binary("*", x, A.Num(scale, False)),))
    found = example([A.Unary("not", A.Binary("<=", scaled, A.Num(pi, False)))])
    assert found is not None and abs(found[x] * scale) > pi
