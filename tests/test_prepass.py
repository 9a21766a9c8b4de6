"""The pre-pass before z3 (`smt.prepass`) and RF509's witnesses
(`annotations.witness`): sound, and the same diagnostics as z3 alone (issue 13)."""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix import api
from robotfix.analysis import consistency
from robotfix.annotations import ast as A
from robotfix.annotations.parser import parse_predicate
from robotfix.annotations.witness import has_witness
from robotfix.smt.prepass import proves
from robotfix.smt.solver import check
from robotfix.vc import VC, Proved, Undecided, Verdict
from tests.test_cases import CASES, check_case

X, Y, N = A.Sym(1, "real"), A.Sym(2, "real"), A.Sym(3, "int")


def term(text: str) -> A.Expr:
    """An annotation with x, y (reals) and n (an int) as solver symbols."""
    return A.substitute(parse_predicate(text), {"x": X, "y": Y, "n": N})


def vc(goal: str, *facts: str) -> VC:
    return VC(tuple(term(f) for f in facts), term(goal))


PROVED = [
    ("x > 0", "0 < x and x <= 2"),
    ("x <= 5", "0 <= x and x <= 2"),
    ("abs(x) <= y", "y > 0", "not x > y", "not x < -y"),
    ("abs(x) <= x", "x > 0"),
    ("abs(-x) <= x", "x > 0"),
    ("abs(x * 0.5) <= 1", "0 < x and x < 1"),
    ("2 * x + 1 < 5", "x < 2"),
    ("x - y <= 0", "x <= y"),
    ("x / 4 < 1", "x < 4"),
    ("x == 3", "x == 3"),
    ("x != 1", "x > 2"),
    ("x > 100", "x > 2", "x < 1"),  # facts no value satisfies
    ("not (x > 2)", "x <= 2"),
    ("x > 0 or y > 0", "y == 1"),
]

NOT_PROVED = [
    ("abs(x) <= y", "x <= y"),  # -x <= y is not known
    ("x < 1", "x <= 1"),
    ("x > 0", "x >= 0"),
    ("n >= 1", "n > 0"),  # true for an int, but not read as such: z3 decides
    ("n >= 0", "n > -1/2"),
    ("x * y >= 0", "x > 0", "y > 0"),  # a product of two terms
    ("x / y > 0", "x > 0", "y > 0"),  # division by a term
    ("x == 1", "x >= 1"),
    ("x <= y", "x <= 1", "y >= 0"),
    ("x > 0", "x > 0 or y > 0"),
    ("n % 4 <= 0", "n <= 0"),  # floored: -1 % 4 is 3, not the quotient -1/4
    ("n // 4 <= n / 4 - 1", "n <= 0"),
    ("x // 1 >= x", "x >= 0"),
]


@pytest.mark.parametrize("case", PROVED, ids=lambda c: c[0])
def test_bound_checks_are_proved_and_z3_agrees(case: tuple[str, ...]) -> None:
    question = vc(*case)
    assert proves(question)
    assert check(question) == Proved()


@pytest.mark.parametrize("case", NOT_PROVED, ids=lambda c: c[0])
def test_what_it_cannot_read_goes_to_z3(case: tuple[str, ...]) -> None:
    assert not proves(vc(*case))


def test_numbers_the_encoder_does_not_take_are_left_to_z3() -> None:
    huge = A.Num(Fraction(10**1200), True)
    assert not proves(VC((), A.Binary("<", X, huge)))
    assert not proves(VC((), A.Binary("<", A.Name("speed"), A.Num(Fraction(1), True))))
    assert not proves(VC((), A.Binary("<", A.Sym(4, "str"), X)))


def sorts(name: str) -> str:
    return {"n": "int", "flag": "bool"}.get(name, "real")


@pytest.mark.parametrize(
    "text",
    ["0 < _ <= 2", "abs(v) <= limit", "0 < x < 1 and y > x", "min(a, 3) == 3", "n > 2"],
)
def test_a_satisfiable_refinement_has_a_witness(text: str) -> None:
    assert has_witness(parse_predicate(text), sorts)


@pytest.mark.parametrize(
    "text",
    [
        "_ > 2 and _ < 1",
        "0 < n < 1",  # an int strictly between 0 and 1
        "flag == True",  # a boolean: the solver's question
        "x / (y - y) > 1",
        "a < b < c < d",  # four names: more than it tries
    ],
)
def test_no_witness_where_none_is_found(text: str) -> None:
    assert not has_witness(parse_predicate(text), sorts)


def _run(paths: list[Path], fast: bool, monkeypatch: pytest.MonkeyPatch) -> Any:

    asked: list[tuple[VC, Verdict, bool]] = []
    original = api.Discharger.__call__
    witness = consistency.has_witness
    pending: list[bool] = []

    def call(self: api.Discharger, question: VC) -> Verdict:
        verdict = original(self, question)
        asked.append((question, verdict, bool(pending) and pending.pop()))
        return verdict

    def no_witness(predicate: A.Expr, sort: Any, budget: Any = None) -> bool:
        pending[:] = [witness(predicate, sort)]
        return False

    with monkeypatch.context() as patch:
        patch.setattr(api.Discharger, "__call__", call)
        patch.setattr(api.Discharger, "prepass", fast)
        if not fast:
            patch.setattr(consistency, "has_witness", no_witness)
        found = [repr(d) for path in paths for d in check_case(path)]
    return found, asked


def test_the_fast_path_gives_the_diagnostics_of_z3_alone(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    paths = sorted(CASES.rglob("*.py"))
    fast, _ = _run(paths, True, monkeypatch)
    slow, asked = _run(paths, False, monkeypatch)
    assert fast == slow  # byte for byte, counterexample values included
    proved_here = [q for q, verdict, _ in asked if proves(q)]
    assert proved_here, "the cases exercise the pre-pass"
    for question, verdict, _ in asked:
        if proves(question):
            assert verdict == Proved(), question
    witnessed = [(q, verdict) for q, verdict, w in asked if w]
    assert witnessed, "the cases exercise the witnesses"
    for question, verdict in witnessed:
        assert verdict != Proved(), question  # z3 found it satisfiable too


def _terms() -> st.SearchStrategy[A.Expr]:
    leaves = st.one_of(
        st.sampled_from([X, Y, N]),
        st.integers(-3, 3).map(lambda v: A.Num(Fraction(v), True)),
        st.sampled_from([Fraction(1, 2), Fraction(-3, 2)]).map(
            lambda v: A.Num(v, False)
        ),
    )
    return st.recursive(
        leaves,
        lambda inner: st.one_of(
            st.builds(A.Binary, st.sampled_from(["+", "-", "*", "/"]), inner, inner),
            st.builds(A.Unary, st.just("-"), inner),
            inner.map(lambda t: A.Func("abs", (t,))),
        ),
        max_leaves=4,
    )


def _comparisons() -> st.SearchStrategy[A.Expr]:
    compare = st.builds(
        A.Binary,
        st.sampled_from(["<", "<=", ">", ">=", "==", "!="]),
        _terms(),
        _terms(),
    )
    return st.recursive(
        compare,
        lambda inner: st.one_of(
            st.builds(A.Binary, st.sampled_from(["and", "or"]), inner, inner),
            st.builds(A.Unary, st.just("not"), inner),
        ),
        max_leaves=3,
    )


@settings(max_examples=300, deadline=None)
@given(facts=st.lists(_comparisons(), max_size=3), goal=_comparisons())
def test_what_the_pre_pass_proves_z3_proves(facts: list[A.Expr], goal: A.Expr) -> None:
    question = VC(tuple(facts), goal)
    if proves(question):
        verdict = check(question)
        # z3 may give up (unknown) where the pre-pass proves; it never disagrees
        assert isinstance(verdict, (Proved, Undecided)), (question, verdict)
