"""The terms the analysis makes by the thousand (`Sym`, `Unary`, `Binary`) are
slotted and set their fields without object.__setattr__ (issue 25), and are still
frozen, compared, hashed, copied and pickled as frozen dataclasses."""

from __future__ import annotations

import dataclasses
import pickle
from fractions import Fraction

import pytest

from robotfix.annotations import ast as A


def test_the_many_made_terms_are_slotted_frozen_dataclasses() -> None:
    sym = A.Sym(7, "real")
    one = A.Num(Fraction(1), True)
    for term in (sym, A.Unary("-", sym), A.Binary("+", sym, one)):
        assert not hasattr(term, "__dict__"), type(term)  # slotted
        fields = {f.name: getattr(term, f.name) for f in dataclasses.fields(term)}
        for name in fields:
            with pytest.raises(dataclasses.FrozenInstanceError):
                setattr(term, name, None)
        values = tuple(fields.values())
        assert hash(term) == hash(values)  # the generated __hash__ of a frozen one
        assert term == type(term)(*values) == type(term)(**fields)
        assert type(term)(*values) is not term
        assert pickle.loads(pickle.dumps(term)) == term
    assert A.Sym(7, "real") != A.Sym(7, "int")
    assert A.Sym(7, "real") != (7, "real")
    assert dataclasses.replace(A.Binary("+", sym, one), op="-") == A.Binary(
        "-", sym, one
    )
    assert repr(A.Unary("-", sym)) == "Unary(op='-', operand=Sym(ident=7, sort='real'))"
