"""`robotfix suggest` follows flows (issue 11, item 6): every program under
tests/suggest_cases/ is a small correct node whose `# suggest: name unit[, ...]`
comments list exactly the suggestions on that line (the others are near misses that
must get none); the suggestions applied must parse, add no diagnostic, and leave
nothing more to suggest."""

from __future__ import annotations

import difflib
import io
import re
import tokenize
from pathlib import Path

import pytest

from robotfix import api
from robotfix.api import check_source
from robotfix.config import Config
from robotfix.ros.catalog import MsgCatalog
from robotfix.suggest import UnsafeEditError, annotate
from tests.test_cases import CASES as CASES_ROOT
from tests.test_cases import SINGLE_FILES, catalog_for
from tests.test_cli import run

CASES = Path(__file__).parent / "suggest_cases"
_EXPECTED = re.compile(r"#\s*suggest:\s*(.*)$")


@pytest.fixture(scope="module")
def catalog() -> MsgCatalog:
    return MsgCatalog([])


def expected(source: str) -> set[tuple[int, str, str, str]]:
    """(line, name, unit, kind) from `# suggest: name unit` (a float) or
    `# suggest: name unit list[float]`."""
    found = set()
    for tok in tokenize.generate_tokens(io.StringIO(source).readline):
        match = _EXPECTED.match(tok.string) if tok.type == tokenize.COMMENT else None
        if match:
            for part in match.group(1).split(","):
                name, unit, *kind = part.split()
                found.add((tok.start[0], name, unit, kind[0] if kind else "float"))
    return found


CASE_FILES = sorted(CASES.glob("*.py"))


@pytest.mark.parametrize("path", CASE_FILES, ids=lambda p: p.stem)
def test_suggestions_are_exactly_the_expected(path: Path, catalog: MsgCatalog) -> None:
    source = path.read_text(encoding="utf-8")
    got = {
        (s.line, s.name, s.unit, s.kind)
        for s in api.unit_suggestions(source, str(path), catalog)
    }
    assert got == expected(source)


@pytest.mark.parametrize("path", CASE_FILES, ids=lambda p: p.stem)
def test_applied_suggestions_check_clean(path: Path, catalog: MsgCatalog) -> None:
    source = path.read_text(encoding="utf-8")
    assert check_source(source, str(path), Config(), catalog) == []
    changed = annotate(source, str(path), catalog)
    assert changed != source
    assert check_source(changed, str(path), Config(), catalog) == []
    assert annotate(changed, str(path), catalog) == changed  # nothing left


def test_the_annotations_catch_a_later_bug(catalog: MsgCatalog) -> None:
    source = (CASES / "drive_helper.py").read_text(encoding="utf-8")
    bug = ("self.drive(self.slow, self.turn_speed)", "self.drive(self.turn_speed, 0.0)")
    assert check_source(source.replace(*bug), "node.py", Config(), catalog) == []
    annotated = annotate(source, "node.py", catalog).replace(*bug)
    found = check_source(annotated, "node.py", Config(), catalog)
    assert [d.code for d in found] == ["RF201"]


def test_each_kind_of_place_is_written_where_it_belongs(catalog: MsgCatalog) -> None:
    source = (CASES / "drive_helper.py").read_text(encoding="utf-8")
    changed = annotate(source, "node.py", catalog)
    unit = "Annotated[float, \"Unit('{}')\"]"
    assert f"CRUISE: {unit.format('m/s')} = 0.4" in changed  # a module constant
    assert (  # a parameter with a default
        f"def __init__(self, turn_speed: {unit.format('rad/s')} = 0.6):" in changed
    )
    assert f"self.slow: {unit.format('m/s')} = CRUISE * 0.5" in changed  # __init__
    assert (  # parameters
        f"def drive(self, speed: {unit.format('m/s')}, turn: {unit.format('rad/s')}):"
        in changed
    )


def test_apply_from_the_command_line(tmp_path: Path) -> None:
    node = tmp_path / "patrol.py"
    node.write_bytes((CASES / "rospy_patrol.py").read_bytes())
    assert run("suggest", "patrol.py", "--apply", cwd=tmp_path).returncode == 0
    text = node.read_text()
    assert text.startswith("#!/usr/bin/env python\n")
    assert "def wait_for_simulator(timeout: Annotated[float, \"Unit('s')\"]):" in text
    assert run("check", "patrol.py", cwd=tmp_path).returncode == 0
    again = run("suggest", "patrol.py", cwd=tmp_path)
    assert again.stdout == "No suggestions in 1 file.\n"


def test_no_suggestion_when_the_analysis_stopped_early(
    catalog: MsgCatalog, monkeypatch: pytest.MonkeyPatch
) -> None:
    from robotfix import budget

    source = (CASES / "drive_helper.py").read_text(encoding="utf-8")
    assert api.unit_suggestions(source, "node.py", catalog)
    # stopped before `self.wait(None)`: `seconds` would look like a time
    monkeypatch.setattr(budget, "FILE_STEPS", 100)
    assert api.unit_suggestions(source, "node.py", catalog) == []


def test_a_constructor_stored_into_a_field_takes_the_units_of_that_place(
    tmp_path: Path,
) -> None:
    folder = tmp_path / "pkg" / "msg"
    folder.mkdir(parents=True)
    (folder / "Drive.msg").write_text(
        'geometry_msgs/Vector3 vel  #RobotFix# Unit(vel.x) == "m/s"\n', encoding="utf-8"
    )
    catalog = MsgCatalog(api.interface_files([folder]))
    source = (
        "from geometry_msgs.msg import Vector3\n"
        "from pkg.msg import Drive\n"
        "def send(pub, forward):\n"
        "    msg = Drive()\n"
        "    msg.vel = Vector3(forward, 0.0, 0.0)\n"
        "    pub.publish(msg)\n"
    )
    got = [
        (s.line, s.name, s.unit) for s in api.unit_suggestions(source, "n.py", catalog)
    ]
    assert got == [(3, "forward", "m/s")]  # Vector3 has no unit: Drive.vel has


def test_suggest_sees_the_users_stubs_and_the_modules_the_file_imports(
    tmp_path: Path,
) -> None:
    """As `check` sees them: a unit from a `stub-paths` stub, and one from a refined
    parameter of a function in another module of the package; a name that meets
    both a stub's s and the other module's rad gets nothing (it did get s, and the
    applied file then failed its check with RF201)."""
    (tmp_path / "pyproject.toml").write_text(
        '[tool.robotfix]\nstub-paths = ["stubs"]\n', encoding="utf-8"
    )
    (tmp_path / "stubs").mkdir()
    (tmp_path / "stubs" / "mylib.pyi").write_text(
        "from typing import Annotated\n"
        "def wait(duration: Annotated[float, \"Unit('s')\"]) -> None: ...\n",
        encoding="utf-8",
    )
    (tmp_path / "navigator.py").write_text(
        "from typing import Annotated\n"
        "class Navigator:\n"
        "    def spin(self, spin_dist: Annotated[float, \"Unit('rad')\"]) -> None:\n"
        "        pass\n",
        encoding="utf-8",
    )
    (tmp_path / "demo.py").write_text(
        "import mylib\n"
        "from navigator import Navigator\n"
        "LOOK_AROUND = 3.14\n"
        "BOTH = 3.0\n"
        "def main():\n"
        "    pause = 2.0\n"
        "    mylib.wait(pause)\n"
        "    Navigator().spin(spin_dist=LOOK_AROUND)\n"
        "    mylib.wait(BOTH)\n"
        "    Navigator().spin(BOTH)\n",
        encoding="utf-8",
    )
    shown = run("suggest", "demo.py", cwd=tmp_path)
    assert shown.returncode == 0, shown.stderr
    added = [line for line in shown.stdout.splitlines() if line.startswith("+ ")]
    added += [line for line in shown.stdout.splitlines() if line.startswith("+L")]
    assert sorted(added) == [
        "+    pause: Annotated[float, \"Unit('s')\"] = 2.0",
        "+LOOK_AROUND: Annotated[float, \"Unit('rad')\"] = 3.14",
    ]
    assert run("suggest", "demo.py", "--apply", cwd=tmp_path).returncode == 0
    assert run("check", "demo.py", cwd=tmp_path).returncode == 0


def _old_lines(source: str, changed: str) -> dict[int, int]:
    """Line of the edited text -> line of the original (the import is new)."""
    matcher = difflib.SequenceMatcher(
        None, source.splitlines(), changed.splitlines(), autojunk=False
    )
    lines = {}
    for tag, i1, i2, j1, j2 in matcher.get_opcodes():
        if tag in ("equal", "replace") and i2 - i1 == j2 - j1:
            lines.update({j1 + k + 1: i1 + k + 1 for k in range(i2 - i1)})
    return lines


_MISMATCH = {"RF202": "RF201"}  # one unit mismatch, told at the operands


@pytest.mark.parametrize(
    "path", SINGLE_FILES, ids=lambda p: str(p.relative_to(CASES_ROOT))
)
def test_applying_every_suggestion_on_a_case_adds_no_finding(path: Path) -> None:
    """Every case of tests/cases/ (clean or buggy) with every suggestion applied:
    the check finds nothing on a line where it found nothing of that rule before
    (a suggestion must never make a clean file fail: `Annotated[float, ...]` on a
    list gave RF401); on a line with a bug the wording may change (`angle` is
    known to be in rad once annotated), and so may where a unit mismatch is told:
    at the store (RF201) or, once the other operand's unit is declared, at the
    operands (RF202: `target + STEP_DEG` with `target` suggested rad/s)."""
    source = path.read_text(encoding="utf-8")
    catalog = catalog_for(path.parent)
    config = Config(ros_distro="ros1" if "ros1" in path.parts else "ros2")
    try:
        changed = annotate(source, str(path), catalog, config)
    except UnsafeEditError:
        return
    if changed == source:
        return
    old = _old_lines(source, changed)
    found = check_source(source, str(path), config, catalog)
    before = {(_MISMATCH.get(d.code, d.code), d.span.line) for d in found}
    after = check_source(changed, str(path), config, catalog)
    new = [
        d
        for d in after
        if (_MISMATCH.get(d.code, d.code), old.get(d.span.line)) not in before
    ]
    assert new == [], changed


def test_suggest_from_the_root_uses_each_packages_own_settings(tmp_path: Path) -> None:
    """A package's `robotfix.toml` (its `stub-paths`) counts when `suggest` runs at
    the workspace root, as it does for `check` (suggest read only the first path's
    configuration, so the root run proposed nothing the package run proposes)."""
    package = tmp_path / "src" / "driver"
    (package / "stubs").mkdir(parents=True)
    (package / "robotfix.toml").write_text('stub-paths = ["stubs"]\n', encoding="utf-8")
    (package / "stubs" / "motor.pyi").write_text(
        "from typing import Annotated\n"
        "def set_speed(v: Annotated[float, \"Unit('m/s')\"]) -> None: ...\n",
        encoding="utf-8",
    )
    (package / "node.py").write_text(
        "import motor\nCRUISE = 0.4\n\ndef main():\n    motor.set_speed(CRUISE)\n",
        encoding="utf-8",
    )
    wanted = "+CRUISE: Annotated[float, \"Unit('m/s')\"] = 0.4"
    for where, target in ((package, "node.py"), (tmp_path, ".")):
        shown = run("suggest", target, cwd=where)
        assert shown.returncode == 0, shown.stderr
        assert wanted in shown.stdout.splitlines(), (where, shown.stdout)
