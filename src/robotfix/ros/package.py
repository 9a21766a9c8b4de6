"""A ROS package's name: the `<name>` of its package.xml (REP 127, 140, 149).

The folder's name is only a fallback: a checkout or a symlink may call the folder
anything, while ROS names the package's types after `<name>`.
"""

from __future__ import annotations

import os
from pathlib import Path
from xml.etree import ElementTree

from robotfix.fs import UnreadableError, probe, read_regular
from robotfix.lazyre import lazy

MAX_PACKAGE_XML_BYTES = 1024 * 1024  # real ones are a few kB
_NAME = lazy(r"[A-Za-z_][A-Za-z0-9_]*")  # what a `pkg/Type` name can hold


def package_name(folder: Path) -> str | None:
    """`<name>` of `folder/package.xml`; None when there is no such file, it is not
    a package manifest (not XML, no `<package>` root) or the name is not usable."""
    try:
        data = read_regular(folder / "package.xml", MAX_PACKAGE_XML_BYTES)
    except UnreadableError:
        return None
    if b"<!DOCTYPE" in data or b"<!ENTITY" in data:
        return None  # no manifest needs them; entities could make up any name
    try:
        root = ElementTree.fromstring(data)  # never fetches external entities
    except (ElementTree.ParseError, ValueError, RecursionError):
        return None
    if root.tag != "package":
        return None
    name = (root.findtext("name") or "").strip()
    return name if _NAME.fullmatch(name) else None


def package_folder(path: Path) -> Path | None:
    """The folder of the ROS package a file lies in: the nearest one above it (or
    its own folder) that holds a package.xml. (Climbed as strings: a cached
    run asks it of every C++, parameter and Python file it keys, 2,244 times
    over the corpus, and made ten `Path`s a folder.)"""
    folder = os.path.dirname(os.path.abspath(path))
    while True:
        if probe("isfile", os.path.join(folder, "package.xml")):
            return Path(folder)
        above = os.path.dirname(folder)
        if above == folder:
            return None
        folder = above


TEST_FOLDERS = frozenset({"test", "tests", "testing"})


def test_code(path: str, within: Path | None = None) -> bool:
    """Whether a file lies in a test folder (its nodes are throwaway); with
    `within`, a folder of its own package's (the folder a package lies in may be
    called `tests` too)."""
    if within is not None:
        path = os.path.relpath(os.path.abspath(path), within)
    return not TEST_FOLDERS.isdisjoint(Path(path).parts[:-1])
