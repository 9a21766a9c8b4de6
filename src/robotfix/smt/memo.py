"""Proofs kept across edits: verdicts by normalised VC.

A keystroke in one function changes that function's VCs; the others come back the
same but for the numbering of their fresh symbols, which an edit above them shifts.
`ProofMemo` keys a VC by its facts, goal, probes and kind with the symbols renumbered
in order of first appearance, and keeps the verdict the solver gave (counterexample
values included), so the editor asks z3 only about what changed. A counterexample
over symbols is stored by their canonical numbers and given back in the new VC's.

What deciding a verdict cost the file's work budget (pre-pass, witnesses, z3) is kept
with it: the `Discharger` charges it again on a hit, so a file that runs out of
budget runs out at about the same VC (the pre-pass and z3 work incrementally, so a
VC decided again after others were kept may cost a little more or less).
Undecided verdicts are never kept (they depend on the budget left, not on the VC).
Bounded: least recently used entries go first; a VC of more than `MAX_KEY_NODES`
nodes (a long function's facts; the cases' largest has 166) is not kept, since
keying it would cost as much as deciding it.
"""

from __future__ import annotations

from collections import OrderedDict
from dataclasses import replace

from robotfix.annotations import ast as A
from robotfix.vc import VC, Undecided, Unproven, Verdict

MAX_ENTRIES = 5_000  # distinct VCs per document; at most about 2.7 kB each
MAX_KEY_NODES = 1_000  # nodes of a VC's facts, goal and probes that are keyed

Key = tuple[object, ...]


class ProofMemo:
    def __init__(self, max_entries: int = MAX_ENTRIES) -> None:
        self._table: OrderedDict[Key, tuple[Verdict, int, bool]] = OrderedDict()
        self._max = max_entries
        self.hits = 0
        self.misses = 0
        # the document's analysis kept per top-level unit, next to its proofs: the
        # analysis's own memo (`analysis/unitmemo.UnitMemo`), which `api` puts here
        # (this layer knows nothing of the analysis)
        self.units: object = None

    def __len__(self) -> int:
        return len(self._table)

    def get(self, key: Key, idents: list[int]) -> tuple[Verdict, int, bool] | None:
        """The verdict kept for a VC whose key is `key`, in terms of its own symbols
        (`idents`: the VC's symbol identities by canonical number), the work it cost
        and whether z3 gave it."""
        found = self._table.get(key)
        if found is None:
            self.misses += 1
            return None
        self._table.move_to_end(key)
        self.hits += 1
        verdict, work, solved = found
        if isinstance(verdict, Unproven) and verdict.sym_values:
            values = sorted((idents[i], value) for i, value in verdict.sym_values)
            verdict = replace(verdict, sym_values=tuple(values))
        return verdict, work, solved

    def put(
        self, key: Key, idents: list[int], verdict: Verdict, work: int, solved: bool
    ) -> None:
        if isinstance(verdict, Undecided):
            return
        if isinstance(verdict, Unproven) and verdict.sym_values:
            number = {ident: i for i, ident in enumerate(idents)}
            if any(ident not in number for ident, _ in verdict.sym_values):
                return
            values = tuple((number[ident], v) for ident, v in verdict.sym_values)
            verdict = replace(verdict, sym_values=values)
        self._table[key] = (verdict, work, solved)
        self._table.move_to_end(key)
        while len(self._table) > self._max:
            self._table.popitem(last=False)


def key(vc: VC) -> tuple[Key, list[int]] | None:
    """The VC with its symbols numbered in order of first appearance (facts, goal,
    probes), and the symbols' identities in that order; None for a VC too deep to
    walk or too large to key."""
    if len(vc.facts) >= MAX_KEY_NODES:  # a node each at least
        return None
    keying = _Keying(MAX_KEY_NODES)
    try:
        facts = tuple(keying.canonical(f) for f in vc.facts)
        goal = keying.canonical(vc.goal)
        probes = tuple(keying.canonical(p) for p in vc.probes)
    except (RecursionError, _TooLargeError):
        return None
    return (facts, goal, probes, vc.question), list(keying.numbers)


class _TooLargeError(Exception):
    pass


class _Keying:
    """A VC's terms as plain tuples, symbols numbered in order; at most `left`
    nodes (shared ones each time), then `_TooLargeError`."""

    def __init__(self, left: int) -> None:
        self.numbers: dict[int, int] = {}
        self.left = left

    def canonical(self, expr: A.Expr) -> object:
        self.left -= 1
        if self.left < 0:
            raise _TooLargeError
        canonical = self.canonical
        if isinstance(expr, A.Sym):
            numbers = self.numbers
            number = numbers.get(expr.ident)
            if number is None:
                number = numbers[expr.ident] = len(numbers)
            return ("s", number, expr.sort)
        if isinstance(expr, A.Binary):
            return (expr.op, canonical(expr.left), canonical(expr.right))
        if isinstance(expr, A.Num):
            return ("n", expr.value, expr.is_int)
        if isinstance(expr, A.Unary):
            return ("u", expr.op, canonical(expr.operand))
        if isinstance(expr, A.Func):
            return ("f", expr.name, *(canonical(a) for a in expr.args))
        if isinstance(expr, A.Ite):
            return (
                "?",
                canonical(expr.cond),
                canonical(expr.then),
                canonical(expr.orelse),
            )
        if isinstance(expr, A.Bool):
            return ("b", expr.value)
        if isinstance(expr, A.Str):
            return ("t", expr.value)
        if isinstance(expr, A.Name):
            return ("x", expr.name)
        return ("k", expr.kind, expr.text, expr.target)
