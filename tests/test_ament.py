"""`colcon test` like the ament linters (issue 11, item 3): `--format junit`,
`ament_robotfix` (main, main_with_errors, AMENT_IGNORE, --config, --xunit-file, the
cache outside the package), the pytest markers, the test_robotfix.py template, the
CMake module; and, marked slow, a real colcon workspace and a CMake project."""

from __future__ import annotations

import ast
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix import ament
from robotfix.diagnostics import Diagnostic, Note, Span
from robotfix.report import junit
from robotfix.rules import ALL_RULES
from tests.release_env import ROOT, Release, release, run
from tests.test_cli import BUGGY, WARN
from tests.test_cli import run as robotfix

UNIT_BUG = """\
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry


def follow(odom: Odometry) -> Twist:
    cmd = Twist()
    cmd.angular.z = odom.pose.pose.position.x
    return cmd
"""
UNIT_FIXED = UNIT_BUG.replace("odom.pose.pose.position.x", "0.5")


def counts(xml: str) -> dict[str, int]:
    """What `colcon test-result` reads: the testsuite's counters (and a check that
    they agree with the test cases)."""
    suite = ET.fromstring(xml).find("testsuite")
    assert suite is not None
    cases = suite.findall("testcase")
    found = {k: int(suite.get(k, "-1")) for k in ("tests", "failures", "errors")}
    assert found["tests"] == len(cases)
    erred = [c for c in cases if c.find("error") is not None]
    failed = [c for c in cases if c.find("failure") is not None and c not in erred]
    assert (found["failures"], found["errors"]) == (len(failed), len(erred))
    return found


# -- --format junit --------------------------------------------------------------
@pytest.fixture
def project(tmp_path: Path) -> Path:
    (tmp_path / "a.py").write_text(BUGGY)
    (tmp_path / "b.py").write_text(WARN)
    (tmp_path / "c.py").write_text("x = 1\n")
    return tmp_path


def test_junit_has_a_case_per_file_and_a_failure_per_error(project: Path) -> None:
    out = robotfix("check", "--format", "junit", "--no-cache", ".", cwd=project)
    assert out.returncode == 1
    assert counts(out.stdout) == {"tests": 3, "failures": 1, "errors": 0}
    cases = {c.get("name"): c for c in ET.fromstring(out.stdout).iter("testcase")}
    assert sorted(cases) == ["a.py", "b.py", "c.py"]
    (failure,) = cases["a.py"].findall("failure")
    assert failure.get("type") == "RF101"
    assert failure.get("message", "").startswith("a.py:2:1: error[RF101]: ")
    # a warning does not fail the run, so it does not fail the test case either
    assert cases["b.py"].find("failure") is None
    assert "warning[RF102]" in (cases["b.py"].findtext("system-out") or "")


def test_junit_under_strict_fails_warnings_too(project: Path) -> None:
    out = robotfix("check", "--format", "junit", "--strict", "b.py", cwd=project)
    assert out.returncode == 1
    assert counts(out.stdout) == {"tests": 1, "failures": 1, "errors": 0}
    clean = robotfix("check", "--format", "junit", "b.py", "c.py", cwd=project)
    assert clean.returncode == 0
    assert counts(clean.stdout) == {"tests": 2, "failures": 0, "errors": 0}


def test_junit_format_from_pyproject(project: Path) -> None:
    (project / "pyproject.toml").write_text('[tool.robotfix]\nformat = "junit"\n')
    out = robotfix("check", "c.py", cwd=project)
    assert out.returncode == 0 and out.stdout.startswith("<?xml")


def test_junit_unreadable_file_is_an_error_case(tmp_path: Path) -> None:
    (tmp_path / "bad.py").write_bytes(b"x = '\xff\xfe'\n")
    out = robotfix("check", "--format", "junit", "bad.py", cwd=tmp_path)
    assert out.returncode == 2
    assert counts(out.stdout) == {"tests": 1, "failures": 0, "errors": 1}


texts = st.text(st.characters(exclude_categories=()), max_size=30)


@settings(max_examples=60, deadline=None)
@given(
    paths=st.lists(texts, min_size=1, max_size=4),
    messages=st.lists(
        st.tuples(st.integers(0, 3), st.sampled_from(sorted(ALL_RULES)), texts),
        max_size=6,
    ),
    strict=st.booleans(),
)
def test_junit_always_parses_and_counts_agree(
    paths: list[str], messages: list[tuple[int, str, str]], strict: bool
) -> None:
    """Any path or message (control characters, lone surrogates from undecodable
    file names) gives XML that parses, with counters that match the cases."""
    surrogate = "\udcff"
    found = [
        Diagnostic(
            ALL_RULES[code],
            paths[i % len(paths)] + (surrogate if i == 3 else ""),
            Span(1, 0, 1, 1),
            text,
            (Note(text, None, None),),
        )
        for i, code, text in messages
    ]
    xml = junit.render(found, paths, strict, 0.5, internal_errors=[(paths[0], "boom")])
    result = counts(xml)
    assert result["tests"] == len(set(paths) | {d.path for d in found})
    assert result["errors"] >= 1  # the internal error


# -- ament_robotfix --------------------------------------------------------------
@pytest.fixture
def package(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """An ament_python package with a unit bug, as the current folder (where colcon
    runs a package's tests); the user cache in a folder of its own."""
    pkg = tmp_path / "drive_check"
    (pkg / "drive_check").mkdir(parents=True)
    (pkg / "test").mkdir()
    (pkg / "package.xml").write_text("<package><name>drive_check</name></package>\n")
    (pkg / "setup.py").write_text("from setuptools import setup\n\nsetup()\n")
    (pkg / "drive_check" / "__init__.py").write_text("")
    (pkg / "drive_check" / "node.py").write_text(UNIT_BUG)
    monkeypatch.chdir(pkg)
    monkeypatch.setenv("ROBOTFIX_CACHE_DIR", str(tmp_path / "user-cache"))
    return pkg


def test_main_with_errors_reports_the_bug_and_keeps_the_package_clean(
    package: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    rc, errors = ament.main_with_errors([])
    assert rc == 1
    (line,) = errors
    assert line.startswith("drive_check/node.py:7:5: error[RF201]: ")
    out = capsys.readouterr().out
    assert "Checked files:" in out and "* drive_check/node.py" in out
    # the cache went to the user cache folder, not into the package
    assert not list(package.rglob(".robotfix_cache"))
    assert list((package.parent / "user-cache" / "ament").glob("*/results.json"))
    (package / "drive_check" / "node.py").write_text(UNIT_FIXED)
    assert ament.main([]) == 0


def test_xunit_file_is_named_as_ament_names_it(package: Path, tmp_path: Path) -> None:
    result_file = tmp_path / "results" / "drive_check" / "robotfix.xunit.xml"
    cache = tmp_path / "build-cache"
    assert ament.main(["--xunit-file", str(result_file), "--cache-dir", str(cache)])
    xml = result_file.read_text(encoding="utf-8")
    assert counts(xml) == {"tests": 3, "failures": 1, "errors": 0}
    suite = ET.fromstring(xml).find("testsuite")
    assert suite is not None and suite.get("name") == "drive_check.robotfix"
    assert (cache / "results.json").is_file()


def test_exclude_takes_names_like_the_ament_linters(package: Path) -> None:
    assert ament.main_with_errors(["--exclude", "node.py"]) == (0, [])
    assert ament.main(["--exclude", "drive_check/"]) == 0
    assert ament.main(["--exclude", "setup.py", "--exclude", "other.py"]) == 1
    # as in the CMake module: paths after `--`, even after --exclude's patterns
    rc, errors = ament.main_with_errors(["--exclude", "x.py", "--", "drive_check"])
    assert rc == 1 and errors[0].startswith("drive_check/node.py:7:5:")
    assert ament.main(["setup.py", "--exclude", "node.py"]) == 0


def test_folders_with_ament_ignore_are_skipped(
    package: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (package / "drive_check" / "vendor").mkdir()
    (package / "drive_check" / "vendor" / "old.py").write_text(BUGGY)
    (package / "drive_check" / "vendor" / "AMENT_IGNORE").write_text("")
    (package / "vendor").mkdir()  # same name elsewhere: still checked
    (package / "vendor" / "kept.py").write_text(BUGGY)
    rc, errors = ament.main_with_errors(["--no-cache"])
    assert rc == 1
    assert [e.split(":")[0] for e in errors] == [
        "drive_check/node.py",
        "vendor/kept.py",
    ]
    assert "old.py" not in capsys.readouterr().out
    (package / "drive_check" / "AMENT_IGNORE").write_text("")
    rc, errors = ament.main_with_errors(["--no-cache", "drive_check"])
    assert rc == 2 and "no Python files found" in errors[0]
    rc, errors = ament.main_with_errors(["--no-cache", "drive_check/node.py"])
    assert rc == 2


def test_config_option(package: Path, tmp_path: Path) -> None:
    config = tmp_path / "robotfix.toml"
    config.write_text('[tool.robotfix]\nexclude = ["drive_check/node.py"]\n')
    assert ament.main(["--config", str(config)]) == 1  # patterns are from its folder
    config.write_text('[tool.robotfix]\nper-file-ignores = {"**" = ["RF201"]}\n')
    assert ament.main(["--config", str(config)]) == 0
    config.write_text("[tool.other]\n")
    rc, errors = ament.main_with_errors(["--config", str(config)])
    assert rc == 2 and "has no [tool.robotfix] table" in errors[0]
    rc, errors = ament.main_with_errors(["--config", str(tmp_path / "missing.toml")])
    assert rc == 2 and "no such config file" in errors[0]
    rc, errors = ament.main_with_errors(["nowhere"])
    assert rc == 2 and "no such file or directory" in errors[0]


def test_module_and_template(package: Path) -> None:
    """`python -m robotfix.ament --template` prints the file users copy; the copy,
    run by pytest in the package folder as colcon runs it, fails on the bug and
    passes once it is fixed. The markers come from our pytest plugin."""
    # our plugin, given explicitly: whether an installed copy's entry point exists
    # must not matter
    env = {
        **os.environ,
        "PYTHONPATH": str(ROOT / "src"),
        "PYTEST_DISABLE_PLUGIN_AUTOLOAD": "1",
    }
    printed = subprocess.run(
        [sys.executable, "-m", "robotfix.ament", "--template"],
        capture_output=True,
        text=True,
        env=env,
        check=True,
    ).stdout
    assert printed == ament.template()
    assert "main_with_errors" in printed and ast.parse(printed)
    (package / "test" / "test_robotfix.py").write_text(printed)
    pytest_cmd = [
        sys.executable,
        "-m",
        "pytest",
        "-p",
        "robotfix.ament.pytest_marker",
        "--strict-markers",
        "-q",
        "-p",
        "no:cacheprovider",
        "test",
    ]
    failing = subprocess.run(
        pytest_cmd, cwd=package, capture_output=True, text=True, env=env, check=False
    )
    assert failing.returncode == 1, failing.stdout + failing.stderr
    assert "drive_check/node.py:7:5: error[RF201]" in failing.stdout
    (package / "drive_check" / "node.py").write_text(UNIT_FIXED)
    passing = subprocess.run(
        pytest_cmd, cwd=package, capture_output=True, text=True, env=env, check=False
    )
    assert passing.returncode == 0, passing.stdout + passing.stderr
    deselected = subprocess.run(
        [*pytest_cmd, "-m", "not linter"],
        cwd=package,
        capture_output=True,
        text=True,
        env=env,
        check=False,
    )
    assert "1 deselected" in deselected.stdout
    assert not list(package.rglob(".robotfix_cache"))


def test_docs_show_the_template_as_shipped() -> None:
    code = ament.template().split("\n\n", 1)[1]  # without the comment header
    assert code.startswith("import pytest\n")
    assert f"```python\n{code}```" in (ROOT / "docs" / "ros.md").read_text()


def test_cache_dir_option_of_check(project: Path, tmp_path: Path) -> None:
    cache = tmp_path / "elsewhere"
    out = robotfix("check", "--cache-dir", str(cache), ".", cwd=project)
    assert out.returncode == 1
    assert (cache / "results.json").is_file()
    assert not (project / ".robotfix_cache").exists()


# -- slow: a real colcon workspace, a real CMake project ------------------------
SETUP_PY = """\
from setuptools import setup

package_name = 'drive_check'

setup(
    name=package_name,
    version='0.0.1',
    packages=[package_name],
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    extras_require={'test': ['pytest']},
)
"""
PACKAGE_XML = """\
<?xml version="1.0"?>
<package format="3">
  <name>drive_check</name>
  <version>0.0.1</version>
  <description>A node with a unit bug.</description>
  <maintainer email="dev@example.com">dev</maintainer>
  <license>MIT</license>
  <test_depend>python3-pytest</test_depend>
  <export>
    <build_type>ament_python</build_type>
  </export>
</package>
"""


@pytest.fixture(scope="module")
def built(tmp_path_factory: pytest.TempPathFactory) -> Release:
    return release(tmp_path_factory)


@pytest.mark.slow
def test_colcon_test_reports_the_planted_bug(built: Release, tmp_path: Path) -> None:
    """colcon-common-extensions and pytest from the package index, RobotFix from the
    wheel; an ament_python package whose test/test_robotfix.py is our template."""
    env = built.env(built.tools)
    pkg = tmp_path / "ws" / "src" / "drive_check"
    for folder in ("drive_check", "test", "resource"):
        (pkg / folder).mkdir(parents=True)
    (pkg / "resource" / "drive_check").write_text("")
    (pkg / "package.xml").write_text(PACKAGE_XML)
    (pkg / "setup.py").write_text(SETUP_PY)
    (pkg / "drive_check" / "__init__.py").write_text("")
    (pkg / "drive_check" / "node.py").write_text(UNIT_BUG)
    template = run([built.tools / "ament_robotfix", "--template"], env, tmp_path)
    (pkg / "test" / "test_robotfix.py").write_text(template.stdout)
    ws = tmp_path / "ws"

    def colcon(*args: str) -> subprocess.CompletedProcess[str]:
        return run([built.tools / "colcon", *args], env, ws)

    build = colcon("build")
    assert build.returncode == 0, build.stdout + build.stderr
    # --strict-markers: our plugin registers `robotfix`, and `linter` as ament_lint does
    assert colcon("test", "--pytest-args", " --strict-markers").returncode == 0
    result = colcon("test-result", "--verbose")
    assert result.returncode == 1, result.stdout
    assert "1 test, 0 errors, 1 failure" in result.stdout
    assert "drive_check/node.py:7:5: error[RF201]" in result.stdout
    assert "is in rad/s" in result.stdout
    assert not list(pkg.rglob(".robotfix_cache"))  # nothing written into the sources

    (pkg / "drive_check" / "node.py").write_text(UNIT_FIXED)
    assert colcon("test").returncode == 0
    fixed = colcon("test-result", "--all")
    assert fixed.returncode == 0, fixed.stdout
    assert "1 test, 0 errors, 0 failures" in fixed.stdout


CMAKE_PROJECT = """\
cmake_minimum_required(VERSION 3.5)
project(drive_check NONE)
enable_testing()

# Stand-ins for what ament_cmake provides, so that our module runs without ROS:
# find_package of ament's own packages, ament_register_extension, ament_add_test.
set(AMENT_TEST_RESULTS_DIR "${CMAKE_BINARY_DIR}/test_results")
macro(find_package name)
  if(NOT "${name}" STREQUAL "ament_cmake_test")
    _find_package(${ARGV})
  endif()
endmacro()
function(ament_register_extension point package file)
  set_property(GLOBAL APPEND PROPERTY STUB_EXTENSIONS "${point}|${package}|${file}")
endfunction()
function(ament_add_test name)
  cmake_parse_arguments(ARG "" "OUTPUT_FILE;RESULT_FILE;TIMEOUT;WORKING_DIRECTORY"
    "COMMAND" ${ARGN})
  add_test(NAME "${name}" COMMAND ${ARG_COMMAND}
    WORKING_DIRECTORY "${ARG_WORKING_DIRECTORY}")
  set_tests_properties("${name}" PROPERTIES TIMEOUT "${ARG_TIMEOUT}")
  file(APPEND "${CMAKE_BINARY_DIR}/stub_tests.txt" "${name}|${ARG_RESULT_FILE}\\n")
endfunction()

set(ament_cmake_robotfix_DIR "@MODULE@/cmake")
include("@MODULE@/ament_cmake_robotfix-extras.cmake")

# what ament_lint_auto does: run the hooks registered for it
get_property(extensions GLOBAL PROPERTY STUB_EXTENSIONS)
foreach(extension ${extensions})
  string(REPLACE "|" ";" parts "${extension}")
  list(GET parts 0 point)
  list(GET parts 2 hook)
  if(point STREQUAL "ament_lint_auto")
    include("${ament_cmake_robotfix_DIR}/${hook}")
  endif()
endforeach()
ament_robotfix(TESTNAME robotfix_strict STRICT EXCLUDE node.py)
"""


@pytest.mark.slow
def test_cmake_module_adds_the_test_and_its_xunit_file(
    built: Release, tmp_path: Path
) -> None:
    """ament_cmake_robotfix's files, with stand-ins for ament_cmake's functions: the
    lint hook adds `robotfix`, labelled robotfix and linter, whose xUnit file
    `colcon test-result` reads; the cache goes to the build folder."""
    cmake, ctest = shutil.which("cmake"), shutil.which("ctest")
    if cmake is None or ctest is None:
        pytest.skip("cmake is not installed")
    env = built.env(built.tools)
    pkg = tmp_path / "drive_check"
    (pkg / "drive_check").mkdir(parents=True)
    (pkg / "drive_check" / "node.py").write_text(UNIT_BUG)
    (pkg / "drive_check" / "warn.py").write_text(WARN)
    module = (ROOT / "ament" / "ament_cmake_robotfix").as_posix()
    (pkg / "CMakeLists.txt").write_text(CMAKE_PROJECT.replace("@MODULE@", module))
    build = tmp_path / "build"
    configured = run([cmake, "-S", pkg, "-B", build], env, tmp_path)
    assert configured.returncode == 0, configured.stdout + configured.stderr
    assert "Added test 'robotfix'" in configured.stdout
    registered = (build / "stub_tests.txt").read_text().splitlines()
    results = build / "test_results" / "drive_check"
    assert registered == [
        f"robotfix|{results / 'robotfix.xunit.xml'}",
        f"robotfix_strict|{results / 'robotfix_strict.xunit.xml'}",
    ]
    labelled = run([ctest, "-N", "-L", "linter"], env, build)
    assert "Total Tests: 2" in labelled.stdout
    tested = run([ctest, "--output-on-failure"], env, build)
    assert tested.returncode != 0  # robotfix found the bug, and the warning (strict)
    assert "error[RF201]" in tested.stdout
    assert "0% tests passed, 2 tests failed out of 2" in tested.stdout
    report = run(
        [built.tools / "colcon", "test-result", "--test-result-base", build, "--all"],
        env,
        tmp_path,
    )
    assert "robotfix.xunit.xml: 2 tests, 0 errors, 1 failure" in report.stdout
    assert "robotfix_strict.xunit.xml: 1 test, 0 errors, 1 failure" in report.stdout
    assert (build / "ament_robotfix" / "robotfix_cache" / "results.json").is_file()
    assert not list(pkg.rglob(".robotfix_cache"))


@pytest.mark.slow
def test_template_follows_ament_flake8_style(built: Release, tmp_path: Path) -> None:
    """ament_flake8's settings: 99 columns, google import order, single quotes."""
    copy = tmp_path / "test_robotfix.py"
    copy.write_text(ament.template())
    checked = run(
        [
            built.tools / "flake8",
            "--max-line-length=99",
            "--import-order-style=google",
            "--isolated",
            copy,
        ],
        built.env(built.tools),
        tmp_path,
    )
    assert checked.returncode == 0, checked.stdout + checked.stderr
