"""Whole-package analysis as a run does it: the packages under tests/cases/packages/
checked as trees (inline expectations in every file), the result cache re-checking
exactly the importers of a helper whose summary changed, `-j` output identical to
`-j 1`, and the `python-paths` setting."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from robotfix import run as run_module
from robotfix.api import check_paths
from robotfix.config import Config, load_file
from robotfix.testing.expectations import compare_files

PACKAGES = Path(__file__).parent / "cases" / "packages"


@pytest.mark.parametrize(
    "name",
    [
        "ros2_pkg",
        "ros1_pkg",
        "cycle",
        "near_misses",
        "alias_pkg",
        "helper_classes",
        "typed_pkg",
    ],
)
def test_a_checked_tree_sees_its_own_modules(name: str) -> None:
    root = PACKAGES / name
    result = check_paths([root], Config(root=root))
    assert not result.internal_errors
    # every diagnostic of the run: one in a file other than the modules is unexpected
    problems = compare_files(sorted(root.rglob("*.py")), result.diagnostics)
    assert not problems, "\n".join(problems)


def _copy(tmp_path: Path, *names: str) -> Path:
    for name in names:
        shutil.copytree(PACKAGES / name, tmp_path / name)
    return tmp_path


def _run(root: Path, jobs: int = 1, cache: bool = True) -> tuple[int, list[str]]:
    result = check_paths([root], Config(root=root), jobs=jobs, use_cache=cache)
    assert not result.internal_errors
    shown = [
        f"{d.path}:{d.span.line}:{d.span.col}:{d.code}:{d.message}:{d.notes}"
        for d in result.diagnostics
    ]
    return result.from_cache, shown


@pytest.mark.parametrize("jobs", [1, 2])
def test_a_changed_helper_rechecks_exactly_its_importers(
    tmp_path: Path, jobs: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    """In one process and in workers (which send back what each check consulted,
    for the cache; a run without the cache does not ask for it)."""
    monkeypatch.setattr(run_module, "MIN_PARALLEL", 1)
    root = _copy(tmp_path, "ros2_pkg")
    files = len(list(root.rglob("*.py")))  # setup.py, __init__, 4 modules
    cached, first = _run(root, jobs)
    assert cached == 0 and any(":RF101:" in line for line in first)
    assert _run(root, jobs) == (files, first)

    util = root / "ros2_pkg" / "my_pkg" / "util.py"
    # a body that changes, lines that do not: the summary is the same
    util.write_text(util.read_text().replace("return step / 10.0", "return step / 9.0"))
    cached, again = _run(root, jobs)
    assert (cached, again) == (files - 1, first)  # only util.py itself

    limits = root / "ros2_pkg" / "my_pkg" / "limits.py"
    limits.write_text(limits.read_text().replace("= 0.22", "= 0.6"))
    cached, after = _run(root, jobs)
    # limits.py, util.py (imports it) and driver.py (imports both) are re-checked
    assert cached == files - 3
    assert after != first
    assert not any("clamp_speed(0.5)" in line for line in after)  # 0.5 <= 0.6 now
    fresh = _run(root, jobs, cache=False)[1]
    assert after == fresh  # a cached run prints what an uncached one prints


def test_jobs_give_the_same_output_as_one_process(tmp_path: Path) -> None:
    root = _copy(tmp_path, "ros2_pkg", "ros1_pkg", "cycle")
    for index in range(12):  # enough files for worker processes (run.MIN_PARALLEL)
        (root / f"plain_{index}.py").write_text(f"VALUE = {index}\n")
    one = _run(root, jobs=1, cache=False)[1]
    two = _run(root, jobs=2, cache=False)[1]
    assert one == two
    assert sum(":RF101:" in line for line in one) >= 8


def test_python_paths_find_modules_outside_the_checked_tree(tmp_path: Path) -> None:
    shared = tmp_path / "shared" / "robot_limits"
    shared.mkdir(parents=True)
    (shared / "__init__.py").write_text("")
    (shared / "speeds.py").write_text(
        "from typing import Annotated\n\n"
        "def drive(v: Annotated[float, \"Unit('m/s') and _ <= 1\"]) -> None:\n"
        "    pass\n"
    )
    node = tmp_path / "node" / "main.py"
    node.parent.mkdir()
    node.write_text("from robot_limits.speeds import drive\n\ndrive(2.0)\n")
    (tmp_path / "node" / "pyproject.toml").write_text(
        '[tool.robotfix]\npython-paths = ["../shared"]\n'
    )
    bare = check_paths([node.parent], Config(root=node.parent))
    assert not bare.diagnostics  # not found: unknown, as any library
    config = load_file(node.parent / "pyproject.toml")
    found = check_paths([node.parent], config)
    assert [(d.code, d.span.line) for d in found.diagnostics] == [("RF101", 3)]


def _rechecked(root: Path) -> tuple[int, list[str]]:
    """How many files a cached run re-checked, and its output (which must be a
    fresh run's, byte for byte)."""
    files = len(list(root.rglob("*.py")))
    cached, shown = _run(root)
    assert shown == _run(root, cache=False)[1]
    return files - cached, shown


def test_a_member_no_importer_reads_rechecks_only_its_module(tmp_path: Path) -> None:
    root = _copy(tmp_path, "ros2_pkg")
    _, first = _run(root)
    util = root / "ros2_pkg" / "my_pkg" / "util.py"
    util.write_text(
        util.read_text()
        + "\n\ndef wrap(a: Annotated[float, \"Unit('rad') and _ >= 0\"]) -> float:\n"
        "    return a\n"
    )
    assert _rechecked(root) == (1, first)  # util.py alone: nobody reads `wrap`
    text = util.read_text()
    util.write_text(text.replace("\"Unit('rad') and _ >= 0\"", '"_ <= 1"'))
    assert _rechecked(root) == (1, first)  # nor its refinement
    util.write_text(text[: text.index("\n\ndef wrap")] + "\n")
    assert _rechecked(root) == (1, first)  # nor its removal


def test_a_read_member_that_changes_rechecks_its_readers(tmp_path: Path) -> None:
    root = _copy(tmp_path, "ros2_pkg")
    _, first = _run(root)
    util = root / "ros2_pkg" / "my_pkg" / "util.py"
    text = util.read_text()
    # ramp's refinement: util.py and driver.py (which calls ramp) are re-checked
    util.write_text(text.replace('"0 <= _ < 10"', '"0 <= _ < 11"'))
    count, after = _rechecked(root)
    assert count == 2
    assert len(after) == len(first) - 1  # ramp(10, 10) is fine now
    # a member driver.py reads is removed: driver.py is re-checked
    util.write_text(text.replace("def ramp(", "def _ramp("))
    count, after = _rechecked(root)
    assert count == 2
    assert not any("ramp" in line for line in after)
    # and comes back
    util.write_text(text)
    assert _rechecked(root) == (2, first)


def test_a_constant_read_through_a_helper_rechecks_both(tmp_path: Path) -> None:
    root = _copy(tmp_path, "ros2_pkg")
    _run(root)
    limits = root / "ros2_pkg" / "my_pkg" / "limits.py"
    text = limits.read_text()
    limits.write_text(text + "\nUNUSED_LIMIT = 3.0\n")
    assert _rechecked(root)[0] == 1
    # WHEEL_BASE: nobody reads it
    limits.write_text(limits.read_text().replace("= 0.16", "= 0.2"))
    assert _rechecked(root)[0] == 1
    # MAX_TURN: driver.py reads it, util.py does not
    limits.write_text(limits.read_text().replace("= 2.84", "= 2.5"))
    assert _rechecked(root)[0] == 2
    # MAX_SPEED: util.py's clamp_speed reads it, so driver.py too
    limits.write_text(limits.read_text().replace("= 0.22", "= 0.3"))
    assert _rechecked(root)[0] == 3


def test_a_constant_an_imported_alias_names_rechecks_its_users(tmp_path: Path) -> None:
    root = _copy(tmp_path, "alias_pkg")
    _, first = _run(root)
    assert len(first) == 6
    limits = root / "alias_pkg" / "alias_pkg" / "limits.py"
    # MAX_SPEED: Speed's refinement names it; cruise.py reads Speed through
    # types.Cruise (a re-export and an alias of an alias)
    limits.write_text(limits.read_text().replace("MAX_SPEED = 0.5", "MAX_SPEED = 0.7"))
    count, after = _rechecked(root)
    assert count == 4  # limits.py, types.py, cruise.py, teleop_script.py
    assert len(after) == 4  # command(0.6, 0.0) and send(0.6) are fine now


def test_a_class_constant_an_alias_names_rechecks_its_users(tmp_path: Path) -> None:
    root = _copy(tmp_path, "alias_pkg")
    _, first = _run(root)
    geometry = root / "alias_pkg" / "alias_pkg" / "geometry.py"
    text = geometry.read_text()
    geometry.write_text(text.replace("MAX_ACCEL = 0.5", "MAX_ACCEL = 0.7"))
    count, after = _rechecked(root)
    assert count == 2  # geometry.py, steer.py
    assert len(after) == len(first) - 1  # steer(0.0, 0.6) is fine now
    geometry.write_text(text.replace("RATE = 10.0", "RATE = 5.0"))
    count, after = _rechecked(root)
    assert count == 2
    assert len(after) == len(first)  # rate == 10 fails, 1 / RATE == 0.2 holds


def test_a_travelling_refinement_is_shown_with_its_constants_names(
    tmp_path: Path,
) -> None:
    """An importer's message shows the refinement as the declaring module writes it
    (`speed <= MAX_SPEED`, `heading <= math.pi`), not the values put in for the
    check; renaming a constant re-checks its users, whose messages then say so."""
    root = _copy(tmp_path, "alias_pkg")
    _, first = _run(root)
    shown = "\n".join(first)
    for part in (
        "violates `speed <= MAX_SPEED`",  # cruise.py, through types.Cruise
        "violates `abs(turn) <= MAX_TURN`",
        "violates `heading <= math.pi`",  # steer.py does not import math
        "violates `accel <= Limits.MAX_ACCEL`",  # nor Limits
    ):
        assert part in shown
    assert "3.14159" not in shown and "<= 0.5`" not in shown
    limits = root / "alias_pkg" / "alias_pkg" / "limits.py"
    limits.write_text(limits.read_text().replace("MAX_SPEED", "TOP_SPEED"))
    count, after = _rechecked(root)
    assert count == 4  # limits.py, types.py, cruise.py, teleop_script.py
    cruise = "\n".join(line for line in after if "cruise.py" in line)
    assert "violates `speed <= TOP_SPEED`" in cruise
    assert "MAX_SPEED" not in cruise  # (teleop_script.py imports the old name)


def test_package_folder_climbs_as_pathlib_did(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """`package_folder` climbs the folders as strings (a cached run asks it
    thousands of times): the nearest folder with a package.xml, as the pathlib
    climb found it, for nested packages, a file beside its package.xml, a
    relative spelling, `..` and no package at all (probing up to `/`)."""
    import os

    from robotfix.fs import probe
    from robotfix.ros.package import package_folder

    def by_pathlib(path: Path) -> Path | None:
        folder = Path(os.path.abspath(path)).parent
        for candidate in (folder, *folder.parents):
            if probe("isfile", candidate / "package.xml"):
                return candidate
        return None

    outer = tmp_path / "ws" / "outer"
    inner = outer / "sub" / "inner"
    for folder in (outer, inner):
        folder.mkdir(parents=True)
        (folder / "package.xml").write_text("<package/>")
    (inner / "deep" / "er").mkdir(parents=True)
    monkeypatch.chdir(outer)
    for path in [
        inner / "deep" / "er" / "x.py",
        inner / "x.py",
        outer / "sub" / "y.py",
        outer / "package.xml",
        Path("sub/inner/deep/x.py"),
        Path("sub/../sub/inner/x.py"),
        Path("z.py"),
        tmp_path / "ws" / "none.py",
        Path("/"),
    ]:
        assert package_folder(path) == by_pathlib(path), path
    assert package_folder(inner / "x.py") == inner
    assert package_folder(tmp_path / "ws" / "none.py") is None
