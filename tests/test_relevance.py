"""The file-level skip is sound: a file `analysis/relevance.py` skips gets no
diagnostic from the full analysis (every case file, generated programs), and the
files with something to find are not skipped."""

from __future__ import annotations

import ast
from functools import cache
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from robotfix.analysis import relevance
from robotfix.api import check_source, interface_files, make_project
from robotfix.config import Config
from robotfix.ros.catalog import MsgCatalog
from robotfix.stubs.load import stub_set

CASES = Path(__file__).parent / "cases"


@cache
def catalog_for(folder: Path) -> MsgCatalog:
    """As tests/test_cases.py builds it: the shared interfaces and the case's own."""
    folders = [CASES / "msgs", folder / "msg"]
    return MsgCatalog(interface_files([f for f in folders if f.is_dir()]))


def _skipped(text: str, path: Path, catalog: MsgCatalog) -> bool:
    project = make_project([], Config(), catalog)
    return relevance.skippable(
        ast.parse(text), text, catalog, stub_set(), project.resolver(path)
    )


def _full(text: str, path: Path, catalog: MsgCatalog) -> list[str]:
    """The diagnostics of the analysis with the skip turned off."""
    saved = relevance.ENABLED
    relevance.ENABLED = False
    try:
        return [d.code for d in check_source(text, str(path), Config(), catalog)]
    finally:
        relevance.ENABLED = saved


CASE_FILES = sorted(CASES.rglob("*.py"))


def test_a_skipped_case_file_has_no_finding() -> None:
    skipped = []
    for path in CASE_FILES:
        text = path.read_text(encoding="utf-8")
        catalog = catalog_for(path.parent)
        if _skipped(text, path, catalog):
            skipped.append(path)
            assert _full(text, path, catalog) == [], path
    assert skipped, "the rule skips no case file: the test proves nothing"


UNBOUND = {
    "branch": "def f(c):\n    if c:\n        x = 1\n    return x\n",
    "loop": "def f(xs):\n    for v in xs:\n        last = v\n    return last\n",
    "try": "def f(g):\n    try:\n        r = g()\n    except OSError:\n        pass\n"
    "    return r\n",
    "handler name": "def f(g):\n    try:\n        g()\n    except OSError as e:\n"
    "        pass\n    return e\n",
    "undefined": "def f(xs):\n    ys = [m for m in xs]\n    return m\n",
    "deleted": "def f():\n    x = 1\n    del x\n    return x\n",
    "declared": "def f():\n    x: int\n    return x\n",
    "comprehension": "def f(xs):\n    ys = [v + k for v in xs]\n    k = 1\n"
    "    return ys\n",
    "class body": "class C:\n    if len('a') > 2:\n        y = 1\n    z = y\n",
}


@pytest.mark.parametrize("name", sorted(UNBOUND))
def test_a_possibly_unbound_read_is_analysed(name: str) -> None:
    catalog = catalog_for(CASES / "init")
    assert not _skipped(UNBOUND[name], CASES / "init" / "x.py", catalog)


RELEVANT = {
    "annotation": "x = 'Annotated'\n",
    "message": "from geometry_msgs.msg import Twist\n",
    "message package": "import std_msgs\n",
    "module message": "import a.msg\n",
    "stub api": "import time\n\ndef f():\n    return time.time()\n",
    "method by name": "def f(node):\n    node.create_timer(1.0, f)\n",
    "parameter": "def f(node):\n    return node.get_parameter('x')\n",
    "ros 1 parameter": "import rospy\nrate = rospy.get_param('~rate', 10)\n",
    "declared parameters": "def f(node):\n"
    "    node.declare_parameters('', [('a', 1.0)])\n",
    "parameter listener": "def f(node, ns):\n    return ns.ParamListener(node)\n",
    # a stub member known only by the name it is imported as
    "stub member renamed": "import time\nfrom math import degrees as deg\n\n"
    "def wait(angle):\n    time.sleep(deg(angle))\n",
    "stub members renamed": "from time import time as wall, monotonic_ns as ticks\n\n"
    "def spent():\n    return ticks() - wall()\n",
    # Python reads identifiers NFKC-normalised: `\uff52adians` is `radians`
    "fullwidth name": "import math\n\ndef f(a):\n"
    "    return math.\uff52adians(a) + math.\uff44egrees(a)\n",
    "fullwidth marker": "from typing import \uff21nnotated\n"
    "speed: \uff21nnotated[float, '_ <= 1'] = 2.0\n",
}


@pytest.mark.parametrize("name", sorted(RELEVANT))
def test_a_file_with_a_source_of_units_is_analysed(name: str) -> None:
    catalog = catalog_for(CASES / "init")
    assert not _skipped(RELEVANT[name], CASES / "init" / "x.py", catalog)


def test_plain_helper_code_is_skipped() -> None:
    text = (
        "import os\n\n"
        "def scan(folder):\n"
        "    found = []\n"
        "    for name in os.listdir(folder):\n"
        "        if name.endswith('.yaml'):\n"
        "            found.append(name)\n"
        "        else:\n"
        "            continue\n"
        "    try:\n"
        "        first = found[0]\n"
        "    except IndexError:\n"
        "        first = None\n"
        "    return first, [n.upper() for n in found]\n"
    )
    assert _skipped(text, CASES / "init" / "x.py", catalog_for(CASES / "init"))


# -- imports of the tree: a member counts when its summary carries something -----
TREE = {
    "pkg/__init__.py": "",
    "pkg/util.py": "import os\n\nSCALE = 2\n\n"
    "def scale(v, k=SCALE):\n    return v * k\n\n"
    "class Counter:\n    START = 0\n\n    def bump(self, n):\n        return n + 1\n",
    "pkg/limits.py": "from typing import Annotated\n\n"
    "def set_speed(v: Annotated[float, 'Unit(\"m/s\") and 0 <= v <= 2']) -> None:\n"
    "    pass\n",
    "pkg/reexport.py": "from pkg.limits import set_speed\n",
}
IMPORTERS = {
    # the near misses: each gives the file something to find with
    "refined function": ("from pkg.limits import set_speed\n", False),
    "re-export": ("from pkg.reexport import set_speed\n", False),
    "module": ("from pkg import util\n", False),
    "plain import": ("import pkg.util\n", False),
    "star": ("from pkg.util import *\n", False),
    # plain members: nothing an unknown name would not give
    "plain function": ("from pkg.util import scale\n", True),
    "plain class and constant": ("from pkg.util import Counter, SCALE\n", True),
    "relative": ("from .util import scale\n", True),
}


@pytest.mark.parametrize("name", sorted(IMPORTERS))
def test_an_import_of_the_tree_counts_when_it_carries_something(
    tmp_path: Path, name: str
) -> None:
    for relative, text in TREE.items():
        (tmp_path / relative).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / relative).write_text(text, encoding="utf-8")
    head, skipped = IMPORTERS[name]
    text = head + "\n\ndef main():\n    return set_speed(5.0)\n"
    if "set_speed" not in head:
        text = head + "\n\ndef main(v):\n    return v\n"
    node = tmp_path / "pkg" / "node.py"
    node.write_text(text, encoding="utf-8")
    catalog = catalog_for(CASES / "init")
    project = make_project([tmp_path], Config(), catalog)
    tree = ast.parse(text)
    assert (
        relevance.skippable(tree, text, catalog, stub_set(), project.resolver(node))
        is skipped
    )
    saved = relevance.ENABLED
    relevance.ENABLED = False
    try:
        full = check_source(text, str(node), Config(), catalog)
    finally:
        relevance.ENABLED = saved
    codes = [d.code for d in full]
    assert codes == (["RF101"] if "set_speed" in head else []), codes


# -- generated programs: nested control flow over a few names ---------------------
NAMES = ["a", "b", "c"]


def _block(depth: int) -> st.SearchStrategy[list[str]]:
    simple = st.one_of(
        st.sampled_from(NAMES).map(lambda n: f"{n} = 1"),
        st.tuples(st.sampled_from(NAMES), st.sampled_from(NAMES)).map(
            lambda p: f"{p[0]} = {p[1]} + 1"
        ),
        st.sampled_from(NAMES).map(lambda n: f"print({n})"),
        st.sampled_from(NAMES).map(lambda n: f"del {n}"),
        st.sampled_from(["return", "pass", "raise ValueError()"]),
    )
    if depth == 0:
        return st.lists(simple, min_size=1, max_size=3)
    inner = _block(depth - 1)
    compound = st.one_of(
        st.tuples(inner, inner).map(
            lambda p: ["if flag:", *_indent(p[0]), "else:", *_indent(p[1])]
        ),
        inner.map(lambda b: ["for i in range(3):", *_indent(b)]),
        inner.map(lambda b: ["while flag:", *_indent([*b, "break"])]),
        st.tuples(inner, inner).map(
            lambda p: ["try:", *_indent(p[0]), "except OSError:", *_indent(p[1])]
        ),
        inner.map(lambda b: ["with open('f') as fh:", *_indent(b)]),
    )
    return st.lists(
        st.one_of(simple.map(lambda s: [s]), compound), min_size=1, max_size=3
    ).map(lambda parts: [line for part in parts for line in part])


def _indent(lines: list[str]) -> list[str]:
    return ["    " + line for line in lines]


@settings(
    max_examples=60,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)
@given(_block(2))
def test_a_skipped_generated_program_has_no_finding(body: list[str]) -> None:
    text = "\n".join(["def f(flag):", *_indent(body), ""])
    path = CASES / "init" / "generated.py"
    catalog = catalog_for(CASES / "init")
    if _skipped(text, path, catalog):
        assert _full(text, path, catalog) == [], text


@pytest.mark.parametrize(
    "text",
    [
        "def area(w, h):\n    return w * h\n",  # skipped
        "from geometry_msgs.msg import Twist\n\n"  # analysed
        "def stop(pub):\n    t = Twist()\n    t.linear.x = 0.0\n    pub.publish(t)\n",
    ],
)
def test_a_checked_tree_is_freed_without_the_cycle_collector(text: str) -> None:
    """Nothing a check builds makes a reference cycle that holds the file's tree:
    the relevance pass's module scope once referred to itself, so every tree lived
    on until a collection (cyclic garbage on corpus2: 7,614 objects after the fix,
    the whole run's trees before; 0.26 -> 0.10 s of collections)."""
    import gc
    import weakref

    from robotfix.api import check_file
    from robotfix.source import SourceFile

    source = SourceFile.from_text("node.py", text)
    assert source.tree is not None
    tree = weakref.ref(source.tree)
    catalog = catalog_for(CASES)
    gc.disable()
    try:
        check_file("node.py", text.encode(), catalog, parsed=source)
        del source
        assert tree() is None
    finally:
        gc.enable()


def test_a_skipped_importer_is_checked_again_when_its_member_carries_something(
    tmp_path: Path,
) -> None:
    """The skip read the member's summary: the cache keeps that, so a member that
    gains a refinement re-checks the file that was skipped."""
    from robotfix.api import check_paths

    (tmp_path / "pkg").mkdir()
    (tmp_path / "pkg" / "__init__.py").write_text("")
    util = tmp_path / "pkg" / "util.py"
    util.write_text("def scale(v):\n    return v * 2\n")
    node = tmp_path / "pkg" / "node.py"
    node.write_text("from pkg.util import scale\n\n\ndef main():\n    scale(5.0)\n")

    def run() -> list[str]:
        result = check_paths([tmp_path], Config(root=tmp_path), use_cache=True)
        return [f"{Path(d.path).name}:{d.code}" for d in result.diagnostics]

    assert run() == []
    util.write_text(
        "from typing import Annotated\n\n\n"
        "def scale(v: Annotated[float, '0 <= v <= 2']):\n    return v * 2\n"
    )
    assert run() == ["node.py:RF101"]


def _write(root: Path, files: dict[str, str]) -> None:
    for relative, text in files.items():
        (root / relative).parent.mkdir(parents=True, exist_ok=True)
        (root / relative).write_text(text, encoding="utf-8")


def _codes(root: Path) -> list[str]:
    from robotfix.api import check_paths
    from robotfix.config import load

    result = check_paths([root], load(root))
    return sorted(f"{Path(d.path).name}:{d.code}" for d in result.diagnostics)


def test_a_message_imported_from_its_own_package_relatively_is_a_source(
    tmp_path: Path,
) -> None:
    """`from . import Cmd` in a package that is also an interface package: the
    analysis reads `robot_cmds.Cmd` as the message `robot_cmds/Cmd`."""
    _write(
        tmp_path,
        {
            "robot_cmds/package.xml": "<package format='3'>"
            "<name>robot_cmds</name></package>",
            "robot_cmds/msg/Cmd.msg": "float64 speed #RobotFix# speed <= 1.0\n",
            "robot_cmds/robot_cmds/__init__.py": "",
            "robot_cmds/robot_cmds/node.py": "from . import Cmd\n\n\n"
            "def fill(c: Cmd):\n    c.speed = 5.0\n",
        },
    )
    assert _codes(tmp_path) == ["node.py:RF101"]


def test_a_user_stub_member_re_exported_under_another_name_is_a_source(
    tmp_path: Path,
) -> None:
    _write(
        tmp_path,
        {
            "pyproject.toml": '[tool.robotfix]\nstub-paths = ["stubs"]\n',
            "stubs/motorlib/__init__.pyi": "from motorlib.core import (\n"
            "    read_speed as speed,\n    read_heading as heading,\n)\n",
            "stubs/motorlib/core.pyi": "from typing import Annotated\n\n"
            "def read_speed() -> Annotated[float, \"Unit('m/s')\"]: ...\n"
            "def read_heading() -> Annotated[float, \"Unit('rad')\"]: ...\n",
            "drive.py": "import motorlib\n\n\ndef drive():\n"
            "    return motorlib.speed() + motorlib.heading()\n",
        },
    )
    assert _codes(tmp_path) == ["drive.py:RF202"]


WRITTEN = [
    "x = time.sleep(1)",  # a receiver's attribute
    "xtime = 1\ntime_of_day = 2\n",  # a longer run: no stub word
    "time",  # the whole text
    "(time)",
    "Timer2 = 1",
    "a = Timer\n",
    "# now\n",  # a comment counts (the text is asked, not the tree)
    "know = nowhere_now\n",
    "x = '__add__'",
    "x.atan2(y)",
    "x9atan2 = 1",
    "_now = 1",
    "",
    "caf\u00e9now = 1",  # not ASCII: the pattern (`\u00e9` is a word character)
    "caf\u00e9 now = 1",
    "\u2014now\u2014",
]


def test_a_stub_word_is_found_in_the_text_as_the_pattern_finds_it() -> None:
    """`_written` (words split in C for an ASCII text) answers as the pattern
    `\\b(word|...)\\b` does, on every case file and on edges of words."""
    vocabulary = relevance._vocabulary(stub_set())
    pattern = relevance._pattern(vocabulary)
    texts = [*WRITTEN, *(path.read_text(encoding="utf-8") for path in CASE_FILES)]
    answers = {relevance._written(text, vocabulary) for text in texts}
    assert answers == {True, False}
    for text in texts:
        assert relevance._written(text, vocabulary) == (
            pattern.search(text) is not None
        ), text[:80]


def test_an_ascii_text_is_not_searched_with_the_pattern(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The pattern tries every word at every letter (about 300 instructions a
    character of a text without a stub word); an ASCII text is split instead."""
    vocabulary = relevance._vocabulary(stub_set())

    def refused(_: frozenset[str]) -> None:
        raise AssertionError("searched with the pattern")

    monkeypatch.setattr(relevance, "_pattern", refused)
    assert relevance._written("rclpy.time.Time()", vocabulary)
    assert not relevance._written("x = 1", vocabulary)


def test_a_vocabulary_word_outside_ascii_is_searched_with_the_pattern() -> None:
    vocabulary = frozenset({"caf\u00e9"})
    assert relevance._ascii_words(vocabulary) is None
    assert relevance._written("x = caf\u00e9", vocabulary)
    assert not relevance._written("x = cafe", vocabulary)
