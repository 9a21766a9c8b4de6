"""`values.replace` (the fast copy of a Value, issue 13) gives what
`dataclasses.replace` gives, for Values and for other dataclasses."""

from __future__ import annotations

import dataclasses

import pytest

from robotfix.analysis.values import Items, Uninit, Value, replace
from robotfix.annotations import ast as A


def test_a_value_is_copied_with_its_changes() -> None:
    value = Value(
        "float",
        A.Sym(3, "real"),
        None,
        True,
        ref=None,
        name="x",
        elements=(Value("int"),),
        uninit=Uninit("x", False),
        factors=(2.0,),
        default_of=(1, "x"),
        rad_free=True,
        items=Items("float"),
        frame="map",
    )
    for changes in [
        {},
        {"unit": None, "literal": False},
        {"frame": None, "factors": ()},
    ]:
        fast = replace(value, **changes)
        assert fast == dataclasses.replace(value, **changes)
        assert fast is not value
        assert fast.default_of == dataclasses.replace(value, **changes).default_of
        assert {f.name: getattr(fast, f.name) for f in dataclasses.fields(fast)} == {
            f.name: getattr(value, f.name) for f in dataclasses.fields(value)
        } | changes
    with pytest.raises(AttributeError):
        replace(value, colour="red")


def test_other_dataclasses_go_to_dataclasses_replace() -> None:
    assert replace(Items("int"), kind="float") == Items("float")


def test_every_slot_of_a_value_is_copied() -> None:
    # `replace` writes the slots out: one added to Value must be added there
    marks = [object() for _ in Value.__slots__]
    value = Value(*marks)  # type: ignore[arg-type]
    copy = replace(value)
    assert [getattr(copy, name) for name in Value.__slots__] == marks
