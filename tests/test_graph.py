"""The static ROS graph (issue 23, section 2): the small workspaces under
tests/cases/graph/ (modelled on turtlebot3, nav2_bringup, ros2/demos and
ros_tutorials' turtlesim) with inline expectations in their Python, C++
(`// error: RF603`) and launch files (strict: every diagnostic of the run), each
with a clean near miss (a remapping that makes names match, a relative name under
a namespace, a private topic, a type a parameter chooses); name resolution, QoS,
the extractors on their own, the cache and `-j`, and `robotfix graph`."""

from __future__ import annotations

import ast
import json
import re
import shutil
from pathlib import Path

import pytest

from robotfix import run as run_module
from robotfix.analysis.index import index_of
from robotfix.api import check_paths
from robotfix.cli import main
from robotfix.config import Config
from robotfix.graphcheck import graph_paths
from robotfix.ros.graph import qos as Q
from robotfix.ros.graph.cpp import MAX_CPP_BYTES, read_cpp
from robotfix.ros.graph.model import Endpoint, FileGraph, Qos, dump, load
from robotfix.ros.graph.names import expand, remap
from robotfix.ros.graph.python import read_python
from robotfix.testing.expectations import compare_files

CASES = Path(__file__).parent / "cases" / "graph"
SUFFIXES = (".py", ".yaml", ".xml", ".launch", ".cpp", ".hpp")
GRAPH_CODES = ("RF603", "RF604", "RF605", "RF606", "RF607")


def files_of(root: Path) -> list[Path]:
    return sorted(p for p in root.rglob("*") if p.name.endswith(SUFFIXES))


@pytest.mark.parametrize(
    "workspace", sorted(p for p in CASES.iterdir() if p.is_dir()), ids=lambda p: p.name
)
def test_graph_findings_of_a_workspace(workspace: Path) -> None:
    found = check_paths([workspace], Config(root=workspace)).diagnostics
    problems = compare_files(files_of(workspace), found)
    assert not problems, "\n".join(problems)


def _lines(root: Path, jobs: int = 1, cache: bool = False) -> list[str]:
    result = check_paths([root], Config(root=root), jobs=jobs, use_cache=cache)
    return [
        f"{Path(d.path).relative_to(root)}:{d.span.line}:{d.code}:{d.message}"
        for d in result.diagnostics
    ]


@pytest.mark.parametrize(
    ("workspace", "code", "count", "reread"),
    [
        ("ros2_robot", "RF603", 2, set()),
        # publishers whose subscribers' contracts are checked again on every run
        ("ros2_contracts", "RF101", 1, {"joystick.py", "planner.py", "teleop.py"}),
        # clients whose server's contract is checked again
        (
            "ros2_services",
            "RF101",
            2,
            {"cruise.py", "day_mode.py", "docking.py", "joy_limit.py", "night_mode.py"},
        ),
        # servers whose clients refine the response they receive
        (
            "ros2_responses",
            "RF101",
            2,
            {
                "boost_server.py",
                "clamp_server.py",
                "scale_server.py",
                "turbo_server.py",
            },
        ),
        # a frame its subscriber assumes
        (
            "ros2_frames",
            "RF201",
            2,
            {"ahead.py", "clicked.py", "inspection.py", "patrol_goals.py"},
        ),
        # a unit its subscriber gives a field whose interface gives none
        ("ros2_joint_units", "RF201", 1, {"dial.py", "home.py", "slider.py"}),
        # action clients whose server's goal callback refines the goal
        (
            "ros2_actions",
            "RF101",
            1,
            {"circle_patrol.py", "patrol_client.py", "square_patrol.py"},
        ),
    ],
)
def test_jobs_and_the_cache_give_the_same_graph(
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    workspace: str,
    code: str,
    count: int,
    reread: set[str],
) -> None:
    """Endpoints extracted in worker processes, or kept in the result cache, make
    the graph (and its contracts' findings) one process makes without the cache."""
    monkeypatch.setattr(run_module, "MIN_PARALLEL", 1)
    root = tmp_path / "ws"
    shutil.copytree(CASES / workspace, root)
    one = _lines(root)
    assert sum(f":{code}:" in line for line in one) == count
    assert _lines(root, jobs=2) == one
    assert _lines(root, jobs=2, cache=True) == one
    reads: list[str] = []
    real = run_module.read_regular

    def counting(path: Path, *args: object, **kwargs: object) -> bytes:
        reads.append(str(path))
        return real(path, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(run_module, "read_regular", counting)
    assert _lines(root, jobs=1, cache=True) == one  # the endpoints from the cache
    assert {Path(r).name for r in reads if r.endswith(".py")} == reread


def test_a_single_file_gets_no_graph_findings() -> None:
    """The graph is the workspace's: a file checked alone (or in an editor) would
    get notes that depend on what was opened."""
    node = CASES / "ros2_robot" / "keyboard_teleop" / "keyboard_teleop" / "monitor.py"
    found = check_paths([node], Config(root=node.parent)).diagnostics
    assert not [d for d in found if d.code in GRAPH_CODES]


def test_graph_findings_are_suppressed_on_their_line(tmp_path: Path) -> None:
    """`# robotfix: ignore[RF603]` (Python) and `// robotfix: ignore[...]` (C++)
    silence a graph finding, and the file's own check does not call the Python
    one unused (RF010): the graph check, after it, uses it."""
    root = tmp_path / "ws"
    shutil.copytree(CASES / "ros2_robot", root)
    monitor = root / "keyboard_teleop" / "keyboard_teleop" / "monitor.py"
    monitor.write_text(
        monitor.read_text().replace(
            "self.create_subscription(  # error: RF603",
            "self.create_subscription(  # robotfix: ignore[RF603]",
        )
    )
    driver = root / "base_driver" / "src" / "driver.cpp"
    driver.write_text(
        driver.read_text().replace(
            "// error: RF603", "// robotfix: ignore[topic-type-mismatch]"
        )
    )
    found = check_paths([root], Config(root=root)).diagnostics
    assert not [d for d in found if d.code in ("RF603", "RF010")]
    assert [d.code for d in found if d.code == "RF604"] == ["RF604", "RF604"]


def test_names_resolve_as_ros_resolves_them() -> None:
    assert expand("cmd_vel", "/robot1", "teleop") == "/robot1/cmd_vel"
    assert expand("/scan", "/robot1", "teleop") == "/scan"
    assert expand("~/status", "/robot1", "driver") == "/robot1/driver/status"
    assert expand("~status", "/", "driver") == "/driver/status"  # ROS 1
    assert expand("cmd_vel", "/", "x", handle="~") == "/x/cmd_vel"  # NodeHandle("~")
    assert expand("cmd_vel", None, "x") is None  # a namespace set at launch time
    assert expand("~/x", "/", None) is None  # a private name of an unknown node
    assert expand("{node}/x", "/", "n") is None
    rules = [("cmd_vel", "base/cmd_vel")]
    assert remap("/robot1/cmd_vel", rules, "/robot1", "t") == (
        "/robot1/base/cmd_vel",
        False,
    )
    assert remap("/robot1/odom", rules, "/robot1", "t") == ("/robot1/odom", False)
    # a rule one side of which is computed may match anything: not certain
    assert remap("/odom", [(None, "x")], "/", "t") == ("/odom", True)


def test_qos_compatibility_follows_the_ros_2_table() -> None:
    sensor = Q.PY_PROFILES["qos_profile_sensor_data"]
    reliable = Q.depth_only(10)
    latched = Qos(Q.RELIABLE, Q.TRANSIENT_LOCAL, 1)
    assert Q.incompatible(sensor, reliable)  # best-effort publisher, reliable sub
    assert not Q.incompatible(reliable, sensor)  # the other way round connects
    assert Q.incompatible(reliable, latched)  # volatile publisher, latched sub
    assert not Q.incompatible(latched, reliable)
    unknown = Q.PY_PROFILES["qos_profile_system_default"]
    assert not Q.incompatible(unknown, latched)


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


PACKAGE = """<?xml version="1.0"?>
<package format="3"><name>{0}</name><version>0.1.0</version>
<description>x</description><maintainer email="a@b.c">a</maintainer>
<license>MIT</license></package>
"""


def test_an_overridable_profile_is_a_warning_and_unlaunched_nodes_of_one_package_too(
    tmp_path: Path,
) -> None:
    """RF605: a QoS the user may override by parameter (`qos_overriding_options`);
    two nodes of one package no launch file starts: RF603 and RF605 are warnings."""
    write(tmp_path / "demo" / "package.xml", PACKAGE.format("demo"))
    write(
        tmp_path / "demo" / "demo" / "talker.py",
        "from rclpy.node import Node\n"
        "from rclpy.qos import qos_profile_sensor_data\n"
        "from std_msgs.msg import String\n"
        "class Talker(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('talker')\n"
        "        self.create_publisher(String, 'chatter', qos_profile_sensor_data)\n"
        "        self.create_publisher(String, 'other', 10)\n",
    )
    write(
        tmp_path / "demo" / "demo" / "listener.py",
        "from rclpy.node import Node\n"
        "from rclpy.qos import QoSOverridingOptions\n"
        "from std_msgs.msg import String, Int32\n"
        "class Listener(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('listener')\n"
        "        options = QoSOverridingOptions.with_default_policies()\n"
        "        self.create_subscription(String, 'chatter', print, 10,\n"
        "            qos_overriding_options=options)\n"
        "        self.create_subscription(Int32, 'other', print, 10)\n",
    )
    found = check_paths([tmp_path], Config(root=tmp_path)).diagnostics
    shown = sorted(
        (Path(d.path).name, d.span.line, d.code, d.severity.value)
        for d in found
        if d.code in GRAPH_CODES
    )
    assert shown == [
        ("listener.py", 8, "RF605", "warning"),
        ("listener.py", 10, "RF603", "warning"),
        ("talker.py", 8, "RF603", "warning"),
    ]


def test_programs_of_different_packages_or_test_code_are_never_compared(
    tmp_path: Path,
) -> None:
    """A repository's demos (ros2/demos' rclcpp and rclpy QoS demos use one topic
    name with two types) and test code's throwaway nodes are not one system."""
    for package, kind in (("demo_a", "String"), ("demo_b", "Int32")):
        write(tmp_path / package / "package.xml", PACKAGE.format(package))
        write(
            tmp_path / package / package / "node.py",
            f"from rclpy.node import Node\nfrom std_msgs.msg import {kind}\n"
            "class N(Node):\n    def __init__(self):\n"
            f"        super().__init__('{package}')\n"
            f"        self.create_publisher({kind}, '/chatter', 10)\n",
        )
    write(
        tmp_path / "demo_a" / "test" / "test_node.py",
        "from rclpy.node import Node\nfrom std_msgs.msg import Bool\n"
        "def test_it(node: Node):\n"
        "    node.create_subscription(Bool, '/chatter', print, 10)\n",
    )
    found = check_paths([tmp_path], Config(root=tmp_path)).diagnostics
    assert not [d for d in found if d.code in GRAPH_CODES]


def _py(text: str) -> FileGraph:
    """The file's graph, the same when read with its index's calls (as a
    checked file is: only the statements holding endpoint calls walked)."""
    tree = ast.parse(text)
    found = read_python(tree)
    assert dump(read_python(tree, index_of(tree).calls)) == dump(found)
    return found


def test_python_read_with_the_calls_is_the_whole_walk() -> None:
    """A call where its position does not say (in a decorator, which the walk
    leaves out), two `__init__` calls of a class (taken in the walk's order),
    two classes of one name: the reading with the index's calls is the whole
    walk's."""
    found = _py(
        "import rclpy\nfrom rclpy.node import Node\nfrom std_msgs.msg import String\n"
        "node = rclpy.create_node('solo')\n"
        "@wrap(node.create_publisher(String, 'deco', 1))\n"
        "def f(): pass\n"
        "class A(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('one')\n"
        "    def again(self):\n"
        "        Node.__init__(self, 'two')\n"
        "        self.create_publisher(String, 'a', 1)\n"
        "if rclpy:\n"
        "    class B(Node):\n"
        "        def __init__(self):\n"
        "            super().__init__('hidden')\n"
        "class B(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('b')\n"
        "        self.create_subscription(String, 'b', lambda m: None, 1)\n"
        "def idle(x):\n"
        "    return x + 1\n"
    )
    assert [e.name for e in found.endpoints] == ["a", "b"]
    assert found.nodes == {"node": ["solo"], "A": ["two", "one"], "B": ["b"]}


def test_what_a_client_assumes_of_the_response_is_read_where_it_receives_it() -> None:
    """A synchronous call's refined result is the client's contract (a local
    client of `main` as demos' add_two_ints_client; every assumption joined,
    with the server's callback key); none for a place two clients are kept in."""
    found = _py(
        "from typing import Annotated\n"
        "from rclpy.node import Node\n"
        "from example_interfaces.srv import AddTwoInts as A\n"
        "Small = Annotated[A.Response, 'sum <= 10']\n"
        "class C(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('c')\n"
        "        self.cli = self.create_client(A, 'add')\n"
        "        self.twice = self.create_client(A, 'one')\n"
        "        self.twice = self.create_client(A, 'two')\n"
        "        self.later = self.create_client(A, 'later')\n"
        "        self.create_service(A, 'serve', self.handle)\n"
        "    def handle(self, request, response):\n"
        "        return response\n"
        "    def ask(self, req):\n"
        "        r: Annotated[A.Response, '0 <= sum'] = self.cli.call(req)\n"
        "        s: Small = self.cli.call(req)\n"
        "        t: Small = self.twice.call(req)\n"
        "        f = self.later.call_async(req)\n"
        "        u: Small = f.result()\n"
        "def main(node):\n"
        "    cli = node.create_client(A, 'add')\n"
        "    r: Small = cli.call(A.Request(a=1, b=2))\n"
    )
    got = [(e.kind, e.name, e.contract, e.returns) for e in found.endpoints]
    assert got == [
        ("client", "add", "(0 <= sum) and (sum <= 10)", ""),
        ("client", "one", None, ""),
        ("client", "two", None, ""),
        ("client", "later", "sum <= 10", ""),
        ("service", "serve", None, "C.handle"),
        ("client", "add", "sum <= 10", ""),
    ]


def test_a_futures_refined_result_is_read_only_where_its_client_is_certain() -> None:
    """`future.result()` after `call_async` is read as the call's refined result
    (demos' async add_two_ints_client: a local of `main`; a `self.future` of the
    class, read in another method), only when every binding of the future is a
    `call_async` of one client: not for a name bound to two clients' futures,
    bound otherwise, a parameter (a done callback's), declared `global`, nor an
    attribute a subclass of the file may bind too."""
    found = _py(
        "from typing import Annotated\n"
        "from rclpy.node import Node\n"
        "from example_interfaces.srv import AddTwoInts as A\n"
        "Small = Annotated[A.Response, 'sum <= 10']\n"
        "future = None\n"
        "class C(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('c')\n"
        "        self.cli = self.create_client(A, 'kept')\n"
        "        self.one = self.create_client(A, 'one')\n"
        "        self.two = self.create_client(A, 'two')\n"
        "        self.cb = self.create_client(A, 'cb')\n"
        "        self.glob = self.create_client(A, 'glob')\n"
        "    def send(self, req):\n"
        "        self.future = self.cli.call_async(req)\n"
        "        self.cb.call_async(req).add_done_callback(self.done)\n"
        "    def done(self, future):\n"
        "        r: Small = future.result()\n"
        "    def got(self):\n"
        "        r: Small = self.future.result()\n"
        "    def ask(self, req, which):\n"
        "        f = self.one.call_async(req)\n"
        "        if which:\n"
        "            f = self.two.call_async(req)\n"
        "        u: Small = f.result()\n"
        "        g = self.one.call_async(req)\n"
        "        g = g or None\n"
        "        v: Small = g.result()\n"
        "    def far(self, req):\n"
        "        global future\n"
        "        future = self.glob.call_async(req)\n"
        "        w: Small = future.result()\n"
        "class D(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('d')\n"
        "        self.base = self.create_client(A, 'base')\n"
        "        self.other = self.create_client(A, 'other')\n"
        "    def send(self, req):\n"
        "        self.future = self.base.call_async(req)\n"
        "    def got(self):\n"
        "        r: Small = self.future.result()\n"
        "class E(D):\n"
        "    def send(self, req):\n"
        "        self.future = self.other.call_async(req)\n"
        "def main(node):\n"
        "    cli = node.create_client(A, 'add_two_ints')\n"
        "    future = cli.call_async(A.Request(a=2, b=3))\n"
        "    node.spin_until_future_complete(future)\n"
        "    response: Annotated[A.Response, 'sum == 5'] = future.result()\n"
    )
    got = [(e.name, e.contract) for e in found.endpoints]
    assert got == [
        ("kept", "sum <= 10"),
        ("one", None),
        ("two", None),
        ("cb", None),
        ("glob", None),
        ("base", None),
        ("other", None),
        ("add_two_ints", "sum == 5"),
    ]


def test_python_types_through_imports_names_and_choices() -> None:
    found = _py(
        "import std_msgs.msg as m\n"
        "from geometry_msgs import msg as g\n"
        "from rclpy.node import Node\n"
        "from rclpy.qos import QoSProfile, ReliabilityPolicy\n"
        "BEST = QoSProfile(depth=3, reliability=ReliabilityPolicy.BEST_EFFORT)\n"
        "TOPIC = 'out'\n"
        "class N(Node):\n"
        "    def __init__(self, stamped):\n"
        "        super().__init__('n')\n"
        "        kind = g.TwistStamped if stamped else g.Twist\n"
        "        self.create_publisher(m.String, TOPIC, BEST)\n"
        "        self.create_publisher(kind, 'cmd', 1)\n"
        "        self.create_publisher(stamped, 'x', 1)\n"  # a parameter: unknown
    )
    got = [(e.name, e.types, e.qos) for e in found.endpoints]
    assert got == [
        ("out", ("std_msgs/msg/String",), Qos(Q.BEST_EFFORT, Q.VOLATILE, 3)),
        (
            "cmd",
            ("geometry_msgs/msg/Twist", "geometry_msgs/msg/TwistStamped"),
            Q.depth_only(1),
        ),
        ("x", (), Q.depth_only(1)),
    ]
    assert found.nodes == {"N": ["n"]}


def test_a_changed_qos_object_is_unknown() -> None:
    found = _py(
        "from rclpy.qos import QoSProfile\nfrom std_msgs.msg import String\n"
        "def main(node):\n"
        "    qos = QoSProfile(depth=1)\n"
        "    qos.durability = 1\n"
        "    node.create_publisher(String, 'x', qos)\n"
    )
    assert found.endpoints[0].qos is None


CPP = b"""
#include "rclcpp/rclcpp.hpp"
using geometry_msgs::msg::Twist;
class Driver : public rclcpp::Node {
 public:
  Driver() : Node("driver") {
    pub_ = create_publisher<Twist>(
      "cmd", rclcpp::QoS(rclcpp::KeepLast(5)).best_effort());
    auto c = rclcpp_action::create_client<nav2_msgs::action::NavigateToPose>(
      this, "navigate");
    declare_parameter("speed", 0.5);
    create_publisher<std_msgs::msg::String>(topic_name_, 10);
  }
};
int main(int argc, char ** argv) {
  auto node = rclcpp::Node::make_shared("helper");
  node->create_subscription<std_msgs::msg::String>(
    "chatter", rclcpp::SensorDataQoS(), cb);
}
"""


def test_cpp_endpoints_with_tree_sitter() -> None:
    found = read_cpp(CPP)
    got = [(e.kind, e.name, e.types, e.owner, e.qos) for e in found.endpoints]
    assert got == [
        (
            "publisher",
            "cmd",
            ("geometry_msgs/msg/Twist",),
            "Driver",
            Qos(Q.BEST_EFFORT, Q.VOLATILE, 5),
        ),
        (
            "action_client",
            "navigate",
            ("nav2_msgs/action/NavigateToPose",),
            "Driver",
            None,
        ),
        ("parameter", "speed", ("double",), "Driver", None),
        ("publisher", None, ("std_msgs/msg/String",), "Driver", Q.depth_only(10)),
        (
            "subscription",
            "chatter",
            ("std_msgs/msg/String",),
            "node",
            Q.CPP_PROFILES["SensorDataQoS"],
        ),
    ]
    assert found.nodes == {"Driver": ["driver"], "node": ["helper"]}
    assert found.endpoints[2].value == "0.5"


def test_a_cpp_parameters_literal_default_gives_its_type() -> None:
    """`declare_parameter("one_shot", false)` is a bool parameter, as rclcpp
    makes it (fresh-eyes r5's `?`); a default that is not a literal: unknown."""
    body = "".join(
        f'    declare_parameter("p{i}", {value});\n'
        for i, value in enumerate(["false", "2.5", "3", '"x"', "v_", "0x1f", "1e3"])
    )
    found = read_cpp(
        b'class D : public rclcpp::Node {\n public:\n  D() : Node("d") {\n'
        + body.encode()
        + b"  }\n};\n"
    )
    assert [e.types for e in found.endpoints] == [
        ("bool",),
        ("double",),
        ("int",),
        ("std::string",),
        (),
        ("int",),
        ("double",),
    ]


@pytest.mark.parametrize(
    "data",
    [
        b"\xff\xfe\x00garbage {{{{ create_publisher<(",
        b'class A { void f() { create_publisher<T>("x", 10 ',  # cut off
        b"int f() { return " + b"(" * 50_000 + b"1" + b")" * 50_000 + b"; }",
        b"x" * (MAX_CPP_BYTES + 1),
    ],
    ids=["garbage", "unfinished", "deep", "huge"],
)
def test_bad_cpp_never_fails(data: bytes) -> None:
    found = read_cpp(data)
    assert isinstance(found, FileGraph)


def test_the_cached_form_round_trips_and_refuses_anything_else() -> None:
    found = FileGraph(
        [Endpoint("publisher", "x", ("a/msg/B",), 3, 4, "N", Qos(None, Q.VOLATILE, 1))],
        {"N": ["n"]},
    )
    assert load(json.loads(json.dumps(dump(found)))) == found
    raw = dump(found)
    raw[2][0][0] = "nonsense"
    assert load(raw) is None
    assert load([2, {}, [["publisher"]]]) is None
    assert load("x") is None


def test_graph_command_formats(capsys: pytest.CaptureFixture[str]) -> None:
    root = CASES / "ros2_robot"
    assert main(["graph", str(root), "--format", "json"]) == 1  # RF603, RF604
    data = json.loads(capsys.readouterr().out)
    assert {f["code"] for f in data["findings"]} == {"RF603", "RF604", "RF606", "RF607"}
    driver = [n for n in data["nodes"] if n["qualified"] == "/robot1/driver"]
    assert driver and driver[0]["launch"] is not None
    contracts = {e["resolved"]: e["contract"] for e in data["endpoints"]}
    assert contracts["/robot1/odom"] == "abs(twist.twist.linear.x) <= 0.5"
    marked = [e for e in data["endpoints"] if "RF603" in e["findings"]]
    assert {e["resolved"] for e in marked} == {"/robot1/base/cmd_vel"}
    main(["graph", str(root), "--format", "dot"])
    dot = capsys.readouterr().out
    assert (
        dot.startswith("digraph") and 'color=red, fontcolor=red, label="RF603"' in dot
    )
    main(["graph", str(root), "--format", "mermaid"])
    mermaid = capsys.readouterr().out
    assert mermaid.startswith("flowchart LR") and "linkStyle" in mermaid
    main(["graph", str(root)])
    text = capsys.readouterr().out
    assert "/robot1/teleop" in text and "!RF603" in text
    assert "assumes `abs(twist.twist.linear.x) <= 0.5`" in text


def test_graph_paths_is_the_checks_graph() -> None:
    """`robotfix graph` parses what the check would: the same findings."""
    root = CASES / "ros1_turtles"
    graph = graph_paths([root], Config(root=root))
    checked = check_paths([root], Config(root=root)).diagnostics
    assert sorted(graph.diagnostics(), key=lambda d: d.sort_key()) == [
        d for d in checked if d.code in GRAPH_CODES
    ]


@pytest.mark.parametrize(
    "text",
    [
        "set(a ${a}${a})\n" * 40_000,  # doubles a value 40,000 times
        "function(x)\n" * 80_000,  # openings never closed
        "function(f a)\nf(${a}${a})\nf(${a}${a})\nendfunction()\nf(x)\n",
        "function(x y)\nadd_executable(${y} a.cpp)\nendfunction()\n"
        + "x(z)\n" * 50_000,
        "foreach(x a)\n" * 80_000,  # loops never closed
        "foreach(a 1 2 3 4 5 6 7 8 9)\n" * 12  # 9**12 passes
        + "add_executable(z${a} a.cpp)\n"
        + "endforeach()\n" * 12,
    ],
    ids=["doubling", "unclosed", "recursive", "many-calls", "open-loops", "nested"],
)
def test_hostile_cmake_is_read_in_bounded_work(tmp_path: Path, text: str) -> None:
    """CMake is read, never run: a value too long is unknown, a function's calls
    nest 4 deep at most, and the commands read count against a budget."""
    from robotfix.ros.executables import cpp_executable_files

    write(tmp_path / "CMakeLists.txt", text)
    assert cpp_executable_files(tmp_path, "z") == []


def test_cmake_loops_over_literal_lists_are_followed(tmp_path: Path) -> None:
    """ros_tutorials' `foreach(dir talker listener) rostutorial(${dir})
    endforeach()` with a macro adding `${T}/${T}.cpp` (fresh-eyes r3), `IN ITEMS`,
    `IN LISTS`; a `RANGE` or an unknown list is no target."""
    from robotfix.ros.executables import cpp_executable_files

    for name in ("talker", "listener", "b", "c", "d"):
        write(tmp_path / name / f"{name}.cpp", "int main() {}\n")
    write(
        tmp_path / "CMakeLists.txt",
        "macro(tut T)\n  add_executable(${T} ${T}/${T}.cpp)\nendmacro()\n"
        "foreach(dir\n    talker\n    listener\n    )\n  tut(${dir})\nendforeach()\n"
        "foreach(x IN ITEMS b)\n tut(${x})\nendforeach()\n"
        "set(L c)\nforeach(x IN LISTS L)\n tut(${x})\nendforeach()\n"
        "foreach(x RANGE 3)\n tut(d${x})\nendforeach()\n"
        "foreach(x IN LISTS UNSET)\n tut(${x})\nendforeach()\n",
    )
    for name in ("talker", "listener", "b", "c"):
        assert cpp_executable_files(tmp_path, name) == [tmp_path / name / f"{name}.cpp"]
    assert cpp_executable_files(tmp_path, "d") == []


def test_python_names_are_followed_in_bounded_work() -> None:
    """A name bound 3,000 times to a name bound 3,000 times: the call's type is
    unknown once its budget is spent; the file's other calls still get theirs."""
    text = (
        "from std_msgs.msg import String\n"
        + "y = String\n" * 3000
        + "x = y\n" * 3000
        + "def f(node):\n"
        + "    node.create_publisher(x, 't', 1)\n"
        + "    node.create_publisher(String, 't', 1)\n"
    )
    found = _py(text)
    assert [e.types for e in found.endpoints] == [(), ("std_msgs/msg/String",)]


def test_nested_scopes_are_their_own() -> None:
    """A nested function's parameter hides the outer name, and what a nested
    function stores in `self.x` is one more binding of it."""
    found = _py(
        "from geometry_msgs.msg import Twist, TwistStamped\n"
        "from rclpy.node import Node\n"
        "class N(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('n')\n"
        "        kind = Twist\n"
        "        self.kind = Twist\n"
        "        def later(kind):\n"
        "            self.kind = kind\n"
        "            self.create_publisher(kind, 'a', 1)\n"
        "        self.create_publisher(self.kind, 'b', 1)\n"
        "        self.create_publisher(kind, 'c', 1)\n"
        "        make = lambda kind: self.create_publisher(kind, 'd', 1)\n"
    )
    got = {e.name: e.types for e in found.endpoints}
    assert got == {"a": (), "b": (), "c": ("geometry_msgs/msg/Twist",), "d": ()}


def test_a_contract_naming_the_subscribers_constants_is_not_checked(
    tmp_path: Path,
) -> None:
    """`abs(linear.x) <= LIMIT` means the subscriber module's LIMIT, which the
    publisher's check cannot read: the contract is left unchecked (silent), not
    read with another meaning."""
    root = tmp_path / "ws"
    shutil.copytree(CASES / "ros2_contracts", root)
    limiter = root / "safe_drive" / "safe_drive" / "limiter.py"
    text = limiter.read_text().replace(
        '"abs(linear.x) <= 0.5"', '"abs(linear.x) <= LIMIT"'
    )
    limiter.write_text(text.replace("class Limiter", "LIMIT = 0.5\n\n\nclass Limiter"))
    found = check_paths([root], Config(root=root)).diagnostics
    assert not [d for d in found if d.code in ("RF101", "RF102")]
    # and with the number written out, the planner's 0.8 is reported again
    limiter.write_text(limiter.read_text().replace("<= LIMIT", "<= 0.5"))
    found = check_paths([root], Config(root=root)).diagnostics
    assert [Path(d.path).name for d in found if d.code == "RF101"] == ["planner.py"]


def test_a_fault_in_the_graph_stage_is_an_internal_error_not_a_crash(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A fault of ours while the graph is built is the run's internal error (exit
    status 2); the files' own findings are still reported."""
    from robotfix import graphcheck

    def broken(*args: object, **kwargs: object) -> None:
        raise ValueError("boom")

    monkeypatch.setattr(graphcheck, "check_graph", broken)
    root = tmp_path / "ws"
    shutil.copytree(CASES / "ros2_contracts", root)
    result = check_paths([root], Config(root=root))
    assert [e.summary for e in result.internal_errors] == ["ValueError: boom"]
    assert not [d for d in result.diagnostics if d.code in GRAPH_CODES]


def test_a_parameter_section_of_a_cpp_node_is_no_rf602(tmp_path: Path) -> None:
    """A YAML section keyed by a C++ node's name (`Node("driver")`) names a node
    RobotFix read: no RF602, with the cache too; a section naming no node still
    gets one, worded as what RobotFix read."""
    write(tmp_path / "driver" / "package.xml", PACKAGE.format("driver"))
    write(
        tmp_path / "driver" / "src" / "driver.cpp",
        "class Driver : public rclcpp::Node {\n public:\n"
        '  Driver() : Node("driver") { declare_parameter<double>("max", 0.5); }\n};\n',
    )
    write(
        tmp_path / "driver" / "config" / "driver.yaml",
        "driver:\n  ros__parameters:\n    max: 0.4\n"
        "drivr:\n  ros__parameters:\n    max: 0.4\n",
    )
    for cache in (False, True, True):
        found = check_paths([tmp_path], Config(root=tmp_path), use_cache=cache)
        assert [d.message.split(":")[0] for d in found.diagnostics] == [
            "section `drivr` names no node that RobotFix read in the checked "
            "workspace or its launch files"
        ]


@pytest.mark.parametrize(
    ("body", "expected"),
    [
        (
            "auto qos = rclcpp::QoS(rclcpp::KeepLast(10)); S(qos);",
            Q.depth_only(10),
        ),
        (
            "rclcpp::QoS qos(10); S(qos.best_effort());",
            Qos(Q.BEST_EFFORT, Q.VOLATILE, 10),
        ),
        ("rclcpp::QoS qos{5}; S(qos); P(qos);", Q.depth_only(5)),
        (
            "const auto qos = rclcpp::QoS(1).transient_local().reliable(); S(qos);",
            Qos(Q.RELIABLE, Q.TRANSIENT_LOCAL, 1),
        ),
        ("rclcpp::SensorDataQoS qos; S(qos);", Q.CPP_PROFILES["SensorDataQoS"]),
        # changed, bound twice, or given away: unknown
        ("rclcpp::QoS qos(10); qos.best_effort(); S(qos);", None),
        (
            "auto qos = rclcpp::QoS(10); qos = rclcpp::SensorDataQoS(); S(qos);",
            None,
        ),
        ("rclcpp::QoS qos(10); if (x) { rclcpp::QoS qos(1); } S(qos);", None),
        ("rclcpp::QoS qos(10); tune(qos); S(qos);", None),
        ("S(qos);", None),  # a member or a parameter
        ("S(qos); auto qos = rclcpp::QoS(10);", None),
        ("auto qos = qos; S(qos);", None),
    ],
)
def test_a_cpp_profile_held_in_a_local_bound_once(body: str, expected: object) -> None:
    """A C++ subscription's QoS held in a local variable is read from its one
    declaration (fresh-eyes r1); a local changed, declared twice, or passed to
    another function is unknown."""
    code = re.sub(
        r"\bS\(([^;]*)\);",
        r'sub_ = create_subscription<std_msgs::msg::String>("chatter", \1, cb);',
        body,
    ).replace("P(", 'pub_ = create_publisher<std_msgs::msg::String>("out", ')
    text = (
        "class Base : public rclcpp::Node {\n public:\n"
        '  Base() : Node("base") {\n    ' + code + "\n  }\n};\n"
    )
    found = read_cpp(text.encode())
    assert found.endpoints[0].kind == "subscription"
    assert found.endpoints[0].qos == expected


def test_a_cpp_local_profile_is_found_without_a_walk_of_the_body(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The mentions of a local profile are found in the body's bytes, each at
    its node (regression: every node of the function body was walked in
    Python, for each local a call passes: 7% of the subset's C++ reading); a
    body over `MAX_BODY_NODES` (counted in C) still makes it unknown."""
    from robotfix.ros.graph import cpp

    walked: list[object] = []

    class Body:  # the body node, noting whether its children are listed
        def __init__(self, node: object) -> None:
            self.node = node

        def __getattr__(self, name: str) -> object:
            if name == "children":
                walked.append(self.node)
            return getattr(self.node, name)

    real = cpp._body
    monkeypatch.setattr(cpp, "_body", lambda node: Body(real(node)))
    code = (
        b"class Base : public rclcpp::Node {\n public:\n"
        b'  Base() : Node("base") {\n    rclcpp::QoS qos(10);  // qos\n'
        b"    auto qos_other = 1;\n"
        b'    sub_ = create_subscription<T>("chatter", qos.best_effort(), cb);\n'
        b"  }\n};\n"
    )
    assert read_cpp(code).endpoints[0].qos == Qos(Q.BEST_EFFORT, Q.VOLATILE, 10)
    assert not walked
    monkeypatch.setattr(cpp, "MAX_BODY_NODES", 20)
    assert read_cpp(code).endpoints[0].qos is None


def test_cpp_functions_are_read_for_callbacks_only_when_a_subscription_asks(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """A function's first parameter is a roscpp subscription's message type only
    when the subscription names the function: a file without one reads none of
    its functions (regression: every function of every file was read)."""
    from robotfix.ros.graph import cpp

    read: list[object] = []
    real = cpp._File._function
    monkeypatch.setattr(
        cpp._File, "_function", lambda self, *a: read.append(a) or real(self, *a)
    )
    ros2 = (
        b"class Talker : public rclcpp::Node {\n public:\n"
        b'  Talker() : Node("talker") {\n'
        b'    pub_ = create_publisher<std_msgs::msg::String>("chatter", 10);\n  }\n'
        b"  void tick(int n) {}\n};\n"
    )
    assert [e.types for e in read_cpp(ros2).endpoints] == [("std_msgs/msg/String",)]
    assert not read
    ros1 = (
        b"void other(int n) {}\n"
        b"void cb(const std_msgs::String::ConstPtr & msg) {}\n"
        b"int main() {\n  ros::NodeHandle nh;\n"
        b'  ros::Subscriber s = nh.subscribe("chatter", 10, cb);\n}\n'
    )
    assert [e.types for e in read_cpp(ros1).endpoints] == [("std_msgs/msg/String",)]
    # those around the name `cb` (its definition, main's), not `other`
    assert [node.text.split(b"(")[0] for node, _ in read] == [b"void cb", b"int main"]


def test_qos_is_compared_only_between_endpoints_whose_types_can_meet(
    tmp_path: Path,
) -> None:
    """A best-effort `Twist` publisher never meets a reliable `TwistStamped`
    subscription (ROS connects no other types), so no RF604; the same node's
    `TwistStamped` publisher is the one compared."""
    write(tmp_path / "demo" / "package.xml", PACKAGE.format("demo"))
    write(
        tmp_path / "demo" / "demo" / "nodes.py",
        "from geometry_msgs.msg import Twist, TwistStamped\n"
        "from rclpy.node import Node\n"
        "from rclpy.qos import qos_profile_sensor_data\n"
        "class Teleop(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('teleop')\n"
        "        self.create_publisher(Twist, 'cmd_vel', qos_profile_sensor_data)\n"
        "        self.create_publisher(TwistStamped, 'cmd_vel', 10)\n"
        "class Base(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('base')\n"
        "        self.create_subscription(TwistStamped, 'cmd_vel', print, 10)\n",
    )
    found = check_paths([tmp_path], Config(root=tmp_path)).diagnostics
    assert not [d for d in found if d.code in GRAPH_CODES]


def test_a_cpp_node_class_named_by_its_caller_has_no_known_name() -> None:
    """`: Node(node_name)` computes the class's node name: unknown, never the
    name of the file's other node class (fresh-eyes r5)."""
    from robotfix.ros.graph.build import build

    found = read_cpp(
        b"class Logger : public rclcpp::Node {\n public:\n"
        b"  explicit Logger(const std::string & node_name) : Node(node_name) {\n"
        b'    create_subscription<std_msgs::msg::String>("output", 10, cb);\n  }\n};\n'
        b"class Test : public rclcpp::Node {\n public:\n"
        b'  Test() : Node("TestNode") {\n'
        b'    create_publisher<std_msgs::msg::String>("output", 10);\n  }\n};\n'
    )
    graph = build({"two_nodes.cpp": found}, [])
    assert sorted(n.qualified for n in graph.nodes) == [
        "/?(two_nodes.cpp)",
        "/TestNode",
    ]


def test_cpp_reading_is_the_same_every_time() -> None:
    """tree-sitter gives one name's captures in an order that varies between
    parses: functions of one name (a free `cb0` taking the message by value, a
    method `cb0` taking a `ConstPtr`) made a roscpp callback's type change from
    read to read (61 outcomes in 200 reads); the file's last one, in source
    order, is taken every time."""
    parts = ['#include "ros/ros.h"\n']
    parts += [f"void cb{i}(const std_msgs::String& msg) {{}}\n" for i in range(12)]
    parts.append("class Listener {\n public:\n")
    parts += [
        f"  void cb{i}(const std_msgs::String::ConstPtr& msg) {{}}\n" for i in range(12)
    ]
    parts.append("};\nint main(int argc, char** argv) {\n  ros::NodeHandle n;\n")
    parts += [f'  n.subscribe("t{i}", 10, cb{i});\n' for i in range(12)]
    data = "".join([*parts, "}\n"]).encode()
    reads = {tuple(e.types for e in read_cpp(data).endpoints) for _ in range(20)}
    assert reads == {(("std_msgs/msg/String",),) * 12}


def test_cpp_file_naming_no_endpoint_maker_is_not_parsed(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """`param` in `get_parameter`, `create_` in `create_wall_timer`: the words
    are there, but no name that makes an endpoint stands as a word."""
    from robotfix.ros.graph import cpp

    def parser() -> None:
        raise AssertionError("parsed")

    monkeypatch.setattr(cpp, "_parser", parser)
    data = (
        b'Timer() : Node("timer") {\n  this->get_parameter("period", period_);\n'
        b"  timer_ = create_wall_timer(1s, cb);\n}\n"
    )
    assert not read_cpp(data).endpoints


def test_cpp_scan_finds_the_makers_a_regex_between_word_boundaries_finds() -> None:
    """The bytes scan before a parse finds a maker's name (`makers_in`) only
    where it stands as a whole word, as the `\\b`-led regex it replaces did
    (regression: that regex tried every byte of every C++ file, 1% of
    corpus25's run in instructions)."""
    from robotfix.ros.graph import cpp_scan as scan

    words = sorted(w.decode() for w in scan._MAKERS)
    makers = re.compile(rb"\b(?:%b)\b" % "|".join(words).encode())
    assert all(any(w.startswith(s) for s in scan._MAKER_STARTS) for w in scan._MAKERS)
    samples = [
        b"x.param(a); get_param(b); @param c\n nh.advertiseService(s); subscribe",
        b"declare_parameter_if_not_declared(n, p) advertise_ create_server<T>(x)",
        b"Xadd_parameter(1) add_parameter(2) ClassLoader myClassLoader\n",
        b"allow_undeclared_parameters( true) zallow_undeclared_parameters(true)",
        b"_TwistPublisher TwistPublisher \xc3\xa9param param\xc3\xa9 paramx",
    ]
    for data in samples:
        found = [(m.start(), m.end(), m.group()) for m in makers.finditer(data)]
        assert sorted(scan.makers_in(data)) == found


def _counting_parses(monkeypatch: pytest.MonkeyPatch) -> list[bytes]:
    """The bytes of each C++ file tree-sitter parses from now on."""
    from robotfix.ros.graph import cpp

    parsed: list[bytes] = []
    real = cpp._parser()

    class Counting:
        def parse(self, data: bytes) -> object:
            parsed.append(data)
            return real.parse(data)

    monkeypatch.setattr(cpp, "_parser", Counting)
    return parsed


def test_cpp_file_naming_a_maker_in_its_comments_only_is_not_parsed(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """`@param` in a header's comments, `subscribe` in prose: a word, but no
    call; what the parse would find besides (a base class of another package's
    node, `::rclcpp::Node` too, a node class, or a maker called) still makes it
    parsed."""

    parsed = _counting_parses(monkeypatch)
    comment = b"/**\n * @param node the node to subscribe with\n */\n"
    header = comment + b"class Server {\n  rclcpp::Node::SharedPtr node_;\n};\n"
    assert not read_cpp(header).endpoints and not parsed
    for base in (b"nav2_util::LifecycleNode", b"::rclcpp::Node", b"util :: Node"):
        other = comment + b"class Server : public " + base + b" {\n};\n"
        found = read_cpp(other).endpoints
        assert [e.value for e in found] == [base.replace(b" ", b"").decode()]
    spaced = comment + b'void f() {\n  nh.param /* x */ ("rate", rate_, 1.0);\n}\n'
    assert [e.kind for e in read_cpp(spaced).endpoints] == ["parameter"]
    assert len(parsed) == 4


@pytest.mark.parametrize(
    ("code", "nodes", "ros"),
    [
        (  # a node class's header: its endpoints are made in its .cpp
            b"class Talker : public rclcpp::Node {\n public:\n"
            b"  /** @param options node options */\n"
            b"  explicit Talker(const rclcpp::NodeOptions & options);\n};\n",
            {"Talker": []},
            2,
        ),
        (
            b"class Talker : public rclcpp::Node {\n  /// @param options the options\n"
            b'  Talker() : Node("talker") {}\n};\n',
            {"Talker": ["talker"]},
            2,
        ),
        (  # ros_comm's rosbag/src/play.cpp, test_roscpp's nodes
            b"/**\n * @param argc the count\n */\nint main(int argc, char ** argv)\n"
            b'{\n  ros::init(argc, argv, "play");\n  ros::spin();\n}\n',
            {"": ["play"]},
            1,
        ),
        (
            b"/// @param argc the count\nint main(int argc, char ** argv) {\n"
            b'  auto node = rclcpp::Node::make_shared("talker");\n}\n',
            {"node": ["talker"]},
            2,
        ),
        (  # ros_comm's ros/topic.h: a ROS 1 file
            b"/** @param nh the handle to subscribe with */\n"
            b"void wait() {\n  ros::NodeHandle nh;\n  spin(nh);\n}\n",
            {},
            1,
        ),
    ],
)
def test_cpp_file_naming_a_maker_in_its_comments_only_still_names_its_node(
    code: bytes, nodes: dict[str, list[str]], ros: int
) -> None:
    """A file whose makers stand in comments only is still read for the node it
    names and whether it is ROS 1 (regression: the text test skipped the parse,
    and `@param` headers lost their node classes, roscpp mains their names)."""
    found = read_cpp(code)
    assert (found.nodes, found.ros, found.endpoints) == (nodes, ros, [])


def test_the_runs_cpp_reading_parses_no_file_that_can_make_no_endpoint(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The run keeps no graph without endpoints (`read_cpp_files`): a header
    that only names its node class, a roscpp header that declares
    `Publisher advertise(...)` (no call on a receiver: `_File._call` takes none
    without) are not parsed for it; `read_cpp` alone still reads their names,
    and a maker called on a receiver is parsed as before."""
    from robotfix.graphcheck import read_cpp_files

    parsed = _counting_parses(monkeypatch)
    header = (
        b"class Talker : public rclcpp::Node {\n  /// @param options the options\n"
        b'  Talker() : Node("talker") {}\n};\n'
    )
    declares = (
        b"namespace ros {\nclass NodeHandle {\n public:\n"
        b"  Publisher advertise(AdvertiseOptions & ops);\n"
        b"  Subscriber subscribe (SubscribeOptions & ops);\n};\n}\n"
    )
    calls = [
        b'void f() {\n  ros::NodeHandle nh;\n  nh.advertise<T>("a", 1);\n}\n',
        b'void f() {\n  auto nh = g();\n  nh->subscribe("/b", 1, cb);\n}\n',
        b'void f() {\n  ros::NodeHandle nh;\n  nh .\n    param("c", c, 1.0);\n}\n',
    ]
    paths = []
    for i, data in enumerate([header, declares, *calls]):
        paths.append(tmp_path / f"f{i}.cpp")
        paths[-1].write_bytes(data)
    found = read_cpp_files(paths)
    assert sorted(found) == [str(p) for p in paths[2:]]
    assert [e.name for p in paths[2:] for e in found[str(p)].endpoints] == [
        "a",
        "/b",
        "c",
    ]
    assert parsed == calls
    assert read_cpp(header).nodes == {"Talker": ["talker"]}


_CODE = b'void f() {\n  ros::NodeHandle nh;\n  *pub = nh.advertise<T>("a", 1);\n}\n'


def test_cpp_file_naming_another_node_class_as_a_scope_only_is_not_parsed(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """`nav2::LifecycleNode::WeakPtr parent`: another package's node class with
    `::` after it is no base class's last name (nav2's headers: 142 of the 150
    files of corpus25 parsed for no endpoint); as a base, or with a comment
    before the `::`, it is parsed, and reads what a parse reads."""
    from robotfix.ros.graph import cpp

    parsed = _counting_parses(monkeypatch)
    scope = (
        b"/** @param parent the node */\nclass Server {\n"
        b"  void configure(const nav2::LifecycleNode :: WeakPtr & parent);\n};\n"
    )
    assert not read_cpp(scope, names=False).endpoints and not parsed
    for text in (
        scope.replace(b"class Server", b"class S : public nav2::LifecycleNode"),
        scope.replace(b"Node :: ", b"Node/**/::"),
    ):
        found = read_cpp(text, names=False).endpoints
        assert len(parsed) == 1
        with monkeypatch.context() as m:
            m.setattr(cpp, "may_make", lambda *args: True)  # the parse's reading
            assert found == read_cpp(text, names=False).endpoints
        parsed.clear()
    based = scope.replace(b"class Server", b"class S : nav2::LifecycleNode")
    assert [e.value for e in read_cpp(based).endpoints] == ["nav2::LifecycleNode"]


@pytest.mark.parametrize(
    ("text", "parse"),
    [
        (  # roscpp's node_handle.h: example code in a doc comment
            b"class NodeHandle {\n  /**\n   * \\code\n   *   ros::Publisher pub = "
            b'handle.advertise<std_msgs::Empty>("my_topic", 1);\n   * \\endcode\n'
            b"   */\n  Publisher advertise(AdvertiseOptions & ops);\n};\n",
            False,
        ),
        (b"/*\n" + _CODE + b"*/\n", False),  # code commented out
        (b"/* x */\n" + _CODE, True),  # the comment ends before
        (b'const char * s = "/*";\n' + _CODE, True),  # a string's `/*`
        (b"int x; /* y\n" + _CODE + b"*/\n", True),  # after code: a lexer's to say
        (b"// a line comment going on \\\n/*\n" + _CODE, True),
        (b'#define S "a\\\n/*"\n' + _CODE, True),  # a string going on
        (b'auto s = R"(\n/*)";\n' + _CODE, True),  # a raw string's
        (b"/*/\n" + _CODE, True),  # `/*/` opens a comment, `*/` after is unsure
    ],
)
def test_a_maker_called_in_a_block_comment_makes_no_parse(
    text: bytes, parse: bool, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A call written inside a `/* */` comment that surely is one (its `/*`
    begins its line, no line going on before it, no raw string before it: roscpp's
    `node_handle.h`, 103 KB) makes no parse; what only a lexer could tell is
    parsed. Either way the endpoints are what the parse reads."""
    from robotfix.ros.graph import cpp

    parsed = _counting_parses(monkeypatch)
    found = read_cpp(text, names=False).endpoints
    assert bool(parsed) is parse
    monkeypatch.setattr(cpp, "may_make", lambda *args: True)  # the parse's reading
    assert found == read_cpp(text, names=False).endpoints


def test_the_cpp_scan_parses_every_file_of_the_cases_that_makes_an_endpoint(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Every C++ file of the tests: the endpoints read after the byte scan are
    those a parse of each file reads (the scan only spares parses)."""
    from robotfix.ros.graph import cpp

    files = [
        p
        for p in sorted(Path(__file__).parent.rglob("*"))
        if p.suffix in (".cpp", ".hpp", ".h", ".cc", ".hh", ".cxx")
    ]
    assert len(files) >= 9
    scanned = [read_cpp(p.read_bytes(), names=False).endpoints for p in files]
    monkeypatch.setattr(cpp, "may_make", lambda *args: True)
    assert scanned == [read_cpp(p.read_bytes(), names=False).endpoints for p in files]


def test_python_graph_walks_no_nested_statement_where_no_wanted_call_starts(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """With the check's calls given, a loop or branch inside a statement that
    holds an endpoint call is not walked when none of the wanted calls starts
    in it (regression: the whole `try` around a `main` was walked node by node)."""
    from robotfix.ros.graph import python as G

    tree = ast.parse(
        "import rclpy\nimport std_msgs.msg\ndef main():\n"
        "    node = rclpy.create_node('n')\n    try:\n"
        "        for i in range(3):\n            print(sum(x * x for x in range(i)))\n"
        "        node.create_publisher(std_msgs.msg.String, 'out', 10)\n"
        "    finally:\n        rclpy.shutdown()\n"
    )
    loop = tree.body[2].body[1].body[0]
    inside = {id(n) for n in ast.walk(loop)}
    seen: list[ast.AST] = []
    real = G.children
    monkeypatch.setattr(G, "children", lambda node: seen.append(node) or real(node))
    found = G.read_python(tree, index_of(tree).calls)
    assert [(e.name, e.types, e.owner) for e in found.endpoints] == [
        ("out", ("std_msgs/msg/String",), "node")
    ]
    assert found.nodes == {"node": ["n"]}
    assert seen and not [n for n in seen if id(n) in inside]


def test_python_graph_looks_up_only_calls_whose_last_name_may_make_something(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """With the check's calls given, a call `x.y()` whose `y` names neither an
    endpoint nor a node maker is not looked up through the imports (nor met
    again in the walk); an alias imported under another name still is."""
    from robotfix.ros.graph import python_names

    source = (
        "import rclpy\nfrom rospy import Publisher as P\nimport std_msgs.msg as m\n"
        "class A(rclpy.node.Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('a')\n"
        "        self.log.info(len(str(self.x.y.z())))\n"
        "        self.p = P('chatter', m.String, queue_size=1)\n"
        "        rclpy.create_node('b')\n"
    )
    tree = ast.parse(source)
    looked: list[str] = []
    qualified = python_names.File.qualified

    def counting(self: object, node: ast.expr) -> str | None:
        looked.append(ast.unparse(node))
        return qualified(self, node)  # type: ignore[arg-type]

    monkeypatch.setattr(python_names.File, "qualified", counting)
    found = read_python(tree, index_of(tree).calls)
    assert [(e.kind, e.name) for e in found.endpoints] == [("publisher", "chatter")]
    assert found.nodes == {"A": ["a"]}
    assert "self.log.info" not in looked and "self.x.y.z" not in looked
    assert "len" not in looked and "str" not in looked  # no import binds them
    assert "P" in looked and "rclpy.create_node" in looked


def _ros1_system(root: Path, package: str, files: dict[str, str]) -> list[tuple]:
    """A ROS 1 package whose `scripts/` a bringup launch file starts (each script
    as the node its stem names), checked: each finding's file, line and code."""
    write(root / "bringup" / "package.xml", PACKAGE.format("bringup"))
    nodes = "".join(
        f'  <node pkg="{package}" type="{name}" name="{name[:-3]}"/>\n'
        for name in files
        if name.endswith(".py")
    )
    write(root / "bringup" / "launch" / "all.launch", f"<launch>\n{nodes}</launch>\n")
    write(root / package / "package.xml", PACKAGE.format(package))
    for name, text in files.items():
        folder = "scripts" if name.endswith(".py") else "action"
        write(root / package / folder / name, text)
    found = check_paths([root], Config(root=root)).diagnostics
    return [(Path(d.path).name, d.span.line, d.code) for d in found]


def test_a_rospy_publisher_in_a_class_meets_its_subscribers_contract(
    tmp_path: Path,
) -> None:
    """A ROS 1 file's endpoints have no owner (one node per file), but its
    publisher kept in `self.pub` is that class's: the contract is checked there
    (it was never matched before)."""
    listener = (
        "from typing import Annotated\nimport rospy\nfrom std_msgs.msg import Float64\n"
        "def callback(msg: Annotated[Float64, '0 <= data <= 20']):\n"
        "    rospy.loginfo(msg.data)\n"
        "rospy.init_node('listener')\n"
        "rospy.Subscriber('effort', Float64, callback)\n"
    )
    talker = (
        "import rospy\nfrom std_msgs.msg import Float64\n"
        "class Talker:\n"
        "    def __init__(self):\n"
        "        self.pub = rospy.Publisher('effort', Float64, queue_size=10)\n"
        "    def squeeze(self):\n"
        "        self.pub.publish(Float64(40.0))\n"
        "rospy.init_node('talker')\n"
    )
    found = _ros1_system(
        tmp_path, "grip", {"listener.py": listener, "talker.py": talker}
    )
    assert found == [("talker.py", 7, "RF101")]


def test_an_actionlib_goal_meets_its_simple_action_servers_contract(
    tmp_path: Path,
) -> None:
    """actionlib_tutorials' Fibonacci: the server's `execute_cb` takes the goal,
    and refines it (int32 overflows past the 46th number); a client's
    `send_goal` of a goal that breaks it is RF101, one that keeps it nothing."""
    server = (
        "from typing import Annotated\nimport actionlib\nimport rospy\n"
        "from fib.msg import FibonacciAction, FibonacciGoal\n"
        "class FibonacciServer:\n"
        "    def __init__(self):\n"
        "        self._as = actionlib.SimpleActionServer(\n"
        "            'fibonacci', FibonacciAction, execute_cb=self.execute_cb,\n"
        "            auto_start=False)\n"
        "        self._as.start()\n"
        "    def execute_cb(\n"
        "            self, goal: Annotated[FibonacciGoal, '0 <= order <= 46']):\n"
        "        rospy.loginfo(goal.order)\n"
        "rospy.init_node('fibonacci')\n"
        "server = FibonacciServer()\n"
    )
    client = (
        "import actionlib\nimport rospy\n"
        "from fib.msg import FibonacciAction, FibonacciGoal\n"
        "class Client:\n"
        "    def __init__(self):\n"
        "        self.client = actionlib.SimpleActionClient(\n"
        "            'fibonacci', FibonacciAction)\n"
        "    def run(self):\n"
        "        self.client.send_goal(FibonacciGoal(order=20))\n"
        "        self.client.send_goal(FibonacciGoal(order=50))\n"
        "rospy.init_node('client')\n"
    )
    files = {
        "Fibonacci.action": "int32 order\n---\nint32[] sequence\n---\nint32[] a\n",
        "fibonacci.py": server,
        "client.py": client,
    }
    assert _ros1_system(tmp_path, "fib", files) == [("client.py", 10, "RF101")]


def test_a_contract_finding_shows_the_way_through_the_graph() -> None:
    """The note of a contract's finding names the sender, the name and the
    taker, and points at the launch entry that starts the sender."""
    root = CASES / "ros2_services"
    found = check_paths([root], Config(root=root)).diagnostics
    [error] = [
        d for d in found if d.code == "RF101" and Path(d.path).name == "cruise.py"
    ]
    note = error.notes[-1]
    assert "(/cruise -> /set_max_speed -> /limit_server)" in note.message
    assert "the server's callback assumes this of every request" in note.message
    assert (Path(note.path or "").name, note.line) == ("speed.launch.py", 8)


def test_a_rospy_proxy_called_with_some_fields_by_position_is_not_checked(
    tmp_path: Path,
) -> None:
    """genpy builds a request of every field by position (or some by keyword):
    `proxy(0.2)` of a two-field request raises TypeError before anything is
    sent, so what the other field would hold is not checked; all of them by
    position is (the server assumes `width <= 0.08`)."""
    root = tmp_path / "ws"
    shutil.copytree(CASES / "ros1_services", root)
    place = root / "arm_control" / "scripts" / "place.py"
    text = place.read_text()
    place.write_text(
        text.replace(
            "self.set_gripper(width=0.05, effort=5.0)", "self.set_gripper(0.2)"
        )
    )
    assert not [
        d
        for d in check_paths([root], Config(root=root)).diagnostics
        if "place" in d.path
    ]
    place.write_text(text.replace("width=0.05, effort=5.0", "0.2, 5.0"))
    found = check_paths([root], Config(root=root)).diagnostics
    assert [(Path(d.path).name, d.code) for d in found if "place" in d.path] == [
        ("place.py", "RF101")
    ]


ASSUMED = "success == True"  # what place.py assumes of the gripper's response


@pytest.mark.parametrize(
    ("returned", "codes"),
    [
        ("SetGripperResponse(True)", []),
        ("SetGripperResponse(False)", ["RF101"]),
        ("SetGripperResponse(success=req.width <= 0.05)", ["RF102"]),
    ],
)
@pytest.mark.parametrize(
    "received",
    [
        "self.set_gripper(0.05, 5.0)",
        "self.set_gripper.call(SetGripperRequest(0.05, 0))",
    ],
)
def test_a_rospy_clients_refined_response_is_checked_at_the_servers_return(
    tmp_path: Path, returned: str, codes: list[str], received: str
) -> None:
    """What a rospy client assumes of the response a proxy's call returns
    (`ok: Annotated[SetGripperResponse, "success == True"] = self.set_gripper(...)`)
    is checked at the `return` of its server's handler."""
    root = tmp_path / "ws"
    shutil.copytree(CASES / "ros1_services", root)
    place = root / "arm_control" / "scripts" / "place.py"
    place.write_text(
        place.read_text()
        .replace(
            "import rospy\n",
            "from typing import Annotated\n\nimport rospy\n",
        )
        .replace("SetGripperRequest\n", "SetGripperRequest, SetGripperResponse\n")
        .replace(
            "        self.set_gripper(width=0.05, effort=5.0)\n",
            f"        ok: Annotated[SetGripperResponse, {ASSUMED!r}] = {received}\n",
        )
    )
    server = root / "arm_control" / "scripts" / "gripper_server.py"
    server.write_text(server.read_text().replace("SetGripperResponse(True)", returned))
    found = check_paths([root], Config(root=root)).diagnostics
    at_server = [d for d in found if d.path == str(server)]
    assert [d.code for d in at_server] == codes
    for d in at_server:
        assert d.span.line == 12
        assert d.notes[0].path == str(place)
        assert "the client assumes this of every response" in d.notes[-1].message


def test_a_contract_through_an_alias_meets_publishers_held_in_locals(
    tmp_path: Path,
) -> None:
    """rospy_tutorials' talker keeps its publisher in a local of `talker()`, and a
    subscriber may write its refinement once as a module-level alias: both were
    silent (a contract was read only as `Annotated[...]` written in the callback's
    signature, and only publishers kept in `self.x` were matched). Each function's
    local is its own publisher."""
    listener = (
        "from typing import Annotated\nimport rospy\nfrom std_msgs.msg import Float64\n"
        "Effort = Annotated[Float64, '0 <= data <= 20']\n"
        "def callback(msg: Effort):\n"
        "    rospy.loginfo(msg.data)\n"
        "rospy.init_node('listener')\n"
        "rospy.Subscriber('effort', Float64, callback)\n"
    )
    talker = (
        "import rospy\nfrom std_msgs.msg import Float64\n"
        "def squeeze():\n"
        "    pub = rospy.Publisher('effort', Float64, queue_size=10)\n"
        "    pub.publish(Float64(40.0))\n"
        "def hold():\n"
        "    pub = rospy.Publisher('effort', Float64, queue_size=10)\n"
        "    pub.publish(Float64(5.0))\n"
        "class Recorder:\n"
        "    def publish(self, msg):\n"
        "        rospy.loginfo(msg)\n"
        "def rehearse():\n"
        "    pub = rospy.Publisher('effort', Float64, queue_size=10)\n"
        "    pub = Recorder()  # a dry run: nothing is sent\n"
        "    pub.publish(Float64(40.0))\n"
        "rospy.init_node('talker')\n"
    )
    found = _ros1_system(
        tmp_path, "grip", {"listener.py": listener, "talker.py": talker}
    )
    assert found == [("talker.py", 5, "RF101")]


def test_a_clash_a_remapping_makes_points_at_the_remapping(tmp_path: Path) -> None:
    """A launch file's `<remap>` that puts a Twist publisher on a TwistStamped
    topic: the RF603 at both endpoints says where the remapping is, the line a
    user changes (fresh-eyes round w05: only the endpoints were shown)."""
    write(tmp_path / "bringup" / "package.xml", PACKAGE.format("bringup"))
    write(
        tmp_path / "bringup" / "launch" / "teleop.launch",
        "<launch>\n"
        '  <node pkg="teleop" type="keys.py" name="keys">\n'
        '    <remap from="key_vel" to="cmd_vel"/>\n'
        "  </node>\n"
        '  <node pkg="teleop" type="base.py" name="base"/>\n'
        "</launch>\n",
    )
    write(tmp_path / "teleop" / "package.xml", PACKAGE.format("teleop"))
    write(
        tmp_path / "teleop" / "scripts" / "keys.py",
        "import rospy\nfrom geometry_msgs.msg import Twist\n"
        "rospy.init_node('keys')\n"
        "pub = rospy.Publisher('key_vel', Twist, queue_size=1)\n",
    )
    write(
        tmp_path / "teleop" / "scripts" / "base.py",
        "import rospy\nfrom geometry_msgs.msg import TwistStamped\n"
        "def on_cmd(msg):\n    pass\n"
        "rospy.init_node('base')\n"
        "rospy.Subscriber('cmd_vel', TwistStamped, on_cmd)\n",
    )
    found = check_paths([tmp_path], Config(root=tmp_path)).diagnostics
    clashes = [d for d in found if d.code == "RF603"]
    assert len(clashes) == 2
    for diag in clashes:
        [note] = [n for n in diag.notes if "remapping makes" in n.message]
        assert (
            note.message == "this remapping makes `key_vel` of node `/keys` `/cmd_vel`"
        )
        assert (Path(note.path or "").name, note.line) == ("teleop.launch", 3)


def test_an_extensionless_rospy_script_meets_its_subscribers_contract(
    tmp_path: Path,
) -> None:
    """ROS 1's usual layout: `scripts/draw_square` with a shebang and no `.py`.
    Its publisher was read for the graph but never checked against a contract
    (only `.py` files were taken for Python; the second fresh-eyes round, c08)."""
    write(tmp_path / "bringup" / "package.xml", PACKAGE.format("bringup"))
    write(
        tmp_path / "bringup" / "launch" / "all.launch",
        '<launch>\n  <node pkg="guard" type="draw_square" name="draw_square"/>\n'
        '  <node pkg="guard" type="guard" name="guard"/>\n</launch>\n',
    )
    write(tmp_path / "guard" / "package.xml", PACKAGE.format("guard"))
    write(
        tmp_path / "guard" / "scripts" / "guard",
        "#!/usr/bin/env python\nfrom typing import Annotated\nimport rospy\n"
        "from geometry_msgs.msg import Twist\n"
        "def on_cmd(msg: Annotated[Twist, 'abs(linear.x) <= 2.0']):\n"
        "    rospy.loginfo(msg.linear.x)\n"
        "rospy.init_node('guard')\n"
        "rospy.Subscriber('turtle1/cmd_vel', Twist, on_cmd)\n",
    )
    write(
        tmp_path / "guard" / "scripts" / "draw_square",
        "#!/usr/bin/env python\nimport rospy\nfrom geometry_msgs.msg import Twist\n"
        "rospy.init_node('draw_square')\n"
        "pub = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=1)\n"
        "twist = Twist()\ntwist.linear.x = 4.0\npub.publish(twist)\n",
    )
    found = check_paths([tmp_path], Config(root=tmp_path)).diagnostics
    assert [(Path(d.path).name, d.span.line, d.code) for d in found] == [
        ("draw_square", 8, "RF101")
    ]


def test_a_frame_contract_on_any_message_with_a_header(tmp_path: Path) -> None:
    """`Frame('laser')` on a `sensor_msgs/LaserScan` callback: the header's frame
    is compared for every message type with a `header`, not only the geometry
    types whose data the header frames (the second fresh-eyes round's c02, after
    f1tenth's gym_bridge, was a miss); the near miss names the frame assumed."""
    listener = (
        "from typing import Annotated\nimport rospy\n"
        "from sensor_msgs.msg import LaserScan\n"
        "def on_scan(msg: Annotated[LaserScan, \"Frame('laser')\"]):\n"
        "    rospy.loginfo(msg.range_max)\n"
        "rospy.init_node('follower')\n"
        "rospy.Subscriber('scan', LaserScan, on_scan)\n"
    )
    talker = (
        "import rospy\nfrom sensor_msgs.msg import LaserScan\n"
        "rospy.init_node('bridge')\n"
        "pub = rospy.Publisher('scan', LaserScan, queue_size=1)\n"
        "scan = LaserScan()\nscan.header.frame_id = 'base_link'\npub.publish(scan)\n"
        "ok = LaserScan()\nok.header.frame_id = 'laser'\npub.publish(ok)\n"
    )
    found = _ros1_system(
        tmp_path, "scanner", {"follower.py": listener, "bridge.py": talker}
    )
    assert found == [("bridge.py", 7, "RF201")]


def test_a_node_and_a_client_made_inside_a_block_are_read() -> None:
    """demos' add_two_ints_client makes its node and client inside `try:` /
    `with rclpy.init():`: the node's name and the client's holder (`:main/cli`,
    which the client's check names at `call_async`) come from the statement that
    makes each, not from the block that holds it. (They were read only from a
    function's own statements: the node was `?(...)` and the contract unchecked.)"""
    found = _py(
        "import rclpy\n"
        "from example_interfaces.srv import AddTwoInts\n"
        "def main():\n"
        "    try:\n"
        "        with rclpy.init():\n"
        "            node = rclpy.create_node('add_two_ints_client')\n"
        "            if node:\n"
        "                cli = node.create_client(AddTwoInts, 'add_two_ints')\n"
        "    except KeyboardInterrupt:\n"
        "        pass\n"
    )
    assert found.nodes == {"node": ["add_two_ints_client"]}
    assert [(e.name, e.holder) for e in found.endpoints] == [
        ("add_two_ints", ":main/cli")
    ]
