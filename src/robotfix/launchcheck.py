"""A run's launch files against the code of the nodes they start.

Each launch entry (`ros.launch`) is mapped to its node's code: the package is a
folder of the run with that `<name>` in its package.xml, the executable a file
`ros.executables` finds (console_scripts, install(PROGRAMS), scripts/), and the
node's code that file and the modules of its package it imports. Then, with the
table `paramcheck` builds of every node's declarations:

- the name a launch file gives a node (`Node(name='bridge')`, `<node name=>`)
  makes a parameter file's `bridge:` section apply to that code (`renamed`);
- an inline value (`parameters=[{'max_speed': 2.0}]`, `<param name value>`) is
  checked as a parameter file's value is (RF401, RF101), at the launch file;
- a parameter the launch entry sets, inline or in the section of a file it names
  for its node, that the node's code does not declare is RF601 (a warning), when
  every parameter the node declares is known by name;
- a ROS 2 parameter file's section whose node name no node of the run has, in
  code or in a launch file, is RF602 (a note);
- a launch file that cannot be read or parsed is RF004, and so is a value launch
  cannot load (an integer PyYAML refuses).

A fault of ours on one launch file (reading it, or checking its entries) is a
`faults.Fault` of that file: its findings are dropped, the others checked.
"""

from __future__ import annotations

import ast
import contextlib
import hashlib
import os
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

from robotfix import messages
from robotfix.astwalk import children
from robotfix.diagnostics import Diagnostic, Note, Span
from robotfix.faults import Fault, guard
from robotfix.fs import (
    Noted,
    UnreadableError,
    noting,
    probe,
    read_text,
    remembered,
    replay,
)
from robotfix.ros import paramfile as P
from robotfix.ros.executables import (
    MAX_BUILD_BYTES,
    executable_file,
    module_file,
)
from robotfix.ros.launch.model import FileParam, InlineParam, NodeEntry
from robotfix.ros.launch.reader import Reader
from robotfix.ros.launch.tree import MAX_LAUNCH_BYTES
from robotfix.ros.package import package_folder, package_name
from robotfix.ros.yamlfile import WALK_BUDGET

if TYPE_CHECKING:  # the checks' own imports come with paramcheck, after the cache
    from robotfix.analysis.paramsummary import Summary
    from robotfix.paramcheck import Parameter, Table

BUILD_FILES = ("package.xml", "setup.py", "setup.cfg", "CMakeLists.txt")
# every rclpy node declares these itself
IMPLICIT = ("use_sim_time", "start_type_description_service")
IMPLICIT_PREFIXES = ("qos_overrides.",)


# one import statement as `_imported` reads it: the level of a `from` import
# (None for `import a, b`), its module, the names it takes
ImportLine = tuple[int | None, str | None, tuple[str, ...]]
# a file's path -> the length and hash of its text, and its import statements
# (as `import_lines`: no syntax tree is kept for the launch files' reading)
Imports = dict[str, tuple[int, int, list[ImportLine]]]


@dataclass
class _Started:
    """A launch entry and the files of the code it starts."""

    entry: NodeEntry
    files: set[str] = field(default_factory=set)  # real paths of its code


@dataclass(frozen=True)
class Read:
    """What reading one launch file gave: why it was not read, or its entries
    with the real paths of their code; the launch files it parsed (itself and
    what it includes)."""

    problem: tuple[str, int, int] | None
    started: list[tuple[NodeEntry, list[str]]]
    reading: list[str]


class Kept(Protocol):
    """Launch files' readings kept by an earlier run (`run._KeptReads`), each with
    what it read and probed: `get` gives one only while that holds."""

    def get(self, path: str, context: str) -> tuple[Noted, Read] | None: ...

    def put(self, path: str, context: str, noted: Noted, read: Read) -> None: ...


class LaunchRun:
    """The launch files of a run, read, and what they add to its parameter check
    (`paramcheck.Launches`)."""

    def __init__(
        self,
        launch_files: list[Path],
        code_files: list[Path],
        faults: list[Fault] | None = None,
        imports: Imports | None = None,
        kept: Kept | None = None,
    ) -> None:
        """`imports`: the import statements of the files this process's checks
        parsed (`import_lines`): not parsed again (`_imported`). `kept`: each launch
        file's reading as an earlier run made it, while what it read holds
        (`Kept`): not read again."""
        self.imports = imports
        self.kept = kept
        self._fresh: list[tuple[str, Noted, Read]] = []  # for `kept`, once all read
        self._kept_texts: list[str] = []  # files read by kept readings
        self.packages = _packages([*launch_files, *code_files])
        # what a launch file's reading depends on besides what it reads: where
        # each package is, the current folder (a relative path is read from it)
        where = sorted((k, str(v)) for k, v in self.packages.items())
        text = repr([os.getcwd(), where]).encode("utf-8", "surrogateescape")
        self._context = hashlib.sha256(text).hexdigest()
        self.notices: list[Diagnostic] = []
        self.started: list[_Started] = []
        self.renamed: dict[str, set[str]] = {}
        self.files: list[Path] = []
        self.names: set[str] = set()  # every node name a launch entry gives
        self.reader = Reader(self.packages.get)
        self._build: dict[tuple[str, Path], Any] = {}  # packages' build files
        self._codes: dict[tuple[Path, str], Any] = {}  # by executable
        # each package's CMake targets, read once a run for the C++ nodes'
        # parameters and the graph (`graphcheck.started_entries`; kept through
        # `fs.remembered`: a use hands the traces what the reading read)
        self.targets: dict[Path, Any] = {}
        # and what each (package, executable) is built from, alike
        self.executables: dict[tuple[Path, str], Any] = {}
        for path in launch_files:
            with guard(path, self.notices, faults):
                self._read(path)
            self.reader.release()  # a later include parses a file again
        self.entries = len(self.started)
        if kept is not None and not self.reader.order_dependent:
            for name, noted, read in self._fresh:
                kept.put(name, self._context, noted, read)
        # the entries are read: what reading them held (trees, readings, the
        # packages' build files) goes now, before the checks that use them
        self._fresh = []
        self._build.clear()
        self._codes.clear()
        self.reader.done()

    def _read(self, path: Path) -> None:
        """One launch file's entries, kept only once all are read (a fault on
        the file leaves nothing of it)."""
        name = str(path)
        known = self.kept.get(name, self._context) if self.kept is not None else None
        if known is not None:
            noted, read = known
            replay(noted)
            self.reader.touched.update(read.reading)
            self._kept_texts += read.reading
        else:
            # what it read, for `kept` (none without it: nothing to keep)
            fresh = Noted() if self.kept is not None else None
            self.reader.reading = set()
            with noting(fresh):
                launch = self.reader.read(path)
                started = [
                    (entry, sorted(self._code(entry)))
                    for entry in (launch.entries if launch.launch else [])
                ]
            read = Read(launch.problem, started, sorted(self.reader.reading))
            if fresh is not None:
                self._fresh.append((name, fresh, read))
        if read.problem is not None:
            text, line, col = read.problem
            self.notices.append(messages.launch_file_not_read(name, line, col, text))
            return
        for entry, files in read.started:
            self._add(_Started(entry, set(files)))

    def texts(self) -> dict[str, str]:
        """The texts of the launch files read (for suppressions), those a kept
        reading read too."""
        for name in self._kept_texts:
            if name not in self.reader.texts:
                with contextlib.suppress(UnreadableError):
                    self.reader.texts[name] = read_text(name, MAX_LAUNCH_BYTES)
        self._kept_texts = []
        return self.reader.texts

    def touched(self) -> set[str]:
        """Every file the launch check depends on: launch files, the parameter
        files they name, the packages' manifests and build files, the nodes' code."""
        found = set(self.reader.touched) | {str(p) for p in self.files}
        for folder in self.packages.values():
            found |= {str(folder / name) for name in BUILD_FILES}
        for started in self.started:
            found |= started.files
        return found

    def _add(self, started: _Started) -> None:
        entry = started.entry
        self.started.append(started)
        if entry.name:
            self.names.add(entry.name.rsplit("/", 1)[-1])
            if started.files:
                self.renamed.setdefault(entry.name.rsplit("/", 1)[-1], set()).update(
                    started.files
                )
        for parameter in entry.parameters:
            if isinstance(parameter, FileParam) and parameter.path is not None:
                path = Path(parameter.path)
                if path not in self.files:
                    self.files.append(path)

    def _code(self, entry: NodeEntry) -> set[str]:
        folder = self.packages.get(entry.package or "")
        if folder is None or not entry.executable:
            return set()
        executable = entry.executable

        def code() -> set[str]:
            main = executable_file(folder, executable, self._build)
            if main is None:
                return set()
            imported = _imported(main, folder, self.imports)
            return {probe("realpath", p) for p in [main, *imported]}

        # many entries start one executable
        return set(remembered(self._codes, (folder, executable), code))

    # -- the checks (called by paramcheck with its table) -------------------------
    def by_file(self) -> dict[str, list[_Started]]:
        """The entries by the file they are written in (an included file's
        entries are its own), in the order they were read."""
        found: dict[str, list[_Started]] = {}
        for started in self.started:
            found.setdefault(started.entry.place.path, []).append(started)
        return found

    def check_file(
        self,
        path: str,
        entries: list[_Started],
        table: Table,
        loaded: dict[str, P.ParamFile],
        faults: list[Fault] | None = None,
    ) -> list[Diagnostic]:
        """One file's entries against their nodes' code, under a `guard` of its
        own; the table needs only the summaries of the code they start."""
        out: list[Diagnostic] = []
        by_real = table.by_real  # each summary by its file's real path
        with guard(path, out, faults):
            for started in entries:
                cpp = table.cpp.owners_of(started.entry)  # its C++ node
                if cpp and started.entry.ros == 2:
                    out += _ros2_entry(started.entry, cpp, table, loaded)
                code = [by_real[f] for f in sorted(started.files) if f in by_real]
                if not code:
                    continue
                if started.entry.ros == 2:
                    out += _ros2_entry(started.entry, _owners_of(code), table, loaded)
                else:
                    out += _ros1_entry(started.entry, code, table)
        return out

    def sections(
        self,
        table: Table,
        loaded: dict[str, P.ParamFile],
        faults: list[Fault] | None = None,
    ) -> list[Diagnostic]:
        """RF602 for each parameter file, with the node names of the code and of
        the launch files."""
        from robotfix.paramcheck import unmatched_sections

        out: list[Diagnostic] = []
        known = self._known(table)
        passing = self._passing()
        for path, parameters in sorted(loaded.items()):
            with guard(path, out, faults):
                out += unmatched_sections(path, parameters, known)
                out += self._passed_for_nothing(path, parameters, passing.get(path, []))
        return out

    def _passing(self) -> dict[str, list[NodeEntry]]:
        """Each parameter file's ROS 2 entries that pass it, in their order (found
        once: not each file against every entry, 1,500 on corpus25)."""
        found: dict[str, list[NodeEntry]] = {}
        for started in self.started:
            entry = started.entry
            if entry.ros != 2:
                continue
            paths = {
                p.path
                for p in entry.parameters
                if isinstance(p, FileParam) and p.path is not None
            }
            for path in paths:
                found.setdefault(path, []).append(entry)
        return found

    def check(
        self,
        table: Table,
        loaded: dict[str, P.ParamFile],
        faults: list[Fault] | None = None,
    ) -> list[Diagnostic]:
        """The entries against their nodes' code, each launch file's under a
        `guard` of its own (an entry's file: an included file's entries are its
        own), then RF602 for each parameter file."""
        out = list(self.notices)
        for path, entries in self.by_file().items():
            out += self.check_file(path, entries, table, loaded, faults)
        return unique([*out, *self.sections(table, loaded, faults)])

    def _passed_for_nothing(
        self, path: str, parameters: P.ParamFile, passing: list[NodeEntry]
    ) -> list[Diagnostic]:
        """RF602 (a warning) at each launch entry that passes a ROS 2 parameter
        file none of whose sections applies to any node the entries passing it
        start (each named by the entry: `Node(name='sim_bridge')`), no key with a
        wildcard: the file gives those nodes nothing (a rename that left the
        section behind: f1tenth's `bridge:` file passed to `sim_bridge`). An
        entry that passes it without naming its node leaves the file unjudged.
        `passing`: the ROS 2 entries that pass it (`_passing`)."""
        if parameters.layout != "ros2":
            return []
        keys = sorted({item.node for item in parameters.entries if item.node})
        names = [e.name.rsplit("/", 1)[-1] if e.name else "" for e in passing]
        if (
            not keys
            or not passing
            or any("*" in k for k in keys)
            or any(not n or "$" in n or "{" in n for n in names)
            or any(
                _keyed_for(k, {n}, e.namespace)
                for k in keys
                for n, e in zip(names, passing, strict=True)
            )
        ):
            return []
        first = next(i for i in parameters.entries if i.node == keys[0])
        section = Note(f"the section `{keys[0]}`", path, first.line)
        return [
            messages.section_applies_to_none(
                e.place.path, e.place.line, e.place.col, n, keys, section
            )
            for n, e in zip(names, passing, strict=True)
        ]

    def _known(self, table: Table) -> set[str]:
        """Every node name of the code and the launch files."""
        return set(self.names) | table.node_names()


def unique(found: list[Diagnostic]) -> list[Diagnostic]:
    """One diagnostic per place, rule and message (two launch files naming one
    parameter file for one node find its typos twice)."""
    return list({(d.path, d.span, d.code, d.message): d for d in found}.values())


def _packages(files: list[Path]) -> dict[str, Path]:
    """Package name -> folder, for the packages the run's files lie in."""
    folders: dict[Path, Path | None] = {}
    found: dict[str, Path] = {}
    named: set[Path] = set()  # package folders whose name was read (once each)
    for path in files:
        parent = path.parent
        if parent not in folders:
            folders[parent] = _package_folder(parent)
        folder = folders[parent]
        if folder is not None and folder not in named:
            named.add(folder)
            name = package_name(folder)
            if name is not None:
                found.setdefault(name, folder)
    return found


def _package_folder(folder: Path) -> Path | None:
    """The package folder around `folder`, spelled as `folder` is (a relative run
    reports relative paths)."""
    for candidate in (folder, *folder.parents):
        if probe("isfile", candidate / "package.xml"):
            return candidate
    if not folder.is_absolute():
        return package_folder(folder / "x")
    return None


def _imported(main: Path, package: Path, known: Imports | None = None) -> list[Path]:
    """The modules of `package` that `main` imports (`from pkg.node import N`,
    `from .node import N`, `from ..pkg import node`, `import pkg.node`): where an
    entry point's node class often lives. A name a `from` import takes may be a
    submodule, so that is tried too. `known`: the import statements of files this
    process's checks parsed, by path, with their text's length and hash (a file
    whose text is still that is not parsed again)."""
    try:
        text = read_text(main, MAX_BUILD_BYTES)
        kept = (known or {}).get(str(main))
        if kept is not None and kept[:2] == (len(text), hash(text)):
            lines = kept[2]
        else:
            lines = import_lines(_statements(ast.parse(text)))
    except (UnreadableError, SyntaxError, ValueError, RecursionError, MemoryError):
        return []
    here = Path(os.path.relpath(main.parent, package)).parts
    here = () if here == (".",) else here
    found = []
    for level, module, taken in lines:
        modules: list[str] = []
        if level is not None:  # `from ... import`
            if level > len(here) + 1:
                continue  # above the package: not one of its modules
            base = here[: len(here) - level + 1] if level else ()
            head = ".".join([*base, *(module or "").split(".")]).strip(".")
            names = [n for n in taken if n != "*"]
            modules = [head] + [f"{head}.{n}" if head else n for n in names]
        else:
            modules = list(taken)
        for module in modules:
            path = module_file(package, module) if module else None
            if path is not None and path != main:
                found.append(path)
    return found


def import_lines(statements: Iterable[ast.AST]) -> list[ImportLine]:
    """The import statements among `statements`, as `_imported` reads them."""
    found: list[ImportLine] = []
    for node in statements:
        if isinstance(node, ast.ImportFrom):
            names = tuple([a.name for a in node.names])
            found.append((node.level, node.module, names))
        elif isinstance(node, ast.Import):
            found.append((None, None, tuple([a.name for a in node.names])))
    return found


def _statements(tree: ast.Module) -> Iterator[ast.AST]:
    """Every statement of a module, nested ones too, without walking the
    expressions (most of a file's nodes): where imports are."""
    todo: list[ast.AST] = [tree]
    while todo:
        node = todo.pop()
        yield node
        todo += [c for c in children(node) if not isinstance(c, ast.expr)]


def _owners_of(code: list[Summary]) -> list[tuple[Summary, str]]:
    from robotfix.analysis.paramsummary import ROSPY
    from robotfix.paramcheck import owners as declaring_owners

    return [
        (summary, owner)
        for summary in code
        for owner in sorted({*declaring_owners(summary), *summary.node_names})
        if owner != ROSPY
    ]


def _closed(summary: Summary, owner: str) -> bool:
    """Whether every parameter `owner` declares is known by name."""
    if "#" in owner:
        return False  # a node object in a variable: it may be handed anywhere
    lineage = summary.lineage(owner)
    return not any(
        o in summary.open_owners
        or o in summary.auto_declare
        or summary.listeners.get(o)
        for o in lineage
    )


def _declared(summary: Summary, owner: str, name: str) -> bool:
    return any(
        d.name == name and d.ros == 2 and d.owner in summary.lineage(owner)
        for d in summary.decls
    )


def _node_words(entry: NodeEntry, owners: list[tuple[Summary, str]]) -> str:
    if entry.name:
        return f"`{entry.name}`"
    names = sorted({n for s, o in owners for n in s.names_of(o)})
    return f"`{names[0]}`" if len(names) == 1 else f"`{entry.executable}`"


def _ros2_entry(
    entry: NodeEntry,
    owners: list[tuple[Summary, str]],
    table: Table,
    loaded: dict[str, P.ParamFile],
) -> list[Diagnostic]:
    """RF401/RF101 and RF601 for one entry, against its code's node objects."""
    if not owners:
        return []
    out: list[Diagnostic] = []
    node = _node_words(entry, owners)
    started_at = Note(
        f"the launch entry that starts it ({entry.package}/{entry.executable})",
        entry.place.path,
        entry.place.line,
    )
    closed = all(_closed(s, o) for s, o in owners)
    budget = [WALK_BUDGET]
    for parameter in entry.parameters:
        if isinstance(parameter, InlineParam):
            found = _inline(parameter, owners, table, node, budget)
            if found is not None:
                out.append(found)
            elif closed and _undeclared(parameter.name, owners):
                place = parameter.key or parameter.place
                out.append(
                    messages.launch_parameter_undeclared(
                        place.path,
                        place.line,
                        place.col,
                        parameter.name,
                        node,
                        _declared_in(owners),
                    )
                )
        elif parameter.path is not None and closed:
            out += _file_typos(entry, parameter, owners, loaded, node, started_at)
    return out


def _undeclared(name: str, owners: list[tuple[Summary, str]]) -> bool:
    if name in IMPLICIT or name.startswith(IMPLICIT_PREFIXES):
        return False
    return not any(_declared(s, o, name) for s, o in owners)


def _declared_in(owners: list[tuple[Summary, str]]) -> Note:
    summary, owner = owners[0]
    where = [d.line for d in summary.decls if d.owner in summary.lineage(owner)]
    return Note(
        f"the parameters `{owner}` declares",
        summary.path,
        min(where) if where else None,
    )


def _inline(
    parameter: InlineParam,
    owners: list[tuple[Summary, str]],
    table: Table,
    node: str,
    budget: list[int],
) -> Diagnostic | None:
    """RF401/RF101 when the value is wrong for every declaration it may meet;
    RF004 for a value launch cannot load, set for a declared parameter."""
    if parameter.value is None:
        return None
    candidates = [
        c
        for s, o in owners
        if (c := table.ros2_parameter(s, o, parameter.name)) is not None
    ]
    return _judged(parameter, candidates, node, budget)


def _judged(
    parameter: InlineParam, candidates: list[Parameter], node: str, budget: list[int]
) -> Diagnostic | None:
    """RF401/RF101 when the value is wrong for every candidate declaration."""
    value = parameter.value
    if value is None or not candidates:
        return None
    place = parameter.place
    span = Span.point(place.line, place.col)
    if isinstance(value, P.Unread):
        subject = f"`{parameter.name}: ...` (launched node {node})"
        return messages.parameter_value_not_checked(
            place.path, span, subject, value.why
        )
    failures = [c.judge(value, budget) for c in candidates]
    if any(f is None for f in failures):
        return None
    first = failures[0]
    assert first is not None
    shown = f'"{value.text}"' if value.type == "string" else value.text
    subject = f"`{parameter.name}: {shown[:40]}` (launched node {node})"
    from robotfix.paramcheck import report_failure

    return report_failure(place.path, span, subject, value, first)


def _file_typos(
    entry: NodeEntry,
    parameter: FileParam,
    owners: list[tuple[Summary, str]],
    loaded: dict[str, P.ParamFile],
    node: str,
    started_at: Note,
) -> list[Diagnostic]:
    """RF601 in the sections of a parameter file the entry names that are keyed
    for this node (not `/**`: those serve every node)."""
    assert parameter.path is not None
    parameters = loaded.get(parameter.path)
    if parameters is None or parameters.layout != "ros2":
        return []
    names = (
        {entry.name} if entry.name else {n for s, o in owners for n in s.names_of(o)}
    )
    out = []
    for item in parameters.entries:
        if not _keyed_for(item.node, names, entry.namespace):
            continue
        if _undeclared(item.name, owners):
            out.append(
                messages.launch_parameter_undeclared(
                    parameter.path, item.line, item.col, item.name, node, started_at
                )
            )
    return out


def _keyed_for(key: str, names: set[str], namespace: str | None) -> bool:
    """Whether a section key (`driver`, `/ns/driver`) names this node itself."""
    head, _, last = key.strip("/").rpartition("/")
    if last not in names or "*" in last:
        return False
    if not key.startswith("/") or namespace is None or "*" in head:
        return True
    return head == namespace.strip("/")


def _ros1_entry(
    entry: NodeEntry, code: list[Summary], table: Table
) -> list[Diagnostic]:
    """A `<param>` inside a roslaunch `<node>` is the node's private `~name`:
    checked against the refinements where the node's code reads it."""
    out: list[Diagnostic] = []
    budget = [WALK_BUDGET]
    for parameter in entry.parameters:
        if not isinstance(parameter, InlineParam) or parameter.value is None:
            continue
        name = (
            parameter.name
            if parameter.name.startswith(("/", "~"))
            else f"~{parameter.name}"
        )
        candidates = [
            c for summary in code if (c := _ros1_parameter(summary, name)) is not None
        ]
        node = f"`{entry.name or entry.executable}`"
        found = _judged(parameter, candidates, node, budget)
        if found is not None:
            out.append(found)
    return out


def _ros1_parameter(summary: Summary, name: str) -> Parameter | None:
    from robotfix.analysis.paramsummary import ROSPY
    from robotfix.paramcheck import Parameter, ros1_name

    nodes = summary.node_names.get(ROSPY, [])
    if not any(d.ros == 1 and ros1_name(d.name, nodes) == name for d in summary.decls):
        return None
    candidate = Parameter(name, 1)
    candidate.refinements = [
        a
        for a in summary.attached
        if a.owner == ROSPY and ros1_name(a.name, nodes) == name
    ]
    return candidate
