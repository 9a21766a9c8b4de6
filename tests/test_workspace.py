"""RobotFix in a ROS workspace (issue 11 item 1): interface files of the sourced
install space, extensionless ROS 1 scripts, build/install output and ignore markers
skipped, a workspace root checked once, and interface files the checked code does
not use never failing the run. Layouts are built in tmp_path."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix import discovery, fs, run
from robotfix.api import Result, check_paths
from robotfix.config import Config
from robotfix.diagnostics import Severity
from robotfix.ros.catalog import MsgCatalog
from robotfix.ros.install import InstallSpace

ROS_VARIABLES = ("AMENT_PREFIX_PATH", "CMAKE_PREFIX_PATH", "ROS_PACKAGE_PATH")
USES_CMD = (
    "from my_msgs.msg import Cmd\n"
    "\n"
    "def drive() -> None:\n"
    "    c = Cmd()\n"
    "    c.speed = {speed}\n"
)
BUGGY = 'from typing import Annotated\ntimeout: Annotated[int, "_ < 200"] = 200\n'
posix = pytest.mark.skipif(os.name != "posix", reason="FIFOs")


@pytest.fixture(autouse=True)
def no_ros_sourced(monkeypatch: pytest.MonkeyPatch) -> None:
    """Each test decides what is sourced, whatever the machine has."""
    for name in ROS_VARIABLES:
        monkeypatch.delenv(name, raising=False)


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


def package(folder: Path, name: str) -> Path:
    write(folder / "package.xml", f'<package format="3"><name>{name}</name></package>')
    return folder


def cmd_msg(folder: Path, bound: float) -> Path:
    """my_msgs/Cmd with `speed <= bound`, in `folder/msg/`."""
    return write(
        folder / "msg" / "Cmd.msg",
        f'float64 speed  #RobotFix# Unit(speed) == "m/s" and speed <= {bound}\n',
    )


def ros2_install(prefix: Path, bound: float = 1.0) -> Path:
    """An isolated colcon install of my_msgs: share/my_msgs/ with .msg, .srv,
    .action, and the .idl files rosidl puts beside them."""
    share = package(prefix / "share" / "my_msgs", "my_msgs")
    cmd_msg(share, bound)
    write(share / "msg" / "Cmd.idl", "module my_msgs { module msg { struct Cmd {\n")
    write(
        share / "srv" / "Set.srv", "int32 level  #RobotFix# level > 0\n---\nbool ok\n"
    )
    write(share / "srv" / "Set.idl", "}}} not read\n")
    write(
        share / "action" / "Go.action",
        "float64 distance  #RobotFix# distance < 10\n"
        "---\nbool done\n---\nfloat64 left\n",
    )
    return prefix


def check(*paths: Path, root: Path, **overrides: Any) -> Result:
    return check_paths(list(paths), Config(root=root, **overrides))


def found(result: Result) -> list[tuple[str, int, str]]:
    return [(Path(d.path).name, d.span.line, d.code) for d in result.diagnostics]


def node(tmp_path: Path, text: str) -> Path:
    """A checked ROS package `drive` holding node.py."""
    pkg = package(tmp_path / "ws" / "src" / "drive", "drive")
    write(pkg / "drive" / "node.py", text)
    return pkg


# -- install space -------------------------------------------------------------


def test_an_installed_package_resolves_without_msg_path(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    pkg = node(tmp_path, USES_CMD.format(speed=2.0))
    assert found(check(pkg, root=tmp_path)) == []  # nothing sourced: not known
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(ros2_install(tmp_path / "install")))
    result = check(pkg, root=tmp_path)
    assert found(result) == [("node.py", 5, "RF101")]
    origin = result.diagnostics[0].notes[0]
    assert origin.path == str(tmp_path / "install/share/my_msgs/msg/Cmd.msg")


def test_services_and_actions_come_from_the_install_space_too(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    pkg = node(
        tmp_path,
        "from my_msgs.action import Go\n"
        "from my_msgs.srv import Set\n"
        "\n"
        "def call() -> None:\n"
        "    request = Set.Request()\n"
        "    request.level = -1\n"
        "    goal = Go.Goal()\n"
        "    goal.distance = 12.0\n",
    )
    prefixes = [tmp_path / "missing", ros2_install(tmp_path / "install")]
    monkeypatch.setenv("AMENT_PREFIX_PATH", os.pathsep.join(map(str, prefixes)))
    assert found(check(pkg, root=tmp_path)) == [
        ("node.py", 6, "RF101"),
        ("node.py", 8, "RF101"),
    ]


def test_ros1_shares_and_package_path_are_searched(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    pkg = node(tmp_path, USES_CMD.format(speed=2.0))
    # ROS 1: an install prefix on CMAKE_PREFIX_PATH ...
    cmd_msg(package(tmp_path / "opt" / "share" / "my_msgs", "my_msgs"), 1.0)
    monkeypatch.setenv("CMAKE_PREFIX_PATH", str(tmp_path / "opt"))
    assert found(check(pkg, root=tmp_path)) == [("node.py", 5, "RF101")]
    # ... or a source folder on ROS_PACKAGE_PATH, named by package.xml, not folder
    monkeypatch.delenv("CMAKE_PREFIX_PATH")
    source = package(tmp_path / "catkin" / "src" / "repo" / "messages", "my_msgs")
    cmd_msg(source, 1.0)
    ignored = package(tmp_path / "catkin" / "src" / "old", "my_msgs")
    cmd_msg(ignored, 5.0)
    write(ignored / "CATKIN_IGNORE", "")
    monkeypatch.setenv("ROS_PACKAGE_PATH", str(tmp_path / "catkin" / "src"))
    result = check(pkg, root=tmp_path)
    assert found(result) == [("node.py", 5, "RF101")]
    assert result.diagnostics[0].notes[0].path == str(source / "msg" / "Cmd.msg")


def test_overlays_win_over_underlays(tmp_path: Path) -> None:
    overlay = ros2_install(tmp_path / "ws_install", bound=3.0)
    underlay = ros2_install(tmp_path / "opt", bound=1.0)
    env = {"AMENT_PREFIX_PATH": f"{overlay}{os.pathsep}{underlay}"}
    space = InstallSpace.from_environment(env)
    assert space is not None
    assert space.find("my_msgs/Cmd") == overlay / "share/my_msgs/msg/Cmd.msg"
    assert space.find("my_msgs/Set_Response") == overlay / "share/my_msgs/srv/Set.srv"
    assert (
        space.find("my_msgs/Go_Feedback") == overlay / "share/my_msgs/action/Go.action"
    )
    assert space.find("my_msgs/Absent") is None
    assert space.find("other_msgs/Cmd") is None
    assert InstallSpace.from_environment({}) is None


@pytest.mark.parametrize(
    ("layers", "speed", "expected"),
    [
        # the checked package's own file wins over a msg path's and the install's;
        # the msg path's different copy is named (RF510), the install space's is not
        (("package", "msg_path", "install"), 2.5, [("Cmd.msg", 1, "RF510")]),
        (("msg_path", "install"), 2.5, [("node.py", 5, "RF101")]),
        (("msg_path", "install"), 1.5, []),
        (("install",), 1.5, [("node.py", 5, "RF101")]),
    ],
)
def test_precedence_checked_package_msg_path_install_space(
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    layers: tuple[str, ...],
    speed: float,
    expected: list[tuple[str, int, str]],
) -> None:
    pkg = node(tmp_path, USES_CMD.format(speed=speed))
    paths = [pkg]
    msg_paths: tuple[Path, ...] = ()
    if "package" in layers:
        paths.append(package(tmp_path / "ws/src/my_msgs", "my_msgs"))
        cmd_msg(paths[-1], 3.0)
    if "msg_path" in layers:
        cmd_msg(package(tmp_path / "vendor" / "my_msgs", "my_msgs"), 2.0)
        msg_paths = (tmp_path / "vendor",)
    if "install" in layers:
        monkeypatch.setenv("AMENT_PREFIX_PATH", str(ros2_install(tmp_path / "install")))
    result = check(*paths, root=tmp_path, msg_paths=msg_paths)
    assert found(result) == expected


def test_the_install_space_wins_over_the_bundled_definitions(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    code = (
        "from geometry_msgs.msg import Twist\n"
        "\n"
        "def f() -> None:\n"
        "    t = Twist()\n"
        "    t.linear.x = 0.8\n"
    )
    pkg = node(tmp_path, code)
    share = package(tmp_path / "opt" / "share" / "geometry_msgs", "geometry_msgs")
    write(
        share / "msg" / "Twist.msg",
        "# This expresses velocity in free space.\n"
        "Vector3  linear  #RobotFix# linear.x <= 0.5\n"
        "Vector3  angular\n",
    )
    assert found(check(pkg, root=tmp_path)) == []
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(tmp_path / "opt"))
    assert found(check(pkg, root=tmp_path)) == [("node.py", 5, "RF101")]


def test_a_sourced_copy_of_a_checked_package_does_not_double_diagnostics(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A built and sourced workspace: install/ holds a copy of src/my_msgs."""
    pkg = node(tmp_path, USES_CMD.format(speed=2.0))
    source = package(tmp_path / "ws/src/my_msgs", "my_msgs")
    cmd_msg(source, 1.0)
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(ros2_install(tmp_path / "ws/install")))
    result = check(pkg, source, root=tmp_path)
    assert found(result) == [("node.py", 5, "RF101")]
    assert result.diagnostics[0].notes[0].path == str(source / "msg" / "Cmd.msg")


@pytest.mark.parametrize(
    ("speed", "broken"), [(-1.0, "speed >= 0"), (2.0, "speed <= 1.0")]
)
def test_a_refinement_only_file_adds_to_the_installed_type(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, speed: float, broken: str
) -> None:
    pkg = node(tmp_path, USES_CMD.format(speed=speed))
    overlay = write(
        tmp_path / "refinements" / "Cmd.msg", "[my_msgs/Cmd]:\n#RobotFix# speed >= 0\n"
    )
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(ros2_install(tmp_path / "install")))
    result = check(pkg, root=tmp_path, msg_paths=(overlay.parent,))
    assert found(result) == [("node.py", 5, "RF101")]
    assert broken in result.diagnostics[0].message


@pytest.mark.parametrize("base", ["package", "msg_path", "install", "standard"])
@pytest.mark.parametrize("overlay_first", [True, False])
@pytest.mark.parametrize("cached", [False, True])
def test_an_overlay_adds_to_its_type_wherever_the_type_is_defined(
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    base: str,
    overlay_first: bool,
    cached: bool,
) -> None:
    """Issue 24: a `#RobotFix#`-only file on a type of a message package in the
    same workspace replaced it (RF505 "not a field", RF510 "remove or rename")."""
    if base == "standard":
        code = USES_CMD.replace(
            "my_msgs.msg import Cmd", "geometry_msgs.msg import Vector3"
        )
        code = code.replace("Cmd()", "Vector3()").replace("c.speed", "c.x")
        overlay_text = "[geometry_msgs/Vector3]:\n#RobotFix# x >= 0\n"
    else:
        code, overlay_text = USES_CMD, "[my_msgs/Cmd]:\n#RobotFix# speed >= 0\n"
    pkg = node(tmp_path, code.format(speed=-1.0))
    overlay = write(tmp_path / "refinements" / "Cmd.msg", overlay_text).parent
    paths, msg_paths = [pkg], [overlay]
    if base == "package":  # a third-party message package cloned into src/
        paths.append(cmd_msg(package(tmp_path / "ws/src/my_msgs", "my_msgs"), 3).parent)
        paths[-1] = paths[-1].parent
    elif base == "msg_path":
        cmd_msg(package(tmp_path / "vendor" / "my_msgs", "my_msgs"), 3.0)
        msg_paths.append(tmp_path / "vendor")
    elif base == "install":
        monkeypatch.setenv("AMENT_PREFIX_PATH", str(ros2_install(tmp_path / "install")))
    if not overlay_first:
        msg_paths.reverse()
    for _ in range(2 if cached else 1):  # the second run's catalog is read lazily
        result = check_paths(
            paths,
            Config(root=tmp_path, msg_paths=tuple(msg_paths)),
            use_cache=cached,
        )
        assert found(result) == [("node.py", 5, "RF101")]
        assert "speed >= 0" in result.diagnostics[0].message or base == "standard"
        assert result.diagnostics[0].notes[0].path == str(overlay / "Cmd.msg")


def test_two_overlays_and_a_definition_add_up_in_order(tmp_path: Path) -> None:
    definition = cmd_msg(package(tmp_path / "a" / "my_msgs", "my_msgs"), 3.0)
    first = write(tmp_path / "b" / "Cmd.msg", "[my_msgs/Cmd]:\n#RobotFix# speed >= 0\n")
    second = write(
        tmp_path / "c" / "Cmd.msg", "[my_msgs/Cmd]:\n#RobotFix# speed != 1\n"
    )
    for order in ([first, definition, second], [second, first, definition]):
        catalog = MsgCatalog(order)
        assert catalog.problems == []
        spec = catalog.lookup("my_msgs/Cmd")
        assert spec is not None and list(spec.fields) == ["speed"]
        overlays = [i.text for i in spec.invariants][1:]
        expected = ["speed >= 0", "speed != 1"]
        assert overlays == (expected if order[0] == first else expected[::-1])


def test_installed_files_that_do_not_parse_or_resolve_are_not_used_or_reported(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    code = (
        "from geometry_msgs.msg import Twist\n"
        "from my_msgs.msg import Fix\n"
        "\n"
        "def f() -> None:\n"
        "    t = Twist()\n"
        "    t.linear.x = 0.8\n"
        "    fix = Fix()\n"
        "    fix.quality = 7\n"
    )
    pkg = node(tmp_path, code)
    opt = tmp_path / "opt" / "share"
    # a line this reader cannot parse: the bundled Twist is used instead
    write(
        package(opt / "geometry_msgs", "geometry_msgs") / "msg" / "Twist.msg",
        "Vector3 linear  #RobotFix# linear.x <= 0.5\n@verbatim (language=x)\n",
    )
    # an unknown field type: used, but its RF504 is not the user's to fix
    write(
        package(opt / "my_msgs", "my_msgs") / "msg" / "Fix.msg",
        "geographic_msgs/GeoPoint where\nint8 quality  #RobotFix# quality < 5\n",
    )
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(tmp_path / "opt"))
    assert found(check(pkg, root=tmp_path)) == [("node.py", 8, "RF101")]


def test_the_language_server_looks_in_the_install_space(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    server = pytest.importorskip("robotfix.lsp.server")
    pkg = node(tmp_path, USES_CMD.format(speed=2.0))
    env = {"AMENT_PREFIX_PATH": str(ros2_install(tmp_path / "install"))}
    monkeypatch.setattr(server, "_INSTALLED", discovery.install_space(env))
    editor = server.Session()  # no document open
    catalog = server._catalog(editor, pkg / "drive" / "node.py")
    assert catalog.lookup("my_msgs/Cmd") is not None


# -- extensionless scripts -------------------------------------------------------


@pytest.mark.parametrize(
    "shebang",
    [
        "#!/usr/bin/env python",
        "#!/usr/bin/env python3",
        "#!/usr/bin/python2",
        "#!/usr/bin/python2.7",
        "#! /usr/bin/python3.10",
        "#!/usr/bin/env -S python3 -u",
        "#!python\r",
    ],
)
def test_extensionless_python_scripts_are_checked(tmp_path: Path, shebang: str) -> None:
    write(tmp_path / "pkg" / "nodes" / "drive", f"{shebang}\n{BUGGY}")
    result = check(tmp_path, root=tmp_path)
    assert result.files == 1
    assert found(result) == [("drive", 3, "RF101")]


def test_a_python2_script_is_a_python2_warning(tmp_path: Path) -> None:
    write(tmp_path / "scripts" / "talker", "#!/usr/bin/env python\nprint 'hello'\n")
    assert found(check(tmp_path, root=tmp_path)) == [("talker", 2, "RF002")]


@pytest.mark.parametrize(
    ("name", "text"),
    [
        ("run", "#!/bin/bash\necho python\n"),
        ("tool", "#!/usr/bin/env pythonista\nx = 1\n"),
        ("notes", "python is used here\n"),
        ("Makefile", "all:\n\tpython x.py\n"),
        ("drive.sh", "#!/usr/bin/env python3\nx = 1\n"),
        (".hidden", "#!/usr/bin/env python3\nx = 1\n"),
        ("blob", "\x00\x01#!/usr/bin/env python3\n"),
        ("empty", ""),
    ],
)
def test_other_files_are_not_checked(tmp_path: Path, name: str, text: str) -> None:
    write(tmp_path / "scripts" / name, text)
    assert discovery.python_files([tmp_path]) == []


@posix
def test_a_fifo_without_extension_is_not_read(tmp_path: Path) -> None:
    os.mkfifo(tmp_path / "node")  # opening it to read would block
    write(tmp_path / "a.py", "x = 1\n")
    assert discovery.python_files([tmp_path]) == [tmp_path / "a.py"]


def test_only_the_head_of_a_file_is_read(tmp_path: Path) -> None:
    big = tmp_path / "big"
    big.write_bytes(b"#!/usr/bin/env python3\n" + b"x" * (fs.MAX_FILE_BYTES + 1))
    assert fs.read_head(big, 10) == b"#!/usr/bin"
    with pytest.raises(fs.UnreadableError):
        fs.read_head(tmp_path, 10)


@settings(max_examples=60, deadline=None)
@given(
    prefix=st.sampled_from(["", "/usr/bin/", "/opt/ros/venv/bin/", "/usr/local/bin/"]),
    env=st.sampled_from(["", "env ", "env -S ", "env -i "]),
    version=st.sampled_from(["", "2", "3", "2.7", "3.12"]),
    space=st.sampled_from(["", " ", "\t"]),
    tail=st.sampled_from(["", " -u", "\r", " -O -W ignore"]),
)
def test_python_shebangs_are_recognised(
    prefix: str, env: str, version: str, space: str, tail: str
) -> None:
    line = f"#!{space}{prefix}{env}python{version}{tail}\nx = 1\n".encode()
    assert discovery._SHEBANG.match(line) is not None
    assert discovery._SHEBANG.match(line.replace(b"python", b"pythonx")) is None


# -- build output, ignore markers, workspace roots ---------------------------------


def colcon_workspace(root: Path) -> Path:
    """src/pkg with a bug, and the copies colcon leaves in build/ and install/."""
    pkg = package(root / "src" / "pkg", "pkg")
    write(pkg / "pkg" / "node.py", BUGGY)
    write(root / "build" / "pkg" / "pkg" / "node.py", BUGGY)
    write(root / "build" / "COLCON_IGNORE", "")
    site = root / "install" / "pkg" / "lib" / "python3.12" / "site-packages"
    write(site / "pkg" / "node.py", BUGGY)
    package(root / "install" / "pkg" / "share" / "pkg", "pkg")
    write(root / "log" / "latest_build" / "pkg" / "stdout.log", "")
    return root


def test_a_workspace_root_checks_src_once(tmp_path: Path) -> None:
    ws = colcon_workspace(tmp_path / "ws")
    write(ws / "install" / "__init__.py", "")  # at a workspace root: still output
    write(ws / "install" / "stray.py", BUGGY)
    result = check(ws, root=ws)
    assert result.files == 1
    assert found(result) == [("node.py", 2, "RF101")]


def test_a_folder_named_on_the_command_line_is_checked(tmp_path: Path) -> None:
    ws = colcon_workspace(tmp_path / "ws")
    result = check(ws, ws / "build", root=ws)
    assert sorted(map(str, discovery.python_files([ws, ws / "build"]))) == [
        str(ws / "build/pkg/pkg/node.py"),
        str(ws / "src/pkg/pkg/node.py"),
    ]
    assert result.files == 2


@pytest.mark.parametrize(
    "folder",
    [
        "build",
        "install",
        "log",
        "devel",
        "dist",
        "venv",
        ".venv",
        "_build",
        "site-packages",
        "__pycache__",
        "node_modules",
        "deep/er/venv",
    ],
)
def test_output_folders_are_skipped(tmp_path: Path, folder: str) -> None:
    write(tmp_path / folder / "lib" / "x.py", BUGGY)
    write(tmp_path / "code.py", "x = 1\n")
    assert discovery.python_files([tmp_path]) == [tmp_path / "code.py"]
    assert discovery.python_files([tmp_path / folder]) == [
        tmp_path / folder / "lib/x.py"
    ]


def test_a_python_package_named_like_output_is_code(tmp_path: Path) -> None:
    write(tmp_path / "robot" / "log" / "__init__.py", "")
    write(tmp_path / "robot" / "log" / "writer.py", BUGGY)
    result = check(tmp_path, root=tmp_path)
    assert found(result) == [("writer.py", 2, "RF101")]


@pytest.mark.parametrize("marker", ["COLCON_IGNORE", "AMENT_IGNORE", "CATKIN_IGNORE"])
def test_folders_with_an_ignore_marker_are_skipped_unless_named(
    tmp_path: Path, marker: str
) -> None:
    src = tmp_path / "src"
    write(src / "wip" / marker, "")
    write(src / "wip" / "pkg" / "node.py", BUGGY)
    write(src / "kept" / "node.py", "x = 1\n")
    assert discovery.python_files([src]) == [src / "kept" / "node.py"]
    # named too, after its parent: the parent's walk does not swallow it
    assert discovery.python_files([src, src / "wip"]) == [
        src / "kept" / "node.py",
        src / "wip" / "pkg" / "node.py",
    ]


def test_exclude_adds_to_the_defaults(tmp_path: Path) -> None:
    write(tmp_path / "venv" / "x.py", BUGGY)
    write(tmp_path / "legacy" / "y.py", BUGGY)
    write(tmp_path / "kept.py", "x = 1\n")
    config = Config(root=tmp_path, exclude=("legacy/",))
    assert discovery.python_files([tmp_path], config) == [tmp_path / "kept.py"]


def test_a_msg_path_at_a_workspace_root_reads_src_only(tmp_path: Path) -> None:
    """The install space's copies of a workspace's .msg files are not read twice."""
    ws = tmp_path / "ws"
    cmd_msg(package(ws / "src" / "my_msgs", "my_msgs"), 1.0)
    ros2_install(ws / "install" / "my_msgs")
    write(ws / "build" / "COLCON_IGNORE", "")
    found_files = discovery.interface_files([ws])
    assert found_files == [ws / "src/my_msgs/msg/Cmd.msg"]


# -- interface files the checked code does not use -----------------------------------


def nav_msgs_like(folder: Path) -> Path:
    """nav2_msgs as shipped: an action names a package that is not here; plus a
    message with a typo in a package that is (not shipped: planted)."""
    pkg = package(folder / "nav2_msgs", "nav2_msgs")
    write(
        pkg / "action" / "FollowGPSWaypoints.action",
        "uint32 number_of_loops\ngeographic_msgs/GeoPose[] gps_poses\n---\n"
        "int16 error_code\n---\nuint32 current_waypoint\n",
    )
    write(pkg / "msg" / "Route.msg", "geometry_msgs/PoseStampd[] poses\nbool loop\n")
    write(
        pkg / "msg" / "Costmap.msg", "float32 resolution  #RobotFix# resolution > 0\n"
    )
    return pkg


def user(module: str, name: str, field: str, value: str) -> str:
    return (
        f"from nav2_msgs.{module} import {name.split('.')[0]}\n"
        "\n"
        "def go() -> None:\n"
        f"    m = {name}()\n"
        f"    m.{field} = {value}\n"
    )


GPS_USER = user("action", "FollowGPSWaypoints.Goal", "number_of_loops", "1")
ROUTE_USER = user("msg", "Route", "loop", "True")
COSTMAP_USER = user("msg", "Costmap", "resolution", "0.05")


def rf504(result: Result) -> list[tuple[str, Severity]]:
    return [
        (Path(d.path).name, d.severity) for d in result.diagnostics if d.code == "RF504"
    ]


@pytest.mark.parametrize("as_msg_path", [False, True])
def test_a_problem_in_an_unused_interface_file_is_a_note(
    tmp_path: Path, as_msg_path: bool
) -> None:
    nav = nav_msgs_like(tmp_path / "vendor")
    pkg = node(tmp_path, COSTMAP_USER)
    paths = [pkg] if as_msg_path else [pkg, nav]
    msg_paths = (nav,) if as_msg_path else ()
    result = check(*paths, root=tmp_path, msg_paths=msg_paths)
    assert found(result) == [
        ("FollowGPSWaypoints.action", 2, "RF504"),
        ("Route.msg", 1, "RF504"),
    ]
    assert rf504(result) == [
        ("FollowGPSWaypoints.action", Severity.NOTE),
        ("Route.msg", Severity.NOTE),
    ]
    assert result.count(Severity.ERROR) == result.count(Severity.WARNING) == 0


@pytest.mark.parametrize(
    ("code", "expected"),
    [
        # a typo in a package that is known: the checked file reads a broken type
        (ROUTE_USER, ("Route.msg", Severity.ERROR)),
        # a package that is nowhere to be found: not checked, not wrong
        (GPS_USER, ("FollowGPSWaypoints.action", Severity.WARNING)),
    ],
)
def test_a_problem_in_a_used_interface_file_counts(
    tmp_path: Path, code: str, expected: tuple[str, Severity]
) -> None:
    nav = nav_msgs_like(tmp_path / "vendor")
    pkg = node(tmp_path, code)
    result = check(pkg, root=tmp_path, msg_paths=(nav,))
    assert expected in rf504(result)
    assert [severity for _, severity in rf504(result)].count(Severity.NOTE) == 1


def test_used_types_count_from_cached_and_parallel_checks(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    nav = nav_msgs_like(tmp_path / "vendor")
    pkg = node(tmp_path, ROUTE_USER)
    for index in range(3):
        write(pkg / "drive" / f"other{index}.py", COSTMAP_USER)
    config = Config(root=tmp_path, msg_paths=(nav,))
    monkeypatch.setattr(run, "MIN_PARALLEL", 1)
    parallel = check_paths([pkg], config, jobs=2, use_cache=True)
    cached = check_paths([pkg], config, jobs=2, use_cache=True)
    assert cached.from_cache == 4
    assert rf504(parallel) == rf504(cached)
    assert ("Route.msg", Severity.ERROR) in rf504(cached)


def cli(*args: str, cwd: Path, **env: str) -> subprocess.CompletedProcess[str]:
    environ = {k: v for k, v in os.environ.items() if k not in ROS_VARIABLES}
    return subprocess.run(
        [sys.executable, "-m", "robotfix", *args],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=120,
        env={**environ, **env},
    )


def test_an_unused_interface_file_cannot_fail_the_run(tmp_path: Path) -> None:
    nav = nav_msgs_like(tmp_path / "vendor")
    node(tmp_path, COSTMAP_USER)
    for extra in ([], ["--strict"]):
        result = cli("check", "ws", "--msg-path", str(nav), *extra, cwd=tmp_path)
        assert result.returncode == 0, result.stdout + result.stderr
        assert "note[RF504]: unknown message type `geographic_msgs/GeoPose`" in (
            result.stdout
        )
        assert "no interface files of geographic_msgs were found" in result.stdout
    node(tmp_path, GPS_USER)
    result = cli("check", "ws", "--msg-path", str(nav), cwd=tmp_path)
    assert result.returncode == 0
    assert "warning[RF504]" in result.stdout
    result = cli("check", "ws", "--msg-path", str(nav), "--strict", cwd=tmp_path)
    assert result.returncode == 1
    node(tmp_path, ROUTE_USER)
    result = cli("check", "ws", "--msg-path", str(nav), cwd=tmp_path)
    assert result.returncode == 1
    assert "error[RF504]: unknown message type `geometry_msgs/PoseStampd`" in (
        result.stdout
    )


def test_the_cli_finds_a_sourced_install_space(tmp_path: Path) -> None:
    node(tmp_path, USES_CMD.format(speed=2.0))
    install = ros2_install(tmp_path / "install")
    assert cli("check", "ws", cwd=tmp_path).returncode == 0
    result = cli("check", "ws", cwd=tmp_path, AMENT_PREFIX_PATH=str(install))
    assert result.returncode == 1
    assert "error[RF101]" in result.stdout


def test_a_catalog_without_an_install_space_is_unchanged(tmp_path: Path) -> None:
    catalog = MsgCatalog([cmd_msg(package(tmp_path / "my_msgs", "my_msgs"), 1.0)])
    assert catalog.lookup("my_msgs/Cmd") is not None
    assert catalog.lookup("my_msgs/Absent") is None
    assert catalog.types_in(str(tmp_path / "my_msgs/msg/Cmd.msg")) == ("my_msgs/Cmd",)


def test_interface_problem_levels_are_the_same_with_workers(tmp_path: Path) -> None:
    """With -j the main process loads its catalog only for the interface problems:
    their levels (a missing package is a warning) must not depend on that."""
    pkg = package(tmp_path / "nav_like", "nav_like")
    write(pkg / "action" / "Go.action", "geographic_msgs/GeoPose[] poses\n---\n---\n")
    for index in range(40):  # enough files for a worker pool
        write(pkg / "nav_like" / f"m{index}.py", "from nav_like.action import Go\n")
    levels = {
        jobs: [
            (d.code, d.severity.value)
            for d in check_paths([pkg], Config(root=tmp_path), jobs=jobs).diagnostics
        ]
        for jobs in (1, 2)
    }
    assert levels[1] == levels[2] == [("RF504", "warning")]


def test_a_standard_package_type_of_a_newer_distribution_is_a_warning(
    tmp_path: Path,
) -> None:
    """nav2 names nav_msgs/Goals, newer than the bundled definitions: not a typo
    (nothing in nav_msgs is spelled like it), so a warning; PoseStampd stays one."""
    pkg = package(tmp_path / "nav_like", "nav_like")
    write(
        pkg / "msg" / "Plan.msg", "nav_msgs/Goals goals\ngeometry_msgs/PoseStampd p\n"
    )
    write(pkg / "nav_like" / "node.py", "from nav_like.msg import Plan\n")
    levels = [
        (d.span.line, d.severity.value)
        for d in check(pkg, root=tmp_path).diagnostics
        if d.code == "RF504"
    ]
    assert levels == [(1, "warning"), (2, "error")]
