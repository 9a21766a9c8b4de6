"""Issue 25 target 1 (ninth session): a module's set-up for its importers does less.

- The import edges of a module (`Project._imports`, for the import ranks that cut
  cycles) are read without visiting the compound statements whose lines hold no
  `import`: `modules.imported_names` with the source text must name what the walk
  of every statement names, in the same order, on every case file and on texts made
  to defeat the line count (continuations, carriage returns, match statements,
  `import` inside strings and comments).
- A module checked before its first importer has its summary built from the parse
  of its own check when `project/foresee.py` guesses that importer from the bytes:
  each file is parsed once, and the output is the one without the guess (which
  parses each helper twice, as main did).
"""

from __future__ import annotations

import ast
import shutil
from pathlib import Path

import pytest

from robotfix.project import foresee, modules
from robotfix.source import SourceFile
from tests.test_parse_once import _parses, _shown

CASES = Path(__file__).parent / "cases"
FILES = sorted(CASES.rglob("*.py"))
PACKAGES = CASES / "packages"
IMPORTS = (ast.Import, ast.ImportFrom)


def _both(text: str, package: str | None = "pkg.sub") -> tuple[list[str], list[str]]:
    source = SourceFile.from_text("pkg/sub/mod.py", text)
    assert source.tree is not None, source.problem
    walked = modules.imported_names(source.tree, package)  # every statement
    return modules.imported_names(source.tree, package, source.text), walked


@pytest.mark.parametrize("package", [None, "pkg.sub"])
def test_the_import_lines_name_what_every_statement_names(package: str | None) -> None:
    compared = 0
    for path in FILES:
        source = SourceFile.from_bytes(str(path), path.read_bytes())
        if source.tree is None:
            continue
        walked = modules.imported_names(source.tree, package)
        assert modules.imported_names(source.tree, package, source.text) == walked
        compared += bool(walked)
    assert compared > 200


NESTED = """\
import a.b as ab
from . import c
from ..d import e, f

def g():
    import h
    class K:
        from .i import j
    try:
        import k
    except ImportError:
        from l import *
    else:
        import m
    finally:
        import n
    while x:
        import o
    else:
        import p
    with q:
        import r
    match s:
        case 1:
            import t
        case _:
            from u import v

def w():
    return "no import here"  # nor here: import

@decorator(
    "import"
)
def y():
    if z:
        from \\
            aa \\
            import bb
    for cc in dd:
        from ee import (
            ff,
        )
"""


def test_imports_nested_anywhere_are_found() -> None:
    indexed, walked = _both(NESTED)
    assert indexed == walked
    assert {"h", "k", "l", "n", "p", "r", "t", "u", "aa", "ee.ff"} <= set(walked)
    assert "pkg.sub.i.j" in walked


@pytest.mark.parametrize(
    "text",
    [
        "def f():\r    import a\r\rdef g():\r\n    import b\n",  # \r ends a line too
        "x = 1\n",
        "",
        "def f():\n    pass\n",
        "if x:\n    import a\nelif y:\n    import b\nelse:\n    import c\n",
        "try:\n    pass\nexcept* E:\n    import a\n",
        "async def f():\n    async with x:\n        import a\n",
        "s = '''\nimport fake\n'''\ndef f():\n    import real\n",
        "\x0cdef f():\n    import a\n\x0cdef g():\n    x = 1\n",
        "def f():\n    '\u00e9'; import a\n",
    ],
)
def test_made_texts_name_what_every_statement_names(text: str) -> None:
    indexed, walked = _both(text)
    assert indexed == walked


# -- summaries foreseen (`project/foresee.py`) ---------------------------------------


def _importer_last(tmp_path: Path) -> Path:
    """The driver of `ros2_pkg` renamed to sort (and be checked) after the helper
    modules it imports: each helper is checked before its importer."""
    root = tmp_path / "ros2_pkg"
    shutil.copytree(PACKAGES / "ros2_pkg", root)
    (root / "my_pkg" / "driver.py").rename(root / "my_pkg" / "z_driver.py")
    return root


HELPERS = ("limits.py", "units.py", "util.py")


def test_a_module_checked_before_its_importer_is_parsed_once(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    root = _importer_last(tmp_path)
    counted = _parses(monkeypatch)
    shown = _shown(root)
    assert any("z_driver.py" in line for line in shown)  # its imports were read
    parsed = {Path(p).name: n for p, n in counted.items()}
    assert all(parsed[name] == 1 for name in (*HELPERS, "z_driver.py")), parsed


def test_without_the_guess_each_helper_is_parsed_again_and_nothing_differs(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    root = _importer_last(tmp_path)
    foreseen = _shown(root)
    monkeypatch.setattr(foresee, "imported_later", lambda index, paths, key: {})
    counted = _parses(monkeypatch)
    assert _shown(root) == foreseen
    parsed = {Path(p).name: n for p, n in counted.items()}
    assert all(parsed[name] == 2 for name in HELPERS), parsed  # as on main


def test_the_guess_names_what_one_line_imports_name() -> None:
    text = b"""\
import a.b as ab, c
from . import d
from ..e import (f, g as h,
    i)
from .j.k import *
x = 1; import l
'''
import m
'''
def n():
    from o import p  # import q
"""
    found = foresee.named_modules(text, "pkg.sub")
    assert found >= {"a.b", "c", "pkg.sub", "pkg.sub.d", "pkg.e", "pkg.e.f"}
    assert found >= {"pkg.e.g", "pkg.sub.j.k", "o", "o.p"}
    assert "pkg.e.i" not in found  # a continued line is not read: a miss, no error


def test_the_guess_holds_every_one_line_import_of_the_cases() -> None:
    compared = 0
    for path in FILES:
        data = path.read_bytes()
        source = SourceFile.from_bytes(str(path), data)
        if source.tree is None:
            continue
        lines = [n for n in ast.walk(source.tree) if isinstance(n, IMPORTS)]
        one_line = [n for n in lines if n.lineno == n.end_lineno]
        for package in (None, "pkg.sub"):
            expected = set(modules.import_names(one_line, package))
            assert expected <= foresee.named_modules(data, package), path
        compared += bool(one_line)
    assert compared > 200
