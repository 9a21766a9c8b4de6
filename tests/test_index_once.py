"""A run indexes each tree once (`analysis/index.index_of`): a module's summary, its
parameter summary and its own check share one index, and the parameter summary
made for the run's parameter files is the one the check reads. Sharing changes no
output: the same run with a fresh index and summary at every request reports the
same."""

from __future__ import annotations

import ast
import shutil
from collections import Counter
from pathlib import Path

import pytest

from robotfix.analysis import index as index_module
from robotfix.analysis import parameters
from robotfix.astwalk import walk
from robotfix.config import Config
from robotfix.run import check_paths
from robotfix.source import SourceFile

CASES = Path(__file__).parent / "cases"
PACKAGES = CASES / "packages"


def _package(tmp_path: Path) -> Path:
    """A node that imports its helpers (summarised before their own check) and
    declares parameters."""
    root = tmp_path / "ros2_pkg"
    shutil.copytree(PACKAGES / "ros2_pkg", root)
    return root


def _shown(root: Path) -> list[str]:
    result = check_paths([root], Config(root=root), jobs=1)
    assert not result.internal_errors
    return [
        f"{d.path}:{d.span.line}:{d.span.col}:{d.code}:{d.message}:{d.notes}"
        for d in result.diagnostics
    ]


def _counting(
    monkeypatch: pytest.MonkeyPatch, module: object, name: str
) -> list[ast.Module]:
    """The trees `module.name(..., tree, ...)` is called on, in call order (kept
    alive, so no two are confused by their ids)."""
    seen: list[ast.Module] = []
    original = getattr(module, name)

    def counting(*args: object) -> object:
        seen.append(next(a for a in args if isinstance(a, ast.Module)))
        return original(*args)

    monkeypatch.setattr(module, name, counting)
    return seen


def _times_each(trees: list[ast.Module]) -> list[int]:
    return [sum(t is other for other in trees) for t in trees]


def test_each_tree_is_indexed_once_per_run(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    root = _package(tmp_path)
    indexed = _counting(monkeypatch, index_module, "index_module")
    summarised = _counting(monkeypatch, parameters, "_summarize")
    assert _shown(root)
    assert len(indexed) >= 4  # the modules analysed (`__init__.py` is skipped)
    assert _times_each(indexed) == [1] * len(indexed)
    assert summarised  # driver.py declares parameters
    assert _times_each(summarised) == [1] * len(summarised)


def test_sharing_the_index_changes_no_output(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    root = _package(tmp_path)
    shared = _shown(root)
    with monkeypatch.context() as fresh:
        fresh.setattr(index_module, "index_of", index_module.index_module)
        for module in ("interpreter", "parameters"):
            fresh.setattr(
                f"robotfix.analysis.{module}.index_of", index_module.index_module
            )
        fresh.setattr(parameters, "_SUMMARIES", _Forgetful())
        again = _shown(root)
    assert again == shared


class _Forgetful(dict[ast.Module, parameters.Summary]):
    """A memo that remembers nothing."""

    def __setitem__(self, key: ast.Module, value: parameters.Summary) -> None:
        pass


def test_a_scope_of_another_tree_leaves_the_index_as_built() -> None:
    tree = ast.parse("def f(a):\n    g(a)\n")
    index = index_module.index_of(tree)
    scopes, calls = dict(index.scopes), list(index.calls)
    other = ast.parse("def h(b):\n    c = k(b)\n    o.x = c\n").body[0]
    found = index_module.index_scope(index, other)
    assert found.local_names == {"b", "c"}
    assert index_module.index_scope(index, other) is found
    assert index.scopes == scopes and index.calls == calls
    assert not index.attribute_stores and not index.assigned
    assert index_module.index_of(tree) is index


STORES = """
import math
LIMIT = 2.0
def f(a: [k for k in range(3)], b: (w := 1) = 2) -> (r := int):
    global LIMIT
    for i in range(3):
        LIMIT = i
    del a
    return [j for j in range(b) if (m := j)]
class C:
    SPEED = 1.0
    g = lambda self, x=(y := 3): x
"""


def _walked_stores(tree: ast.AST) -> Counter[str]:
    return Counter(
        n.id
        for n in walk(tree)
        if isinstance(n, ast.Name) and not isinstance(n.ctx, ast.Load)
    )


@pytest.mark.parametrize("path", sorted(CASES.rglob("*.py")), ids=str)
def test_the_index_counts_stores_as_a_walk_of_every_node(path: Path) -> None:
    source = SourceFile.from_bytes(str(path), path.read_bytes())
    if source.tree is not None:
        index = index_module.index_module(source.tree)
        assert index.stores == _walked_stores(source.tree)


def test_stores_in_annotations_are_counted() -> None:
    tree = ast.parse(STORES)
    index = index_module.index_module(tree)
    assert index.stores == _walked_stores(tree)
    assert {"k", "w", "r", "y", "m"} <= set(index.stores)
    assert index.stores["LIMIT"] == 2
