"""Issue 25, the calls' fast paths: each one equals the slow path it replaced (the
slow path is kept here as the reference)."""

from __future__ import annotations

import ast
from itertools import chain

import pytest

from robotfix.analysis.calls import _argument, _literal_arguments
from robotfix.analysis.values import Value
from robotfix.api import check_source
from robotfix.config import Config
from robotfix.diagnostics import Diagnostic
from robotfix.stubs.load import Class, StubSet

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


def _lines_and_codes(found: list[Diagnostic]) -> list[tuple[int, str]]:
    return [(d.span.line, d.code) for d in found]


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


def test_a_method_of_an_unknown_value_is_checked_by_its_name_starred_or_not() -> None:
    """`library_call` asks the stubs for the method's name first (most names are
    no stub's) and for starred arguments after: positions unknown, keywords kept."""
    code = (
        "from typing import Annotated\n"
        "T: Annotated[float, \"Unit('ms')\"] = 500.0\n"
        "def f(client, xs):\n"
        "    client.wait_for_service(timeout_sec=T)\n"
        "    client.wait_for_service(T)\n"
        "    client.wait_for_service(*xs, timeout_sec=T)\n"
        "    client.wait_for_service(*xs)\n"
        "    client.no_stub_has_this(T)\n"
        "    f2 = lambda: 0\n"
        "    f2(T)\n"
    )
    found = check_source(code, "a.py", Config())
    assert _lines_and_codes(found) == [(4, "RF201"), (5, "RF201"), (6, "RF201")]
    assert all(
        "`timeout_sec` argument of Client.wait_for_service" in d.message for d in found
    )


@pytest.mark.parametrize(
    "text",
    [
        *CALLS,
        "f(1, 'a', None)",
        "f(1, x=2.5)",
        "f(1, x=y)",
        "f(-1)",
        "f(*())",
        "f(**{})",
    ],
)
def test_literal_arguments_is_every_argument_a_constant(text: str) -> None:
    node = ast.parse(text, mode="eval").body
    assert isinstance(node, ast.Call)
    reference = all(isinstance(a, ast.Constant) for a in node.args) and all(
        isinstance(k.value, ast.Constant) for k in node.keywords
    )
    assert _literal_arguments(node) is reference


@pytest.mark.parametrize(
    ("qualified", "attrs"),
    [
        ("rclpy.node.Node", ["get_logger", "create_timer", "get_clock", "no_such"]),
        ("rospy.Duration", ["to_sec", "from_sec", "__add__", "no_such"]),
        ("rclpy.time.Time", ["nanoseconds", "__sub__", "to_msg"]),
    ],
)
def test_stub_member_is_kept_and_equals_the_walk_of_the_lineage(
    qualified: str, attrs: list[str]
) -> None:
    """`StubSet.member` keeps its answer per class and name: the same as walking
    the class and its bases again, on a fresh set and once kept."""
    fresh = StubSet()
    cls = fresh.lookup(qualified)
    assert isinstance(cls, Class)
    for attr in attrs:
        walked = next(
            (f for f in (c.method(attr) for c in fresh._lineage(cls)) if f), None
        )
        assert fresh.member(cls, attr) is walked
        assert fresh.member(cls, attr) is walked
        assert (id(cls), attr) in fresh._members


def test_a_file_function_call_checks_refined_parameters_only_when_declared() -> None:
    """`call_known` reads the arguments only for a function with refinements or a
    refined return (or when `suggest` logs flows): the rest gives the same."""
    code = (
        "from typing import Annotated\n"
        "M = Annotated[float, \"Unit('m')\"]\n"
        "MS: Annotated[float, \"Unit('ms')\"] = 5.0\n"
        "def refined(x: M) -> None: ...\n"
        "def returns() -> M: ...\n"
        "def plain(x, y=1): return x\n"
        "refined(MS)\n"
        "refined(x=MS)\n"
        "plain(MS, y=MS)\n"
        "d: Annotated[float, \"Unit('s')\"] = returns()\n"
        "e: Annotated[float, \"Unit('s')\"] = plain(MS)\n"
    )
    found = check_source(code, "a.py", Config())
    assert _lines_and_codes(found) == [
        (7, "RF201"),
        (8, "RF201"),
        (10, "RF201"),
        (11, "RF201"),
    ]
