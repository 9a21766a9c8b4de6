"""Lists of messages (issue 8, item 5, last part): an element of a message array
field is a message of its element type. One that arrived satisfies its type's
refinements; one of an array of unknown origin is typed but unknown (a read can
only warn); a write into it is checked against its type."""

from __future__ import annotations

from pathlib import Path

from robotfix.api import check_source, interface_files
from robotfix.config import Config
from robotfix.ros.catalog import MsgCatalog

HEADER = (
    "from typing import Annotated\n\nfrom rclpy.node import Node\n"
    "from my_pkg.msg import Route, Waypoint\n\n\n"
)
SHIFT = HEADER.count("\n")


def catalog(tmp_path: Path) -> MsgCatalog:
    folder = tmp_path / "my_pkg" / "msg"
    folder.mkdir(parents=True)
    (folder / "Waypoint.msg").write_text(
        "float64 x  # [m]\nfloat64 speed  #RobotFix# 0 <= _ <= 2\n", encoding="utf-8"
    )
    (folder / "Route.msg").write_text(
        "Waypoint[] points\nWaypoint[3] corners\n", encoding="utf-8"
    )
    return MsgCatalog(interface_files([folder]))


def check(tmp_path: Path, source: str) -> list[tuple[str, int]]:
    found = check_source(HEADER + source, "node.py", Config(), catalog(tmp_path))
    return sorted((d.code, d.span.line - SHIFT) for d in found)


def test_a_received_element_satisfies_its_type(tmp_path: Path) -> None:
    source = (
        "def on_route(route: Route) -> None:\n"
        '    a: Annotated[float, "0 <= _ <= 2"] = route.points[0].speed\n'
        '    c: Annotated[list[float], "_ >= 0"] = [p.speed for p in route.points]\n'
        "    d: Annotated[float, \"Unit('m')\"] = route.corners[2].x\n"
        '    e: Annotated[float, "_ <= 1"] = route.points[0].speed\n'
        "    f: Annotated[float, \"Unit('s')\"] = route.points[0].x\n"
        "    for p in route.points:\n"
        '        b: Annotated[float, "_ <= 2"] = p.speed\n'
    )
    assert check(tmp_path, source) == [("RF102", 5), ("RF201", 6)]


def test_an_element_of_unknown_origin_is_typed_but_unknown(tmp_path: Path) -> None:
    source = (
        "class Planner(Node):\n"
        "    route: Route\n\n"
        "    def on_timer(self) -> None:\n"
        "        a: Annotated[float, \"Unit('m')\"] = self.route.points[0].x\n"
        '        b: Annotated[float, "_ <= 2"] = self.route.points[0].speed\n'
    )
    found = check(tmp_path, source)
    assert all(code != "RF201" for code, _ in found)
    assert all(code == "RF102" for code, line in found if line == 6)


def test_a_write_into_an_element_is_checked(tmp_path: Path) -> None:
    source = (
        "def on_route(route: Route) -> None:\n"
        '    s: Annotated[list[float], "_ <= 4"] = [\n'
        "        a.speed + b.speed for a, b in zip(route.points, route.corners)]\n"
        "    route.points[0].speed = 5.0\n"
        "    route.points[1].speed = 1.0\n"
        "    for p in route.points:\n"
        "        p.speed = -1.0\n"
    )
    assert check(tmp_path, source) == [("RF101", 4), ("RF101", 7)]
