"""The data shipped so that a first run computes nothing (issue 13, item 4): fresh,
and used."""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parent.parent
TOOL = ROOT / "tools" / "build_package_data.py"


def tool():  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location("build_package_data", TOOL)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_shipped_standard_messages_are_what_rosbags_gives() -> None:
    build = tool()
    for distro, text in build.standard_messages().items():
        shipped = build.STANDARD / f"{distro}.json"
        assert shipped.read_text(encoding="utf-8") == text, (
            f"{shipped} is stale: run python tools/build_package_data.py"
        )


def test_the_shipped_units_are_what_pint_gives() -> None:
    build = tool()
    assert build.UNITS.read_text(encoding="utf-8") == build.units(), (
        "units.json is stale: run python tools/build_package_data.py"
    )


NODE = """import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan


class Driver(Node):
    def __init__(self):
        super().__init__("driver")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_subscription(LaserScan, "scan", self.on_scan, 10)

    def on_scan(self, scan):
        cmd = Twist()
        cmd.linear.x = 0.2 if scan.range_min > 0.5 else 0.0
        cmd.angular.z = scan.angle_increment
        self.pub.publish(cmd)
"""


def _imported_by_a_check(
    node: Path, modules: tuple[str, ...], env: dict[str, str] | None = None
) -> object:
    """Which of `modules` a `robotfix check` of `node` imports (in a fresh
    process, from the node's folder); its output when the probe fails."""
    probe = (
        "import sys\n"
        "from robotfix.cli import main\n"
        f"status = main(['check', '--no-cache', {str(node)!r}])\n"
        f"print(sorted(m for m in {modules!r} if m in sys.modules))\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", probe],
        capture_output=True,
        text=True,
        env={**os.environ, "PYTHONPATH": str(ROOT / "src"), **(env or {})},
        cwd=node.parent,
        check=False,
    )
    last = done.stdout.strip().splitlines()[-1:] or [""]
    return [] if last[0] == "[]" else done.stdout + done.stderr


@pytest.mark.parametrize("distro", ["ros2", "ros1"])
def test_a_first_run_imports_neither_pint_nor_rosbags(
    tmp_path: Path, distro: str
) -> None:
    node = tmp_path / "driver.py"
    node.write_text(NODE)
    (tmp_path / "pyproject.toml").write_text(
        f'[tool.robotfix]\nros-distro = "{distro}"\n'
    )
    cache = {"ROBOTFIX_CACHE_DIR": str(tmp_path / "empty-cache")}
    imported = _imported_by_a_check(node, ("pint", "rosbags"), cache)
    assert imported == [], imported


def test_data_of_another_conversion_version_is_ignored(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """After a change to the conversion (a new cache key version), stale shipped
    data is not used: the first run converts, as without it."""
    from robotfix.annotations import units
    from robotfix.ros import catalog

    catalog._shipped_standard.cache_clear()
    units._shipped.cache_clear()
    try:
        assert catalog._shipped_standard("ros2")
        assert units._shipped()
        catalog._shipped_standard.cache_clear()
        units._shipped.cache_clear()
        monkeypatch.setattr(catalog, "standard_format", lambda d: f"msgs-v99-{d}")
        monkeypatch.setattr(units, "units_format", lambda: "units-v99")
        assert catalog._shipped_standard("ros2") is None
        assert units._shipped() == {}
    finally:
        catalog._shipped_standard.cache_clear()
        units._shipped.cache_clear()


def test_the_shipped_tables_are_their_toml() -> None:
    build = tool()
    assert build.TABLES_JSON.read_text(encoding="utf-8") == build.tables(), (
        "tables.json is stale: run python tools/build_package_data.py"
    )


def test_a_run_without_a_pyproject_reads_no_toml(tmp_path: Path) -> None:
    """The tables every run reads come from their JSON copy: tomllib (5 ms to
    import) is imported only for a pyproject.toml."""
    node = tmp_path / "driver.py"
    node.write_text(NODE)
    imported = _imported_by_a_check(node, ("tomllib", "tomli"))
    assert imported == [], imported


def test_an_edited_table_is_read_from_its_toml(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A table whose JSON copy was made of other bytes (edited, the tool not run
    again) is read from the TOML: the TOML is the source of truth."""
    from robotfix.ros import catalog

    for name in catalog.TABLES:
        text = (catalog.TABLE_DIR / f"{name}.toml").read_text("utf-8")
        if name == "rep103":
            text = text.replace('"m/s"', '"km/h"', 1)
        (tmp_path / f"{name}.toml").write_text(text, encoding="utf-8")
    catalog.table.cache_clear()
    try:
        shipped = catalog.table("rep103")
        catalog.table.cache_clear()
        monkeypatch.setattr(catalog, "TABLE_DIR", tmp_path)
        fresh = catalog.table("rep103")
        unchanged = catalog.table("defaults")
    finally:
        catalog.table.cache_clear()
    assert unchanged == catalog.table("defaults")
    assert shipped != fresh and "km/h" in str(fresh) and "km/h" not in str(shipped)


def test_the_shipped_parser_tables_parse_as_the_grammar_does() -> None:
    """grammar.json is this grammar's, for this lark, and the parser loaded from it
    reads every annotation of the test cases (and their errors) as one built from
    the grammar does; a stale file is not used (tools/build_package_data.py)."""
    import re

    from robotfix.annotations import parser

    assert parser.tables_format() in parser.TABLES.read_text(encoding="utf-8")[:200], (
        "grammar.json is stale: run python tools/build_package_data.py"
    )
    parser._parser.cache_clear()
    loaded, built = parser._parser(), parser.build_parser()
    assert loaded.source_path == "<deserialized>"  # the shipped tables, not a build
    texts = {
        match.group(1)
        for case in sorted((ROOT / "tests" / "cases").rglob("*.py"))
        for match in re.finditer(r'Annotated\[[^"\]]*"([^"]*)"', case.read_text())
    }
    texts |= {"0 <= _ <=", "_ > > 1", "Unit('m/s') and abs(_) <= limit", "len(_) == 3"}
    assert len(texts) > 200

    def outcome(lark: object, text: str) -> object:
        try:
            return lark.parse(text)  # type: ignore[attr-defined]
        except Exception as err:  # the error is what is compared
            where = getattr(err, "pos_in_stream", None), getattr(err, "column", None)
            return type(err).__name__, where, sorted(getattr(err, "expected", ()))

    for text in sorted(texts):
        assert outcome(loaded, text) == outcome(built, text), text


def test_the_shipped_stub_predicates_are_what_the_parser_gives() -> None:
    build = tool()
    assert (
        build.STUB_PREDICATES.read_text(encoding="utf-8") == build.stub_predicates()
    ), "stub_predicates.json is stale: run python tools/build_package_data.py"


def test_the_shipped_stub_names_are_what_the_stubs_define() -> None:
    build = tool()
    assert build.SHIPPED_NAMES.read_text(encoding="utf-8") == build.shipped_names(), (
        "shipped_names.json is stale: run python tools/build_package_data.py"
    )
    from robotfix.stubs.load import DATA, _shipped_names, root_names

    assert _shipped_names() == root_names(DATA)


def test_a_run_parses_no_shipped_stub_to_know_its_vocabulary(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """`relevance._vocabulary` takes the shipped stubs' names from
    shipped_names.json: checking `x = 1` parses no stub."""
    import ast

    from robotfix.analysis import relevance
    from robotfix.api import check_source
    from robotfix.stubs.load import DATA

    stubs = {p.read_text(encoding="utf-8") for p in DATA.rglob("*.pyi")}
    relevance._vocabulary.cache_clear()
    parsed: list[object] = []
    real = ast.parse

    def parse(source: Any, *args: Any, **kwargs: Any) -> Any:
        if source in stubs:
            parsed.append(source)
        return real(source, *args, **kwargs)

    monkeypatch.setattr(ast, "parse", parse)
    check_source("x = 1\n", "x.py")
    assert parsed == []
