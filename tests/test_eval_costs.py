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
