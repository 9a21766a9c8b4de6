"""Issue 25 target 1 (ninth session): the import edges of a module (`Project._imports`,
for the import ranks that cut cycles) are read without visiting the compound
statements whose lines hold no `import`. `modules.imported_names` with the source
text must name what the walk of every statement names, in the same order, on every
case file and on texts made to defeat the line count (continuations, carriage
returns, match statements, `import` inside strings and comments)."""

from __future__ import annotations

from pathlib import Path

import pytest

from robotfix.project import modules
from robotfix.source import SourceFile

CASES = Path(__file__).parent / "cases"
FILES = sorted(CASES.rglob("*.py"))


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
