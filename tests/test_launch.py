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
    marker = tmp_path / "ran"  # the launch file's own first line would make it
    outer = write(
        pkg / "launch" / "outer.launch.py",
        f"""
import os
open({str(marker)!r}, 'w')
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node, PushRosNamespace

def generate_launch_description():
    share = get_package_share_directory('demo')
    inner = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(share, 'launch', 'inner.launch.py')),
        launch_arguments={{'who': 'passed'}}.items())
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
    assert not marker.exists()
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


# -- launch values typed as parameter files are (the merge of fix/yaml) -----------

RACER_NODE = """from rclpy.node import Node


class Racer(Node):
    def __init__(self):
        super().__init__("racer")
        self.declare_parameter("max_speed", 1.0)
        self.declare_parameter("count", 1)
"""


def racer(root: Path) -> Path:
    """A package whose node `racer` declares the double `max_speed` and the
    integer `count`, started by `ros2 run racer racer`."""
    pkg = package(root, "racer")
    write(
        pkg / "setup.py",
        "from setuptools import setup\nsetup(name='racer', entry_points="
        "{'console_scripts': ['racer = racer.node:main']})\n",
    )
    write(pkg / "racer" / "__init__.py", "")
    write(pkg / "racer" / "node.py", RACER_NODE)
    return pkg


def test_huge_numbers_and_nested_lists_in_launch_values_are_rf401(
    tmp_path: Path,
) -> None:
    """An inline launch value is typed as rcl reads the parameter file launch
    writes of it (PyYAML's value, `yaml.dump`ed): `1e999` is a string (strtod:
    ERANGE), an integer beyond int64 a double, with the note a parameter file
    gets; a list of lists is refused by launch. Each is RF401 at its launch line,
    as in a YAML file, in Python, YAML and XML launch files. Before the merge a
    huge integer was an integer (silent) and `[[1.0]]` no value at all."""
    pkg = racer(tmp_path)
    write(
        pkg / "launch" / "racer.launch.py",
        """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="racer", executable="racer", parameters=[{
            "max_speed": "1e999",
        }]),
        Node(package="racer", executable="racer", parameters=[{
            "max_speed": [[1.0]],
            "count": 100000000000000000000,
        }]),
        Node(package="racer", executable="racer", parameters=[{
            "max_speed": 2.0, "count": 3,
        }]),
    ])
""",
    )
    write(
        pkg / "launch" / "racer.launch.yaml",
        "launch:\n- node:\n    pkg: racer\n    exec: racer\n    param:\n"
        "    - {name: max_speed, value: 1e999}\n"
        "    - {name: count, value: 99999999999999999999}\n"
        "- node:\n    pkg: racer\n    exec: racer\n    param:\n"
        "    - {name: max_speed, value: [[1.0]]}\n"
        f"    - {{name: count, value: {'9' * 5000}}}\n",
    )
    write(
        pkg / "launch" / "racer.launch.xml",
        '<launch>\n  <node pkg="racer" exec="racer">\n'
        '    <param name="max_speed" value="[[1.0]]"/>\n'
        '    <param name="count" value="1e999"/>\n'
        '    <param name="count" value="7"/>\n'
        "  </node>\n</launch>\n",
    )
    write(
        pkg / "config" / "racer.yaml",
        "racer:\n  ros__parameters:\n    max_speed: 1e999\n",
    )
    found = check_paths([pkg], Config(root=tmp_path)).diagnostics
    at = sorted((Path(d.path).name, d.span.line, d.code) for d in found)
    assert at == [
        ("racer.launch.py", 8, "RF401"),
        ("racer.launch.py", 11, "RF401"),
        ("racer.launch.py", 12, "RF401"),
        ("racer.launch.xml", 3, "RF401"),
        ("racer.launch.xml", 4, "RF401"),
        ("racer.launch.yaml", 6, "RF401"),
        ("racer.launch.yaml", 7, "RF401"),
        ("racer.launch.yaml", 12, "RF401"),
        ("racer.launch.yaml", 13, "RF004"),  # PyYAML refuses it: launch fails
        ("racer.yaml", 3, "RF401"),
    ]
    notes = {
        (Path(d.path).name, d.span.line): [n.message for n in d.notes] for d in found
    }
    erange = "rcl reads `1e999` as a string: it overflows a double (strtod: ERANGE)"
    for where in [("racer.yaml", 3), ("racer.launch.py", 8), ("racer.launch.yaml", 6)]:
        assert erange in notes[where], where
    assert any("beyond a 64-bit integer" in n for n in notes["racer.launch.py", 12])
    assert any(
        "launch refuses a list of lists" in n for n in notes["racer.launch.xml", 3]
    )
    messages = {(Path(d.path).name, d.span.line): d.message for d in found}
    assert (
        "is a double, but the parameter is declared an integer"
        in messages["racer.launch.yaml", 7]
    )
    assert "launch cannot load" in messages["racer.launch.yaml", 13]
    # a Python integer launch cannot write (`0x` and 5,000 hex digits): not checked
    from robotfix.ros import paramfile
    from robotfix.ros.launch import values

    written = values.from_python(1 << 20_000)
    assert not isinstance(written, paramfile.Typed) or written.type == "string"


def test_a_fault_on_one_launch_file_is_its_internal_error(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """As for a parameter file: a fault of ours while a launch file is read or
    its entries checked is an internal error of that file; the other launch
    files are checked, and nothing is cached."""
    from robotfix import launchcheck
    from robotfix.ros.launch import reader

    pkg = racer(tmp_path)
    good = (
        "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n"
        "def generate_launch_description():\n    return LaunchDescription([Node(\n"
        "        package='racer', executable='racer', parameters=[{'count': 2.5}])])\n"
    )
    for name in ("good", "bad_read", "bad_check"):
        write(pkg / "launch" / f"{name}.launch.py", good)
    parse, entry = reader._parse, launchcheck._ros2_entry

    def parse_fails(path: Path, *args: object) -> object:
        if path.name == "bad_read.launch.py":
            raise ValueError("read boom")
        return parse(path, *args)  # type: ignore[arg-type]

    def check_fails(found: object, *args: object) -> object:
        if found.place.path.endswith("bad_check.launch.py"):  # type: ignore[attr-defined]
            raise ValueError("check boom")
        return entry(found, *args)  # type: ignore[arg-type]

    monkeypatch.setattr(reader, "_parse", parse_fails)
    monkeypatch.setattr(launchcheck, "_ros2_entry", check_fails)
    for _ in range(2):  # the second run: nothing was cached
        result = check_paths([pkg], Config(root=tmp_path), use_cache=True)
        assert sorted(
            (Path(e.path).name, e.summary) for e in result.internal_errors
        ) == [
            ("bad_check.launch.py", "ValueError: check boom"),
            ("bad_read.launch.py", "ValueError: read boom"),
        ]
        assert [(Path(d.path).name, d.code) for d in result.diagnostics] == [
            ("good.launch.py", "RF401")
        ]


def test_a_python_launch_file_is_checked_as_python_too(tmp_path: Path) -> None:
    """A launch file is Python code as well: its own bugs (here RF301, as in
    nav2_common's ReplaceString, whose `finally` closes a file `open` may not have
    made) are reported. When launch files came, the Python walk dropped every file
    of a `launch/` folder, and a tree of navigation2 checked 56 files of 108."""
    launch = tmp_path / "pkg" / "launch"
    launch.mkdir(parents=True)
    (tmp_path / "pkg" / "package.xml").write_text("<package><name>pkg</name></package>")
    (launch / "replace_string.py").write_text(
        "def perform(name):\n"
        "    try:\n"
        "        src = open(name)\n"
        "        text = src.read()\n"
        "    except OSError:\n"
        "        text = ''\n"
        "    finally:\n"
        "        src.close()\n"
        "    return text\n"
    )
    (launch / "bringup.launch.py").write_text(
        "from launch import LaunchDescription\n\n\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([])\n"
    )
    result = check_paths([tmp_path / "pkg"], Config(root=tmp_path))
    found = [(Path(d.path).name, d.code, d.span.line) for d in result.diagnostics]
    assert found == [("replace_string.py", "RF301", 8)]
    assert result.files == 2


@pytest.mark.parametrize(
    "imports",
    [
        "from racer import node",  # a submodule named in `from pkg import`
        "from . import node",
        "from .node import Racer",
        "from ..racer.node import Racer",  # two levels up, then down
    ],
)
def test_an_entry_point_finds_its_node_class_however_it_imports_it(
    tmp_path: Path, imports: str
) -> None:
    """The entry point `racer.main:main` declares nothing; the node class it
    imports does, so the launch value is checked against it (RF401 for a string
    where `max_speed` is a double) whichever way the import is written."""
    pkg = racer(tmp_path)
    write(
        pkg / "setup.py",
        "from setuptools import setup\nsetup(name='racer', entry_points="
        "{'console_scripts': ['racer = racer.main:main']})\n",
    )
    write(pkg / "racer" / "main.py", f"{imports}\n\ndef main():\n    pass\n")
    write(
        pkg / "launch" / "r.launch.py",
        "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n"
        "def generate_launch_description():\n    return LaunchDescription([Node(\n"
        "        package='racer', executable='racer',\n"
        "        parameters=[{'max_speed': 'fast'}])])\n",
    )
    found = check_paths([pkg], Config(root=tmp_path)).diagnostics
    assert [(d.code, d.span.line) for d in found if d.path.endswith(".launch.py")] == [
        ("RF401", 7)
    ]


def test_a_launch_files_suppressions_are_judged_by_the_check_that_owns_them(
    tmp_path: Path,
) -> None:
    """In a Python launch file, an `ignore` of a rule only the file's own check
    reports (RF201) that silences nothing is RF010, as in any file; one of the
    launch check's rules (RF401 on a launch value), or a bare one, is left to the
    launch check. Every suppression of a launch file was passed over before."""
    pkg = racer(tmp_path)
    write(
        pkg / "launch" / "r.launch.py",
        "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n"
        "def generate_launch_description():\n"
        "    period = 0.5  # robotfix: ignore[RF201]\n"
        "    return LaunchDescription([Node(\n"
        "        package='racer', executable='racer',\n"
        "        parameters=[{'max_speed': 'fast'}])])  # robotfix: ignore[RF401]\n",
    )
    found = check_paths([pkg], Config(root=tmp_path)).diagnostics
    assert [(d.code, d.span.line) for d in found if d.path.endswith(".launch.py")] == [
        ("RF010", 5)
    ]


# a launch file that names racer's parameter files in its share folder, as real ones do
SHARE_LAUNCH = (
    "import os\nfrom ament_index_python.packages import get_package_share_directory\n"
    "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n"
    "def generate_launch_description():\n"
    "    share = get_package_share_directory('racer')\n"
)


@pytest.mark.parametrize(
    ("names", "keys", "warned"),
    [
        # f1tenth's bridge renamed again: its `bridge:` file applies to nothing
        (["sim_bridge"], ["bridge"], [8]),
        # the node's own name as the key, renamed away by the launch file
        (["sim_bridge"], ["racer"], [8]),
        (["bridge"], ["bridge"], []),  # the section follows the rename
        (["sim_bridge"], ["/**"], []),  # a wildcard serves every node
        (["sim_bridge"], ["sim_bridge", "bridge"], []),
        # one file for two entries: it configures one of them
        (["sim_bridge", "racer"], ["racer"], []),
        (["sim_bridge", "fast_racer"], ["racer"], [8, 10]),
        ([None], ["racer"], []),  # a node the entry does not name: not judged
    ],
)
def test_a_parameter_file_that_gives_its_nodes_nothing_is_a_warning(
    tmp_path: Path, names: list[str | None], keys: list[str], warned: list[int]
) -> None:
    """Launch entries that pass a parameter file none of whose sections applies
    to any node they start get RF602 as a warning each: the nodes silently run
    with their defaults (fresh-eyes round w01: only the file's RF602 note said
    anything, and the run passed)."""
    pkg = racer(tmp_path)
    write(
        pkg / "config" / "sim.yaml",
        "".join(f"{k}:\n  ros__parameters:\n    max_speed: 0.5\n" for k in keys),
    )
    entries = "".join(
        f"        Node(package='racer', executable='racer'"
        f"{f', name={name!r}' if name else ''},\n"
        "             parameters=[os.path.join(share, 'config', 'sim.yaml')]),\n"
        for name in names
    )
    write(
        pkg / "launch" / "racer.launch.py",
        SHARE_LAUNCH + "    return LaunchDescription([\n" + entries + "    ])\n",
    )
    found = check_paths([pkg], Config(root=tmp_path)).diagnostics
    lines = [
        d.span.line for d in found if d.code == "RF602" and d.severity.name == "WARNING"
    ]
    assert lines == warned


def test_a_cached_run_judges_a_passed_file_again_when_the_namespace_changes(
    tmp_path: Path,
) -> None:
    """RF602's warning at an entry is kept with the parameter files' part of the
    cache: a namespace changed in the launch file (names and files the same)
    makes it judged again."""
    pkg = racer(tmp_path)
    write(
        pkg / "config" / "fleet.yaml",
        "/robot2/racer:\n  ros__parameters:\n    max_speed: 0.5\n",
    )
    launch = write(
        pkg / "launch" / "racer.launch.py",
        SHARE_LAUNCH + "    return LaunchDescription([\n"
        "        Node(package='racer', executable='racer', name='racer',\n"
        "             namespace='robot1',\n"
        "             parameters=[os.path.join(share, 'config', 'fleet.yaml')]),\n"
        "    ])\n",
    )
    config = Config(root=tmp_path)

    def warned() -> bool:
        found = check_paths([pkg], config, use_cache=True).diagnostics
        return any(d.code == "RF602" and d.severity.name == "WARNING" for d in found)

    assert warned() and warned()
    launch.write_text(launch.read_text().replace("'robot1'", "'robot2'"))
    assert not warned()


def test_the_entries_passing_parameter_files_are_looked_at_once_for_all_files(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """RF602 at an entry asks which entries pass each ROS 2 parameter file: each
    entry's parameters were read again for every file (27 x 1,500 on corpus25);
    now as often with six files as with one."""
    from robotfix import launchcheck

    reads: list[int] = []

    class Counted(list):  # type: ignore[type-arg]
        def __iter__(self):  # type: ignore[no-untyped-def]
            reads.append(1)
            return super().__iter__()

    add = launchcheck.LaunchRun._add

    def counting(self: launchcheck.LaunchRun, started: object) -> None:
        entry = started.entry  # type: ignore[attr-defined]
        entry.parameters = Counted(entry.parameters)
        add(self, started)  # type: ignore[arg-type]

    monkeypatch.setattr(launchcheck.LaunchRun, "_add", counting)

    def run(files: int) -> int:
        root = tmp_path / str(files)
        pkg = racer(root)
        for i in range(files):
            text = "racer:\n  ros__parameters:\n    max_speed: 0.5\n"
            write(pkg / "config" / f"p{i}.yaml", text)
        passed = ", ".join(
            f"os.path.join(share, 'config', 'p{i}.yaml')" for i in range(files)
        )
        entries = "".join(
            f"        Node(package='racer', executable='racer', name='n{n}',\n"
            f"             parameters=[{passed}]),\n"
            for n in range(4)
        )
        write(
            pkg / "launch" / "racer.launch.py",
            SHARE_LAUNCH + "    return LaunchDescription([\n" + entries + "    ])\n",
        )
        reads.clear()
        found = check_paths([pkg], Config(root=root)).diagnostics
        assert sum(d.code == "RF602" and d.severity.name == "WARNING" for d in found)
        return len(reads)

    assert run(6) == run(1)
