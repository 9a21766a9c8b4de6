"""Issue 25, the calls' fast paths: each one equals the slow path it replaced (the
slow path is kept here as the reference)."""

from __future__ import annotations

import ast
from itertools import chain

import pytest

from robotfix.analysis.calls import _argument
from robotfix.analysis.values import Value

CALLS = [
    "f()",
    "f(a)",
    "f(a, b.c, 1)",
    "f(x=1)",
    "f(a, x=m, y=n)",
    "f(*xs, x=m)",
    "f(a, **kw)",
    "f(a, x=m, **kw, y=n)",
    "f(**k1, x=m, **k2)",
    "o.publish(m, qos=q)",
]


def _kwargs(node: ast.Call) -> dict[str | None, Value]:
    """What `eval_Call` makes of the keywords: a value per name, `**` under None."""
    return {k.arg: Value("unknown", name=ast.unparse(k.value)) for k in node.keywords}


def _reference(node: ast.Call, args: list[Value], kwargs: dict[str | None, Value]):
    """`_forget_after_call`'s pairs as they were: positional, then keywords."""
    keywords = {k.arg: k.value for k in node.keywords}
    pairs = zip(args, node.args, strict=False)
    return list(chain(pairs, ((v, keywords[k]) for k, v in kwargs.items())))


@pytest.mark.parametrize("text", CALLS)
def test_argument_pairs_each_value_with_its_expression(text: str) -> None:
    node = ast.parse(text, mode="eval").body
    assert isinstance(node, ast.Call)
    args = [Value("unknown", name=ast.unparse(a)) for a in node.args]
    kwargs = _kwargs(node)
    values = [*args, *kwargs.values()]
    found = [(v, _argument(node, kwargs, i)) for i, v in enumerate(values)]
    reference = _reference(node, args, kwargs)
    assert found == reference
    assert all(a is b for (_, a), (_, b) in zip(found, reference, strict=True))
