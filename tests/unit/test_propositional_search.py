"""The pruned search of `smt/propositional.py` (each node evaluates only what its
parent left undecided) answers as the plain search did, visit budget included."""

from __future__ import annotations

import random

from robotfix.smt import propositional as P
from robotfix.smt.propositional import Formula


def _plain(formulas: list[Formula], count: int) -> bool | None:
    """The search before issue 13: every formula at every node."""
    model: dict[int, bool] = {}
    visited = 0

    def go(index: int) -> bool | None:
        nonlocal visited
        visited += 1
        if visited > P.BUDGET:
            return None
        values = [P._value(f, model) for f in formulas]
        if any(v is False for v in values):
            return False
        if all(v is True for v in values) or index >= count:
            return all(v is True for v in values)
        for choice in (True, False):
            model[index] = choice
            found = go(index + 1)
            if found is not False:
                del model[index]
                return found
        del model[index]
        return False

    return go(0)


def _formula(rng: random.Random, atoms: int, depth: int) -> Formula:
    if depth == 0 or rng.random() < 0.3:
        if rng.random() < 0.1:
            return ("const", rng.random() < 0.5)
        return ("atom", rng.randrange(atoms))
    tag = rng.choice(["not", "and", "or", "iff"])
    if tag == "not":
        return ("not", _formula(rng, atoms, depth - 1))
    return (tag, _formula(rng, atoms, depth - 1), _formula(rng, atoms, depth - 1))


def test_the_pruned_search_answers_as_the_plain_one() -> None:
    rng = random.Random(13)
    answers = set()
    for _ in range(3000):
        atoms = rng.randint(1, 14)
        formulas = [_formula(rng, atoms, 4) for _ in range(rng.randint(0, 8))]
        expected = _plain(formulas, atoms)
        assert P._search(formulas, atoms) == expected, formulas
        answers.add(expected)
    assert {True, False} <= answers


def test_the_budget_still_cuts_the_search() -> None:
    # x0 xor x1 xor ... needs the whole tree when the last formula is unsatisfiable
    atoms = 14
    chain: Formula = ("atom", 0)
    for i in range(1, atoms):
        chain = ("not", ("iff", chain, ("atom", i)))
    formulas = [chain, ("and", ("atom", atoms - 1), ("not", ("atom", atoms - 1)))]
    assert _plain([chain, ("atom", 0)], atoms) is True
    assert P._search(formulas, atoms) is _plain(formulas, atoms)
