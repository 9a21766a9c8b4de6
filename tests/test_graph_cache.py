"""The launch files' reading and the graph's findings kept in the result cache
(issue 23, speed): a cached run over an unchanged tree reads no launch file and
checks no graph, and each edit they depend on makes the next run see it. Each
test edits one file so that the findings change, and compares the cached run
with a run without the cache (a stale cache would give the old findings)."""

from __future__ import annotations

import json
import os
import time
from pathlib import Path

import pytest

import robotfix.cache
import robotfix.discovery
import robotfix.fs
import robotfix.ros.graph.cpp
import robotfix.run
from robotfix.api import check_paths
from robotfix.config import Config

TALKER = """import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Talker(Node):
    def __init__(self):
        super().__init__("talker")
        self.declare_parameter("rate", 1.0)
        self.pub = self.create_publisher(String, "chatter", 10)


def main():
    rclpy.init()
    rclpy.spin(Talker())
"""

LISTENER = """import rclpy
from rclpy.node import Node
from std_msgs.msg import Int32


class Listener(Node):
    def __init__(self):
        super().__init__("listener")
        self.declare_parameter("gain", 1.0)
        self.create_subscription(Int32, "numbers", self.on_number, 10)

    def on_number(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Listener())
"""

MONITOR = LISTENER.replace("Listener", "Monitor").replace('"listener"', '"monitor"')

SETUP = """from setuptools import setup

setup(
    name="demo",
    entry_points={
        "console_scripts": [
            "talker = demo.talker:main",
            "listener = demo.listener:main",
        ],
    },
)
"""

OUTER = """import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node


def generate_launch_description():
    share = get_package_share_directory("demo")
    return LaunchDescription([
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(
                os.path.join(share, "launch", "inner.launch.py")
            )
        ),
        Node(
            package="demo",
            executable="talker",
            name="talker",
            parameters=[{"rate": 2.0}, os.path.join(share, "settings", "talker.yaml")],
        ),
    ])
"""

INNER = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(
            package="demo",
            executable="listener",
            name="listener",
            remappings=[("numbers", "numbers")],
        ),
    ])
"""

PARAMS = "talker:\n  ros__parameters:\n    rate: 5.0\n"


@pytest.fixture()
def workspace(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A package whose launch file starts a talker and (through an included
    launch file) a listener; no stamp is too recent to trust (every edit below
    changes a file's size)."""
    for module in (robotfix.cache, robotfix.discovery, robotfix.run):
        monkeypatch.setattr(module, "RACY_NS", 0)
    pkg = tmp_path / "src" / "demo"
    files = {
        "package.xml": "<package><name>demo</name></package>",
        "setup.py": SETUP,
        "demo/__init__.py": "",
        "demo/talker.py": TALKER,
        "demo/listener.py": LISTENER,
        "demo/monitor.py": MONITOR,  # no launch file starts it
        "launch/demo.launch.py": OUTER,
        "launch/inner.launch.py": INNER,
        "settings/talker.yaml": PARAMS,
    }
    for name, text in files.items():
        (pkg / name).parent.mkdir(parents=True, exist_ok=True)
        (pkg / name).write_text(text, encoding="utf-8")
    return tmp_path


def run(root: Path, cache: bool) -> list[str]:
    config = Config(root=root, cache_dir=root / "cache")
    found = check_paths([root / "src"], config, use_cache=cache).diagnostics
    return [f"{d.path}:{d.span.line}: {d.code} {d.message}" for d in found]


def edit(path: Path, old: str, new: str) -> None:
    text = path.read_text(encoding="utf-8")
    assert old in text
    path.write_text(text.replace(old, new), encoding="utf-8")


def settled(root: Path) -> list[str]:
    """Two cached runs (the second from what the first kept) agree with a run
    without the cache; the findings."""
    fresh = run(root, cache=False)
    assert run(root, cache=True) == fresh
    assert run(root, cache=True) == fresh
    return fresh


def finds_after(
    root: Path, file: str, old: str, new: str, code: str, where: str
) -> None:
    """No `code` finding in a file named `where` before the edit, one after."""
    before = settled(root)
    assert not any(code in line and where in line for line in before)
    edit(root / file, old, new)
    assert any(code in line and where in line for line in settled(root))


def counting_parses(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """The names of the launch files parsed from now on."""
    import robotfix.ros.launch.reader as reader

    parsed: list[str] = []
    real = reader._parse
    monkeypatch.setattr(
        reader, "_parse", lambda path, *a: parsed.append(path.name) or real(path, *a)
    )
    return parsed


def one_more_launch_file(
    root: Path, monkeypatch: pytest.MonkeyPatch, name: str, text: str
) -> tuple[Path, list[str]]:
    """`<name>.launch.py` beside the others, the runs settled; the launch folder
    and the names of the launch files parsed from then on."""
    launch = root / "src/demo/launch"
    (launch / f"{name}.launch.py").write_text(text, encoding="utf-8")
    settled(root)
    return launch, counting_parses(monkeypatch)


def counting_readings(monkeypatch: pytest.MonkeyPatch) -> list[object]:
    """Each reading of the run's launch files (`run._launches`) from now on."""
    read: list[object] = []
    real = robotfix.run._launches
    monkeypatch.setattr(
        robotfix.run, "_launches", lambda *a: read.append(a) or real(*a)
    )
    return read


def test_an_unchanged_tree_reads_no_launch_file(
    workspace: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Not even when a folder above the workspace changed: a file outside any
    package makes `package.xml` be looked for up to `/`, and those answers are
    kept as they are, not as the stamps of those folders."""
    (workspace / "src/tool.py").write_text(LISTENER, encoding="utf-8")
    before = settled(workspace)
    (workspace.parent / f"{workspace.name}.tmp").write_text("", encoding="utf-8")
    (workspace.parent / f"{workspace.name}.tmp").unlink()
    read = counting_readings(monkeypatch)
    graphed: list[object] = []
    real_graph = robotfix.run._graph_problems
    monkeypatch.setattr(
        robotfix.run,
        "_graph_problems",
        lambda *a: graphed.append(a) or real_graph(*a),
    )
    assert run(workspace, cache=True) == before
    assert not read and not graphed


def test_an_edited_launch_file_is_read_again(workspace: Path) -> None:
    """A remapping in the launch file that makes the talker's `chatter` the
    listener's `numbers`: RF603 (String and Int32 on one topic)."""
    finds_after(
        workspace,
        "src/demo/launch/demo.launch.py",
        'name="talker",',
        'name="talker",\n            remappings=[("chatter", "numbers")],',
        "RF603",
        "",
    )


def test_an_edited_included_launch_file_is_read_again(workspace: Path) -> None:
    """The same remapping made in the included file, on the listener's side."""
    finds_after(
        workspace,
        "src/demo/launch/inner.launch.py",
        '("numbers", "numbers")',
        '("numbers", "chatter")',
        "RF603",
        "",
    )


def test_an_edited_parameter_file_is_checked_again(workspace: Path) -> None:
    """A parameter the talker does not declare, in the section of the file its
    launch entry names (in no folder discovery takes parameter files from: only
    the launch file leads to it): RF601."""
    finds_after(
        workspace,
        "src/demo/settings/talker.yaml",
        "rate: 5.0",
        "rate: 5.0\n    rte: 1",
        "RF601",
        "talker.yaml",
    )


def test_an_edited_node_is_checked_again(workspace: Path) -> None:
    """The node's declarations (the launch entry's inline `rate` no longer
    declared: RF601) and its endpoints (it publishes Int32 on `numbers` then,
    the listener's topic: the notes of a topic published nowhere go)."""
    before = settled(workspace)
    edit(
        workspace / "src/demo/demo/talker.py",
        'self.declare_parameter("rate", 1.0)',
        'self.declare_parameter("speed", 1.0)',
    )
    declared = settled(workspace)
    assert any("RF601" in line and "demo.launch.py" in line for line in declared)
    edit(
        workspace / "src/demo/demo/talker.py", '(String, "chatter"', '(Int32, "numbers"'
    )
    edit(workspace / "src/demo/demo/talker.py", "import String", "import Int32")
    moved = settled(workspace)
    assert [x for x in before if "RF60" in x] != [x for x in moved if "RF60" in x]


def test_an_edited_node_no_launch_file_starts_is_seen(workspace: Path) -> None:
    """Code the launch files' reading never reads: its endpoints are part of the
    graph's key (the monitor takes `chatter`, which the talker publishes as
    String, as Int32: RF603)."""
    monitor = "src/demo/demo/monitor.py"
    finds_after(workspace, monitor, '"numbers"', '"chatter"', "RF603", "")


def test_an_included_file_given_other_arguments_is_checked_again(
    workspace: Path,
) -> None:
    """The included file's bytes stay, what its includer passes changes: the
    name its node gets, so another section of the parameter file it names
    applies (an undeclared `volume` in `ears:`: RF601 while the listener is
    named `ears`)."""
    pkg = workspace / "src/demo"
    (pkg / "config").mkdir()
    (pkg / "config/ears.yaml").write_text(
        "ears:\n  ros__parameters:\n    volume: 3\n", encoding="utf-8"
    )
    inner = (
        INNER.replace(
            "from launch_ros.actions import Node",
            "from launch.actions import DeclareLaunchArgument\n"
            "from launch.substitutions import LaunchConfiguration\n"
            "from launch_ros.actions import Node\n"
            "from ament_index_python.packages import get_package_share_directory\n"
            "import os",
        )
        .replace(
            "    return LaunchDescription([\n",
            "    share = get_package_share_directory('demo')\n"
            "    return LaunchDescription([\n"
            "        DeclareLaunchArgument('who', default_value='mouth'),\n",
        )
        .replace(
            'name="listener",',
            'name=LaunchConfiguration("who"),\n'
            '            parameters=[os.path.join(share, "config", "ears.yaml")],',
        )
    )
    (pkg / "launch/inner.launch.py").write_text(inner, encoding="utf-8")
    edit(
        pkg / "launch/demo.launch.py",
        '"inner.launch.py")\n            )',
        '"inner.launch.py")\n            ),\n'
        '            launch_arguments={"who": "ears"}.items()',
    )
    before = settled(workspace)
    assert any("RF601" in line and "ears.yaml" in line for line in before)
    edit(pkg / "launch/demo.launch.py", '"who": "ears"', '"who": "mouths"')
    after = settled(workspace)
    assert not any("RF601" in line and "ears.yaml" in line for line in after)


def test_an_edited_launch_file_summarises_only_the_code_it_starts(
    workspace: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A value changed in one launch entry: the parameter files' findings and
    the other launch files' are kept, only the talker's code is summarised."""
    settled(workspace)
    import robotfix.paramcheck

    summarised: list[str] = []
    real = robotfix.paramcheck.summarize
    monkeypatch.setattr(
        robotfix.paramcheck,
        "summarize",
        lambda source, **kw: summarised.append(source.path) or real(source, **kw),
    )
    edit(workspace / "src/demo/launch/demo.launch.py", '"rate": 2.0', '"rate": 3.0')
    found = run(workspace, cache=True)
    assert [Path(p).name for p in summarised] == ["talker.py"]
    monkeypatch.setattr(robotfix.paramcheck, "summarize", real)
    assert found == run(workspace, cache=False)


def test_the_names_launch_files_give_decide_the_parameter_files_findings(
    workspace: Path,
) -> None:
    """The parameter files' findings are kept apart from the launch files': they
    depend on the names the launch files give and the code those start. Renaming
    the talker `speaker` (the node names stay: another entry is called
    `speaker`) makes `speaker:` apply to the talker's code (RF401: a string for
    its double `rate`); naming another entry `nobody` matches `nobody:` (its
    RF602 goes)."""
    pkg = workspace / "src/demo"
    (pkg / "config").mkdir()
    (pkg / "config/speaker.yaml").write_text(
        "speaker:\n  ros__parameters:\n    rate: fast\n"
        "nobody:\n  ros__parameters:\n    x: 1\n",
        encoding="utf-8",
    )
    edit(
        pkg / "launch/demo.launch.py",
        "        Node(\n",
        '        Node(package="other", executable="x", name="speaker"),\n'
        '        Node(package="other", executable="y", name="talker"),\n'
        "        Node(\n",
    )
    before = settled(workspace)
    assert any("RF602" in line and "speaker.yaml" in line for line in before)
    assert not any("RF401" in line for line in before)
    edit(pkg / "launch/demo.launch.py", 'name="talker",', 'name="speaker",')
    renamed = settled(workspace)
    assert any("RF401" in line and "speaker.yaml" in line for line in renamed)
    edit(
        pkg / "launch/demo.launch.py",
        'executable="x", name="speaker"',
        'executable="x", name="nobody"',
    )
    named = settled(workspace)
    assert not any("RF602" in line and "speaker.yaml" in line for line in named)


def test_a_parameter_file_only_a_launch_file_names_is_checked_again(
    workspace: Path,
) -> None:
    """Its values against the talker's declarations (RF401: a string for the
    double `rate`), though discovery does not find it."""
    params = "src/demo/settings/talker.yaml"
    finds_after(workspace, params, "rate: 5.0", "rate: fast", "RF401", "talker.yaml")


def test_an_edited_launch_file_is_the_only_one_read_again(
    workspace: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Each launch file's reading is kept with what it read: an edit re-reads the
    file and those that include it, no other."""
    launch, parsed = one_more_launch_file(workspace, monkeypatch, "other", INNER)
    edit(launch / "other.launch.py", '"numbers", "numbers"', '"numbers", "other"')
    found = run(workspace, cache=True)
    assert parsed == ["other.launch.py"]
    assert found == run(workspace, cache=False)
    parsed.clear()
    edit(launch / "inner.launch.py", '"numbers", "numbers"', '"numbers", "inner"')
    found = run(workspace, cache=True)
    assert sorted(parsed) == ["demo.launch.py", "inner.launch.py"]
    assert found == run(workspace, cache=False)


def test_an_edited_cpp_node_is_seen(workspace: Path) -> None:
    """A C++ file's endpoints and node names count by its bytes: publishing
    Int32 on `chatter` (RF603 with the talker's String), then naming its node
    `driver` (the section `driver:` of a parameter file names a node then: its
    RF602 goes)."""
    driver = workspace / "src/demo"  # one package with the talker: they may meet
    (driver / "src").mkdir(parents=True)
    (driver / "config").mkdir()
    (driver / "config/driver.yaml").write_text(
        "driver:\n  ros__parameters:\n    max: 0.4\n", encoding="utf-8"
    )
    source = driver / "src/driver.cpp"
    source.write_text(
        "class Driver : public rclcpp::Node {\n public:\n"
        '  Driver() : Node("motor") {\n'
        '    pub_ = create_publisher<std_msgs::msg::Int32>("numbers", 10);\n'
        "  }\n};\n",
        encoding="utf-8",
    )
    before = settled(workspace)
    assert any("RF602" in line and "driver.yaml" in line for line in before)
    edit(source, '"numbers"', '"/chatter"')
    published = settled(workspace)
    assert any("RF603" in line for line in published)
    edit(source, 'Node("motor")', 'Node("driver")')
    named = settled(workspace)
    assert not any("RF602" in line and "driver.yaml" in line for line in named)


def test_per_file_ignores_apply_to_kept_graph_findings(workspace: Path) -> None:
    """The graph's findings are kept before `per-file-ignores`: a run with other
    settings over the same cache silences what they say."""
    edit(
        workspace / "src/demo/launch/demo.launch.py",
        'name="talker",',
        'name="talker",\n            remappings=[("chatter", "numbers")],',
    )
    found = settled(workspace)
    assert any("RF603" in line for line in found)
    ignoring = (("*.py", frozenset({"RF603"})),)
    config = Config(
        root=workspace, cache_dir=workspace / "cache", per_file_ignores=ignoring
    )
    for _ in range(2):
        quiet = check_paths([workspace / "src"], config, use_cache=True).diagnostics
        assert not any(d.code == "RF603" for d in quiet)
    assert run(workspace, cache=True) == found


def test_a_parameter_file_made_where_a_launch_file_looks_is_seen(
    workspace: Path,
) -> None:
    """A launch file names a parameter file that is not there (nothing to check),
    then it is made, with a typo (RF601): the launch file's reading is done again
    (what it found missing is kept as the stamp of the folder above)."""
    pkg = workspace / "src/demo"
    params = pkg / "settings/talker.yaml"
    params.unlink()
    params.parent.rmdir()
    before = settled(workspace)
    assert not any("talker.yaml" in line for line in before)
    params.parent.mkdir()
    params.write_text(PARAMS + "    rte: 1\n", encoding="utf-8")
    assert any("RF601" in line and "talker.yaml" in line for line in settled(workspace))


def test_a_module_made_where_a_node_imports_from_is_seen(workspace: Path) -> None:
    """The talker imports `limits`, which its package does not have (the places
    looked at are kept as the stamp of the package's folder); once made, its
    node class declares `rte`: the typo RF601 in the talker's parameter file
    goes."""
    pkg = workspace / "src/demo"
    edit(pkg / "demo/talker.py", "import rclpy\n", "import rclpy\nimport limits\n")
    edit(pkg / "settings/talker.yaml", "rate: 5.0", "rate: 5.0\n    rte: 1")
    before = settled(workspace)
    assert any("RF601" in line and "talker.yaml" in line for line in before)
    (pkg / "limits.py").write_text(
        "from rclpy.node import Node\n\n\nclass Limits(Node):\n"
        "    def __init__(self):\n"
        '        super().__init__("talker")\n'
        '        self.declare_parameter("rte", 1)\n',
        encoding="utf-8",
    )
    after = settled(workspace)
    assert not any("RF601" in line and "talker.yaml" in line for line in after)


def test_damaged_kept_parts_are_done_again(workspace: Path) -> None:
    """A kept reading, part or stage that is not exactly what RobotFix writes is
    not used (the run does that part again), never a crash."""
    fresh = settled(workspace)
    results = workspace / "cache/results.json"
    data = json.loads(results.read_text(encoding="utf-8"))
    reads, parts = json.loads(data["reads"]), data["parts"]  # reads: as text
    for name in reads:
        reads[name][2][1] = [[["NodeEntry", 2], []], [["Nope"], ["x"]]]
    for name in parts:
        parts[name][1] = [["RF999", "x", [0, 0, 0, 0], "m", []]]
    data["reads"] = json.dumps(reads)
    data["stage"]["graph"] = "nothing"
    results.write_text(json.dumps(data), encoding="utf-8")
    assert run(workspace, cache=True) == fresh
    for damaged in ("[1, 2]", "{", '{"x": "\\udc80"}', "{" * 100_000):
        data = json.loads(results.read_text(encoding="utf-8"))
        data["reads"], data["stage"] = damaged, None
        results.write_text(json.dumps(data), encoding="utf-8")
        assert run(workspace, cache=True) == fresh


def test_entries_come_back_from_their_json_form_or_not_at_all() -> None:
    from robotfix.ros.launch.model import NodeEntry, Place, dump, load
    from robotfix.ros.paramfile import Typed

    entry = NodeEntry(2, Place("a.py", 3, 4), "p", "x", "n", "/ns")
    entry.arguments = ["--a", None]
    assert repr(load(json.loads(json.dumps(dump(entry))))) == repr(entry)
    with pytest.raises(ValueError):
        dump(Typed("integer_array", (1, 2), "[1, 2]"))  # a tuple: a list back
    for bad in (["Place", "a.py", 1], ["Other", 1], {"x": 1}, [[]] * 2):
        with pytest.raises((ValueError, TypeError)):
            load(bad)


def test_a_deleted_launch_files_kept_parts_go(workspace: Path) -> None:
    launch = workspace / "src/demo/launch/other.launch.py"
    launch.write_text(INNER, encoding="utf-8")
    settled(workspace)
    results = workspace / "cache/results.json"
    assert str(launch) in results.read_text(encoding="utf-8")
    launch.unlink()
    settled(workspace)
    assert str(launch) not in results.read_text(encoding="utf-8")


ARGUED = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument("who", default_value="listener"),
        DeclareLaunchArgument("level", default_value="info"),
        Node(
            package="demo",
            executable="listener",
            name=LaunchConfiguration("who"),
            arguments=["--ros-args", "--log-level", LaunchConfiguration("level")],
        ),
    ])
"""


def test_a_launch_file_read_with_its_arguments_is_kept(
    workspace: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """An entry whose name and arguments are a launch argument's text is kept
    like any other (that text was not kept: such a file was read again on every
    run that read launch files, 68 of nav2's and turtlebot3's 470)."""
    launch, parsed = one_more_launch_file(workspace, monkeypatch, "argued", ARGUED)
    edit(launch / "inner.launch.py", '"numbers", "numbers"', '"numbers", "inner"')
    found = run(workspace, cache=True)
    assert sorted(parsed) == ["demo.launch.py", "inner.launch.py"]
    assert found == run(workspace, cache=False)
    parsed.clear()
    edit(launch / "argued.launch.py", '"info"', '"debug"')
    found = run(workspace, cache=True)
    assert parsed == ["argued.launch.py"]
    assert found == run(workspace, cache=False)


def touch_all(root: Path, seconds: float = 5.0) -> None:
    """Every file of the tree rewritten alike, as a checkout or a CI cache
    restored onto a fresh clone leaves it: new mtimes and ctimes, same bytes."""
    earlier = time.time() - seconds
    for path in (root / "src").rglob("*"):
        if path.is_file():
            os.utime(path, (earlier, earlier))


def test_a_touched_tree_reads_no_launch_file_again(
    workspace: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Files whose stamps changed but whose bytes did not (hashed at the stamp
    a trace noted, and alike now) hold: no launch file is read and no graph
    checked (every one was, and the discovery walked again), and the traces
    are kept with the new stamps: the run after that does not hash them."""
    before = settled(workspace)
    touch_all(workspace)
    read = counting_readings(monkeypatch)
    walked: list[object] = []
    real_walk = robotfix.discovery._Walker.walk
    monkeypatch.setattr(
        robotfix.discovery._Walker,
        "walk",
        lambda *a: walked.append(a) or real_walk(*a),
    )
    assert run(workspace, cache=True) == before
    assert not read and not walked
    kept = json.loads((workspace / "cache/results.json").read_text(encoding="utf-8"))
    launch = str(workspace / "src/demo/launch/demo.launch.py")
    now = robotfix.fs.stamp(launch)
    assert kept["stage"]["trace"]["stamps"][launch] == now
    assert json.loads(kept["reads"])[launch][1]["stamps"][launch] == now
    assert run(workspace, cache=True) == before
    assert not read and not walked


def test_a_touched_file_with_other_bytes_or_mode_is_read_again(
    workspace: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The bytes decide, with the size and the mode: an edit of the same size
    whose mtime is put back (RF401: a string for the talker's double `rate`)
    and a launch file made executable are read again."""
    before = settled(workspace)
    assert not any("RF401" in line for line in before)
    touch_all(workspace)
    parsed = counting_parses(monkeypatch)
    outer = workspace / "src/demo/launch/demo.launch.py"
    stamp = outer.stat()
    edit(outer, '{"rate": 2.0}', '{"rate": "x"}')
    os.utime(outer, ns=(stamp.st_atime_ns, stamp.st_mtime_ns))
    assert outer.stat().st_size == stamp.st_size
    found = run(workspace, cache=True)
    assert any("RF401" in line and "demo.launch.py" in line for line in found)
    assert sorted(parsed) == ["demo.launch.py", "inner.launch.py"]  # it includes
    assert found == run(workspace, cache=False)
    settled(workspace)
    parsed.clear()
    outer.chmod(0o755)
    assert run(workspace, cache=True) == run(workspace, cache=False)
    assert "demo.launch.py" in parsed


def test_a_file_touched_just_now_holds_by_its_bytes_and_is_renewed_later(
    workspace: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A new stamp too young to trust (`RACY_NS`): the bytes, read now, still
    decide for this run (no launch file read), but the trace keeps the old stamp
    and the record of the bytes at it, so the next run hashes the file again
    and then keeps the new stamp."""
    before = settled(workspace)
    touch_all(workspace)
    read = counting_readings(monkeypatch)
    launch = str(workspace / "src/demo/launch/demo.launch.py")
    results = workspace / "cache/results.json"
    monkeypatch.setattr(robotfix.cache, "RACY_NS", 3600 * 10**9)
    assert run(workspace, cache=True) == before
    assert not read
    stamps = json.loads(results.read_text(encoding="utf-8"))["stage"]["trace"]["stamps"]
    assert stamps[launch] != robotfix.fs.stamp(launch)
    monkeypatch.setattr(robotfix.cache, "RACY_NS", 0)
    assert run(workspace, cache=True) == before
    assert not read
    stamps = json.loads(results.read_text(encoding="utf-8"))["stage"]["trace"]["stamps"]
    assert stamps[launch] == robotfix.fs.stamp(launch)


def test_the_cpp_files_graphs_outlive_a_run_that_read_none(
    workspace: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A run whose stage and parameter check hold reads no C++ file; when it
    saves the cache (here: a touched node's hash kept again), the C++ files'
    graphs are kept too. They were dropped, and the next edit that re-did the
    parameter check parsed every C++ file again (1,528 in the corpus)."""
    import robotfix.graphcheck

    driver = workspace / "src/demo/src/driver.cpp"
    driver.parent.mkdir(parents=True)
    driver.write_text(
        'class Driver : public rclcpp::Node {\n public:\n  Driver() : Node("driver")'
        ' {\n    declare_parameter("gain", 1.0);\n  }\n};\n',
        encoding="utf-8",
    )
    settled(workspace)
    monitor = workspace / "src/demo/demo/monitor.py"
    earlier = time.time() - 5
    os.utime(monitor, (earlier, earlier))
    assert run(workspace, cache=True) == run(workspace, cache=False)
    parsed: list[object] = []
    real = robotfix.ros.graph.cpp.read_cpp  # (graphcheck imports it when it reads C++)
    monkeypatch.setattr(
        robotfix.ros.graph.cpp,
        "read_cpp",
        lambda *a, **k: parsed.append(a) or real(*a, **k),
    )
    edit(
        monitor,
        '"gain", 1.0)',
        '"gain", 1.0)\n        self.declare_parameter("bias", 0.0)',
    )
    assert run(workspace, cache=True) == run(workspace, cache=False)
    assert len(parsed) == 1  # the run without the cache's
