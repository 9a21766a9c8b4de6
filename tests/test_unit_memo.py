"""The editor's per-unit analysis memo (analysis/unitmemo.py) changes nothing: after
random edits to one unit, a check that replays the other units gives the same
diagnostics, byte for byte, as a fresh check of the edited text."""

from __future__ import annotations

import ast
import random
import sys
import zlib
from collections.abc import Iterator
from pathlib import Path

import pytest

from robotfix.analysis.skeleton import (
    TEXT_WORDS,
    comment_only,
    lines_of,
    numbers_only,
    same_skeleton,
    skeleton,
)
from robotfix.analysis.unitmemo import UnitMemo
from robotfix.api import check_source
from robotfix.config import Config
from robotfix.smt.memo import ProofMemo

sys.path.insert(0, str(Path(__file__).parent))
from test_cases import CASES, catalog_for

ROOT = Path(__file__).parent.parent


def _bodies(tree: ast.Module) -> list[ast.FunctionDef | ast.AsyncFunctionDef]:
    return [
        n
        for n in ast.walk(tree)
        if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef)) and n.body
    ]


def _replace(lines: list[str], node: ast.AST, new: str) -> str | None:
    line, col = node.lineno, node.col_offset  # type: ignore[attr-defined]
    if node.end_lineno != line:  # type: ignore[attr-defined]
        return None
    raw = lines[line - 1].encode()
    raw = raw[:col] + new.encode() + raw[node.end_col_offset :]  # type: ignore[attr-defined]
    out = list(lines)
    out[line - 1] = raw.decode()
    return "".join(out)


def _outside_functions(node: ast.AST) -> Iterator[ast.AST]:
    for child in ast.iter_child_nodes(node):
        if not isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)):
            yield child
            yield from _outside_functions(child)


def _insert(lines: list[str], before: ast.stmt, text: str) -> str:
    indent = lines[before.lineno - 1][: before.col_offset]
    if indent.strip():  # `if x: y` on one line
        return "".join(lines)
    out = list(lines)
    out.insert(before.lineno - 1, f"{indent}{text}\n")
    return "".join(out)


KINDS = (
    "literal",
    "insert",
    "delete",
    "line_above",
    "rename",
    "field",
    "init_attribute",
    "constant",
)


def edit(text: str, rng: random.Random, kinds: tuple[str, ...] = KINDS) -> str | None:
    """`text` with one random edit of one unit (or of a module constant): the kinds
    are tried in a random order, each a few times (it may pick a function with
    nothing of its kind), so None means none of them found anything to edit."""
    for kind in rng.sample(kinds, len(kinds)):
        for _ in range(3):
            new = _edit(text, rng, kind)
            if new is not None:
                return new
    return None


def _edit(text: str, rng: random.Random, kind: str) -> str | None:
    tree = ast.parse(text)
    lines = text.splitlines(keepends=True)
    functions = _bodies(tree)
    if kind == "constant":  # a number in module code or a class body (a script's)
        consts = [
            n
            for n in _outside_functions(tree)
            if isinstance(n, ast.Constant) and type(n.value) in (int, float)
        ]
        if not consts:
            return None
        node = rng.choice(consts)
        return _replace(lines, node, repr(node.value * 2 + 1))  # type: ignore[operator]
    if not functions:
        return None
    function = rng.choice(functions)
    inside = list(ast.walk(function))
    statements = [s for s in inside if isinstance(s, ast.stmt) and s is not function]
    if kind == "literal":
        numbers = [
            n
            for n in inside
            if isinstance(n, ast.Constant) and type(n.value) in (int, float)
        ]
        if not numbers:
            return None
        node = rng.choice(numbers)
        value = rng.choice([0, 1, -1, 2.5, 1000, node.value + 1])  # type: ignore[operator]
        return _replace(lines, node, f"({value!r})")
    if kind == "insert":
        if not statements:
            return None
        filler = rng.choice(["pass", "_memo_edit = 1.5", "_memo_edit = [1, 2]"])
        return _insert(lines, rng.choice(statements), filler)
    if kind == "delete":
        simple = [
            s
            for s in statements
            if isinstance(s, (ast.Assign, ast.Expr, ast.AugAssign, ast.Return))
            and s.lineno == s.end_lineno
        ]
        if not simple:
            return None
        return _replace(lines, rng.choice(simple), "pass")
    if kind == "line_above":
        out = list(lines)
        out.insert(function.lineno - 1, "\n")
        return "".join(out)
    if kind == "rename":
        stores = sorted(
            {
                n.id
                for n in inside
                if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Store)
            }
        )
        if not stores:
            return None
        name = rng.choice(stores)
        names = [n for n in inside if isinstance(n, ast.Name) and n.id == name]
        new = text
        for node in sorted(names, key=lambda n: (n.lineno, n.col_offset), reverse=True):
            found = _replace(new.splitlines(keepends=True), node, f"{name}_r")
            if found is None:
                return None
            new = found
        return new
    if kind == "field":
        attributes = [
            n
            for n in inside
            if isinstance(n, ast.Attribute) and n.lineno == n.end_lineno
        ]
        if not attributes:
            return None
        node = rng.choice(attributes)
        swap = {"x": "y", "y": "z", "z": "x", "linear": "angular", "data": "value"}
        new_attr = swap.get(node.attr, node.attr + "_e")
        source = ast.get_source_segment(text, node) or ""
        if not source.endswith(node.attr):
            return None
        return _replace(lines, node, source[: -len(node.attr)] + new_attr)
    # init_attribute: add or remove an attribute assignment in an __init__
    inits = [f for f in functions if f.name == "__init__"]
    if not inits:
        return None
    init = rng.choice(inits)
    stores = [
        s
        for s in init.body
        if isinstance(s, ast.Assign)
        and any(isinstance(t, ast.Attribute) for t in s.targets)
        and s.lineno == s.end_lineno
    ]
    if stores and rng.random() < 0.5:
        return _replace(lines, rng.choice(stores), "pass")
    self_name = init.args.args[0].arg if init.args.args else "self"
    return _insert(lines, init.body[-1], f"{self_name}.memo_extra = 0.25")


def _parses(text: str) -> bool:
    try:
        ast.parse(text)
    except SyntaxError:
        return False
    return True


def differential(path: Path, text: str, catalog: object, edits: int, seed: int) -> int:
    """Check `edits` successive random edits of `text` with one memo and fresh;
    the number of edits compared."""
    rng = random.Random(seed)
    # proofs kept too: a kept verdict's counterexample is the one a fresh check
    # finds (`smt.solver.Session._example`: it depends on the VC alone)
    memo = ProofMemo()
    config = Config()

    def check(source: str, kept: ProofMemo | None) -> str:
        return repr(check_source(source, str(path), config, catalog, memo=kept))  # type: ignore[arg-type]

    check(text, memo)
    compared = 0
    current = text
    for _ in range(edits * 3):
        if compared >= edits:
            break
        new = edit(current, rng)
        if new is None or new == current or not _parses(new):
            continue
        kept, fresh = check(new, memo), check(new, None)
        assert kept == fresh, f"{path}: memoised check differs after an edit\n{new}"
        compared += 1
        current = new if rng.random() < 0.7 else text
    return compared


def _case(path: Path) -> object:
    """A case file, skipped (visibly) when `edit` finds nothing in it to edit."""
    if edit(path.read_text(encoding="utf-8"), random.Random(0)) is not None:
        return path
    reason = "nothing to edit: no function and no number in it"
    return pytest.param(path, marks=pytest.mark.skip(reason=reason))


CASE_FILES = sorted(CASES.rglob("*.py"))


@pytest.mark.parametrize(
    "path", [_case(p) for p in CASE_FILES], ids=lambda p: str(p.relative_to(CASES))
)
def test_case_files_memoised_like_fresh(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    seed = zlib.crc32(str(path.relative_to(CASES)).encode()) % 1000
    assert differential(path, text, catalog_for(path.parent), 4, seed) >= 1


def test_generated_modules_memoised_like_fresh(tmp_path: Path) -> None:
    sys.path.insert(0, str(ROOT / "benchmarks"))
    from generate_annotated import generate

    from robotfix.ros.catalog import MsgCatalog

    catalog = MsgCatalog([])
    for lines, seed in ((300, 1), (600, 2)):
        path = tmp_path / f"generated_{lines}.py"
        assert differential(path, generate(lines), catalog, 6, seed) >= 3


def test_memo_replays_units_an_edit_did_not_touch(tmp_path: Path) -> None:
    """The memo is used: after a literal changes in one function, the others come
    from it (a test that would pass with the memo never hit proves nothing)."""
    sys.path.insert(0, str(ROOT / "benchmarks"))
    from generate_annotated import generate

    from robotfix.ros.catalog import MsgCatalog

    catalog = MsgCatalog([])
    text = generate(300)
    path = tmp_path / "node.py"
    memo = ProofMemo()
    check_source(text, str(path), Config(), catalog, memo=memo)
    units = memo.units
    # a skeleton checked once is not recorded (an edit of code changes it at
    # every keystroke); twice in a row, it is
    assert isinstance(units, UnitMemo) and len(units) == 0
    check_source(text, str(path), Config(), catalog, memo=memo)
    assert len(units) > 10
    edited = text.replace("= 0.5\n", "= 0.75\n", 1)
    assert edited != text
    before = units.hits
    found = check_source(edited, str(path), Config(), catalog, memo=memo)
    assert units.hits - before >= len(units) // 2
    assert repr(found) == repr(check_source(edited, str(path), Config(), catalog))


def test_skeleton_blanks_only_numbers_no_other_unit_reads() -> None:
    text = (
        "import rclpy\n"
        "LIMIT = 2.0\n"
        "def f(self, x=3.0):\n"
        "    y = 0.5\n"
        "    self.z = 0.25\n"
        "    rclpy.sleep(1.5)\n"
        "    if y > 4.0:\n"
        "        return y * 7.0\n"
        "def kmh_to_ms(v):\n"
        "    return v / 3.6\n"
    )
    blanked = skeleton(ast.parse(text), text.splitlines(keepends=True))
    # 3.6: callers evaluate the one-expression helper (analysis/inline.py)
    for kept in ("2.0", "3.0", "0.25", "1.5", "4.0", "3.6"):
        assert kept in blanked
    assert "0.5" not in blanked and "7.0" not in blanked
    assert "y * #3#" not in blanked and "y * #" in blanked  # last on its line


def test_kept_proofs_show_the_counterexample_of_a_fresh_check(tmp_path: Path) -> None:
    """A verdict kept across edits carries the values a fresh check shows: they are
    found in a context of their own (`Session._example`), not in the session's
    model, which depends on what it was asked before (these edits of this
    generated program gave "`v` = -0.5, `limit` = 0.25" kept against "`v` =
    -0.25, `limit` = 0.125" fresh)."""
    sys.path.insert(0, str(ROOT / "benchmarks"))
    from generate_annotated import generate

    from robotfix.ros.catalog import MsgCatalog

    path = tmp_path / "generated_450.py"
    assert differential(path, generate(450), MsgCatalog([]), 8, 3) >= 3


def test_edit_of_an_evaluated_helper_replays_no_caller(tmp_path: Path) -> None:
    """A caller reads a one-expression helper's literals (analysis/inline.py): an
    edit of `3.6` there gives the caller's fresh diagnostics, not its kept ones."""
    from robotfix.ros.catalog import MsgCatalog

    catalog = MsgCatalog([])
    text = (
        "from typing import Annotated\n"
        "def kmh_to_ms(v):\n"
        "    return v / 3.6\n"
        "def drive(speed: Annotated[float, \"Unit('km/h')\"]) -> None:\n"
        "    out: Annotated[float, \"Unit('m/s')\"] = kmh_to_ms(speed)\n"
    )
    path = tmp_path / "node.py"
    memo = ProofMemo()
    assert not check_source(text, str(path), Config(), catalog, memo=memo)
    edited = text.replace("3.6", "1.0")
    found = check_source(edited, str(path), Config(), catalog, memo=memo)
    assert repr(found) == repr(check_source(edited, str(path), Config(), catalog))
    assert [d.rule.code for d in found] == ["RF201"]


def test_edits_of_code_cost_the_memo_no_recording(tmp_path: Path) -> None:
    """Typing code changes the skeleton at every keystroke, so no item of the
    check before can hit: nothing is recorded or looked up (on real nodes the
    memo made such edits 17-25% slower for no hit), and the output is a fresh
    check's."""
    sys.path.insert(0, str(ROOT / "benchmarks"))
    from generate_annotated import generate

    from robotfix.ros.catalog import MsgCatalog

    catalog = MsgCatalog([])
    text = generate(200)
    path = tmp_path / "node.py"
    memo = ProofMemo()
    for typed in ("", "x = 1\n", "x = 12\n", "x = 12 + y\n"):
        found = check_source(text + typed, str(path), Config(), catalog, memo=memo)
        assert repr(found) == repr(
            check_source(text + typed, str(path), Config(), catalog)
        )
    units = memo.units
    assert isinstance(units, UnitMemo) and len(units) == 0 and units.misses == 0


@pytest.mark.parametrize(
    ("before", "after", "numbers"),
    [
        ("a = 0.5\nb = 1\n", "a = 0.75\nb = 1\n", True),
        ("a = 1e3\n", "a = 2.5e-3\n", True),
        ("a = 1\n", "a = 1\n", True),
        ("a = 0.5\n", "a = 0.5  # m/s\n", False),
        ("x\n# a note\ny\n", "x\n# a notes\ny\n", False),
        ("f(1)\n", "g(1)\n", False),
        ("x = 1  # edit 11\n", "x = 1  # edit 12\n", False),
        ("a = 1\n", "a = 1\nb = 2\n", False),
    ],
)
def test_an_edit_of_numbers_only_is_told_from_the_text(
    before: str, after: str, numbers: bool
) -> None:
    assert numbers_only(before, after) is numbers


def _class_node(methods: int) -> str:
    """A node class of `methods` methods, each computing with a local number (one
    the skeleton blanks) and reporting a unit error of its own."""
    out = [
        "from typing import Annotated\n",
        "\n",
        "Speed = Annotated[float, \"Unit('m/s')\"]\n",
        "Length = Annotated[float, \"Unit('m')\"]\n",
        "\n",
        "\n",
        "class Drive:\n",
    ]
    for i in range(methods):
        out += [
            f"    def step_{i}(self, v: Speed, d: Length) -> None:\n",
            f"        gain = {i + 1}.5\n",
            "        total: Length = d + v * gain\n",
            "\n",
        ]
    return "".join(out)


def test_a_method_is_replayed_after_an_edit_of_a_sibling(tmp_path: Path) -> None:
    """A node's methods share one top-level statement, their class: a number
    edited in one method must not make the others run again (each is keyed by
    its own text; the rest of the class is in the skeleton)."""
    from robotfix.ros.catalog import MsgCatalog

    text = _class_node(8)
    edited = text.replace("gain = 4.5", "gain = 4.7")
    assert _replayed(tmp_path, text, edited) >= 7  # every method but the edited one
    found = check_source(edited, str(tmp_path / "node.py"), Config(), MsgCatalog([]))
    assert [d.rule.code for d in found] == ["RF203"] * 8


SIBLING_READ = {
    "module": (
        "from geometry_msgs.msg import Pose, Twist\n"
        "\n"
        "\n"
        "def pair(a: Pose, b: Twist):\n"
        "    t = (a, b)\n"
        "    u = t[0]\n"
        "    return u\n"
        "\n"
        "\n"
        "def use(a: Pose, b: Twist):\n"
        "    v = pair(a, b)\n"
        "    a.position.x += v.linear.x\n"
    ),
    "class": (
        "from geometry_msgs.msg import Pose, Twist\n"
        "\n"
        "\n"
        "class Node:\n"
        "    def pair(self, a: Pose, b: Twist):\n"
        "        t = (a, b)\n"
        "        u = t[0]\n"
        "        return u\n"
        "\n"
        "    def use(self, a: Pose, b: Twist):\n"
        "        v = self.pair(a, b)\n"
        "        a.position.x += v.linear.x\n"
    ),
}


def _clean_then_edited(
    tmp_path: Path, text: str, edited: str, folder: Path
) -> list[object]:
    """`text` checked twice with one memo (clean, and recorded), then `edited`
    with it: its diagnostics, which must be a fresh check's (`_replayed`)."""
    catalog = catalog_for(folder)
    path = str(tmp_path / "node.py")
    assert not check_source(text, path, Config(), catalog)
    _replayed(tmp_path, text, edited, catalog=catalog)
    return check_source(edited, path, Config(), catalog)  # type: ignore[return-value]


@pytest.mark.parametrize("where", sorted(SIBLING_READ))
def test_what_an_item_reads_of_a_sibling_body_is_in_its_key(
    tmp_path: Path, where: str
) -> None:
    """The type model reads other functions' bodies: `pair` returns a Pose, then
    (`t[0]` made `t[1]`, a number the skeleton blanks) a Twist, so `use` adds a
    velocity to a position. `use`'s own text did not change; what it asked the
    model did (`Record.reads`), so it is analysed again, not replayed."""
    text = SIBLING_READ[where]
    edited = text.replace("t[0]", "t[1]")
    found = _clean_then_edited(tmp_path, text, edited, CASES / "types")
    assert [d.rule.code for d in found] == ["RF202"]


def _number_edits(text: str) -> Iterator[str]:
    """`text` with each of its numbers changed, to one of the same length and to
    a longer one."""
    lines = text.splitlines(keepends=True)
    for node in ast.walk(ast.parse(text)):
        if not (
            isinstance(node, ast.Constant)
            and type(node.value) in (int, float)
            and node.lineno == node.end_lineno
        ):
            continue
        raw = lines[node.lineno - 1].encode()[node.col_offset : node.end_col_offset]
        digit = next((i for i in range(len(raw)) if raw[i : i + 1].isdigit()), None)
        if digit is None:
            continue
        other = b"7" if raw[digit : digit + 1] != b"7" else b"3"
        for new in (raw[:digit] + other + raw[digit + 1 :], raw + b"5"):
            edited = _replace(lines, node, new.decode())
            if edited is not None and _parses(edited):
                yield edited


@pytest.mark.parametrize(
    "path", CASE_FILES[::7], ids=lambda p: str(p.relative_to(CASES))
)
def test_an_unchanged_skeleton_is_told_from_the_number_edited(path: Path) -> None:
    """`same_skeleton` (which spares making the skeleton when one number changed)
    says what making it would: True only when it is the same, False only when
    it changed."""
    text = path.read_text(encoding="utf-8")
    if not _parses(text):
        return
    before = skeleton(ast.parse(text), text.splitlines(keepends=True))
    edits = decided = 0
    for edited in _number_edits(text):
        edits += 1
        tree = ast.parse(edited)
        same = same_skeleton(tree, text, edited)
        if same is None:
            continue
        decided += 1
        after = skeleton(tree, edited.splitlines(keepends=True))
        assert same == (after == before), edited
    # None ("cannot be told") for every edit would pass the loop above unchecked
    assert decided or not edits


def test_what_an_earlier_method_wrote_is_in_a_method_key(tmp_path: Path) -> None:
    """`__init__` is not kept (it writes the frame of `self.odom_frame`, which
    `tick` reads), and the frame it writes comes from a number the skeleton
    blanks (`frames[0]` made `frames[1]`): `tick`'s key holds what `__init__`
    was (`_wrote`), so `tick` is analysed again and finds the two frames."""
    text = (
        "from geometry_msgs.msg import PointStamped\n"
        "from rclpy.node import Node\n"
        "\n"
        "\n"
        "class Follower(Node):\n"
        "    def __init__(self) -> None:\n"
        '        super().__init__("follower")\n'
        '        frames = ("map", "odom")\n'
        "        chosen = frames[0]\n"
        "        self.odom_frame = chosen\n"
        "        self.timer = self.create_timer(0.2, self.tick)\n"
        "\n"
        "    def tick(self) -> None:\n"
        "        here = PointStamped()\n"
        "        here.header.frame_id = self.odom_frame\n"
        "        goal = PointStamped()\n"
        '        goal.header.frame_id = "map"\n'
        "        error = goal.point.x - here.point.x\n"
    )
    edited = text.replace("frames[0]", "frames[1]")
    found = _clean_then_edited(tmp_path, text, edited, CASES / "frames")
    assert [d.rule.code for d in found] == ["RF202"]


COMMENTED = """class A:
    # c0
    def f(self, x=(1,
                   # c1
                   2)):
        # c2
        y = foo(1,
                # c3
                2)
        # c4
        if (y and
            # c5
            x):
            pass
        # c6
        try:
            pass
        # c7
        except (ValueError,
                # c8
                KeyError):
            # c9
            pass
        s = '''
        # c10
        '''
# c11
"""


@pytest.mark.parametrize(
    ("line", "alone"),
    [
        (0, True),  # between a class's statements
        (1, False),  # inside a default value
        (2, True),
        (3, False),  # inside a call
        (4, True),
        (5, False),  # inside an `if` test
        (6, True),
        (7, True),  # between a `try` body and its handler
        (8, False),  # inside the handler's exception types
        (9, True),
        (10, False),  # inside a string
        (11, True),
    ],
)
def test_a_comment_line_between_statements_is_told_from_the_text(
    line: int, alone: bool
) -> None:
    edited = COMMENTED.replace(f"# c{line}\n", f"# c{line} edited\n")
    assert comment_only(ast.parse(edited), COMMENTED, edited) is alone


@pytest.mark.parametrize(
    "new", ["# c4\n\n", "z = 1\n", "# the node\n", "# Annotated\n", "# a := b\n"]
)
def test_more_than_a_comment_is_not_a_comment_edit(new: str) -> None:
    """A line added, code, or a word the analysis looks for in the text."""
    edited = COMMENTED.replace("# c4\n", new)
    assert not comment_only(ast.parse(edited), COMMENTED, edited)


def test_every_word_the_analysis_reads_in_the_text_is_a_text_word() -> None:
    """The analysis tests the whole text for some words (`":=" in
    source.text`): a comment holding one is not a comment alone (`TEXT_WORDS`)."""
    import re

    found = set()
    for module in (ROOT / "src" / "robotfix" / "analysis").glob("*.py"):
        found.update(
            re.findall(r'"([^"]+)" (?:not )?in [\w.]*source\.text', module.read_text())
        )
    assert found and found <= set(TEXT_WORDS)


def _replayed(tmp_path: Path, text: str, *edits: str, catalog: object = None) -> int:
    """Items replayed over `edits`, each checked after `text` was checked twice
    with one memo (recorded), every check a fresh check's output."""
    from robotfix.ros.catalog import MsgCatalog

    catalog = MsgCatalog([]) if catalog is None else catalog
    path = str(tmp_path / "node.py")
    memo = ProofMemo()

    def alike(source: str) -> None:
        found = check_source(source, path, Config(), catalog, memo=memo)  # type: ignore[arg-type]
        assert repr(found) == repr(check_source(source, path, Config(), catalog))  # type: ignore[arg-type]

    for _ in range(2):
        alike(text)
    units = memo.units
    assert isinstance(units, UnitMemo)
    before = units.hits
    for edited in edits:
        alike(edited)
    return units.hits - before


def test_methods_are_replayed_after_a_comment_edit(tmp_path: Path) -> None:
    """Typing in a comment line between statements leaves the skeleton as it
    was: every method but the one whose text holds the comment is replayed."""
    text = _class_node(8).replace(
        "        gain = 4.5\n", "        gain = 4.5\n        # a note\n"
    )
    edits = [text.replace("# a note", note) for note in ("# a note!", "# a note!!")]
    assert _replayed(tmp_path, text, *edits) >= 2 * 7


def test_a_comment_holding_a_text_word_is_not_replayed_around(tmp_path: Path) -> None:
    """RF508 is reported only in a file that says `Annotated` somewhere, a
    comment too: a comment that comes to say it is an edit of what the analysis
    reads (fails with "Annotated" left out of `TEXT_WORDS`)."""
    from robotfix.ros.catalog import MsgCatalog

    catalog = MsgCatalog([])
    text = (
        "from geometry_msgs.msg import Twist\n"
        "\n"
        "\n"
        "class Node:\n"
        "    def first(self, cmd: Twist):\n"
        "        gain = 1.5\n"
        "        # a note\n"
        "        cmd.linear.x = gain\n"
        "\n"
        "    def second(self, cmd: Twist):\n"
        "        from nav_msgs.msg import Odometryy\n"
        "        cmd.linear.x = 2.5\n"
    )
    path = str(tmp_path / "node.py")
    assert not check_source(text, path, Config(), catalog)
    edited = text.replace("# a note", "# Annotated")
    _replayed(tmp_path, text, edited)  # the memo's output is a fresh check's
    found = check_source(edited, path, Config(), catalog)
    assert [d.rule.code for d in found] == ["RF508"]


def test_a_class_body_is_keyed_without_its_methods_bodies(tmp_path: Path) -> None:
    """A class body with a constant writes what its methods read, so each
    method's key holds what it was (`_writers`); it does not run its methods'
    bodies, so a number edited in one method leaves it, and the keys of the
    methods after it, alike (keyed by the whole class text, none was replayed)."""
    text = "".join(
        [
            "from geometry_msgs.msg import Twist\n\n\nclass Node:\n",
            "    RATE = 10.0\n",
            *(
                f"    def step_{i}(self, cmd: Twist):\n"
                f"        gain = {i + 1}.5\n"
                "        cmd.linear.x = gain\n\n"
                for i in range(6)
            ),
        ]
    )
    edited = text.replace("gain = 1.5", "gain = 1.7")
    assert _replayed(tmp_path, text, edited) >= 5


def _callers_of_later_helpers(helper_header: str) -> str:
    """A node whose methods each call a helper defined below them (the call
    builds the helper's signature), each with a local number of its own."""
    return "".join(
        [
            "from typing import Annotated\n",
            "from geometry_msgs.msg import Twist\n\n\nclass Node:\n",
            *(
                f"    def step_{i}(self, cmd: Twist):\n"
                f"        gain = {i + 1}.5\n"
                f"        cmd.linear.x = self.helper_{i}(gain)\n\n"
                for i in range(6)
            ),
            *(
                f"    def helper_{i}(self, {helper_header}):\n        return v\n\n"
                for i in range(6)
            ),
        ]
    )


def test_a_method_that_builds_a_later_signature_is_replayed(tmp_path: Path) -> None:
    """Calling a method defined below builds its signature, which other items
    read: the replay builds it again (`Record.signed`), so the caller is kept
    and the items after it still find the state they were recorded in (with
    the signatures not built again on a replay, or callers not kept, 5 fewer
    hits)."""
    text = _callers_of_later_helpers("v")
    edited = text.replace("gain = 1.5", "gain = 1.7")
    assert _replayed(tmp_path, text, edited) >= 5 + 6  # the other steps, helpers


def test_a_signature_that_reports_is_not_built_on_a_replay(tmp_path: Path) -> None:
    """A signature whose refinement is reported when it is built belongs to the
    item that built it: that item is not kept, and the output is a fresh
    check's."""
    from robotfix.ros.catalog import MsgCatalog

    catalog = MsgCatalog([])
    text = _callers_of_later_helpers("v: Annotated[float, \"Unit('parsec/')\"]")
    edits = [text.replace("gain = 1.5", f"gain = {gain}") for gain in ("1.7", "1.9")]
    _replayed(tmp_path, text, *edits)  # the memo's output is a fresh check's
    for edited in edits:
        assert check_source(edited, str(tmp_path / "node.py"), Config(), catalog)


def test_a_replay_spends_the_work_a_fresh_check_spends() -> None:
    """Building some signatures spends work steps (`SimBridge.stop`'s here): such
    a build is not built again on a replay (the item that did it is not kept),
    or its steps would be spent twice, and a file near its budget would stop
    (RF902) where a fresh check does not (707 steps against 702 with every build
    taken for quiet)."""
    from robotfix import api
    from robotfix.source import SourceFile
    from robotfix.stubs.load import stub_set

    path = ROOT / "tests" / "cases" / "types" / "stub_class_objects.py"
    catalog, stubs = catalog_for(path.parent), stub_set()

    def spent(memo: ProofMemo | None) -> tuple[int, int, int]:
        source = SourceFile.from_text(str(path), path.read_text())
        ctx = api._analyze(source, catalog, stubs=stubs, memo=memo)
        return ctx._next, ctx.budget.used, len(ctx.diagnostics)

    memo = ProofMemo()
    for _ in range(2):
        spent(memo)
    assert spent(memo) == spent(None)
    assert isinstance(memo.units, UnitMemo) and memo.units.hits >= 10


def test_the_region_an_edit_changed_is_found_by_halves() -> None:
    """`skeleton.region` (slices compared by halves) finds what a character
    by character walk from both ends finds."""
    from robotfix.analysis.skeleton import region

    def walked(x: str, y: str) -> tuple[int, int, int]:
        start = 0
        while start < min(len(x), len(y)) and x[start] == y[start]:
            start += 1
        tail = 0
        while tail < min(len(x), len(y)) - start and x[-1 - tail] == y[-1 - tail]:
            tail += 1
        return start, len(x) - tail, len(y) - tail

    rng = random.Random(25)
    for _ in range(3000):
        x = "".join(rng.choice("ab\n") for _ in range(rng.randrange(12)))
        y = list(x)
        for _ in range(rng.randrange(3)):
            at = rng.randrange(len(y) + 1)
            if rng.random() < 0.5 or not y:
                y.insert(at, rng.choice("ab\n"))
            else:
                y[min(at, len(y) - 1)] = rng.choice("ab\n#")
        assert region(x, "".join(y)) == walked(x, "".join(y))


@pytest.mark.parametrize("breaks", ["\x0c", "\x1c", "\u2028"])
def test_a_line_break_only_str_splitlines_sees_leaves_lines_alike(breaks: str) -> None:
    """`same_skeleton` counts lines as ast does: a comment holding a form feed
    (or another break `str.splitlines` makes but ast does not) before the edit
    must not shift it onto the line below, where a blanked number sits in the
    same columns (the call's `10` is kept: the skeleton changed)."""
    text = (
        "class A:\n"
        "    def f(self):\n"
        f"        # page{breaks} break\n"
        "        foo(10)\n"
        "        y = 20\n"
    )
    edited = text.replace("foo(10)", "foo(11)")
    tree = ast.parse(edited)
    changed = skeleton(tree, lines_of(edited)) != skeleton(
        ast.parse(text), lines_of(text)
    )
    assert changed and same_skeleton(tree, text, edited) is not True


def test_an_item_keyed_by_its_whole_class_holds_the_methods_bodies() -> None:
    """A class body's item is keyed by its class without its methods' bodies
    (`_class_text`); an item keyed by the whole class (a method once an item
    outside every statement ran: `_whole`) holds them, whichever was keyed
    first (a blanked number edited in `f` must change `f`'s key)."""
    from types import SimpleNamespace

    from robotfix.analysis.unitmemo import Check

    text = "class A:\n    X = 1\n\n    def f(self):\n        y = 1.5\n"
    tree = ast.parse(text)
    ctx = SimpleNamespace(_next=0, resolver=None)
    check = Check(UnitMemo(), ctx, None, tree, {}, lines_of(text), "")  # type: ignore[arg-type]
    body, method = tree.body[0], tree.body[0].body[1]  # type: ignore[attr-defined]
    assert "y = 1.5" not in str(check._key(body, 0)[1])
    check._whole = True
    assert "y = 1.5" in str(check._key(method, 0)[1])


def test_methods_reading_module_attributes_are_replayed(tmp_path: Path) -> None:
    """`Program.module_attributes` keeps what `math.pi` or `rospy.loginfo` means
    for the rest of the file: the same answer whoever asks first, so it is no
    state an item writes. Counted in the fingerprint, every method that read an
    attribute first was kept unreplayable (nav2's node: 35.6 -> 16.5 replays an
    edit, slower with the memo than without)."""
    methods = "".join(
        f"    def step{i}(self, cmd: Twist) -> None:\n"
        f"        rospy.loginfo('step {i}')\n"
        f"        cmd.angular.z = math.pi / {i + 2}\n"
        f"        print(os.path.join('a', 'b{i}'))\n"
        for i in range(6)
    )
    text = (
        "import math\nimport os\n\nimport rospy\n"
        "from geometry_msgs.msg import Twist\n\n\nclass Node:\n"
        + methods.replace("'step 0')\n", "'step 0')\n        # a note\n")
    )
    edits = [text.replace("# a note", note) for note in ("# a note!", "# a note!!")]
    assert _replayed(tmp_path, text, *edits) >= 2 * 5
