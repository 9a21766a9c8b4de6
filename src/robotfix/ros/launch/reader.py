"""Read launch files, following the includes of files in the checked tree.

A `Reader` evaluates each file once per set of arguments: an included file is
read again only when it is given other arguments. A file's parse is kept until
the caller `release`s the parses (after each launch file it reads), but those of
files an include read, which may be read again with other arguments (a file
included once released is parsed again); `done` drops them all. So the run's
launch files' trees are not all held at once. `touched` is every file it read,
for the run's cache key.
"""

from __future__ import annotations

import ast
import copy
import warnings
from collections.abc import Callable
from pathlib import Path

from robotfix.fs import Noted, UnreadableError, read_text, remembered
from robotfix.ros import yamlfile as Y
from robotfix.ros.launch.frontend import read_tree
from robotfix.ros.launch.model import LaunchFile
from robotfix.ros.launch.names import YAML_SUFFIXES
from robotfix.ros.launch.python import read_python
from robotfix.ros.launch.substitution import Context
from robotfix.ros.launch.tree import (
    MAX_LAUNCH_BYTES,
    Element,
    LaunchSyntaxError,
    from_yaml,
    parse_xml,
)

MAX_INCLUDE_DEPTH = 8
MAX_READS = 2_000  # evaluations of launch files in one run (arguments differ)

Parsed = tuple[ast.Module, str] | Element | LaunchFile  # LaunchFile: not read


class Reader:
    def __init__(self, packages: Callable[[str], Path | None]) -> None:
        self.packages = packages
        # each file's parse and each reading's result, with what it read
        # (`fs.remembered`: a cached launch file's trace holds what its includes read)
        self.parsed: dict[str, tuple[Parsed, Noted]] = {}
        self.results: dict[
            tuple[str, tuple[tuple[str, str | None], ...]], tuple[LaunchFile, Noted]
        ] = {}
        self.touched: set[str] = set()
        self.reading: set[str] = set()  # the files parsed since the caller emptied it
        # an include cut (a cycle, MAX_INCLUDE_DEPTH) or MAX_READS met: what a file
        # reads then depends on the order files are read in (not kept apart)
        self.order_dependent = False
        self.texts: dict[str, str] = {}  # each file's text, for suppressions
        self.included: set[str] = set()  # files an include read: parses kept

    def read(
        self,
        path: Path,
        args: dict[str, str | None] | None = None,
        chain: tuple[str, ...] = (),
    ) -> LaunchFile:
        """The launch entries of `path`; a file that cannot be read or parsed has
        `problem` set, one that is no launch file `launch` False."""
        key = str(path)
        memo = (key, tuple(sorted((args or {}).items())))
        if memo in self.results:
            return _copy(remembered(self.results, memo, _unused))
        if len(self.results) >= MAX_READS:
            self.order_dependent = True
            return LaunchFile(key, 2, launch=False)
        found = remembered(self.results, memo, lambda: self._read(path, args, chain))
        return _copy(found)

    def _read(
        self, path: Path, args: dict[str, str | None] | None, chain: tuple[str, ...]
    ) -> LaunchFile:
        key = str(path)

        def follow(included: Path, passed: dict[str, str | None]) -> LaunchFile | None:
            if str(included) in chain or len(chain) >= MAX_INCLUDE_DEPTH:
                self.order_dependent = True
                return None
            return self.read(included, passed, (*chain, key))

        ctx = Context(path, self.packages, dict(args or {}), len(chain), follow)
        parsed = self.parse(path, chain)
        if isinstance(parsed, LaunchFile):
            found = parsed
        elif isinstance(parsed, Element):
            found = read_tree(parsed, ctx, 2 if key.endswith(YAML_SUFFIXES) else None)
        else:
            found = read_python(parsed[0], parsed[1], ctx)
        return found

    def release(self) -> None:
        """Drop the parses (trees, XML elements) kept for the readings to come,
        but those of files another includes (read again with other arguments)."""
        included = self.included
        for key in [k for k in self.parsed if k not in included]:
            del self.parsed[key]

    def done(self) -> None:
        """Nothing more is read: the readings' memo goes too (`touched`,
        `texts` and `order_dependent` stay)."""
        self.included = set()
        self.release()
        self.results.clear()

    def parse(self, path: Path, chain: tuple[str, ...] = ()) -> Parsed:
        key = str(path)
        self.touched.add(key)
        self.reading.add(key)
        if chain:
            self.included.add(key)
        parsed: Parsed = remembered(self.parsed, key, lambda: _parse(path, self.texts))
        return parsed


def _unused() -> LaunchFile:
    raise AssertionError("remembered")


def _copy(found: LaunchFile) -> LaunchFile:
    """A result's entries may be namespaced by an includer: each gets its own."""
    fresh = copy.copy(found)
    fresh.entries = [copy.copy(e) for e in found.entries]
    return fresh


def _parse(path: Path, texts: dict[str, str]) -> Parsed:
    key = str(path)
    try:
        text = read_text(path, MAX_LAUNCH_BYTES)
    except UnreadableError as err:
        return LaunchFile(key, 2, problem=(f"cannot read: {err.reason}", 1, 0))
    texts[key] = text
    name = path.name
    if name.endswith(".launch") and not text.lstrip("\ufeff \t\r\n").startswith("<"):
        name += ".py"  # nav2's test_case_py.launch is Python
    if name.endswith(".py"):
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # SyntaxWarning: not ours to show
                return ast.parse(text, key), text
        except (SyntaxError, ValueError, RecursionError, MemoryError) as err:
            line = getattr(err, "lineno", None) or 1
            return LaunchFile(key, 2, problem=(f"not valid Python: {err}", line, 0))
    if name.endswith(YAML_SUFFIXES):
        root = Y.parse(text)
        if isinstance(root, Y.YamlProblem):
            return LaunchFile(key, 2, problem=(root.message, root.line, root.col))
        element = from_yaml(root)
        return element if element is not None else LaunchFile(key, 2, launch=False)
    try:
        element = parse_xml(text)
    except LaunchSyntaxError as err:
        return LaunchFile(key, 1, problem=(str(err), err.line, err.col))
    return element if element.tag == "launch" else LaunchFile(key, 1, launch=False)
