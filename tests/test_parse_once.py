"""A run parses a file once: a module parsed for its summary (because a file checked
before it imports it) keeps its tree until its own check takes it (`Project.take`),
with the same output as parsing it again; the trees kept are bounded."""

from __future__ import annotations

import shutil
from collections import Counter
from pathlib import Path

import pytest

from robotfix import paramcheck
from robotfix import source as source_module
from robotfix.api import make_project
from robotfix.config import Config
from robotfix.project import summary as summary_module
from robotfix.ros.catalog import MsgCatalog
from robotfix.run import check_paths

PACKAGES = Path(__file__).parent / "cases" / "packages"


def _parses(monkeypatch: pytest.MonkeyPatch) -> Counter[str]:
    """Every parse of a Python file, by its resolved path."""
    counted: Counter[str] = Counter()
    original = source_module.SourceFile.from_text

    def counting(path: str, text: str) -> source_module.SourceFile:
        counted[str(Path(path).resolve())] += 1
        return original(path, text)

    monkeypatch.setattr(source_module.SourceFile, "from_text", staticmethod(counting))
    return counted


def _shown(root: Path, jobs: int = 1) -> list[str]:
    result = check_paths([root], Config(root=root), jobs=jobs)
    assert not result.internal_errors
    return [
        f"{d.path}:{d.span.line}:{d.span.col}:{d.code}:{d.message}:{d.notes}"
        for d in result.diagnostics
    ]


def _package(tmp_path: Path) -> Path:
    """A node that imports its helpers, which sort (and are checked) after it."""
    root = tmp_path / "ros2_pkg"
    shutil.copytree(PACKAGES / "ros2_pkg", root)
    return root


def test_a_module_imported_before_its_check_is_parsed_once(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    root = _package(tmp_path)
    helpers = {"limits.py", "units.py", "util.py"}
    counted = _parses(monkeypatch)
    shown = _shown(root)
    assert shown  # the package's cases report something: the check did run
    parsed = {Path(p).name: n for p, n in counted.items()}
    assert helpers <= set(parsed)
    assert all(parsed[name] == 1 for name in helpers), parsed
    assert parsed["driver.py"] == 1


def test_sharing_the_parse_changes_no_diagnostic(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    root = _package(tmp_path)
    shared = _shown(root)
    monkeypatch.setattr(summary_module.Project, "take", lambda self, p, d: None)
    assert _shown(root) == shared


def _project(root: Path) -> summary_module.Project:
    return make_project([root], Config(root=root), MsgCatalog([]))


def test_take_hands_over_a_summarised_module_once(tmp_path: Path) -> None:
    root = _package(tmp_path)
    project = _project(root)
    helper = root / "my_pkg" / "limits.py"
    data = helper.read_bytes()
    project.expect([helper])
    assert project.summary(helper) is not None
    taken = project.take(helper, data)
    assert taken is not None and taken.tree is not None
    assert taken.path == str(helper)
    assert project.take(helper, data) is None  # the check owns it now


def test_take_refuses_a_parse_of_other_bytes(tmp_path: Path) -> None:
    root = _package(tmp_path)
    project = _project(root)
    helper = root / "my_pkg" / "limits.py"
    project.expect([helper])
    project.summary(helper)
    assert project.take(helper, helper.read_bytes() + b"\n# edited\n") is None


def test_only_files_still_to_check_keep_their_tree(tmp_path: Path) -> None:
    root = _package(tmp_path)
    project = _project(root)
    helper = root / "my_pkg" / "limits.py"
    project.expect([])  # checked already, or by another worker
    project.summary(helper)
    assert project.take(helper, helper.read_bytes()) is None
    project.expect([helper])
    project.summary(helper)  # built before: not parsed again
    assert project.take(helper, helper.read_bytes()) is None


def test_the_trees_kept_are_bounded(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    root = _package(tmp_path)
    project = _project(root)
    helper = root / "my_pkg" / "limits.py"
    monkeypatch.setattr(summary_module, "PENDING_BYTES", 10)
    project.expect([helper])
    project.summary(helper)
    assert project.take(helper, helper.read_bytes()) is None


def test_a_resolver_finds_each_name_once(tmp_path: Path) -> None:
    root = _package(tmp_path)
    project = _project(root)
    driver = root / "my_pkg" / "driver.py"
    resolver = project.resolver(driver)
    first = resolver.module("my_pkg.limits")
    assert first is not None
    asked: list[str] = []
    find_in = project.index.find_in

    def spy(number: int, name: str, importer: Path | str) -> Path | None:
        asked.append(name)
        return find_in(number, name, importer)

    project.index.find_in = spy  # type: ignore[method-assign]
    assert resolver.module("my_pkg.limits") is first
    assert resolver.module("rclpy") is None
    assert resolver.module("rclpy") is None
    assert asked == ["rclpy"]
    assert resolver.consulted[f"{driver}\0rclpy"] == summary_module.ABSENT


PARAMS = Path(__file__).parent / "cases" / "params" / "packages"


@pytest.mark.parametrize("name", ["ros2_driver", "ros1_tracker", "gpl_turtle"])
def test_parameter_files_use_the_checks_parse(
    name: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    root = tmp_path / name
    shutil.copytree(PARAMS / name, root)
    counted = _parses(monkeypatch)
    shared = _shown(root)
    assert shared  # each package's parameter files have findings
    words = [w for ws in paramcheck.MENTIONS.values() for w in ws]
    declaring = [
        str(p.resolve())
        for p in root.rglob("*.py")
        if any(w in p.read_bytes() for w in words)
    ]
    assert declaring
    assert all(counted[p] == 1 for p in declaring), counted
    original = paramcheck._summaries
    monkeypatch.setattr(
        paramcheck,
        "_summaries",
        lambda files, words, known, project, faults=None, config=None: original(
            files, words, {}, project, faults, config
        ),
    )
    # paramcheck parsing the files again, each seeing its tree (ros2_driver's
    # imported alias) as its check did: the same
    assert _shown(root) == shared


def test_an_edited_module_is_parsed_once_in_a_cached_run(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """After an edit, the cached results of the module's importers ask for its new
    summary (parsed for it), and the module itself is checked again: one parse,
    the output of a run without the cache."""
    root = _package(tmp_path)
    config = Config(root=root)
    assert not check_paths([root], config, use_cache=True).internal_errors
    limits = root / "my_pkg" / "limits.py"
    limits.write_text(limits.read_text() + "\n\nEDITED = 1\n")
    counted = _parses(monkeypatch)
    result = check_paths([root], config, use_cache=True)
    assert counted[str(limits.resolve())] == 1
    assert result.from_cache > 0
    # (equal as diagnostics: the editor's quick fixes, which no report shows, are
    # not kept in the result cache)
    assert result.diagnostics == check_paths([root], config).diagnostics


def test_fresh_summaries_hands_each_summary_over_once(tmp_path: Path) -> None:
    """A worker sends each summary it built with one result only: each call hands
    over those built since the last one, in the order they were built."""
    root = _package(tmp_path)
    project = _project(root)
    package = root / "my_pkg"
    assert project.fresh_summaries() == {}
    assert project.summary(package / "limits.py") is not None
    limits = str(package / "limits.py")
    first = project.fresh_summaries()
    assert list(first) == [limits]
    assert first[limits] == project.built[limits]
    assert project.fresh_summaries() == {}
    project.summary(package / "limits.py")  # known: nothing new is built
    assert project.summary(package / "units.py") is not None
    assert list(project.fresh_summaries()) == [str(package / "units.py")]
    assert project.fresh_summaries() == {}


def test_a_module_parsed_for_its_import_edges_only_is_parsed_once(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """`b`'s summary reads `c`, so the import ranks parse `c`'s imports: `d`, which
    `c` imports only inside a function nobody runs. No summary of `d` is built
    before its own check, which takes that parse (it was parsed again)."""
    root = tmp_path / "ws"
    (root / "pkg").mkdir(parents=True)
    files = {
        "__init__.py": "",
        "a_driver.py": "from pkg import b\n\nSPEED = b.LIMIT\n",
        "b.py": "from pkg import c\n\nLIMIT = c.OTHER\n",
        "c.py": "OTHER = 2.0\n\n\ndef later():\n    import pkg.d  # noqa\n",
        "d.py": "from typing import Annotated\n\nimport rclpy\n\n"
        'R: Annotated[float, "m"] = 0.1\n',
    }
    for name, text in files.items():
        (root / "pkg" / name).write_text(text)
    counted = _parses(monkeypatch)
    shown = _shown(root)
    assert any(":RF511:" in line for line in shown)  # `d`'s own check ran
    assert counted[str(root / "pkg" / "d.py")] == 1
    monkeypatch.setattr(summary_module.Project, "take", lambda *_: None)
    assert _shown(root) == shown  # as when the check parses it itself


def test_a_stub_is_parsed_once_by_the_summaries_and_the_checks(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The checks ask `stub_set(config.stub_paths)`, the summaries `stub_set()`:
    one set for `()` (two before: every stub both read was parsed twice)."""
    from robotfix.stubs import load

    assert load.stub_set() is load.stub_set(())
    root = tmp_path / "ws"
    (root / "pkg").mkdir(parents=True)
    helper = "import rclpy.node\n\n\nclass Base(rclpy.node.Node):\n    pass\n"
    node = (
        "import rclpy\n\nfrom pkg.helper import Base\n\n\n"
        "class Talker(Base):\n    def tick(self):\n"
        "        return self.get_clock().now()\n\n\n"
        "def main():\n    rclpy.init()\n    rclpy.spin(Talker('talker'))\n"
    )
    (root / "pkg" / "__init__.py").write_text("")
    (root / "pkg" / "helper.py").write_text(helper)
    (root / "pkg" / "a_node.py").write_text(node)
    read: Counter[str] = Counter()
    original = load.read_module

    def counting(name: str, *rest: object) -> load.Module:
        read[name] += 1
        return original(name, *rest)  # type: ignore[arg-type]

    load.forget()  # the stubs read by earlier tests
    monkeypatch.setattr(load, "read_module", counting)
    _shown(root)
    assert read["rclpy.node"] == 1, read
    assert max(read.values()) == 1, read


def test_a_file_that_does_not_parse_is_not_parsed_again_for_parameters(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A Python 2 script naming `rospy` (a parameter word): its check finds no tree
    and no declaration; the parameter check does not parse it again to find none."""
    root = tmp_path / "ros1_tracker"
    shutil.copytree(PARAMS / "ros1_tracker", root)
    old = root / "scripts" / "old_tool"
    old.parent.mkdir(exist_ok=True)
    old.write_text(
        "#!/usr/bin/env python\nimport rospy\n\nrate = rospy.get_param('~rate')\n"
        'print "rate", rate\n'
    )
    counted = _parses(monkeypatch)
    shown = _shown(root)
    assert any(":RF002:" in line and "old_tool" in line for line in shown)
    assert counted[str(old.resolve())] == 1, counted
