"""C++ nodes' parameter declarations, for the parameter and launch checks.

`ros.graph.cpp` reads each C++ file's `declare_parameter` calls (the graph's
parameter endpoints); here they become parameter summaries
(`analysis.parameters.Summary`), so a parameter file's section and a launch
entry's values are checked against a C++ node as against a Python one
(`paramcheck.Table`, `launchcheck`):

- a declaration's type is certain only where rclcpp's is: its template argument
  (`declare_parameter<double>("x", 1)`), else its literal default (`0.5` a
  double, `3` an integer, `false`, `"x"`, `rclcpp::ParameterValue(0.5)`,
  `std::string("map")`). rclcpp (since Galactic) refuses an override of
  another type (InvalidParameterTypeException at the declaration). A file that
  mentions `dynamic_typing` has no certain type;
- a node's parameters are all known by name (RF601 may say a set one is not
  declared) only when no file of its code declares one whose name is computed, or
  holds a word of `ros.graph.cpp_scan.OPENING` (bulk or helper declarations, a base
  class's `add_parameter`, generated code, plugins, `allow_undeclared_parameters`),
  and its class derives from rclcpp's own node classes;
- a node made with `automatically_declare_parameters_from_overrides(true)` takes
  any override as declared: its values are not checked (those of every node of
  the file that says so, or of its package when that file has no node class);
- ROS 1 (roscpp's `param`) is not checked: roscpp converts what it can and falls
  back to the default when it cannot, so no value is certainly refused.
"""

from __future__ import annotations

import hashlib
import os
import re
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

from robotfix.faults import Fault, guard
from robotfix.fs import UnreadableError, probe, read_regular
from robotfix.ros.executables import MAX_BUILD_BYTES
from robotfix.ros.graph.cpp_scan import AUTO
from robotfix.ros.graph.model import OPENS, PARAMETER, FileGraph
from robotfix.ros.package import package_folder, test_code

if TYPE_CHECKING:  # the analysis is imported only when the summaries are made
    from robotfix.analysis.paramsummary import Summary
    from robotfix.ros.graph.build import Started
    from robotfix.ros.launch.model import NodeEntry

# an owner that declares what is not known (`launchcheck._closed`: never closed)
MORE = "#more"
CPP_TYPE_WHY = (
    "a ROS 2 parameter keeps the type it was declared with: rclcpp refuses "
    "another (InvalidParameterTypeException) unless it is declared with "
    "dynamic_typing"
)
# a C++ type (spaces removed) -> the ROS 2 parameter type rclcpp gives it
_SCALARS = {
    "bool": "bool",
    "int": "integer",
    "int32_t": "integer",
    "int64_t": "integer",
    "long": "integer",
    "longint": "integer",
    "std::int64_t": "integer",
    "float": "double",
    "double": "double",
    "std::string": "string",
}
_VECTOR = re.compile(r"std::vector<(.+)>")


def ros2_type(written: str) -> str | None:
    """`double` -> `double`, `std::vector<int64_t>` -> `integer_array`; None for
    any other type."""
    text = re.sub(r"\s+", "", written)
    inner = _VECTOR.fullmatch(text)
    if inner is None:
        return _SCALARS.get(text)
    if inner.group(1) in ("uint8_t", "std::uint8_t"):
        return "byte_array"
    scalar = _SCALARS.get(inner.group(1))
    return f"{scalar}_array" if scalar is not None else None


class CppParams:
    """The C++ nodes of a run: the names of every one (RF602), and, made when
    first asked for, their parameter summaries (one per file) and the node
    object each launch entry starts (`started`: `graphcheck.started_entries`,
    called then)."""

    def __init__(
        self,
        graphs: dict[str, FileGraph] | None = None,
        started: Callable[[], list[Started]] | None = None,
        where: str = "",
    ) -> None:
        """`where`: the file a fault of ours in finding the launch entries' code
        is reported at (the run's first path)."""
        self.graphs = graphs or {}
        self._started = started
        self.where = where
        self.names = {
            n for g in self.graphs.values() for names in g.nodes.values() for n in names
        }
        self._summaries: list[Summary] | None = None
        self._entries: dict[int, list[tuple[Summary, str]]] = {}
        self._renamed: dict[str, set[str]] = {}  # launch name -> real paths

    def read(self, faults: list[Fault] | None = None) -> list[Summary]:
        """The summaries, made once; a fault of ours on one file goes to `faults`
        as that file's (`faults.guard`; raised without a list)."""
        if self._summaries is None:
            self._summaries = []
            self._read(self._summaries, faults)
        return self._summaries

    @property
    def summaries(self) -> list[Summary]:
        return self.read()

    @property
    def renamed(self) -> dict[str, set[str]]:
        """A launch entry's name -> the C++ file of the node object it starts."""
        self.summaries  # noqa: B018 (made with them)
        return self._renamed

    def owners_of(self, entry: NodeEntry) -> list[tuple[Summary, str]]:
        """The node object a launch entry starts, and `MORE` (`_entry_owners`)."""
        self.summaries  # noqa: B018
        return self._entries.get(id(entry), [])

    def key(self) -> list[str]:
        """What the checks read, as text (the parameter check's cache key): each
        file's parameter endpoints and nodes, and the build file of its package
        (which says what an executable is built from)."""
        parts = [f"cpp\0{name}" for name in sorted(self.names)]
        folders: set[Path] = set()
        for path in sorted(self.graphs):
            graph = self.graphs[path]
            params = [e for e in graph.endpoints if e.kind in (PARAMETER, OPENS)]
            if graph.ros != 2 or not (params or graph.nodes):
                continue
            shown = [(e.owner, e.name, e.types, e.line, e.col, e.value) for e in params]
            nodes = sorted(graph.nodes.items())
            parts.append(f"cpp-file\0{path}\0{shown}\0{nodes}")
            folder = package_folder(Path(path))
            if folder is not None:
                folders.add(folder)
        for folder in sorted(folders):
            try:
                data = read_regular(folder / "CMakeLists.txt", MAX_BUILD_BYTES)
            except UnreadableError:
                data = b""
            digest = hashlib.sha256(data).hexdigest()
            parts.append(f"cpp-cmake\0{folder}\0{digest}")
        return parts

    def _read(self, summaries: list[Summary], faults: list[Fault] | None) -> None:
        folders: dict[str, Path | None] = {}  # a file's folder -> its package

        def package(path: str) -> Path | None:
            folder = os.path.dirname(path)
            if folder not in folders:
                folders[folder] = package_folder(Path(path))
            return folders[folder]

        auto: set[Path | None] = set()  # packages whose mains declare any override
        by_path: dict[str, Summary] = {}
        failed: set[str] = set()  # files a fault of ours left unread
        for path in sorted(self.graphs):
            graph = self.graphs[path]
            if graph.ros != 2 or test_code(path, package(path)):
                continue  # a test's nodes are throwaway: not the node named so
            summary = None
            failed.add(path)
            with guard(path, [], faults):
                summary = _summary(path, graph)
                failed.discard(path)
            if summary is None:
                continue
            if any(e.kind == OPENS and e.value == AUTO for e in graph.endpoints):
                if any(graph.nodes):  # a node class's own options: its file's
                    summary.auto_declare = {*summary.node_names, *summary.open_owners}
                else:  # a main's: any node of its package may get them
                    auto.add(package(path))
            by_path[path] = summary
            summaries.append(summary)
        for summary in summaries:
            if package(summary.path) in auto:
                summary.auto_declare = {*summary.node_names, *summary.open_owners, ""}
        started: list[Started] = []
        with guard(self.where, [], faults):
            started = self._started() if self._started is not None else []
        for one in started:
            owners = _entry_owners(one, by_path, failed)
            if not owners:
                continue
            self._entries[id(one.entry)] = owners
            if one.entry.name:
                name = one.entry.name.rsplit("/", 1)[-1]
                real = probe("realpath", owners[0][0].path)
                self._renamed.setdefault(name, set()).add(real)


def _summary(path: str, graph: FileGraph) -> Summary | None:
    """A C++ file's declarations as a parameter summary; None when it has none
    and names no node."""
    from robotfix.analysis.paramsummary import ParamDecl, Summary

    summary = Summary(path)
    summary.node_names = {o: list(n) for o, n in graph.nodes.items()}
    for endpoint in graph.endpoints:
        if endpoint.kind not in (PARAMETER, OPENS) or endpoint.ros != 2:
            continue
        if endpoint.name is None:  # computed, or code that declares more
            summary.open_owners.add(endpoint.owner)
            continue
        written = endpoint.types[0] if len(endpoint.types) == 1 else ""
        summary.decls.append(
            ParamDecl(
                endpoint.owner,
                endpoint.name,
                2,
                path,
                endpoint.line,
                endpoint.col,
                type=ros2_type(written),
            )
        )
    if "" in summary.open_owners:  # a word of the file: every node object of it
        summary.open_owners |= {*summary.node_names, *(d.owner for d in summary.decls)}
    if not (summary.decls or summary.node_names or summary.open_owners):
        return None
    return summary


def _entry_owners(
    one: Started, by_path: dict[str, Summary], failed: set[str]
) -> list[tuple[Summary, str]]:
    """The node object a launch entry starts, with `MORE` for each file of its
    code where other objects declare parameters or code it cannot see may (so
    RF601 stays silent): a composable node's plugin class; else the node class
    (or variable) of its code named as the entry names it or its executable
    (`cam2image`: the node `cam2image` or the class `Cam2Image`), or the only
    one when nothing else in its code declares parameters. None when that is
    not one, when a file of its code was not read (a fault), or when the
    package declares any override."""
    if not failed.isdisjoint(one.files):
        return []
    summaries = [by_path[f] for f in one.files if f in by_path]
    nodes = [
        (s, o)
        for s in summaries
        for o in s.node_names
        if o and (one.plugin is None or o == one.plugin)
    ]
    named = one.plugin is not None
    for wanted in (one.entry.name or "", one.entry.executable or ""):
        wanted = wanted.rsplit("/", 1)[-1]
        chosen = [
            (s, o)
            for s, o in nodes
            if wanted in s.node_names[o] or _spelt(o) == _spelt(wanted)
        ]
        if wanted and not named and chosen:  # the one named so, or so spelt
            nodes, named = chosen, True
    if len(nodes) != 1 or nodes[0][1] in nodes[0][0].auto_declare:
        return []
    node = nodes[0][1]
    others = [  # (another node class's declarations are its own node's)
        (s, MORE)
        for s in summaries
        if {*s.open_owners, *(d.owner for d in s.decls)}
        - {node, *(o for o in s.node_names if o != "")}
    ]
    if not named and others:
        return []  # its node may be another object of its code
    return [nodes[0], *others]


def _spelt(name: str) -> str:
    """`ControllerServer` and `controller_server` alike."""
    return name.replace("_", "").lower()
