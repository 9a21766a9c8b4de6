"""The editor's memo after an edit of a number the skeleton keeps (in a call, a
test, a store to an attribute) inside a method (`skeleton.method_number`): the
other items are keyed by the skeleton with that number blanked, and with what
every item before them that wrote was; every check gives a fresh check's output."""

from __future__ import annotations

import ast
import re
import sys
from pathlib import Path

import pytest

from robotfix.api import check_source
from robotfix.config import Config

sys.path.insert(0, str(Path(__file__).parent))
from test_cases import CASES, catalog_for
from test_unit_memo import _class_node, _replayed


def _node(methods: int) -> str:
    """`_class_node`'s class, each method's gain computed by a call (a number the
    skeleton keeps)."""
    return re.sub(r"gain = ([0-9.]+)\n", r"gain = max(\1, 0.5)\n", _class_node(methods))


def test_a_number_in_a_call_edited_in_a_method_replays_the_others(
    tmp_path: Path,
) -> None:
    """Typing a number in a call's arguments (a timeout, a gain) changes the
    skeleton: on main no item was replayed after it. Every method but the edited
    one is replayed from the second keystroke on, numbers of another length too."""
    text = _node(8)
    edits = [text.replace("max(4.5,", f"max({v},") for v in ("4.7", "4.75", "4.8")]
    # the first keystroke records, the next two replay the 7 other methods
    assert _replayed(tmp_path, text, *edits) >= 2 * 7


@pytest.mark.parametrize(
    ("source", "edited", "found"),
    [
        ("    def f(self):\n        g(1.5)\n        return 2\n", "1.5", True),
        ("    def f(self):\n        if x > 1.5:\n            pass\n", "1.5", True),
        ("    def f(self):\n        self.x = 1.5\n", "1.5", True),
        # a parameter word: the parameter summary reads the method's numbers
        ("    def f(self):\n        self.declare_parameter('a', 1.5)\n", "1.5", False),
        ("    def f(self):\n        node.g(1.5)\n", "1.5", False),
        # a one-expression method, a default, a decorator's argument
        ("    def f(self):\n        return g(1.5)\n", "1.5", False),
        ("    def f(self, a=1.5):\n        g(a)\n", "1.5", False),
        ("    @d(1.5)\n    def f(self):\n        g(2)\n", "1.5", False),
        # the class body's own number, a module-level function's
        ("    rate = g(1.5)\n", "1.5", False),
        # a return annotation (a def header), more than one number made one
        ("    def f(self) -> g(1.5):\n        g(2)\n        return 2\n", "1.5", False),
        ("    def f(self):\n        g(1+2)\n", "1+2", False),
        # a function nested in a module-level function (no method)
        (
            "    pass\n\n\ndef k():\n    def f():\n        g(1.5)\n        return 2\n",
            "1.5",
            False,
        ),
    ],
)
def test_a_number_only_its_method_reads(source: str, edited: str, found: bool) -> None:
    from robotfix.analysis.skeleton import method_number

    text = "import x\n\n\nclass A:\n" + source + "\n\ndef h():\n    g(7.5)\n"
    after = text.replace(edited, "2.25")
    assert (method_number(ast.parse(after), text, after) is not None) is found
    after = text.replace("7.5", "7.25")
    assert method_number(ast.parse(after), text, after) is None


def test_what_a_method_wrote_is_in_every_later_key(tmp_path: Path) -> None:
    """`configure` writes the frame of `odom_frame`, chosen by a number the
    skeleton keeps (an attribute's value), and the module-level `use` reads it:
    with that number blanked in the keys, `use`'s key must hold what
    `configure` was (an item outside its class; without it, `use` was replayed
    silent after `[0]` was made `[1]`, where a fresh check finds RF202)."""
    text = (
        "from geometry_msgs.msg import PointStamped\n"
        "\n"
        "\n"
        "class Follower:\n"
        "    def configure(self) -> None:\n"
        '        self.odom_frame = ("map", "odom")[0]\n'
        "\n"
        "\n"
        "def use(f: Follower) -> None:\n"
        "    here = PointStamped()\n"
        "    here.header.frame_id = f.odom_frame\n"
        "    goal = PointStamped()\n"
        '    goal.header.frame_id = "map"\n'
        "    error = goal.point.x - here.point.x\n"
    )
    other = text.replace("[0]", "[1]")
    catalog = catalog_for(CASES / "frames")
    path = str(tmp_path / "node.py")
    assert [d.rule.code for d in check_source(other, path, Config(), catalog)] == [
        "RF202"
    ]
    assert not check_source(text, path, Config(), catalog)
    # every check a fresh check's output (`_replayed`); `use` is replayed where
    # `configure` was the same
    assert _replayed(tmp_path, text, other, text, other, text, catalog=catalog) >= 1


def test_a_replay_takes_the_answers_the_model_keeps_once_per_check() -> None:
    """The model keeps its answers about attributes, a file function's result and
    a class's library bases: the replays of one check ask each once (each asked
    them again: on nav2's robot_navigator.py 41 replayed items asked 273
    questions, 41 of them distinct); what it does not keep (`infer`, a result
    of a function not made yet) is asked every time."""
    from types import SimpleNamespace

    from robotfix.analysis.unitreads import same_reads

    asked: list[tuple[object, ...]] = []

    class Model:
        def attribute(self, class_name: str, attr: str) -> object:
            asked.append(("attribute", class_name, attr))
            return "float"

        def returns(self, key: str) -> object:
            asked.append(("returns", key))
            return None

        def library_bases(self, class_name: str) -> list[object]:
            asked.append(("library_bases", class_name))
            return [SimpleNamespace(qualname="rclpy.node.Node")]

    program = SimpleNamespace(types=Model(), functions={"Drive.step": object()})
    reads = (
        (("library_bases", "Drive"), ("rclpy.node.Node",)),
        (("attribute", "Drive", "gain"), "float"),
        (("returns", "Drive.step"), None),
        (("returns", "Drive.later"), None),  # not made yet: asked again
    )
    answered: dict[tuple[object, ...], object] = {}
    for _ in range(3):
        assert same_reads(program, reads, answered)  # type: ignore[arg-type]
    assert len(asked) == 4 + 2
    # a kept answer that differs from the logged one is no replay
    assert not same_reads(program, ((("attribute", "Drive", "gain"), "int"),), answered)  # type: ignore[arg-type]
