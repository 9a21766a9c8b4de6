"""Every interface file of real packages reads without a diagnostic (issue 10 item 2).

The corpus is not part of the repository: the test reads the repositories below
from the folders in `$ROBOTFIX_CORPUS` (separated by the path separator), else from
/work/corpus, and is skipped for each one that is not there. Only RF504 (a type of a
package that is not in the corpus, such as geographic_msgs) is allowed. The forms
these files use are covered without the corpus by tests/unit/test_iface_*.py and
tests/cases/iface/.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from functools import cache
from pathlib import Path

import pytest

from robotfix import rules
from robotfix.ros.catalog import MsgCatalog, normalize
from robotfix.ros.msg import read_interface

REPOSITORIES = (
    "ros2+common_interfaces",
    "ros2+rcl_interfaces",
    "ros2+example_interfaces",
    "ros2+test_interface_files",
    "ros-navigation+navigation2",
    "mavlink+mavros",
)
SUFFIXES = (".msg", ".srv", ".action", ".idl")


def roots() -> list[Path]:
    value = os.environ.get("ROBOTFIX_CORPUS", "/work/corpus")
    return [Path(entry) for entry in value.split(os.pathsep) if entry]


def repository(name: str) -> Path | None:
    return next((root / name for root in roots() if (root / name).is_dir()), None)


def files_of(folder: Path) -> Iterator[Path]:
    for path in sorted(folder.rglob("*")):
        if path.suffix in SUFFIXES and path.is_file() and ".git" not in path.parts:
            yield path


@cache
def catalog() -> MsgCatalog:
    found = [repository(name) for name in REPOSITORIES]
    files = [
        path for folder in found if folder is not None for path in files_of(folder)
    ]
    made = MsgCatalog(files)
    for path in files:  # resolve every type and field
        for section in read_interface(path, path.read_text(encoding="utf-8")).sections:
            made.lookup(normalize(section.name))
    return made


@pytest.mark.parametrize("name", REPOSITORIES)
def test_every_interface_file_reads_cleanly(name: str) -> None:
    folder = repository(name)
    if folder is None:
        pytest.skip(f"{name} is not in the corpus ($ROBOTFIX_CORPUS)")
    files = list(files_of(folder))
    assert files
    for path in files:
        parsed = read_interface(path, path.read_text(encoding="utf-8"))
        assert parsed.problems == (), path
        assert parsed.sections, path
    inside = str(folder) + os.sep
    problems = [
        f"{p.path}:{p.line}:{p.col}: {p.rule.code} {p.message}"
        for p in catalog().problems
        if p.path.startswith(inside) and p.rule is not rules.UNKNOWN_MESSAGE_TYPE
    ]
    assert problems == []
