"""Issue 25 target 1, the interpreter's cost per node and per body: work that was
done per body run or per occurrence is done once per file or per value, and the
answers stay those of the work it replaced."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from robotfix import api
from robotfix.analysis import interpreter

NODE = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


def helper(x):
    return x + 1


class Talker(Node):
    def __init__(self):
        super().__init__('talker')
        self.pub = self.create_publisher(String, 'chatter', 10)

    def cb(self):
        msg = String()
        msg.data = 'hello'
        self.pub.publish(msg)
        return helper(2)
"""


def _interpreters(monkeypatch: pytest.MonkeyPatch) -> list[Any]:
    """Every `Interpreter` made from now on, in order."""
    made: list[Any] = []
    real = interpreter.Interpreter.__init__

    def init(self: Any, *args: Any, **kwargs: Any) -> None:
        real(self, *args, **kwargs)
        made.append(self)

    monkeypatch.setattr(interpreter.Interpreter, "__init__", init)
    return made


def test_the_bodies_of_one_file_share_one_set_of_collaborators(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """The checks, lookups and libraries an evaluator works with keep nothing of
    one body: one set per file, not one per body run (7.8 -> 2.5 us an
    interpreter; 9,566 of them on corpus25), and another file gets its own."""
    made = _interpreters(monkeypatch)
    api.check_source(NODE, str(tmp_path / "a.py"))
    bodies = list(made)
    assert len(bodies) >= 4  # the module, the class, its methods, the helper
    parts = bodies[0].parts
    for walker in bodies:
        assert walker.parts is parts
        assert walker.check is parts.check and walker.lookups is parts.lookups
        assert walker.libraries is parts.libraries
        assert walker.refined is parts.refined and walker.fields is parts.fields
    api.check_source(NODE, str(tmp_path / "b.py"))
    assert made[len(bodies)].parts is not parts


def test_literal_values_are_made_once_per_literal(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """A string or int literal met again shares its value (values are never
    changed; 34,870 string and 12,307 int literals evaluated on corpus25), equal
    to the one made at each occurrence before; True and 1 stay apart."""
    import ast
    from fractions import Fraction

    from robotfix.analysis.literals import int_value, str_value
    from robotfix.analysis.values import Value
    from robotfix.annotations import ast as A

    assert str_value("chatter") == Value("str", A.Str("chatter"))
    assert str_value("chatter") is str_value("chatter")
    assert int_value(10) == Value("int", A.Num(Fraction(10), True), literal=True)
    assert int_value(10) is int_value(10)
    assert int_value(10**100) is None  # too large to model: an unknown, as before

    from robotfix.analysis.state import State

    source = NODE + "a = 'x'\nb = 'x'\nc = 1\nd = True\ne = 1\nf = None\n"
    made = _interpreters(monkeypatch)
    api.check_source(source, str(tmp_path / "m.py"))
    walker, state = made[0], State()  # the module code's walker
    values = [
        walker.eval(stmt.value, state)
        for stmt in ast.parse(source).body
        if isinstance(stmt, ast.Assign)
    ]
    assert values[0] is values[1] and values[2] is values[4]
    assert values[3] == Value("bool", A.Bool(True)) and values[3] is not values[2]
    assert values[2] == Value("int", A.Num(Fraction(1), True), literal=True)


def test_ros_code_is_kept_with_the_imports_it_was_asked_of() -> None:
    """`FileContext.ros_code` is asked at every annotation read; it is kept with
    the imports it was worked out of, and a context handed other imports (a
    summary's, `project/summary.py`) answers for those (a memo kept without
    them fails this)."""
    from robotfix.analysis.context import FileContext
    from robotfix.ros.catalog import MsgCatalog
    from robotfix.source import SourceFile

    parsed = SourceFile.from_bytes("m.py", b"import os\n")
    ctx = FileContext(parsed, MsgCatalog([]), print)
    ctx.imports = {"os": "os"}
    assert ctx.ros_code is False
    assert ctx.ros_code is False
    ctx.imports = {"rclpy": "rclpy"}
    assert ctx.ros_code is True
    ctx.imports = {"String": "std_msgs.msg.String"}
    assert ctx.ros_code is True
    ctx.imports = {}
    assert ctx.ros_code is False


def test_a_call_asks_no_change_of_values_the_walk_never_watched(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """What a call may change is asked only of values whose version the walk read
    (`State.changed` changes nothing else): `g(a.x, b[0])` hands two unknowns no
    read watched, `g(c.y)` after `if c.y:` one that is."""
    from robotfix.analysis.state import State

    asked: list[object] = []
    real = State.changed

    def changed(self: State, value: Any, firm: bool = False) -> None:
        asked.append(value)
        real(self, value, firm)

    monkeypatch.setattr(State, "changed", changed)
    api.check_source("def f(a, b):\n    g(a.x, b[0])\n", str(tmp_path / "a.py"))
    assert asked == []
    source = "def f(c):\n    if c.y:\n        pass\n    g(c.y)\n"
    api.check_source(source, str(tmp_path / "b.py"))
    assert len(asked) == 1  # `c.y`'s version was read by the test
