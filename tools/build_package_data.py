"""Write the data a first run would otherwise compute, shipped in the wheel:

- src/robotfix/ros/standard/<distro>.json: the standard message definitions of each
  distribution RobotFix knows (`catalog.STORES`), converted from rosbags' type stores;
- src/robotfix/ros/tables.json: the REP 103, comment-unit and default tables
  (ros/*.toml, their source) parsed, which every run reads;
- src/robotfix/annotations/stub_predicates.json: the predicates the shipped stubs
  write (`_ >= 0`), parsed, so that a run with no other annotation imports no lark;
- src/robotfix/stubs/shipped_names.json: the names through which the shipped stubs
  can give a file a unit or a refinement (`stubs/load.defined_names`), which every
  run would otherwise parse the stubs to find, and which arguments of a call by
  method name the stubs' disagreeing methods of that name check
  (`stubs/byname.py`: `super().__init__(...)` parses no stub);
- src/robotfix/annotations/units.json: pint's reading of every unit the REP 103 table,
  the standard messages' comment units, the shipped stubs and the vocabulary of common
  spellings (src/robotfix/ros/unit_vocabulary.toml) use, and pint's unit, prefix and
  suffix names, with which a text that is no unit pint reads is told without pint;
- src/robotfix/annotations/grammar.json: the refinement grammar's LALR tables, which
  lark would otherwise build at every start of a process that parses an annotation
  (35 ms of the language server's cold start; their state numbers vary from one
  build to the next, so tests compare what they parse, not their bytes).

Without them, a first run on a fresh machine imports pint and converts rosbags' stores
(about 0.5 s) before its machine cache exists. Each file names the version of the
conversion that wrote it (the machine cache's key without the library's install), and
is ignored by another. tests/test_package_data.py fails when the shipped files differ
from what this script writes with the installed libraries: run it again then.
Run: python tools/build_package_data.py
"""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path
from typing import Any

import tomllib

ROOT = Path(__file__).resolve().parent.parent
STANDARD = ROOT / "src/robotfix/ros/standard"
UNITS = ROOT / "src/robotfix/annotations/units.json"
TABLES_JSON = ROOT / "src/robotfix/ros/tables.json"
STUB_PREDICATES = ROOT / "src/robotfix/annotations/stub_predicates.json"
SHIPPED_NAMES = ROOT / "src/robotfix/stubs/shipped_names.json"


def standard_messages() -> dict[str, str]:
    """distro -> the JSON text of its converted standard definitions."""
    from robotfix.ros.catalog import STORES, _convert_rosbags, standard_format

    return {
        distro: _dump(
            {
                "format": standard_format(distro),
                "entries": _convert_rosbags(STORES[distro]),
            }
        )
        for distro in STORES
    }


STUB_UNIT = re.compile(r"Unit\('([^']*)'\)")


def unit_texts() -> list[str]:
    ros = ROOT / "src/robotfix/ros"
    found: set[str] = set()
    rep103 = tomllib.loads((ros / "rep103.toml").read_text(encoding="utf-8"))
    for entry in rep103["message"]:
        found.update(entry["units"].values())
    comments = tomllib.loads((ros / "comment_units.toml").read_text(encoding="utf-8"))
    for entry in comments["message"]:
        found.update(entry["units"].values())
    # the spellings robot code and interface comments commonly write
    found.update(vocabulary())
    # the shipped stubs' units (`Unit('rad/s')`), read when a library call is met
    stubs = ROOT / "src/robotfix/stubs/data"
    for stub in sorted(stubs.rglob("*.pyi")):
        found.update(STUB_UNIT.findall(stub.read_text(encoding="utf-8")))
    return sorted(found)


def vocabulary() -> list[str]:
    path = ROOT / "src/robotfix/ros/unit_vocabulary.toml"
    texts = tomllib.loads(path.read_text(encoding="utf-8"))["units"]
    return [str(text) for text in texts]


def units() -> str:
    from robotfix.annotations.units import _resolve_with_pint, pint_names, units_format

    entries = {text: _resolve_with_pint(text) for text in unit_texts()}
    return _dump({"format": units_format(), "entries": entries, "pint": pint_names()})


def tables() -> str:
    """The TOML tables `ros/catalog.table` reads on every run, parsed, each with the
    sha256 of the bytes it was parsed from (an edited table is read from its TOML
    until this is run again)."""
    import hashlib

    from robotfix.ros.catalog import TABLES

    found = {}
    for name in TABLES:
        data = (ROOT / "src/robotfix/ros" / f"{name}.toml").read_bytes()
        found[name] = {
            "sha256": hashlib.sha256(data).hexdigest(),
            "data": tomllib.loads(data.decode("utf-8")),
        }
    return _dump(found)


def stub_predicates() -> str:
    """Every string of an `Annotated[...]` in the shipped stubs that parses as a
    predicate (a unit-only one too: `extract` may hand it to the parser)."""
    import ast

    from robotfix.annotations.parser import (
        AnnotationSyntaxError,
        _parse_uncached,
        parser_key,
        spelt_node,
    )

    texts: set[str] = set()
    for stub in sorted((ROOT / "src/robotfix/stubs/data").rglob("*.pyi")):
        tree = ast.parse(stub.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.Subscript) and "Annotated" in ast.unparse(
                node.value
            ):
                texts.update(
                    n.value
                    for n in ast.walk(node.slice)
                    if isinstance(n, ast.Constant) and isinstance(n.value, str)
                )
    found = {}
    for text in sorted(t for t in texts if t.strip()):
        try:
            found[text] = spelt_node(_parse_uncached(text))
        except AnnotationSyntaxError:
            continue
    return _dump({"key": parser_key(), "predicates": found})


def shipped_names() -> str:
    from robotfix.stubs.load import (
        DATA,
        StubSet,
        by_name_checks,
        root_names,
        shipped_key,
    )

    return _dump(
        {
            "key": shipped_key(),
            "names": sorted(root_names(DATA)),
            "by_name": by_name_checks(StubSet()),
        }
    )


def _dump(data: Any) -> str:
    return json.dumps(data, sort_keys=True, separators=(",", ":")) + "\n"


def main() -> None:
    STANDARD.mkdir(exist_ok=True)
    for distro, text in standard_messages().items():
        (STANDARD / f"{distro}.json").write_text(text, encoding="utf-8")
    UNITS.write_text(units(), encoding="utf-8")
    TABLES_JSON.write_text(tables(), encoding="utf-8")
    from robotfix.annotations import parser

    parser.TABLES.write_text(parser.tables_json(), encoding="utf-8")
    STUB_PREDICATES.write_text(stub_predicates(), encoding="utf-8")
    SHIPPED_NAMES.write_text(shipped_names(), encoding="utf-8")
    print(
        f"wrote {STANDARD}, {UNITS}, {TABLES_JSON}, {parser.TABLES}, "
        f"{STUB_PREDICATES} and {SHIPPED_NAMES}",
        file=sys.stderr,
    )


if __name__ == "__main__":
    main()
