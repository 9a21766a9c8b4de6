"""Issue 25 target 1 (ninth session): without `:=` in the text, the skip rule's
RF301 pass (`analysis/unbound.py`) checks an expression's reads by a stack walk
(`_Scope.reads`) instead of the recursion in evaluation order (`_Scope.expr`,
still used with `:=`). The two must find the same risky reads, everywhere; an
expression deep enough to overflow the recursion is still handed to it (the
file then goes to the analysis, as before)."""

from __future__ import annotations

import ast
from collections import Counter
from contextlib import suppress
from pathlib import Path

import pytest

from robotfix.analysis import unbound
from robotfix.analysis.unbound import _FlatScope, _RiskError, _Scope, may_be_unbound

CASES = Path(__file__).parent / "cases"


def _reads(
    tree: ast.Module, scope: type[_Scope], monkeypatch: pytest.MonkeyPatch
) -> tuple[Counter[tuple[int, str]], Counter[tuple[int, str]]]:
    """The reads the pass makes, (scope node, name): those `read` finds risky, and
    the others; none raises, so the pass goes on to the end."""
    risky: Counter[tuple[int, str]] = Counter()
    sure: Counter[tuple[int, str]] = Counter()
    real = _Scope.read

    def read(self: _Scope, name: str, bound: frozenset[str]) -> None:
        try:
            real(self, name, bound)
        except _RiskError:
            risky[id(self.node), name] += 1
        else:
            sure[id(self.node), name] += 1

    with monkeypatch.context() as patch:
        patch.setattr(_Scope, "read", read)
        with suppress(_RiskError):  # a statement the pass does not follow (both)
            scope(tree, None, frozenset(), scope is _Scope).run(tree.body, frozenset())
    return risky, sure


def test_the_flat_reads_find_what_the_recursive_ones_find_on_every_case_file(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    files = risky_reads = 0
    for path in sorted(CASES.rglob("*.py")):
        text = path.read_text(encoding="utf-8")
        if ":=" in text:
            continue
        tree = ast.parse(text)
        risky, sure = _reads(tree, _Scope, monkeypatch)
        flat_risky, flat_sure = _reads(tree, _FlatScope, monkeypatch)
        assert flat_risky == risky, path
        # a local read where it is bound is not asked (it cannot be risky)
        assert not flat_sure - sure, path
        none = frozenset[str]()
        assert may_be_unbound(tree, none, False) == may_be_unbound(tree, none), path
        files += 1
        risky_reads += sum(risky.values())
    assert files > 200 and risky_reads > 50


SNIPPETS = [
    "def f(a, *b, k=c, **d):\n    return lambda x=a.b[e]: x + y + g(*b, k=d)\n",
    "class C(B, metaclass=M):\n    z = [v + w for v in z if v for w in v]\n",
    "def f(xs):\n    ys = {k: v for k, v in xs}\n    return ys, t\n",
    "x: int = y\ndel x\nprint(x, f'{x!r:{w}}')\n",
    "import a.b as c\nfor i, (j, *k) in c.d:\n    m = n[i:j:k]\nprint(m)\n",
    "try:\n    r = g()\nexcept E as e:\n    pass\nelse:\n    s = r\nprint(r, s, e)\n",
    "with open(p) as (f, g):\n    h = f.read()\nassert h, g\nraise X from h\n",
]


@pytest.mark.parametrize("text", SNIPPETS)
def test_the_flat_reads_of_snippets(text: str, monkeypatch: pytest.MonkeyPatch) -> None:
    tree = ast.parse(text)
    flat_risky, flat_sure = _reads(tree, _FlatScope, monkeypatch)
    risky, sure = _reads(tree, _Scope, monkeypatch)
    assert flat_risky == risky and risky
    assert not flat_sure - sure


def test_an_expression_deep_enough_to_overflow_is_still_sent_to_the_analysis(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """A 2,500-term sum nests 2,500 deep: the recursion overflows, the file is
    analysed (RF902 "nested too deeply"), as it was before the flat walk. The walk
    alone would skip it: the guard is what keeps the answer."""
    tree = ast.parse("x = " + " + ".join(["1"] * 2500) + "\n")
    assert may_be_unbound(tree, frozenset(), walrus=False)
    assert may_be_unbound(tree, frozenset(), walrus=True)
    monkeypatch.setattr(unbound, "FLAT_NODES", 10**9)
    assert not may_be_unbound(tree, frozenset(), walrus=False)
    small = ast.parse("x = " + " + ".join(["1"] * 150) + "\n")
    assert not may_be_unbound(small, frozenset(), walrus=False)
