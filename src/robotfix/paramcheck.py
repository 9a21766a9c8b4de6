"""Parameter files checked against what the code declares.

For a run: the parameters each node declares or reads (`analysis.parameters`,
from the checked Python files and those of the packages around named YAML files),
the generate_parameter_library definitions of the checked packages, and then every
parameter file: a value outside a declared range or refinement is RF101, a value of
another type than declared is RF401, both at the value's line and column.

A parameter file can only be matched to code by names, so where a key could mean
several parameters (two nodes with one name, `/**`, the flat ROS 1 layout) a value
is reported only when it is wrong for every one of them; a key for a node or a
parameter nobody declares is silent.

- ROS 2: `node: ros__parameters:` matches the nodes of that name (`Node('name')`,
  `super().__init__('name')`); `/**` and `*` the nodes of the file's own package.
  A declared type is the default's type (rclpy refuses another, unless
  `dynamic_typing`), the range is the descriptor's, the refinements those written
  where the parameter's value is assigned; a generate_parameter_library definition
  applies to the nodes whose code calls `<root key>.ParamListener(...)`, and to
  nodes named like its root key.
- ROS 1: a flat file's `a/b` is the global `/a/b`, the private `~a/b` of a node of
  the file's package (loaded inside its `<node>`), or the private `~b` of node `a`.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

from robotfix import messages
from robotfix.analysis.parameters import summarize
from robotfix.analysis.paramsummary import ROSPY, Attached, ParamDecl, Summary
from robotfix.annotations import ast as A
from robotfix.config import Config
from robotfix.cppparams import CPP_TYPE_WHY, CppParams
from robotfix.diagnostics import Diagnostic, Span
from robotfix.faults import Fault, guard
from robotfix.fs import UnreadableError, probe, read_text
from robotfix.messages import Declared
from robotfix.ros import paramfile as P
from robotfix.ros import yamlfile as Y
from robotfix.ros.package import package_folder
from robotfix.smt.fold import fold
from robotfix.source import read_mentioning, suppresses

if TYPE_CHECKING:
    from robotfix.project.summary import Project
    from robotfix.stubs.load import StubSet

# A Python file is summarised only if it mentions one of these (bytes, quick).
MENTIONS = {
    "ros2": (b"declare_parameter", b"get_parameter", b"ParamListener"),
    "ros1": (b"rospy",),
}
# a summary with its rospy node names and the names its rospy parameters resolve
# to (`ros1_name`)
Rospy = tuple[Summary, list[str], set[str]]
# what a run's check of a Python file found: the words of MENTIONS its bytes hold,
# and its summary (None: none made, and so made here if one of them is wanted)
Known = tuple[tuple[bytes, ...], Summary | None]
TYPE_WHY = (
    "a ROS 2 parameter keeps the type it was declared with: rclpy refuses "
    "another (InvalidParameterTypeException) unless it is declared with "
    "dynamic_typing"
)
RANGE_WHY = "rclpy refuses the value (InvalidParameterValueException)"


@dataclass(frozen=True)
class Failure:
    """Why a parameter value breaks its declaration (or cannot be decided)."""

    type_error: bool
    rule: str  # what is broken, in words
    got: str = ""  # type errors: the value's type
    expected: str = ""  # type errors: the declared type
    declared: Declared = field(default_factory=lambda: Declared("", None, None))
    why: str = ""
    # not a failure: a refinement that cannot be evaluated for the value (`why`)
    undecided: bool = False


@dataclass
class Parameter:
    """One parameter a YAML key may name, with everything that constrains it."""

    name: str
    ros: int
    decls: list[ParamDecl] = field(default_factory=list)
    refinements: list[Attached] = field(default_factory=list)
    definitions: list[P.Definition] = field(default_factory=list)
    definitions_path: dict[int, str] = field(default_factory=dict)

    def judge(self, typed: P.Typed, budget: list[int]) -> Failure | None:
        """What is wrong with `typed` as this parameter's value (None: nothing
        this checker can tell)."""
        if any(d.ignore_override for d in self.decls):
            return None
        for decl in self.decls:
            found = _declaration_failure(decl, typed)
            if found is not None:
                return found
        undecided = None  # the first refinement it cannot be checked against
        for attached in self.refinements:
            found = _refinement_failure(attached, typed, self.name)
            if found is not None and not found.undecided:
                return found
            undecided = undecided or found
        for definition in self.definitions:
            found = _definition_failure(
                definition, typed, self.definitions_path[id(definition)], budget
            )
            if found is not None:
                return found
        return undecided


def check_parameter_files(
    files: list[Path],
    definition_files: list[Path],
    python_files: Iterable[Path],
    named: Iterable[Path] = (),
    config: Config | None = None,
    known: dict[str, Known] | None = None,
    project: Project | None = None,
    faults: list[Fault] | None = None,
    launches: Launches | None = None,
    cpp_nodes: CppParams | None = None,
    parts: Parts | None = None,
) -> list[Diagnostic]:
    """Diagnostics for the parameter files and generate_parameter_library
    definitions of a run; `python_files` are those whose declarations count. A
    file that is not valid YAML is RF003 when it was `named` on the command line
    or is a definitions file; found in a package's config folder, it is an RF004
    warning (it may be a template or another tool's file). A YAML line ending in
    `# robotfix: ignore[RF101]` and `per-file-ignores` silence as in Python.
    `known`: what the run's checks found of the Python files they read;
    `project`: how a file read here sees the other modules of its tree (an alias
    its refinement imports), as its check does. `faults`: where a fault of ours
    on one file goes, the others being checked (without it, it is raised).
    `launches`: what the run's launch files add (`launchcheck`): the names they
    give nodes, the parameter files they name, and their own checks, made with
    the same table (a fault on one launch file is a fault of that file).
    `cpp_nodes`: the run's C++ nodes (`cppparams`): their names (a section
    naming one is no RF602) and declarations, checked as a Python node's.
    `parts`: what an earlier run found, by part (the parameter files' findings,
    RF602, each launch file's entries'): a part kept is not checked again, and
    then only the code the other launch files' entries start is summarised."""
    if launches is not None:
        files = [*files, *(f for f in launches.files if f not in files)]
    by_file = launches.by_file() if launches is not None else {}
    fixed = parts.fixed() if parts is not None else None
    kept: dict[
        str, list[Diagnostic]
    ] = {}  # a launch file -> its entries' findings, as an earlier run found them
    if parts is not None:
        for name, entries in by_file.items():
            part = parts.launch_file(name, entries)
            if part is not None:
                kept[name] = part
    todo = [name for name in by_file if name not in kept]
    loading = [*definition_files, *files]
    if fixed is not None:  # only the files the entries still to check name
        named_here = {
            parameter.path
            for name in todo
            for started in by_file[name]
            for parameter in started.entry.parameters
            if getattr(parameter, "path", None) is not None
        }
        loading = [*definition_files, *(f for f in files if str(f) in named_here)]
    loud = {str(p) for p in [*named, *definition_files]}
    texts: dict[str, str] = {}
    out: list[Diagnostic] = []
    definitions: dict[str, list[tuple[P.Definition, str]]] = {}
    read: dict[str, P.ParamFile] = {}
    for path in loading:
        key = str(path)
        if key in read:
            continue
        with guard(path, out, faults):
            loaded = _load(path, key in loud, out, texts)
            if loaded is None:
                continue
            read[key] = loaded
            if loaded.layout == "definitions":
                for definition in loaded.definitions:
                    definitions.setdefault(definition.namespace, []).append(
                        (definition, key)
                    )
                out.extend(_definition_defaults(loaded, key))
    # a file with sections but no values still needs the code's node names (RF602)
    layouts = {f.layout for f in read.values() if f.entries or f.sections}
    if launches is not None and launches.entries:
        layouts |= set(MENTIONS)
    words = tuple(w for layout in sorted(layouts) for w in MENTIONS.get(layout, ()))
    if fixed is not None:  # only the code of the entries still to check
        started = {f for name in todo for s in by_file[name] for f in s.files}
        python_files = [p for p in python_files if probe("realpath", p) in started]
    found = (
        _summaries(python_files, words, known or {}, project, faults, config)
        if words and (fixed is None or todo)
        else []
    )
    if cpp_nodes is not None:
        cpp_nodes.read(faults)  # (a fault of ours on one C++ file is that file's)
    table = Table(found, definitions, launches.renamed if launches else None, cpp_nodes)
    sections: list[Diagnostic] = []
    if fixed is None:
        for path in files:
            loaded = read.get(str(path))
            if loaded is None or loaded.layout == "definitions":
                continue
            with guard(path, out, faults):
                out.extend(_check_file(path, loaded, table))
        if launches is not None:
            sections = launches.sections(table, read, faults)
        else:  # RF602 with the code's node names alone (launchcheck adds launch's)
            names = table.node_names()
            for key, loaded in sorted(read.items()):
                with guard(key, out, faults):
                    out += unmatched_sections(key, loaded, names)
    if launches is not None:
        texts.update(launches.texts())

    def heard(found: list[Diagnostic]) -> list[Diagnostic]:
        return [d for d in found if not _silenced(d, texts.get(d.path, ""), config)]

    checked = {name: heard(kept.get(name) or []) for name in by_file}
    for name in todo:
        checked[name] = heard(
            launches.check_file(name, by_file[name], table, read, faults)
            if launches is not None
            else []
        )
    if fixed is None:
        fixed = (heard(out), heard(sections))
        if parts is not None and not faults:
            parts.keep(fixed, checked)
    elif parts is not None and not faults:
        parts.keep(None, {name: checked[name] for name in todo})
    if launches is None:
        return fixed[0]
    from robotfix.launchcheck import unique

    found_here = [*launches.notices, *(d for n in by_file for d in checked[n])]
    return [*fixed[0], *heard(unique([*found_here, *fixed[1]]))]


def unmatched_sections(
    path: str, parameters: P.ParamFile, known: set[str]
) -> list[Diagnostic]:
    """RF602: a ROS 2 parameter file's sections that name no known node."""
    if parameters.layout != "ros2":
        return []
    unmatched = [
        (key, where)
        for key, where in parameters.sections.items()
        if (name := key.rstrip("/").rsplit("/", 1)[-1])
        and "*" not in name
        and name not in known
    ]
    if not unmatched:
        return []
    (line, col) = unmatched[0][1]
    keys = [key for key, _ in unmatched]
    return [messages.parameter_section_unmatched(path, line, col, keys)]


def _check_file(path: Path, loaded: P.ParamFile, table: Table) -> list[Diagnostic]:
    """A parameter file's values against what the run's nodes declare."""
    out: list[Diagnostic] = []
    package = _package_of(path)
    budget = [Y.WALK_BUDGET]
    for entry in loaded.entries:
        candidates = (
            table.ros2(entry, package)
            if loaded.layout == "ros2"
            else table.ros1(entry, package)
        )
        if not candidates:
            continue
        value = entry.value
        typed = (P.ros2_value if loaded.layout == "ros2" else P.ros1_value)(
            value, budget
        )
        if isinstance(typed, P.Unread):
            out.append(_unread(str(path), entry, value, typed))
            continue
        if typed is None:
            continue
        failures = [c.judge(typed, budget) for c in candidates]
        if all(f is not None for f in failures):
            broken = [f for f in failures if f is not None and not f.undecided]
            first = (broken or failures)[0]
            assert first is not None
            out.append(_report(str(path), entry, value, typed, first))
    return out


def _silenced(diag: Diagnostic, text: str, config: Config | None) -> bool:
    if config is not None and (
        {diag.code, diag.rule.name} & config.ignored_codes(Path(diag.path))
    ):
        return True
    lines = text.splitlines()
    line = diag.span.line
    return 0 < line <= len(lines) and suppresses(lines[line - 1], diag)


def _summaries(
    python_files: Iterable[Path],
    words: tuple[bytes, ...],
    known: dict[str, Known],
    project: Project | None = None,
    faults: list[Fault] | None = None,
    config: Config | None = None,
) -> list[Summary]:
    """The summaries of the files that mention one of `words` (a quick filter);
    those in `known` are not read again (unless their check made no summary).
    A fault on one file is kept in `faults` (see `guard`); each file's stubs are
    its settings' (`config`)."""
    found: list[Summary] = []
    seen: set[str] = set()
    for path in python_files:
        mentioned, summary = known.get(str(path), (None, None))
        if mentioned is not None and not any(w in mentioned for w in words):
            continue
        real = probe("realpath", path)
        if real in seen:
            continue
        seen.add(real)
        if summary is not None:
            found.append(summary)
            continue
        with guard(path, [], faults):
            source = read_mentioning(path, words)
            if source is not None:
                resolver = project.resolver(path) if project is not None else None
                stubs = _stubs(config, path)
                found.append(summarize(source, resolver=resolver, stubs=stubs))
    return found


def _stubs(config: Config | None, path: Path) -> StubSet | None:
    """The stubs a file's settings name (where a parameter API may be described)."""
    if config is None:
        return None
    from robotfix.stubs.load import stub_set

    return stub_set(config.for_file(path).stub_paths)


def _load(
    path: Path, named: bool, out: list[Diagnostic], texts: dict[str, str]
) -> P.ParamFile | None:
    """A parameter file's layout and entries; a file that cannot be read or is not
    valid YAML is RF003 (ROS could not load it either)."""
    try:
        text = read_text(path, Y.MAX_YAML_BYTES)
    except UnreadableError as err:
        text = ""
        root: Y.Node | Y.YamlProblem | None = Y.YamlProblem(
            f"cannot read: {err.reason}", 1, 0
        )
    else:
        texts[str(path)] = text
        root = Y.parse(text)
    if isinstance(root, Y.YamlProblem):
        report = (
            messages.parameter_file_unreadable
            if named
            else messages.parameter_file_not_checked
        )
        out.append(report(str(path), root.line, root.col, root.message))
        return None
    loaded = P.classify(root, "*" in text or "<<" in text)
    if loaded is None:
        return None
    for problem in loaded.problems:
        out.append(
            messages.parameter_merge_refused(
                str(path), problem.line, problem.col, problem.message
            )
        )
    reference = loaded.reference
    if reference is not None:
        out.append(
            messages.parameter_file_reference(
                str(path), reference.line, reference.col, isinstance(reference, Y.Alias)
            )
        )
    return loaded


class Launches(Protocol):
    """What a run's launch files add to the check of its parameter files."""

    renamed: dict[str, set[str]]  # a node name -> the Python files of its code
    files: list[Path]  # parameter files the launch entries name
    entries: int  # launch entries read
    notices: list[Diagnostic]  # launch files not read (RF004)

    def by_file(self) -> dict[str, list[Any]]:
        """The entries by the launch file they are written in."""
        ...

    def check_file(
        self,
        path: str,
        entries: list[Any],
        table: Table,
        read: dict[str, P.ParamFile],
        faults: list[Fault] | None = None,
    ) -> list[Diagnostic]:
        """One launch file's entries against their code (`read`: the parameter
        files loaded); a fault of ours goes to `faults` (`guard`)."""
        ...

    def sections(
        self,
        table: Table,
        read: dict[str, P.ParamFile],
        faults: list[Fault] | None = None,
    ) -> list[Diagnostic]:
        """RF602 with the names of the code's and the launch files' nodes."""
        ...

    def texts(self) -> dict[str, str]:
        """The launch files' texts (a `# robotfix: ignore` on a line)."""
        ...


class Parts(Protocol):
    """What an earlier run's check found, by part (`run._ParamParts`, each part
    under a key of what it depends on); `keep` hands over this run's."""

    def fixed(self) -> tuple[list[Diagnostic], list[Diagnostic]] | None:
        """The parameter files' findings (with RF602 when no launch file is
        read) and RF602 with launch files."""
        ...

    def launch_file(self, path: str, entries: list[Any]) -> list[Diagnostic] | None: ...

    def keep(
        self,
        fixed: tuple[list[Diagnostic], list[Diagnostic]] | None,
        launch: dict[str, list[Diagnostic]],
    ) -> None: ...


class Table:
    """The parameters of the run's nodes, by node name and package; `renamed`:
    the names launch files give nodes (`Node(name='bridge')`), with the files
    of the code they start, so a section keyed `bridge:` applies to it."""

    def __init__(
        self,
        summaries: list[Summary],
        definitions: dict[str, list[tuple[P.Definition, str]]],
        renamed: dict[str, set[str]] | None = None,
        cpp_nodes: CppParams | None = None,
    ) -> None:
        self.cpp = cpp_nodes or CppParams()  # C++ nodes: read by `ros.graph.cpp`
        self.summaries = summaries = [*summaries, *self.cpp.summaries]
        self.cpp_nodes = self.cpp.names
        self.definitions = definitions
        self.renamed = {  # real paths
            name: {*(renamed or {}).get(name, ()), *self.cpp.renamed.get(name, ())}
            for name in {*(renamed or {}), *self.cpp.renamed}
        }
        self.real = {s.path: probe("realpath", s.path) for s in summaries}
        # by real path, made once (each launch file's check looks its code up)
        self.by_real = {self.real[s.path]: s for s in summaries}
        self.packages = {s.path: _package_of(Path(s.path)) for s in summaries}
        self._by_node: dict[str, list[tuple[Summary, str, list[str]]]] = {}
        # ROS 1: each summary's rospy nodes and parameter names, by package
        self._declared: list[Rospy] | None = None
        self._by_package: dict[Path | None, list[Rospy]] = {}
        # ROS 2 owners whose parameters a file may set: (summary, owner, names)
        self.owners = [
            (summary, owner, summary.names_of(owner))
            for summary in summaries
            for owner in owners(summary)
            if not any(o in summary.auto_declare for o in summary.lineage(owner))
        ]

    def node_names(self) -> set[str]:
        """Every node name a ROS 2 section can match in the code: the Python and
        C++ nodes', and the root keys of generate_parameter_library definitions."""
        names = set(self.definitions) | self.cpp_nodes
        for summary in self.summaries:
            for found in summary.node_names.values():
                names.update(found)
        return names

    def ros2(self, entry: P.Entry, package: Path | None) -> list[Parameter]:
        node = entry.node_name
        wildcard = node in ("*", "**")
        found: list[Parameter] = []
        for summary, owner, _ in self.owners if wildcard else self._named(node):
            if wildcard and (package is None or self.packages[summary.path] != package):
                continue
            candidate = self.ros2_parameter(summary, owner, entry.name)
            if candidate is not None:
                found.append(candidate)
        if not wildcard:
            for definition, path in self.definitions.get(node, []):
                if definition.matches(entry.name):
                    found.append(_gpl(entry.name, definition, path))
        return found

    def _named(self, node: str) -> list[tuple[Summary, str, list[str]]]:
        """The owners a section keyed `node` is for: named so by their code or
        by a launch file (found once per name: a file has many values)."""
        if node not in self._by_node:
            renamed = self.renamed.get(node, ())
            self._by_node[node] = [
                one
                for one in self.owners
                if node in one[2] or self.real[one[0].path] in renamed
            ]
        return self._by_node[node]

    def ros2_parameter(
        self, summary: Summary, owner: str, name: str
    ) -> Parameter | None:
        candidate = Parameter(name, 2)
        decl = summary.declaration(owner, name)
        if decl is not None:
            candidate.decls.append(decl)
        candidate.refinements = summary.refinements(owner, name, False)
        for namespace in summary.listeners.get(owner, []):
            for definition, path in self.definitions.get(namespace, []):
                if definition.matches(name):
                    candidate.definitions.append(definition)
                    candidate.definitions_path[id(definition)] = path
        if candidate.decls or candidate.refinements or candidate.definitions:
            return candidate
        return None

    def ros1(self, entry: P.Entry, package: Path | None) -> list[Parameter]:
        found: list[Parameter] = []
        head, _, rest = entry.name.partition("/")
        for summary, nodes, declared in self._ros1(package):
            wanted = {f"/{entry.name}", f"~{entry.name}"}
            if rest and head in nodes:
                wanted.add(f"~{rest}")
            for name in sorted(wanted):
                if name in declared:
                    candidate = Parameter(name, 1)
                    candidate.refinements = [
                        a
                        for a in summary.attached
                        if a.owner == ROSPY and ros1_name(a.name, nodes) == name
                    ]
                    found.append(candidate)
        return found

    def _ros1(self, package: Path | None) -> list[Rospy]:
        """The summaries with rospy parameters a flat file of `package` may set
        (all for None), each with its rospy node names and the names its
        parameters resolve to (`ros1_name`): found once per package and summary,
        not for every value of every file."""
        if package not in self._by_package:
            if self._declared is None:
                found = [
                    (
                        s,
                        nodes,
                        {ros1_name(d.name, nodes) for d in s.decls if d.ros == 1},
                    )
                    for s in self.summaries
                    for nodes in [s.node_names.get(ROSPY, [])]
                ]
                self._declared = [one for one in found if one[2]]  # others: none
            self._by_package[package] = [
                one
                for one in self._declared
                if package is None or self.packages[one[0].path] == package
            ]
        return self._by_package[package]


def ros1_name(name: str, nodes: list[str]) -> str:
    """A rospy parameter name resolved for a node in the root namespace: `rate`
    is `/rate`, and `/node/rate` is the node's private `~rate`."""
    if name.startswith("~"):
        return name
    absolute = name if name.startswith("/") else f"/{name}"
    for node in nodes:
        if absolute.startswith(f"/{node}/"):
            return "~" + absolute[len(node) + 2 :]
    return absolute


def owners(summary: Summary) -> list[str]:
    owners = {d.owner for d in summary.decls if d.ros == 2}
    owners |= {a.owner for a in summary.attached if a.owner != ROSPY}
    owners |= set(summary.listeners)
    return sorted(owners)


def _gpl(name: str, definition: P.Definition, path: str) -> Parameter:
    candidate = Parameter(name, 2, definitions=[definition])
    candidate.definitions_path[id(definition)] = path
    return candidate


_package_of = package_folder


# -- the rules ------------------------------------------------------------------


def _declaration_failure(decl: ParamDecl, typed: P.Typed) -> Failure | None:
    declared = Declared(f"parameter `{decl.name}`", decl.path, decl.line)
    if decl.dynamic or decl.type is None:
        return None
    if typed.type != decl.type:
        return Failure(
            True,
            "",
            P.type_words(typed.type),
            P.type_words(decl.type),
            declared,
            TYPE_WHY if decl.path.endswith(".py") else CPP_TYPE_WHY,
        )
    value = typed.value
    if (
        decl.range is not None
        and isinstance(value, (int, float))
        and not isinstance(value, bool)
        and not decl.range.accepts(value)
    ):
        ranged = Declared(
            f"range of parameter `{decl.name}`", decl.path, decl.range.line
        )
        return Failure(
            False,
            f"its declared range {decl.range.text()}",
            declared=ranged,
            why=RANGE_WHY,
        )
    return None


BASES = {
    "int": {"integer", "bool"},
    "float": {"integer", "double", "bool"},
    "bool": {"bool"},
    "str": {"string"},
}


def _refinement_failure(
    attached: Attached, typed: P.Typed, name: str
) -> Failure | None:
    refinement = attached.refinement
    declared = Declared(
        f"annotation of `{attached.target}`", attached.path, attached.line
    )
    allowed = BASES.get(refinement.base)
    if allowed is not None and typed.type not in allowed and "_array" not in typed.type:
        expected = {
            "int": "an integer",
            "float": "a double",
            "bool": "a bool",
            "str": "a string",
        }[refinement.base]
        return Failure(True, "", P.type_words(typed.type), expected, declared)
    short = name.rsplit("/", 1)[-1].rsplit(".", 1)[-1].lstrip("~")
    term = _term(typed)
    undecided = None
    for part in A.conjuncts(refinement.predicate):
        if isinstance(part, A.UnitIs):
            continue  # a unit, a frame: nothing a value in a file can break
        shown = f"`{A.show(A.substitute(part, {'_': A.Name(short)}))}`"
        found = None if term is None else fold(A.substitute(part, {"_": term}))
        if found is False:
            return Failure(False, shown, declared=declared)
        if found is None and undecided is None:
            why = _why_undecided(part, term)
            undecided = Failure(
                False, shown, declared=declared, why=why, undecided=True
            )
    return undecided


def _why_undecided(part: A.Expr, term: A.Expr | None) -> str:
    """Why a refinement's part cannot be evaluated for a value in a file."""
    if term is None:
        return "RobotFix evaluates refinements for numbers, booleans and strings"
    names = sorted({n.name for n in A.names(part) if n.name != "_"})
    if names:
        shown = ", ".join(f"`{n}`" for n in names)
        return (
            f"{shown} is only known to the running code (a file's value is checked "
            "against constants, `math.pi` and the like)"
        )
    return "RobotFix cannot evaluate it for a value"


def _term(typed: P.Typed) -> A.Expr | None:
    value = typed.value
    if isinstance(value, bool):
        return A.Bool(value)
    if isinstance(value, int):
        return A.Num(Fraction(value), True)
    if isinstance(value, float):
        if value != value or value in (float("inf"), float("-inf")):
            return None
        exact = P.exact(typed.text)  # None: past the bounds, or `1_000.5` (ROS 1)
        return A.Num(Fraction(value) if exact is None else exact, False)
    if isinstance(value, str):
        return A.Str(value)
    return None


def _definition_failure(
    definition: P.Definition, typed: P.Typed, path: str, budget: list[int]
) -> Failure | None:
    name = f"{definition.namespace}.{definition.name}"
    expected = definition.ros_type
    if expected is not None and typed.type != expected:
        declared = Declared(f"parameter `{name}`", path, definition.line)
        return Failure(
            True,
            "",
            P.type_words(typed.type),
            P.type_words(expected),
            declared,
            TYPE_WHY,
        )
    for validator, args, line, _ in definition.validations:
        broken = P.gpl_violation(validator, args, typed, budget)
        if broken is not None:
            declared = Declared(f"validation of parameter `{name}`", path, line)
            return Failure(
                False,
                broken,
                declared=declared,
                why="the generated parameter code refuses it",
            )
    return None


def _definition_defaults(loaded: P.ParamFile, path: str) -> list[Diagnostic]:
    """A definition whose default_value breaks its own validation (read as
    generate_parameter_library reads it: YAML 1.1)."""
    out = []
    budget = [Y.WALK_BUDGET]
    for definition in loaded.definitions:
        default = Y.resolve(definition.default, budget)
        if default is None:
            continue
        typed = (
            P.ros2_value(default, budget)
            if isinstance(default, Y.Sequence)
            else P.ros1_value(default, budget)
        )
        if not isinstance(typed, P.Typed):
            continue  # PyYAML refuses it: the generator fails, and says so
        for validator, args, line, _ in definition.validations:
            broken = P.gpl_violation(validator, args, typed, budget)
            if broken is not None:
                name = f"{definition.namespace}.{definition.name}"
                where = (
                    default
                    if isinstance(default, (Y.Scalar, Y.Sequence))
                    else definition
                )
                out.append(
                    messages.parameter_value_violated(
                        path,
                        Span.point(where.line, where.col),
                        f"the default_value `{typed.text}` of parameter `{name}`",
                        broken,
                        Declared(f"validation of parameter `{name}`", path, line),
                        "the generated parameter code refuses its own default",
                    )
                )
                break
    return out


def _subject(entry: P.Entry, value: Y.Node, text: str) -> str:
    """`name: value` (node `n`), the value cut for a message."""
    shown = text
    if isinstance(value, Y.Scalar) and not value.plain:
        shown = f'"{shown}"'
    if len(shown) > 40:
        shown = shown[:37] + "..."
    node = f" (node `{entry.node}`)" if entry.node else ""
    return f"`{entry.name}: {shown}`{node}"


def _span(entry: P.Entry, value: Y.Node) -> Span:
    return Span.point(
        getattr(value, "line", entry.line), getattr(value, "col", entry.col)
    )


def _report(
    path: str, entry: P.Entry, value: Y.Node, typed: P.Typed, failure: Failure
) -> Diagnostic:
    return report_failure(
        path, _span(entry, value), _subject(entry, value, typed.text), typed, failure
    )


def report_failure(
    path: str, span: Span, subject: str, typed: P.Typed, failure: Failure
) -> Diagnostic:
    """RF401 or RF101 for a value (`subject`) at `span`; `typed.how` says how ROS
    came to read it so, when its text does not. RF102, a note, for a value a
    refinement cannot be evaluated for (`Failure.undecided`)."""
    if failure.undecided:
        return messages.parameter_refinement_unchecked(
            path, span, subject, failure.rule, failure.declared, failure.why
        )
    if failure.type_error:
        return messages.parameter_value_type(
            path,
            span,
            subject,
            failure.got,
            failure.expected,
            failure.declared,
            typed.how,
            failure.why,
        )
    return messages.parameter_value_violated(
        path, span, subject, failure.rule, failure.declared, typed.how, failure.why
    )


def _unread(path: str, entry: P.Entry, value: Y.Node, unread: P.Unread) -> Diagnostic:
    text = value.text if isinstance(value, Y.Scalar) else "..."
    return messages.parameter_value_not_checked(
        path, _span(entry, value), _subject(entry, value, text), unread.why
    )
