"""Stubs: the user's `stub-paths` and `--stub-path`, a user stub winning over a shipped
one, RF512 for a stub that does not read (and the rest of it still used), the shipped
stubs reading cleanly, and the libraries' positional order."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from robotfix.api import check_paths, check_source
from robotfix.config import Config, load
from robotfix.run import check_paths as run_paths
from robotfix.stubs.load import DATA, StubSet, forget, stub_set

CALLER = """\
from typing import Annotated

import my_motor

STEP_CM: Annotated[float, "Unit('cm')"] = 5.0
my_motor.move(STEP_CM)
my_motor.move(STEP_CM / 100.0)
reach: Annotated[float, "Unit('cm')"] = my_motor.reach()
"""


def codes_at(result_diagnostics: list, name: str) -> list[tuple[int, str]]:  # type: ignore[type-arg]
    return sorted(
        (d.span.line, d.code) for d in result_diagnostics if d.path.endswith(name)
    )


@pytest.fixture
def project(tmp_path: Path) -> Path:
    (tmp_path / "node.py").write_text(CALLER)
    stubs = tmp_path / "typings"
    stubs.mkdir()
    (stubs / "my_motor.pyi").write_text(
        "from typing import Annotated\n"
        "def move(distance: Annotated[float, \"Unit('m')\"]) -> None: ...\n"
        "def reach() -> Annotated[float, \"Unit('m')\"]: ...\n"
    )
    return tmp_path


def test_stub_paths_setting_gives_units_to_a_library(project: Path) -> None:
    (project / "pyproject.toml").write_text(
        '[tool.robotfix]\nstub-paths = ["typings"]\n'
    )
    config = load(project)
    assert config.stub_paths == (project / "typings",)
    result = check_paths([project], config)
    assert codes_at(result.diagnostics, "node.py") == [(6, "RF201"), (8, "RF201")]


def test_without_stub_paths_the_library_is_unknown_and_silent(project: Path) -> None:
    result = check_paths([project / "node.py"], Config(root=project))
    assert codes_at(result.diagnostics, "node.py") == []


def test_stub_path_flag_on_the_command_line(project: Path) -> None:
    found = subprocess.run(
        [
            sys.executable,
            "-m",
            "robotfix",
            "check",
            "node.py",
            "--stub-path",
            "typings",
            "--no-cache",
        ],
        cwd=project,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert found.returncode == 1, found.stderr
    assert "node.py:6:1: error[RF201]" in found.stdout
    assert (
        "note: annotation of the `distance` argument of my_motor.move() declared here"
        " --> typings/my_motor.pyi:2"
    ) in found.stdout
    missing = subprocess.run(
        [sys.executable, "-m", "robotfix", "check", "node.py", "--stub-path", "nope"],
        cwd=project,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert missing.returncode == 2
    assert "--stub-path nope: no such file or directory" in missing.stderr


def test_a_user_stub_wins_over_the_shipped_one(tmp_path: Path) -> None:
    code = (
        "import time\nfrom typing import Annotated\n"
        "P: Annotated[float, \"Unit('ms')\"] = 20.0\ntime.sleep(P)\n"
    )
    assert [d.code for d in check_source(code, "a.py", Config())] == ["RF201"]
    ours = tmp_path / "stubs"
    ours.mkdir()
    (ours / "time.pyi").write_text(
        "from typing import Annotated\n"
        "def sleep(ms: Annotated[float, \"Unit('ms')\"]) -> None: ...\n"
    )
    config = Config(stub_paths=(ours,))
    assert check_source(code, "a.py", config) == []
    wrong = code.replace(
        "time.sleep(P)", "S: Annotated[float, \"Unit('s')\"] = 0.02\ntime.sleep(S)"
    )
    assert [d.code for d in check_source(wrong, "a.py", config)] == ["RF201"]


def test_malformed_stubs_are_rf512_at_their_line_and_the_rest_works(
    project: Path,
) -> None:
    stubs = project / "typings"
    (stubs / "my_motor.pyi").write_text(
        "from typing import Annotated\n"
        "def move(distance: Annotated[float, \"Unit('m')\"]) -> None: ...\n"
        "def reach() -> Annotated[float, \"Unit('m') and _ >\"]: ...\n"
        "@unit_rule('bogus')\n"
        "def double(x: float) -> float: ...\n"
    )
    (stubs / "broken.pyi").write_text("def f(:\n")
    (stubs / "pkg").mkdir()
    (stubs / "pkg" / "__init__.pyi").write_text(
        "x: Annotated[float, \"Unit('furlongz')\"]\nfrom typing import Annotated\n"
    )
    config = Config(root=project, stub_paths=(stubs,))
    result = run_paths([project / "node.py"], config)
    stub_found = sorted(
        (Path(d.path).name, d.span.line, d.span.col, d.code)
        for d in result.diagnostics
        if d.code == "RF512"
    )
    assert ("broken.pyi", 1, 6, "RF512") in stub_found
    assert [(n, line) for n, line, _, _ in stub_found if n == "my_motor.pyi"] == [
        ("my_motor.pyi", 3),
        ("my_motor.pyi", 4),
    ]
    # move() is still checked; reach() is unannotated now
    assert codes_at(result.diagnostics, "node.py") == [(6, "RF201")]
    # once per run, whatever the number of files using it
    (project / "other.py").write_text(CALLER)
    again = run_paths([project], config)
    assert len([d for d in again.diagnostics if d.code == "RF512"]) == len(stub_found)


def test_the_shipped_stubs_read_cleanly() -> None:
    shipped = StubSet((DATA,))
    assert shipped.problems() == []
    names = {p.relative_to(DATA).as_posix() for p in DATA.rglob("*.pyi")}
    assert {"rospy.pyi", "rclpy/node.pyi", "math.pyi", "numpy.pyi", "time.pyi"} <= names


@pytest.mark.parametrize(
    ("qualified", "params"),
    [
        # ROS 1 takes the service name first (ros_comm rospy/impl/tcpros_service.py)
        ("rospy.wait_for_service", [("service", 0), ("timeout", 1)]),
        ("rospy.wait_for_message", [("topic", 0), ("topic_type", 1), ("timeout", 2)]),
        ("rospy.Duration.__init__", [("secs", 0), ("nsecs", 1)]),
        ("rospy.Duration.from_sec", [("float_seconds", 0)]),
        # rclpy: spin_once's timeout is keyword-only, spin_until_future_complete's 4th
        ("rclpy.spin_once", [("node", 0), ("executor", None), ("timeout_sec", None)]),
        (
            "rclpy.spin_until_future_complete",
            [("node", 0), ("future", 1), ("executor", 2), ("timeout_sec", 3)],
        ),
        (
            "rclpy.duration.Duration.__init__",
            [("seconds", None), ("nanoseconds", None)],
        ),
        (
            "rclpy.node.Node.create_timer",
            [
                ("timer_period_sec", 0),
                ("callback", 1),
                ("callback_group", 2),
                ("clock", 3),
                ("autostart", 4),
            ],
        ),
        (
            "tf2_ros.Buffer.lookup_transform",
            [("target_frame", 0), ("source_frame", 1), ("time", 2), ("timeout", 3)],
        ),
        (
            "tf.transformations.quaternion_from_euler",
            [("ai", 0), ("aj", 1), ("ak", 2), ("axes", 3)],
        ),
    ],
)
def test_shipped_signatures_keep_the_libraries_order(
    qualified: str, params: list[tuple[str, int | None]]
) -> None:
    found = stub_set().lookup(qualified)
    assert found is not None and not isinstance(found, type)
    assert [(p.name, p.positional) for p in found.params] == params  # type: ignore[union-attr]


def test_rospy_wait_for_service_checks_the_timeout_not_the_name() -> None:
    code = (
        "import rospy\nfrom typing import Annotated\n"
        "T: Annotated[float, \"Unit('ms')\"] = 500.0\n"
        "rospy.wait_for_service('add_two_ints', T)\n"
        "rospy.wait_for_service('add_two_ints')\n"
        "rospy.wait_for_service(service='add_two_ints', timeout=T / 1000)\n"
    )
    found = check_source(code, "a.py", Config())
    assert [(d.span.line, d.code) for d in found] == [(4, "RF201")]
    assert "`timeout` argument of rospy.wait_for_service()" in found[0].message


def test_a_conversion_of_a_converted_value_says_drop_it() -> None:
    code = (
        "import math\nimport numpy as np\nfrom typing import Annotated\n"
        "YAW: Annotated[float, \"Unit('rad')\"] = 0.5\n"
        "DEG_S: Annotated[float, \"Unit('degree/s')\"] = 30.0\n"
        "a = np.deg2rad(YAW)\n"
        "w: Annotated[float, \"Unit('rad/s')\"] = math.radians(DEG_S)\n"
        "b: Annotated[float, \"Unit('rad')\"] = math.radians(30)\n"
    )
    found = check_source(code, "a.py", Config())
    assert [(d.span.line, d.code) for d in found] == [(6, "RF201")]
    assert "already in rad: drop the call" in found[0].message
    assert "convert rad to" not in found[0].message


def test_the_fast_path_reads_what_extract_reads() -> None:
    """`Annotated[float, "Unit('s')"]` is read without the refinement parser; it
    must mean exactly what `extract` makes of it."""
    import ast

    from robotfix.annotations.extract import extract
    from robotfix.stubs import reader as stub_reader
    from robotfix.stubs.model import Module

    checked = 0
    for path in sorted(DATA.rglob("*.pyi")):
        text = path.read_text(encoding="utf-8")
        reader = stub_reader._Reader(Module("m"), text, path.name, None)
        reader.read(ast.parse(text))
        for node in ast.walk(ast.parse(text)):
            if not isinstance(node, ast.Subscript):
                continue
            fast = reader._unit_only(node)
            if fast is None:
                continue
            slow, problems = extract(
                node,
                "x",
                reader.qualname,
                lambda _: None,
                reader.segment,
                reader.col_of,
            )
            assert not problems and fast == slow, ast.unparse(node)
            checked += 1
    assert checked > 50


def test_a_changed_user_stub_invalidates_cached_results(project: Path) -> None:
    config = Config(
        root=project, stub_paths=(project / "typings",), cache_dir=project / ".c"
    )
    first = check_paths([project / "node.py"], config, use_cache=True)
    assert codes_at(first.diagnostics, "node.py") == [(6, "RF201"), (8, "RF201")]
    (project / "typings" / "my_motor.pyi").write_text(
        "from typing import Annotated\n"
        "def move(distance: Annotated[float, \"Unit('rad')\"]) -> None: ...\n"
    )
    forget()  # a new run in a new process would read the stub anew
    again = check_paths([project / "node.py"], config, use_cache=True)
    assert again.from_cache == 0
    assert codes_at(again.diagnostics, "node.py") == [(6, "RF201"), (7, "RF201")]


def test_overloaded_operators_are_read_by_operand_type() -> None:
    """`Time - Time` is a Duration and `Time - Duration` a Time (issue 22): each
    `@overload` of an operator is kept under its operand's class."""
    from robotfix.stubs.load import Class, stub_set

    stubs = stub_set()
    time = stubs.lookup("rclpy.time.Time")
    assert isinstance(time, Class)
    minus_time = stubs.member(time, "__sub__:rclpy.time.Time")
    minus_duration = stubs.member(time, "__sub__:rclpy.duration.Duration")
    assert minus_time is not None and minus_duration is not None
    assert minus_time.returns_type == "rclpy.duration.Duration"
    assert minus_duration.returns_type == "rclpy.time.Time"
    assert stubs.member(time, "__sub__") is None  # no meaning without the operand


def test_the_shipped_stubs_are_found_as_by_probing_each_file(tmp_path: Path) -> None:
    """`_find_file` takes the shipped files from one listing (`_shipped_files`):
    every module answers as two probes on disk did, packages and their modules,
    names with no stub, and a user stub path's file first."""

    def probed(stubs: StubSet, name: str) -> tuple[Path, str, bool] | None:
        relative = name.replace(".", "/")
        for root, shipped in [*((p, False) for p in stubs.paths), (DATA, True)]:
            for candidate in (f"{relative}.pyi", f"{relative}/__init__.pyi"):
                path = root / candidate
                if path.exists() and not path.is_dir():
                    return path, candidate if shipped else str(path), shipped
        return None

    files = [p.relative_to(DATA).with_suffix("") for p in DATA.rglob("*.pyi")]
    names = {".".join(f.parts[:-1] if f.name == "__init__" else f.parts) for f in files}
    assert {"rclpy", "rclpy.node", "math"} <= names
    (tmp_path / "rclpy").mkdir()
    (tmp_path / "rclpy" / "node.pyi").write_text("def f() -> None: ...\n")
    asked = [*sorted(names), "rclpy.nothing", "no_such_module", "tf2_ros.x.y"]
    for stubs in (StubSet(()), StubSet((tmp_path,))):
        for name in asked:
            assert stubs._find_file(name) == probed(stubs, name), name
    assert StubSet((tmp_path,))._find_file("rclpy.node") == (
        tmp_path / "rclpy" / "node.pyi",
        str(tmp_path / "rclpy" / "node.pyi"),
        False,
    )
