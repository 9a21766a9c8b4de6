"""The editor (issue 11, item 5): hover on declarations and assignment targets, a
sub-message's field units, and a language server that re-checks the open documents
that depend on a changed interface file or module.

In-process through `api.hover`, and as a real client session with `robotfix lsp`
(as tests/test_lsp.py does)."""

from __future__ import annotations

import keyword
from pathlib import Path
from typing import Any
from urllib.parse import unquote

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from robotfix import api, dependents
from robotfix.ros.catalog import MsgCatalog
from tests.lsp_client import Client

# The new-user report's P11: hover answered on reads of `turn` but was null on its
# declaration and on assignment targets, and showed a sub-message without units.
TELEOP = """from typing import Annotated
from geometry_msgs.msg import Twist

turn: Annotated[float, "Unit('deg/s') and abs(_) <= 90"] = 30.0
speed: Annotated[float, "Unit('m/s')"]
speed = 0.5
twist = Twist()
twist.linear.x = speed
spin = twist.angular


class Teleop:
    limit: Annotated[float, "Unit('m/s') and _ > 0"]

    def __init__(self, rate: Annotated[float, "Unit('Hz')"]) -> None:
        self.limit = 1.0
        self.rate = rate
"""


def hover_at(text: str, line: int, word: str, catalog: MsgCatalog | None = None) -> str:
    """Hover over the first character of `word` on 1-based `line`."""
    col = text.splitlines()[line - 1].index(word)
    found = api.hover(text, "teleop.py", line, col, catalog or MsgCatalog([]))
    assert found is not None, f"no hover on {word!r} at line {line}"
    return found


def test_hover_on_an_annotated_declaration_with_a_value() -> None:
    found = hover_at(TELEOP, 4, "turn")
    assert found.startswith("**turn**: `float` in `deg/s`")
    assert "refinement `abs(_) <= 90` (line 4)" in found


def test_hover_on_a_declaration_without_a_value_and_its_assignment() -> None:
    assert hover_at(TELEOP, 5, "speed").startswith("**speed**: `float` in `m/s`")
    assert hover_at(TELEOP, 6, "speed").startswith("**speed**: `float` in `m/s`")


def test_hover_on_a_field_assignment_target() -> None:
    line = TELEOP.splitlines()[7]
    assert line == "twist.linear.x = speed"
    for col in (line.index(".x") + 1, line.index("linear")):
        found = api.hover(TELEOP, "teleop.py", 8, col, MsgCatalog([]))
        assert found is not None
    x = api.hover(TELEOP, "teleop.py", 8, line.index(".x") + 1, MsgCatalog([]))
    assert x == "**linear.x** of `geometry_msgs/Twist`: `float` in `m/s`"


def test_a_sub_message_shows_its_type_and_the_units_of_its_fields() -> None:
    linear = hover_at(TELEOP, 8, "linear")
    assert linear.startswith("**linear** of `geometry_msgs/Twist`: `geometry_msgs/")
    assert "fields: `x`, `y`, `z` in `m/s`" in linear
    spin = hover_at(TELEOP, 9, "spin")  # an assignment target holding a sub-message
    assert "fields: `x`, `y`, `z` in `rad/s`" in spin
    twist = hover_at(TELEOP, 7, "twist")
    assert "`linear.x`, `linear.y`, `linear.z` in `m/s`" in twist
    assert "`angular.x`, `angular.y`, `angular.z` in `rad/s`" in twist


def test_hover_on_class_attributes_parameters_and_self_targets() -> None:
    limit = hover_at(TELEOP, 13, "limit")
    assert limit.startswith("**limit**: `float` in `m/s` — refinement `_ > 0`")
    assert hover_at(TELEOP, 15, "rate").startswith("**rate**: `float` in `Hz`")
    target = hover_at(TELEOP, 16, "limit")
    assert target.startswith("**self.limit**: `float` in `m/s` — refinement `_ > 0`")
    assert hover_at(TELEOP, 17, "rate =").startswith("**self.rate**: `float` in `Hz`")
    assert hover_at(TELEOP, 16, "self") == "**self**: `Teleop`"


def test_units_of_a_user_sub_message_come_from_the_enclosing_message(
    tmp_path: Path,
) -> None:
    msg = tmp_path / "nav_pkg" / "msg"
    msg.mkdir(parents=True)
    (msg / "Leg.msg").write_text("float64 length\nfloat64 duration\n")
    (msg / "Route.msg").write_text(
        'Leg first\n#RobotFix# Unit(first.length) == "m"\n'
        'float64 eta  #RobotFix# Unit(eta) == "s"\n'
    )
    text = (
        "from nav_pkg.msg import Route\n\nroute = Route()\nroute.first.duration = 1.0\n"
    )
    catalog = MsgCatalog([msg / "Leg.msg", msg / "Route.msg"])
    first = hover_at(text, 4, "first", catalog)
    assert first.startswith("**first** of `nav_pkg/Route`: `nav_pkg/Leg`")
    assert first.endswith("fields: `length` in `m`")
    route = hover_at(text, 3, "route", catalog)
    assert route.endswith("fields: `first.length` in `m`; `eta` in `s`")


UNITS = ["m", "m/s", "rad/s", "s", "kg", "deg"]
NAMES = st.from_regex(r"[a-z][a-z0-9_]{0,8}", fullmatch=True).filter(
    lambda n: not keyword.iskeyword(n) and n not in ("abs", "min", "max")
)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(NAMES, st.sampled_from(UNITS), st.data())
def test_hover_anywhere_on_a_declared_name(name: str, unit: str, data: Any) -> None:
    text = (
        "from typing import Annotated\n"
        f"{name}: Annotated[float, \"Unit('{unit}')\"] = 1.0\n"
        f"{name} = 2.0\n"
        f"other = {name}\n"
    )
    col = data.draw(st.integers(0, len(name) - 1))
    for line in (2, 3, 4):
        at = col + (len("other = ") if line == 4 else 0)
        found = api.hover(text, "n.py", line, at, MsgCatalog([]))
        assert found is not None and found.startswith(f"**{name}**: `float` in `")
    after = api.hover(text, "n.py", 2, len(name), MsgCatalog([]))
    assert after is None  # the colon after the name is not the name


# -- dependents: syntactic scans -------------------------------------------------


def test_imports_module_follows_relative_absolute_and_script_imports(
    tmp_path: Path,
) -> None:
    package = tmp_path / "ws" / "src" / "driver" / "driver"
    package.mkdir(parents=True)
    helper, node = package / "helper.py", package / "node.py"
    for module in (package / "__init__.py", helper, node):
        module.write_text("")
    (package.parent / "package.xml").write_text(
        "<package><name>driver</name></package>"
    )
    forms = [
        "from driver.helper import clamp",
        "from driver import helper",
        "import driver.helper as h",
        "from . import helper",
        "from .helper import clamp",
    ]
    for form in forms:
        assert dependents.imports_module(form + "\n", node, helper), form
    for form in ["import helperx", "from driver import node", "from .. import helper"]:
        assert not dependents.imports_module(form + "\n", node, helper), form
    assert not dependents.imports_module("def f(:\n", node, helper)
    init = package / "__init__.py"
    assert dependents.imports_module("from .helper import x\n", node, init)
    assert dependents.imports_module("import driver.helper\n", node, init)
    scripts = package.parent / "scripts"  # a ROS 1 script imports its neighbour
    scripts.mkdir()
    (scripts / "helper.py").write_text("")
    assert dependents.imports_module(
        "import helper\n", scripts / "n", scripts / "helper.py"
    )
    assert not dependents.imports_module(
        "import helper\n", node, helper
    )  # no implicit relative import
    helper.unlink()  # a deleted module: its importers are still found
    assert dependents.imports_module("from .helper import clamp\n", node, helper)
    # through a module of the tree that imports it (its summary carries aliases)
    helper.write_text("")
    (package / "units.py").write_text("from .helper import Meters\n")
    assert dependents.imports_module("from driver.units import X\n", node, helper)


def test_uses_interface_follows_imports_and_nested_types(tmp_path: Path) -> None:
    msg = tmp_path / "nav_pkg" / "msg"
    msg.mkdir(parents=True)
    (msg / "Leg.msg").write_text("float64 length\n")
    (msg / "Route.msg").write_text("Leg first\n")
    catalog = MsgCatalog([msg / "Leg.msg", msg / "Route.msg"])
    leg = dependents.interface_types(msg / "Leg.msg", "float64 length\n")
    assert leg == {"nav_pkg/Leg"}
    here = tmp_path / "node.py"
    for uses in [
        "from nav_pkg.msg import Leg",
        "from nav_pkg.msg import Route",  # Route contains a Leg
        "import nav_pkg.msg",
        "from nav_pkg import msg",
        "from nav_pkg.msg import *",
        "from nav_pkg import Leg",  # the seed's bare form
    ]:
        assert dependents.uses_interface(uses + "\n", here, catalog, leg), uses
    for other in ["from geometry_msgs.msg import Twist", "import nav_pkg", "x = 1"]:
        assert not dependents.uses_interface(other + "\n", here, catalog, leg), other
    service = dependents.interface_types(Path("pkg/srv/Stop.srv"), "")
    assert service == {"pkg/Stop_Request"}  # a file that is gone: from its path
    ros1 = "from pkg.srv import StopRequest\n"
    assert dependents.uses_interface(ros1, here, catalog, service)


# -- a real language-server session ----------------------------------------------

NODE = """from typing import Annotated
from nav_pkg.msg import Reading

reading = Reading()
far: Annotated[float, "Unit('km')"] = 2.0
reading.dist = far
"""
UNRELATED = """from typing import Annotated
from geometry_msgs.msg import Twist

speed: Annotated[float, "Unit('m/s')"] = 1.0
"""
METRES = 'float64 dist  #RobotFix# Unit(dist) == "m"\n'
KILOMETRES = 'float64 dist  #RobotFix# Unit(dist) == "km"\n'


class Session:
    """A client speaking to `robotfix lsp`, collecting what the server publishes."""

    def __init__(self, dynamic_watchers: bool) -> None:
        self.client = Client()
        self.dynamic = dynamic_watchers
        self.version = 1

    def start(self, root: Path) -> None:
        watched = {"dynamicRegistration": self.dynamic}
        self.client.initialize(root, {"workspace": {"didChangeWatchedFiles": watched}})

    @property
    def registrations(self) -> list[dict[str, Any]]:
        return [
            r["params"]
            for r in self.client.server_requests
            if r["method"] == "client/registerCapability"
        ]

    def settle(self, uri: str) -> dict[str, list[str]]:
        """Wait until the server handled everything sent so far (it answers a
        request after the notifications sent before it, and publishes before it
        answers); the codes published per file since the last call."""
        self.client.hover(uri, 0, 0)
        found = {
            unquote(p["uri"]).rsplit("/", 1)[1]: sorted(
                str(d["code"]) for d in p["diagnostics"]
            )
            for p in self.client.published
        }
        self.client.published.clear()
        return found

    def open(self, path: Path, text: str, language: str = "python") -> str:
        return self.client.open(path, text, language)

    def change(self, uri: str, text: str) -> None:
        self.version += 1
        self.client.change(uri, self.version, {"text": text})

    def notify(self, method: str, params: object) -> None:
        self.client.notify(method, params)

    def stop(self) -> None:
        assert self.client.stop() == 0


def make_package(root: Path) -> tuple[Path, Path, Path]:
    package = root / "nav_pkg"
    (package / "msg").mkdir(parents=True)
    (package / "package.xml").write_text(
        "<package format='3'><name>nav_pkg</name></package>\n"
    )
    reading = package / "msg" / "Reading.msg"
    reading.write_text(METRES)
    (package / "nav_pkg").mkdir()
    node = package / "nav_pkg" / "node.py"
    node.write_text(NODE)
    other = package / "nav_pkg" / "other.py"
    other.write_text(UNRELATED)
    return reading, node, other


def interface_session(root: Path) -> dict[str, Any]:
    root = root / "my ws"  # URIs that need quoting
    reading, node, other = make_package(root)
    session = Session(dynamic_watchers=True)
    try:
        return interface_steps(session, root, reading, node, other)
    finally:
        session.client.kill()


def interface_steps(
    session: Session, root: Path, reading: Path, node: Path, other: Path
) -> dict[str, Any]:
    session.start(root)
    steps: dict[str, Any] = {}
    node_uri = session.open(node, NODE)
    session.open(other, UNRELATED)
    steps["opened"] = session.settle(node_uri)
    steps["registrations"] = list(session.registrations)
    steps["hover_declaration"] = session.client.hover(node_uri, 4, 1)["result"]
    steps["hover_target"] = session.client.hover(node_uri, 5, 9)["result"]
    msg_uri = session.open(reading, METRES, "ros-msg")
    steps["msg_opened"] = session.settle(node_uri)
    session.change(msg_uri, KILOMETRES)  # typed, not saved
    steps["msg_typed"] = session.settle(node_uri)
    session.change(msg_uri, "float64 dist\nfloat64\n")
    steps["msg_broken"] = session.settle(node_uri)
    session.notify("textDocument/didClose", {"textDocument": {"uri": msg_uri}})
    steps["msg_closed"] = session.settle(node_uri)
    reading.write_text(KILOMETRES)  # changed on disk, e.g. by git
    changed = {"uri": reading.as_uri(), "type": 2}  # FileChangeType.Changed
    session.notify("workspace/didChangeWatchedFiles", {"changes": [changed]})
    steps["msg_on_disk"] = session.settle(node_uri)
    session.stop()
    return steps


def test_interface_changes_recheck_the_open_documents_that_use_them(
    tmp_path: Path,
) -> None:
    steps = interface_session(tmp_path)
    # the package's interfaces are found for an opened file (its package.xml)
    assert steps["opened"] == {"node.py": ["RF201"], "other.py": []}
    (registration,) = steps["registrations"][0]["registrations"]
    assert registration["method"] == "workspace/didChangeWatchedFiles"
    watchers = registration["registerOptions"]["watchers"]
    assert [w["globPattern"] for w in watchers] == ["**/*.{msg,srv,action,pyi}"]
    declaration = steps["hover_declaration"]["contents"]["value"]
    assert declaration.startswith("**far**: `float` in `km`")
    target = steps["hover_target"]["contents"]["value"]
    assert target.startswith("**dist** of `nav_pkg/Reading`: `float` in `m`")
    assert steps["msg_opened"] == {"Reading.msg": []}
    # an unsaved edit of the .msg counts; other.py does not use Reading
    assert steps["msg_typed"] == {"Reading.msg": [], "node.py": []}
    assert steps["msg_broken"] == {"Reading.msg": ["RF506"], "node.py": []}
    assert steps["msg_closed"] == {"node.py": ["RF201"]}  # back to the disk's text
    assert steps["msg_on_disk"] == {"node.py": []}


HELPER = "LIMIT = 1.0\n"
USER = "from nav_pkg.helper import LIMIT\n\nx = LIMIT\n"


def module_session(root: Path) -> dict[str, Any]:
    _, node, other = make_package(root)
    helper = node.parent / "helper.py"
    helper.write_text(HELPER)
    user = node.parent / "user.py"
    user.write_text(USER)
    session = Session(dynamic_watchers=False)
    try:
        return module_steps(session, root, helper, user, other)
    finally:
        session.client.kill()


def module_steps(
    session: Session, root: Path, helper: Path, user: Path, other: Path
) -> dict[str, Any]:
    session.start(root)
    steps: dict[str, Any] = {}
    user_uri = session.open(user, USER)
    session.open(other, UNRELATED)
    helper_uri = session.open(helper, HELPER)
    steps["opened"] = session.settle(user_uri)
    steps["registrations"] = list(session.registrations)
    session.change(helper_uri, HELPER + "OTHER = 2\n")
    steps["typed"] = session.settle(user_uri)
    session.notify("textDocument/didSave", {"textDocument": {"uri": helper_uri}})
    steps["saved"] = session.settle(user_uri)
    changed = {"uri": helper.as_uri(), "type": 2}  # FileChangeType.Changed
    session.notify("workspace/didChangeWatchedFiles", {"changes": [changed]})
    steps["on_disk"] = session.settle(user_uri)
    session.stop()
    return steps


def test_a_saved_module_rechecks_the_open_documents_that_import_it(
    tmp_path: Path,
) -> None:
    steps = module_session(tmp_path)
    assert steps["opened"] == {"user.py": [], "other.py": [], "helper.py": []}
    assert steps["registrations"] == []  # the client cannot register watchers
    assert steps["typed"] == {"helper.py": []}  # unsaved: importers see the disk
    assert steps["saved"] == {"helper.py": [], "user.py": []}
    assert steps["on_disk"] == {"user.py": []}  # helper.py's buffer is the editor's


NODES = sorted((Path(__file__).parent / "cases" / "nodes").glob("*.py"))


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(NODES), st.data())
def test_hover_anywhere_in_a_whole_node_answers_text_or_nothing(
    path: Path, data: Any
) -> None:
    text = path.read_text(encoding="utf-8")
    lines = text.splitlines()
    line = data.draw(st.integers(1, len(lines)))
    col = data.draw(st.integers(0, len(lines[line - 1])))
    catalog = MsgCatalog(api.interface_files([path.parent / "msg"]))
    found = api.hover(text, str(path), line, col, catalog)
    assert found is None or (found.startswith(("**", "`")) and found.strip())
