"""Issue 25 target 1 (eighth session): a module summarised for its importers and
then checked is scanned for its constants once (`constants.scan(..., keep=True)`:
the next scan of the same tree takes the kept one). What the second scan gets must
equal a fresh scan on every case file, hold no values, and be taken once only; a
scan whose `qualname` now answers otherwise (other imports) is made anew."""

from __future__ import annotations

import ast
from pathlib import Path

from robotfix.analysis import constants
from robotfix.analysis.constants import ConstantNames, scan
from robotfix.analysis.imported import dotted_name
from robotfix.analysis.index import index_of
from robotfix.analysis.values import Value

CASES = Path(__file__).parent / "cases"


def _syntax(found: ConstantNames) -> tuple[object, ...]:
    return (found.module, found.changed_globals, found.read_only, found.classes)


def _qualname(imports: dict[str, str]):  # type: ignore[no-untyped-def]
    return lambda node: dotted_name(node, imports)


def _imports(tree: ast.Module) -> dict[str, str]:
    found = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for a in node.names:
                found[a.asname or a.name.split(".")[0]] = a.name
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            for a in node.names:
                found[a.asname or a.name] = f"{node.module}.{a.name}"
    return found


def test_a_kept_scan_is_the_fresh_scan_of_every_case_file() -> None:
    seen = 0
    for path in sorted(CASES.rglob("*.py")):
        text = path.read_text(errors="replace")
        try:
            tree = ast.parse(text)
        except SyntaxError:
            continue
        seen += 1
        index = index_of(tree)
        qualname = _qualname(_imports(tree))
        lines = text.splitlines()
        walrus = ":=" in text
        first = scan(tree, index, qualname, walrus, lines, keep=True)
        first.record("module", "<module>", "x", Value("int"))  # the summary's values
        second = scan(tree, index, qualname, walrus, lines)
        fresh = constants._scan(tree, index, qualname, walrus, lines)
        assert _syntax(second) == _syntax(fresh) == _syntax(first), path
        assert second is not first and not second.values and not second.class_values
        assert tree not in constants._KEPT  # taken once: a third scan is made anew
    assert seen > 20


def test_a_scan_kept_under_other_imports_is_not_taken() -> None:
    tree = ast.parse(
        "from typing import Final\nclass C:\n    RATE: Final = 1\nclass D(C):\n"
        "    RATE = 2\n"
    )
    index = index_of(tree)
    kept = scan(tree, index, _qualname({"Final": "typing.Final"}), keep=True)
    assert kept.classes["C"] == {"RATE"}
    other = scan(tree, index, _qualname({"Final": "mine.Final"}))
    assert other.classes["C"] == set()  # not Final here: D may override it
