"""A -j 1 run drops what it can no longer use (`Project.expect(..., release=True)`):
a package's module summaries go once no file still to check can import them, and
the output is the same as when every summary is kept for the run."""

from __future__ import annotations

import gc
import weakref
from pathlib import Path

from robotfix.api import make_project
from robotfix.config import Config
from robotfix.ros.catalog import MsgCatalog
from robotfix.run import check_paths

HELPER = """\
from typing import Annotated
MPS = Annotated[float, "Unit('m/s')"]
MAX_SPEED: MPS = 0.5
def clamp(v: MPS) -> MPS:
    return min(v, MAX_SPEED)
"""
NODE = """\
from typing import Annotated
from {pkg}.helper import MAX_SPEED, clamp
speed: Annotated[float, "Unit('m/s')"] = clamp(MAX_SPEED)
wrong: Annotated[float, "Unit('s')"] = clamp(1.0)  # a finding, through the summary
"""


def _package(root: Path, name: str, nodes: int = 2) -> list[Path]:
    folder = root / name / name
    folder.mkdir(parents=True)
    (root / name / "package.xml").write_text(f"<package><name>{name}</name></package>")
    (folder / "__init__.py").write_text("")
    (folder / "helper.py").write_text(HELPER)
    files = [folder / "__init__.py", folder / "helper.py"]
    for i in range(nodes):
        node = folder / f"node{i}.py"
        node.write_text(NODE.format(pkg=name))
        files.append(node)
    return files


def _project(root: Path):  # type: ignore[no-untyped-def]
    return make_project([root], Config(), MsgCatalog([]))


def test_a_package_summaries_go_once_its_files_are_checked(tmp_path: Path) -> None:
    a = _package(tmp_path, "pkg_a")
    b = _package(tmp_path, "pkg_b")
    project = _project(tmp_path)
    project.expect([*a, *b], release=True)
    helper = a[1]
    for path in a:
        project.take(path, path.read_bytes())
        summary = project.resolver(path).module("pkg_a.helper")
        assert summary is not None  # still importable while pkg_a is checked
    held = weakref.ref(summary)
    del summary
    gc.collect()
    assert held() is not None  # the last file of pkg_a may still be checked
    project.take(b[0], b[0].read_bytes())  # pkg_a done: nothing left imports it
    gc.collect()
    assert held() is None
    assert project.released >= 1
    assert project.types(helper) == frozenset()


def test_a_module_a_later_file_can_import_is_kept(tmp_path: Path) -> None:
    a = _package(tmp_path, "pkg_a")
    late = tmp_path / "pkg_a" / "scripts" / "tool.py"  # same package, checked last
    late.parent.mkdir()
    late.write_text("from pkg_a.helper import clamp\n")
    b = _package(tmp_path, "pkg_b")
    project = _project(tmp_path)
    order = [*a, *b, late]
    project.expect(order, release=True)
    for path in a:
        project.take(path, path.read_bytes())
    summary = project.resolver(a[2]).module("pkg_a.helper")
    held = weakref.ref(summary)
    del summary
    for path in b:
        project.take(path, path.read_bytes())
    gc.collect()
    assert held() is not None


def test_without_release_every_summary_stays(tmp_path: Path) -> None:
    a = _package(tmp_path, "pkg_a")
    b = _package(tmp_path, "pkg_b")
    project = _project(tmp_path)
    project.expect([*a, *b])
    for path in a:
        project.take(path, path.read_bytes())
        project.resolver(path).module("pkg_a.helper")
    for path in b:
        project.take(path, path.read_bytes())
    assert project.released == 0


def test_the_output_is_the_same_with_release(tmp_path: Path) -> None:
    for name in ("pkg_a", "pkg_b", "pkg_c"):
        _package(tmp_path, name, nodes=3)
    # through the checked root, after pkg_a is done: its summary is built again
    (tmp_path / "pkg_c" / "pkg_c" / "late.py").write_text(
        NODE.replace("{pkg}", "pkg_a.pkg_a")
    )
    config = Config()
    one = check_paths([tmp_path], config, jobs=1)
    assert len(one.diagnostics) == 10  # found through the summaries
    many = check_paths([tmp_path], config, jobs=2)
    assert [str(d) for d in one.diagnostics] == [str(d) for d in many.diagnostics]
