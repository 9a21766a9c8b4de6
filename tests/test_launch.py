"""Launch files (issue 23, section 1): the small workspaces under tests/cases/launch/
(modelled on f1tenth_gym_ros, ros2/demos and ros_tutorials) with inline
expectations in their launch, YAML and Python files (strict: every diagnostic of
the run), the readers on their own, hostile launch files, and the cache."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from robotfix.api import check_paths
from robotfix.config import Config
from robotfix.ros.launch.model import FileParam, InlineParam
from robotfix.ros.launch.reader import Reader
from robotfix.testing.expectations import compare_files

CASES = Path(__file__).parent / "cases" / "launch"
SUFFIXES = (".py", ".yaml", ".yml", ".xml", ".launch")


def files_of(package: Path) -> list[Path]:
    return sorted(p for p in package.rglob("*") if p.name.endswith(SUFFIXES))


@pytest.mark.parametrize(
    "package", sorted(p for p in CASES.iterdir() if p.is_dir()), ids=lambda p: p.name
)
def test_launch_files_of_a_package(package: Path) -> None:
    found = check_paths([package], Config(root=package.parent)).diagnostics
    problems = compare_files(files_of(package), found)
    assert not problems, "\n".join(problems)


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


def package(root: Path, name: str) -> Path:
    write(root / name / "package.xml", f"<package><name>{name}</name></package>")
    return root / name


def test_python_launch_file_entries(tmp_path: Path) -> None:
    """Names through variables, launch arguments' defaults and what an includer
    passes, GroupAction namespaces, package share paths; never run."""
    pkg = package(tmp_path, "demo")
    write(pkg / "config" / "a.yaml", "x: {ros__parameters: {}}\n")
    write(
        pkg / "launch" / "inner.launch.py",
        """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('who', default_value='inner_default'),
        Node(package='demo', executable='talker', name=LaunchConfiguration('who'),
             parameters=[{'rate': LaunchConfiguration('who'), 'group': {'gain': 2}}]),
    ])
""",
    )
    outer = write(
        pkg / "launch" / "outer.launch.py",
        """
import os
open('/tmp/robotfix-launch-ran', 'w')
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node, PushRosNamespace

def generate_launch_description():
    share = get_package_share_directory('demo')
    inner = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(share, 'launch', 'inner.launch.py')),
        launch_arguments={'who': 'passed'}.items())
    return LaunchDescription([GroupAction([
        PushRosNamespace('robot1'),
        Node(package='demo', executable='listener', namespace='arm',
             parameters=[os.path.join(share, 'config', 'a.yaml'), 'relative.yaml'],
             remappings=[('chatter', '/talk')]),
        inner,
    ])])
""",
    )
    found = Reader({"demo": pkg}.get).read(outer)
    assert not Path("/tmp/robotfix-launch-ran").exists()
    by_exe = {e.executable: e for e in found.entries}
    listener, talker = by_exe["listener"], by_exe["talker"]
    assert listener.namespace == "/robot1/arm"
    assert [(r.source, r.target) for r in listener.remappings] == [("chatter", "/talk")]
    files = [p for p in listener.parameters if isinstance(p, FileParam)]
    assert [f.path for f in files] == [str(pkg / "config" / "a.yaml"), None]
    assert talker.name == "passed" and talker.namespace == "/robot1"
    inline = {p.name: p for p in talker.parameters if isinstance(p, InlineParam)}
    assert inline["rate"].value is None  # a launch argument: set at launch
    assert inline["group.gain"].value is not None
    assert inline["group.gain"].value.type == "integer"
    alone = Reader({"demo": pkg}.get).read(pkg / "launch" / "inner.launch.py")
    assert alone.entries[0].name == "inner_default"


def test_ros1_and_yaml_launch_entries(tmp_path: Path) -> None:
    pkg = package(tmp_path, "demo")
    ros1 = write(
        pkg / "launch" / "a.launch",
        """<launch>
  <arg name="veh" default="duckie"/>
  <group ns="$(arg veh)">
    <node pkg="demo" type="node.py" name="$(arg veh)_node" ns="sub">
      <param name="rate" value="10"/><param name="ok" value="True"/>
      <param name="t" type="str" value="5"/><param name="e" value="$(env X)"/>
      <remap from="in" to="out"/>
    </node>
  </group>
  <param name="global_p" value="1.5"/>
</launch>""",
    )
    found = Reader({"demo": pkg}.get).read(ros1)
    (entry,) = found.entries
    assert (entry.ros, entry.name, entry.namespace) == (1, "duckie_node", "/duckie/sub")
    values = {p.name: p.value for p in entry.parameters if isinstance(p, InlineParam)}
    assert values["rate"] is not None and values["rate"].type == "integer"
    assert values["ok"] is not None and values["ok"].type == "bool"
    assert values["t"] is not None and values["t"].type == "string"
    assert values["e"] is None
    assert [p.name for p in found.global_params] == ["global_p"]
    yaml_launch = write(
        pkg / "launch" / "b.launch.yaml",
        "launch:\n- node:\n    pkg: demo\n    exec: n\n    namespace: ns\n"
        "    param:\n    - {name: a, value: [1.0, 2.0]}\n    - {name: b, value: 'x'}\n",
    )
    (entry,) = Reader({"demo": pkg}.get).read(yaml_launch).entries
    values = {p.name: p.value for p in entry.parameters if isinstance(p, InlineParam)}
    assert entry.namespace == "/ns"
    assert values["a"] is not None and values["a"].type == "double_array"
    assert values["b"] is not None and values["b"].type == "string"


@pytest.mark.parametrize(
    "text",
    [
        '<?xml version="1.0"?><!DOCTYPE l [<!ENTITY a "aaaaaaaa"><!ENTITY b '
        '"&a;&a;&a;&a;&a;&a;&a;&a;">]><launch><node pkg="p" type="&b;"/></launch>',
        "<launch><node pkg='p'",
        "<launch>" + "<group>" * 500 + "</group>" * 500 + "</launch>",
        "\xff\xfe not text",
    ],
    ids=["entities", "truncated", "deep", "bytes"],
)
def test_hostile_launch_files_are_rf004_warnings(tmp_path: Path, text: str) -> None:
    pkg = package(tmp_path, "p")
    path = pkg / "launch" / "bad.launch"
    path.parent.mkdir(parents=True)
    path.write_bytes(
        text.encode("utf-8", "surrogateescape") if "\xff" not in text else b"\xff\xfe<x"
    )
    write(pkg / "nodes" / "n.py", "import rospy\n")
    found = check_paths([pkg], Config(root=tmp_path)).diagnostics
    assert [(d.code, d.path) for d in found] == [("RF004", str(path))]


def test_a_cached_run_sees_an_edited_launch_file(tmp_path: Path) -> None:
    """The launch files join the parameter check's cache key."""
    pkg = tmp_path / "gym_bridge"
    shutil.copytree(CASES / "gym_bridge", pkg)
    config = Config(root=tmp_path)

    def codes() -> list[tuple[str, int]]:
        result = check_paths([pkg], config, use_cache=True).diagnostics
        return sorted((d.code, d.span.line) for d in result if "launch" in d.path)

    first = codes()
    assert ("RF101", 22) in first and codes() == first
    launch = pkg / "launch" / "gym_bridge_launch.py"
    launch.write_text(launch.read_text().replace('"scan_fov": 7.0', '"scan_fov": 1.0'))
    assert ("RF101", 22) not in codes()
