"""The module index's and the resolvers' memos (issue 25, sixth session): a file's
search path is numbered once per resolver, each search path's folder listings are
kept by its number, and a file's package is kept by its folder's spelling. Each is
asked in an order that a memo shared too widely (or kept from another file)
would answer wrongly."""

from __future__ import annotations

from pathlib import Path

from robotfix.api import make_project
from robotfix.config import Config
from robotfix.project.modules import ModuleIndex
from robotfix.ros.catalog import MsgCatalog


def _scripts(tmp_path: Path) -> Path:
    """Three script folders (no package): `a/` and `b/` each beside their own
    `helpers.py`, `c/` without one; Python finds `helpers` in the script's folder."""
    root = tmp_path / "ws"
    for name in "abc":
        (root / name).mkdir(parents=True)
        (root / name / "node.py").write_text("import helpers\n")
    (root / "a" / "helpers.py").write_text("SPEED = 1.0\n")
    (root / "b" / "helpers.py").write_text("SPEED = 2.0\n")
    return root


def test_each_search_path_reads_its_own_folders(tmp_path: Path) -> None:
    root = _scripts(tmp_path)
    index = ModuleIndex([root])
    # `c` first: its miss must not answer for `b`, nor `a`'s find for `b`
    assert index.find("helpers", root / "c" / "node.py") is None
    assert index.find("helpers", root / "a" / "node.py") == root / "a" / "helpers.py"
    assert index.find("helpers", root / "b" / "node.py") == root / "b" / "helpers.py"
    assert index.find("helpers", root / "c" / "node.py") is None
    assert index.find("helpers.x", root / "b" / "node.py") is None


def test_each_resolver_finds_names_from_its_own_file(tmp_path: Path) -> None:
    root = _scripts(tmp_path)
    project = make_project([root], Config(root=root), MsgCatalog([]))
    found = {}
    for name in "cab":
        resolver = project.resolver(root / name / "node.py")
        assert resolver.exists("helpers") is (name != "c")
        summary = resolver.module("helpers")
        found[name] = summary.path if summary is not None else None
    assert found == {
        "a": str(root / "a" / "helpers.py"),
        "b": str(root / "b" / "helpers.py"),
        "c": None,
    }


def test_a_files_package_is_its_own_folders(tmp_path: Path) -> None:
    root = tmp_path / "ws"
    (root / "pkg" / "sub").mkdir(parents=True)
    (root / "pkg" / "__init__.py").write_text("")
    (root / "pkg" / "sub" / "__init__.py").write_text("")
    (root / "scripts").mkdir()
    index = ModuleIndex([root])
    assert index.package_of(root / "pkg" / "sub" / "a.py") == "pkg.sub"
    assert index.package_of(root / "pkg" / "a.py") == "pkg"
    assert index.package_of(root / "scripts" / "a.py") is None
    assert index.package_of(root / "pkg" / "sub" / "b.py") == "pkg.sub"
    assert index.module_name(root / "pkg" / "sub" / "b.py") == "pkg.sub.b"
