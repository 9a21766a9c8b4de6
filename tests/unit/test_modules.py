"""The project layer alone: where a module name is found, relative imports, and
summaries that do not change with a function's body."""

from __future__ import annotations

from pathlib import Path

from robotfix.analysis.imported import absolute
from robotfix.api import Discharger
from robotfix.project.modules import ModuleIndex
from robotfix.project.summary import ABSENT, Project
from robotfix.ros.catalog import MsgCatalog


def _write(path: Path, text: str = "") -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def test_ros_layouts_scripts_and_python_paths(tmp_path: Path) -> None:
    ros2 = tmp_path / "ws" / "src" / "driver"
    _write(ros2 / "package.xml", "<package><name>driver</name></package>")
    _write(ros2 / "driver" / "__init__.py")
    util = _write(ros2 / "driver" / "util.py")
    node = _write(ros2 / "driver" / "node.py")
    ros1 = tmp_path / "ws" / "src" / "nav"
    _write(ros1 / "package.xml", "<package><name>nav</name></package>")
    _write(ros1 / "src" / "nav" / "__init__.py")
    utils = _write(ros1 / "src" / "nav" / "transform_utils.py")
    script = _write(ros1 / "scripts" / "move.py")
    helper = _write(ros1 / "scripts" / "helper.py")
    shared = _write(tmp_path / "shared" / "limits.py")

    index = ModuleIndex([tmp_path / "ws"], [tmp_path / "shared"])
    assert index.find("driver.util", node) == util
    assert index.find("driver", node) == ros2 / "driver" / "__init__.py"
    assert index.find("util", node) is None  # no implicit relative import
    assert index.find("nav.transform_utils", script) == utils  # catkin's src/
    assert index.find("helper", script) == helper  # a script's own folder
    assert index.find("limits", node) == shared  # python-paths
    assert index.find("rclpy.node", node) is None
    assert index.find("not valid", node) is None
    assert index.package_of(node) == "driver"
    assert index.package_of(script) is None
    assert index.module_name(util) == "driver.util"


def test_relative_imports_become_absolute() -> None:
    assert absolute("a.b", 1, "limits") == "a.b.limits"
    assert absolute("a.b", 2, "limits") == "a.limits"
    assert absolute("a.b", 2, None) == "a"
    assert absolute("a", 2, "x") is None  # above the top package
    assert absolute(None, 1, "limits") is None  # a script: no package


def test_a_body_change_keeps_the_fingerprint_a_signature_change_does_not(
    tmp_path: Path,
) -> None:
    _write(tmp_path / "pkg" / "__init__.py")
    util = _write(
        tmp_path / "pkg" / "util.py",
        "from typing import Annotated\n\n"
        "def clamp(v: Annotated[float, \"Unit('m/s') and _ <= 1\"]) -> float:\n"
        "    return v\n",
    )
    node = _write(tmp_path / "pkg" / "node.py", "from pkg.util import clamp\n")

    def fingerprint() -> str:
        project = Project(ModuleIndex([tmp_path]), MsgCatalog([]), Discharger)
        found = project.resolver(node).module("pkg.util")
        assert found is not None and "clamp" in found.functions
        return found.members["clamp"]  # what an importer of `clamp` reads

    first = fingerprint()
    util.write_text(util.read_text().replace("return v", "return v * 1"))
    assert fingerprint() == first
    util.write_text(util.read_text().replace("_ <= 1", "_ <= 2"))
    assert fingerprint() != first
    project = Project(ModuleIndex([tmp_path]), MsgCatalog([]), Discharger)
    assert project.fingerprint(f"{node}\0pkg.missing") == ABSENT
