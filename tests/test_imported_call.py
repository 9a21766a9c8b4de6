"""Issue 25 target 1 (eighth session): a call of an imported function that refines
nothing (no refined parameter, no refined return: most unannotated code) is its
result's type, without matching the arguments to the parameters first."""

from __future__ import annotations

import ast
from types import SimpleNamespace

import pytest

from robotfix.analysis import imported
from robotfix.analysis.imported import FunctionSummary


def _call(function: FunctionSummary) -> object:
    node = ast.parse("f(1, x=2)").body[0].value  # type: ignore[attr-defined]
    typed = SimpleNamespace(typed=lambda result, node, state: ("typed", result))
    ev = SimpleNamespace(lookups=typed, refined=None, ctx=None, site=None)
    return imported.call(ev, function, [], {}, node, None, False)  # type: ignore[arg-type]


def test_an_unrefined_function_is_its_result_type(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    def matched(*args: object) -> dict[str, object]:
        raise AssertionError("arguments matched for a function that refines nothing")

    monkeypatch.setattr(imported, "call_arguments", matched)
    function = FunctionSummary("f", ("a",), ("x",), (), None, False, result=None)
    assert _call(function) == ("typed", None)
