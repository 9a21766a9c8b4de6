"""A run's static ROS graph (`ros.graph`) and what is wrong in it.

The graph is made of the endpoints each checked Python file's check extracted
(`run.FileResult.graph`, kept in the result cache with the file's entry), those of
the C++ files of the run's packages (read here with tree-sitter), and the launch
entries (`launchcheck.LaunchRun`), which start code under a name and namespace
with remappings: a launch entry's executable is found through setup.py or
CMakeLists.txt (`ros.executables`).

Findings, each at an endpoint with a note at the other side:
- RF603: one resolved name (in one ROS version's graph) used with two certain
  interface types by different nodes (a type chosen at run time, as a parameter
  picks `Twist` or `TwistStamped`, is two possible types: never a finding);
- RF604/RF605: a subscription whose QoS never matches a publisher's (reliable vs
  best effort, transient local vs volatile): RF604 when both profiles are
  constants, RF605 when one may change (QoS overrides by parameter); only
  between endpoints whose types can be one (ROS connects no others);
- RF606/RF607 (notes): a topic subscribed and published nowhere in the checked
  tree, or the reverse; not when an endpoint whose name is not known may be it;
  only in a run whose launch files start nodes (they say which nodes make the
  system: without them a package of one talker would be noted for its listener).

Only `robotfix check` of a folder reports them (`run.py`): the graph of a single
file or of what an editor has open depends on what was opened.
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterable
from dataclasses import dataclass, field, replace
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING

from robotfix import messages
from robotfix.diagnostics import Diagnostic, Note
from robotfix.fs import UnreadableError, probe, read_regular, remembered
from robotfix.ros.executables import CPP_SOURCE_SUFFIXES, cpp_executable_files
from robotfix.ros.graph import qos as Q
from robotfix.ros.graph.build import End, Graph, Started, build
from robotfix.ros.graph.model import (
    ACTION_CLIENT,
    ACTION_SERVER,
    CLIENT,
    PUBLISHER,
    SERVICE,
    SUBSCRIPTION,
    Endpoint,
    FileGraph,
    dump,
    load,
)
from robotfix.ros.package import package_folder, package_name, test_code
from robotfix.source import suppresses

if TYPE_CHECKING:
    from robotfix.api import Contract
    from robotfix.cache import ResultCache
    from robotfix.config import Config
    from robotfix.launchcheck import LaunchRun

# topics rcl itself provides for every node, and those every lifecycle node
# publishes under its own name (rclcpp_lifecycle, rclpy.lifecycle)
BUILTIN_TOPICS = frozenset({"/rosout", "/parameter_events"})
BUILTIN_SUFFIXES = ("/transition_event",)
_CPP_COMMENT = re.compile(r"//(?=\s*robotfix:)")


@dataclass
class Finding:
    """A graph diagnostic and the endpoints it is about."""

    diagnostic: Diagnostic
    end: int  # index in Graph.ends
    other: int | None = None


@dataclass
class GraphResult:
    """A run's graph and its findings."""

    graph: Graph
    findings: list[Finding] = field(default_factory=list)

    def diagnostics(self) -> list[Diagnostic]:
        return [f.diagnostic for f in self.findings]


def read_cpp_files(
    paths: list[Path], cache: ResultCache | None = None
) -> dict[str, FileGraph]:
    """Each C++ file's graph; a file that cannot be read has none. With the
    result cache, a file whose bytes are unchanged is not parsed again."""
    found: dict[str, FileGraph] = {}
    if not paths:
        return found  # (no C++: its reader, ros/graph/cpp.py, is never loaded)
    from robotfix.ros.graph.cpp import MAX_CPP_BYTES, read_cpp

    for path in paths:
        digest = cache.sha(path) if cache is not None else None
        if cache is not None and digest is not None:
            known, raw = cache.cpp_graph(path, digest)
            if known:
                one = load(raw) if raw is not None else None
                if one is not None:
                    found[str(path)] = one
                continue
        try:
            data = (
                cache.take(path)
                if digest is not None and cache is not None
                else read_regular(path, MAX_CPP_BYTES)
            )
        except UnreadableError:
            continue
        one = read_cpp(data, names=False)  # (a graph without endpoints: not kept)
        if cache is not None and digest is not None:
            cache.put_cpp(path, digest, dump(one) if one.endpoints else None)
        if one.endpoints:
            found[str(path)] = one
    return found


def started_entries(
    launches: LaunchRun | None, code: dict[str, FileGraph]
) -> list[Started]:
    """The launch entries of the run, each with the code files it runs."""
    if launches is None:
        return []
    by_real: dict[str, str] = {}
    for path in sorted(code):  # sorted: the output of `-j N` is that of `-j 1`
        by_real.setdefault(probe("realpath", path), path)
    packages = dict(launches.packages)
    folders: set[str] = set()
    names: dict[Path, str | None] = {}  # each package's package.xml read once
    for path in sorted(code):  # a C++ package has no Python file LaunchRun saw
        folder = os.path.dirname(path)
        if folder in folders:
            continue
        folders.add(folder)
        found = package_folder(Path(path))
        if found is not None and found not in names:
            names[found] = package_name(found)
        name = names[found] if found is not None else None
        if found is not None and name is not None:
            packages.setdefault(name, found)
    out: list[Started] = []
    reals = sorted(by_real.items())  # (a plugin's package: the files inside it)
    inside: dict[Path, list[str]] = {}  # each plugin package's files, found once
    targets = launches.targets  # each package's CMake targets, read once a run
    built = launches.executables  # many entries start one, in both calls a run
    # an executable's code files of the run, found once a call: its sources'
    # real paths are asked once, not once an entry that starts it
    running: dict[tuple[Path, str], list[str]] = {}
    for started in launches.started:
        entry = started.entry
        files = [by_real[f] for f in sorted(started.files) if f in by_real]
        package = packages.get(entry.package or "")
        plugin = None
        if package is not None and entry.plugin:
            plugin = entry.plugin.split("::")[-1]
            if package not in inside:
                folder = probe("realpath", package) + os.sep
                inside[package] = [p for r, p in reals if r.startswith(folder)]
            files += inside[package]
        elif package is not None and entry.executable and not files:
            one = (package, entry.executable)
            if one not in running:
                make = partial(cpp_executable_files, package, entry.executable, targets)
                sources = remembered(built, one, make)
                real = [probe("realpath", source) for source in sources]
                running[one] = [by_real[r] for r in real if r in by_real]
            files += running[one]
        out.append(Started(entry, files, plugin))
    return out


def check_graph(
    code: dict[str, FileGraph],
    launches: LaunchRun | None,
    config: Config | None = None,
) -> GraphResult:
    """The graph of the run's code and launch files, and its findings."""
    graph = build(code, started_entries(launches, code))
    result = GraphResult(graph)
    channels = _channels(graph)
    systems = _Systems(graph)
    for (ros, family, name), ends in channels.items():
        mismatched = _type_mismatch(graph, family, name, ends, result, systems)
        if family == "topic" and ros == 2 and not mismatched:
            _qos(graph, name, ends, result, systems)
    if launches is not None and launches.started:
        _unmatched(graph, channels, result)
    texts: dict[str, list[str] | None] = {}
    result.findings = [
        f for f in result.findings if not _silenced(f.diagnostic, texts, config)
    ]
    result.findings.sort(key=lambda f: f.diagnostic.sort_key())
    return result


def _channels(graph: Graph) -> dict[tuple[int, str, str], list[int]]:
    found: dict[tuple[int, str, str], list[int]] = {}
    for index, end in enumerate(graph.ends):
        if end.resolved is None or end.family == "parameter" or not end.certain:
            continue
        found.setdefault((end.endpoint.ros, end.family, end.resolved), []).append(index)
    for ends in found.values():
        ends.sort(key=lambda i: _place(graph.ends[i]))
    return {k: found[k] for k in sorted(found)}


def _place(end: End) -> tuple[str, int, int]:
    return (end.path, end.endpoint.line, end.endpoint.col)


def _note(end: End, what: str) -> Note:
    return Note(what, end.path, end.endpoint.line)


TOGETHER, MAYBE = "together", "maybe"


class _Systems:
    """Whether two node instances run in one system.

    - TOGETHER: launch entries of launch files of one package start both (a
      bringup package's launch files describe one system);
    - MAYBE: code no launch file starts, both in one package and neither test
      code (a package's nodes are meant to talk, but which run together is not
      written down);
    - None: anything else: programs of different packages no launch file starts
      together (a repository's demos), test code (its nodes are throwaway)."""

    def __init__(self, graph: Graph) -> None:
        self.graph = graph
        self.folders: dict[str, str] = {}

    def _package(self, path: str) -> str:
        folder = os.path.dirname(path)
        if folder not in self.folders:
            found = package_folder(Path(path))
            self.folders[folder] = str(found) if found is not None else folder
        return self.folders[folder]

    def relation(self, a: End, b: End) -> str | None:
        first, second = self.graph.nodes[a.node], self.graph.nodes[b.node]
        if first.launch is not None and second.launch is not None:
            same = self._package(first.launch.path) == self._package(second.launch.path)
            return TOGETHER if same else None
        if test_code(a.path) or test_code(b.path):
            return None
        return MAYBE if self._package(a.path) == self._package(b.path) else None


def _type_mismatch(
    graph: Graph,
    family: str,
    name: str,
    ends: list[int],
    result: GraphResult,
    systems: _Systems,
) -> bool:
    """RF603; True when reported."""
    per_node: dict[int, set[tuple[str, ...]]] = {}
    for index in ends:
        end = graph.ends[index]
        per_node.setdefault(end.node, set()).add(end.endpoint.types)
    certain = {
        node: next(iter(types))[0]
        for node, types in per_node.items()
        if len(types) == 1 and len(next(iter(types))) == 1
    }
    groups: dict[str, list[int]] = {}
    for index in ends:
        end = graph.ends[index]
        if end.node in certain:
            groups.setdefault(certain[end.node], []).append(index)
    if len(groups) < 2:
        return False
    reported = False
    for kind, group in sorted(
        groups.items(), key=lambda kv: _place(graph.ends[kv[1][0]])
    ):
        # the first pair of this type's endpoints and another type's that may meet
        pairs = [
            (rank, i, j, relation)
            for i in group
            for t, other_group in groups.items()
            if t != kind
            for j in other_group
            if (relation := systems.relation(graph.ends[i], graph.ends[j])) is not None
            for rank in [0 if relation == TOGETHER else 1]
        ]
        if not pairs:
            continue
        _, first, other, relation = min(
            pairs,
            key=lambda p: (p[0], _place(graph.ends[p[1]]), _place(graph.ends[p[2]])),
        )
        end = graph.ends[first]
        others = sorted({graph.ends[p[2]].endpoint.types[0] for p in pairs})
        other_end = graph.ends[other]
        node = graph.nodes[other_end.node].qualified
        diag = messages.graph_type_mismatch(
            end.path,
            end.endpoint.line,
            end.endpoint.col,
            family,
            name,
            kind,
            others,
            _note(
                other_end,
                f"`{name}` with type `{graph.ends[other].endpoint.types[0]}` "
                f"(node `{node}`)",
            ),
            relation == TOGETHER,
        )
        result.findings.append(
            Finding(_remapped(graph, diag, first, other), first, other)
        )
        reported = True
    return reported


def _qos(
    graph: Graph, name: str, ends: list[int], result: GraphResult, systems: _Systems
) -> None:
    """RF604/RF605 at each subscription that never hears some publisher."""
    publishers = [i for i in ends if graph.ends[i].endpoint.kind == PUBLISHER]
    for index in ends:
        end = graph.ends[index]
        if end.endpoint.kind != SUBSCRIPTION or end.endpoint.qos is None:
            continue
        for other in publishers:
            publisher = graph.ends[other].endpoint
            if publisher.qos is None or not _may_meet(
                publisher.types, end.endpoint.types
            ):
                continue
            why = Q.incompatible(publisher.qos, end.endpoint.qos)
            if not why:
                continue
            relation = systems.relation(end, graph.ends[other])
            if relation is None:
                continue
            certain = publisher.qos.certain and end.endpoint.qos.certain
            apart = relation != TOGETHER
            node = graph.nodes[graph.ends[other].node].qualified
            diag = messages.graph_qos_incompatible(
                end.path,
                end.endpoint.line,
                end.endpoint.col,
                name,
                why,
                _note(
                    graph.ends[other],
                    f"the publisher (node `{node}`): {publisher.qos.shown()}",
                ),
                certain and not apart,
                apart,
            )
            diag = _remapped(graph, diag, index, other)
            result.findings.append(Finding(diag, index, other))
            break


def _remapped(graph: Graph, diag: Diagnostic, *ends: int) -> Diagnostic:
    """`diag` with a note at each launch file's remapping that gave one of its
    endpoints the name they meet on (the cause a user fixes, often)."""
    notes = []
    for index in ends:
        end = graph.ends[index]
        if end.remapped is not None and end.resolved is not None:
            node = graph.nodes[end.node].qualified
            notes.append(
                messages.remapped_here(
                    end.remapped, node, end.endpoint.name, end.resolved
                )
            )
    return replace(diag, notes=(*diag.notes, *notes)) if notes else diag


def _may_meet(one: Iterable[str], other: Iterable[str]) -> bool:
    """Whether endpoints of these possible types can be of one type (none known:
    any): ROS connects no publisher to a subscription of another type, whatever
    their QoS, and a certain type mismatch is RF603's to tell."""
    mine, theirs = set(one), set(other)
    return not mine or not theirs or not mine.isdisjoint(theirs)


def _unmatched(
    graph: Graph,
    channels: dict[tuple[int, str, str], list[int]],
    result: GraphResult,
) -> None:
    """RF606/RF607, once per topic, at its first endpoint."""
    unnamed = [
        e
        for e in graph.ends
        if e.family == "topic" and (e.resolved is None or not e.certain)
    ]
    for (ros, family, name), ends in channels.items():
        if (
            family != "topic"
            or name in BUILTIN_TOPICS
            or name.endswith(BUILTIN_SUFFIXES)
        ):
            continue
        kinds = {graph.ends[i].endpoint.kind for i in ends}
        if len(kinds) != 1:
            continue
        kind = kinds.pop()
        published = kind == PUBLISHER
        types = {t for i in ends for t in graph.ends[i].endpoint.types}
        if any(
            e.endpoint.ros == ros
            and e.endpoint.kind != kind
            and _may_meet(e.endpoint.types, types)
            for e in unnamed
        ):
            continue  # an endpoint whose name is not known may be its peer
        first = graph.ends[ends[0]]
        places = list(
            dict.fromkeys(
                (graph.ends[i].path, graph.ends[i].endpoint.line) for i in ends
            )
        )
        also = "also " + ("published" if published else "subscribed") + " here"
        others = [Note(also, path, line) for path, line in places[1:4]]
        diag = messages.graph_unmatched(
            first.path, first.endpoint.line, first.endpoint.col, name, published, others
        )
        result.findings.append(Finding(diag, ends[0]))


# channel family -> (the contract's family, the side that sends, the side that
# states what it assumes of it, and the section of the interface sent): a
# subscription's callback, a service's of the request, an action server's goal
# callback; a client of the response its server's callback returns
CONTRACT_SIDES = {
    "topic": (("topic", PUBLISHER, SUBSCRIPTION, ""),),
    "service": (
        ("service", CLIENT, SERVICE, "_Request"),
        ("response", SERVICE, CLIENT, "_Response"),
    ),
    "action": (("action", ACTION_CLIENT, ACTION_SERVER, "_Goal"),),
}
# what the side that takes it is called in a note's label
TAKER = {
    "topic": "subscription to",
    "service": "service",
    "action": "action server",
    "response": "client of",
}


def _sender_key(endpoint: Endpoint) -> str:
    """Where the analysis meets what an endpoint sends (`analysis.calls`): a
    service's response at its callback's `return` (`return:Server.handle`), the
    rest where they are kept (`Planner:self.pub`); "" not known."""
    if endpoint.kind == SERVICE:
        return f"return:{endpoint.returns}" if endpoint.returns else ""
    return endpoint.holder


def contracts(result: GraphResult) -> dict[str, list[Contract]]:
    """Sender file -> what the callbacks its senders reach assume of what they
    send (issue 23 §3): a subscription whose callback refines its message
    (`msg: Annotated[Twist, "abs(linear.x) <= 0.5"]`), a service whose callback
    refines its request, an action server whose goal callback refines the goal,
    and a Python publisher or client kept in an attribute (`self.pub =
    self.create_publisher(...)`, one per attribute name in its class; its
    `publish`, `call`, `call_async`, `send_goal`, `send_goal_async` in methods of
    that class); a client that refines the response it receives, of its Python
    server's callback's `return`; of the same certain type, on one certain
    name, started together by one package's launch files."""
    from robotfix.api import Contract

    graph = result.graph
    systems = _Systems(graph)
    holders: dict[tuple[str, str], set[tuple[int, str | None]]] = {}
    senders = {side[1] for sides in CONTRACT_SIDES.values() for side in sides}
    for end in graph.ends:
        key = _sender_key(end.endpoint) if end.endpoint.kind in senders else ""
        if key:
            holders.setdefault((end.path, key), set()).add(
                (end.endpoint.line, end.resolved)
            )
    found: dict[str, list[Contract]] = {}
    for (_, channel, name), ends in _channels(graph).items():
        for family, sending, taking, section in CONTRACT_SIDES.get(channel, ()):
            taken = [
                graph.ends[i]
                for i in ends
                if graph.ends[i].endpoint.kind == taking
                and graph.ends[i].endpoint.contract is not None
                and len(graph.ends[i].endpoint.types) == 1
            ]
            for i in ends:
                sender = graph.ends[i]
                endpoint = sender.endpoint
                key = _sender_key(endpoint)
                if (
                    endpoint.kind != sending
                    or sender.path.endswith(CPP_SOURCE_SUFFIXES)  # Python only
                    or len(holders.get((sender.path, key), ())) != 1
                ):
                    continue
                for taker in taken:
                    if (
                        taker.endpoint.types != endpoint.types
                        or systems.relation(sender, taker) != TOGETHER
                    ):
                        continue
                    package, _, kind = endpoint.types[0].split("/")
                    if family == "action" and endpoint.ros == 1:
                        kind = kind.removesuffix(
                            "Action"
                        )  # actionlib's FibonacciAction
                    node = graph.nodes[taker.node].qualified
                    started = graph.nodes[sender.node].launch
                    route = f"{graph.nodes[sender.node].qualified} -> {name} -> {node}"
                    contract = Contract(
                        key,
                        taker.endpoint.contract or "",
                        f"{package}/{kind}{section}",
                        f"{node}'s {TAKER[family]} {name}",
                        taker.path,
                        taker.endpoint.line,
                        family,
                        route,
                        (started.path, started.line) if started is not None else None,
                    )
                    if contract not in found.setdefault(sender.path, []):
                        found[sender.path].append(contract)
    return found


def _silenced(
    diag: Diagnostic, texts: dict[str, list[str] | None], config: Config | None
) -> bool:
    """`per-file-ignores`, or `# robotfix: ignore[...]` (in C++ `// robotfix:
    ignore[...]`) on the endpoint's line."""
    if config is not None and config.silences(diag.path, diag.code, diag.rule.name):
        return True
    if diag.path not in texts:
        from robotfix.ros.graph.cpp import MAX_CPP_BYTES

        try:
            text = read_regular(diag.path, MAX_CPP_BYTES).decode("utf-8", "replace")
            texts[diag.path] = text.splitlines()
        except UnreadableError:
            texts[diag.path] = None
    lines = texts[diag.path]
    if lines is None or not 0 < diag.span.line <= len(lines):
        return False
    return suppresses(_CPP_COMMENT.sub("#", lines[diag.span.line - 1]), diag)


def code_graphs(
    python: dict[str, list[object]], cpp: dict[str, FileGraph]
) -> dict[str, FileGraph]:
    """The run's code graphs: the checked Python files' (dumped by their checks,
    or kept in the cache) and the C++ files' (`read_cpp_files`)."""
    code: dict[str, FileGraph] = {}
    for path, raw in python.items():
        found = load(raw)
        if found is not None:
            code[path] = found
    code.update(cpp)
    return code


def graph_paths(paths: list[Path], config: Config) -> GraphResult:
    """`robotfix graph`: the graph of `paths` without checking them: each Python
    file that may make an endpoint is parsed for it, as its check would parse it."""
    from robotfix.discovery import discover
    from robotfix.launchcheck import LaunchRun
    from robotfix.ros.api_model import ENDPOINT_WORDS
    from robotfix.ros.graph.python import read_python
    from robotfix.source import read_mentioning

    found = discover(paths, config)
    code: dict[str, FileGraph] = {}
    for path in found.python_files:
        source = read_mentioning(path, ENDPOINT_WORDS)
        if source is None or source.tree is None:  # (None: it does not parse)
            continue
        try:
            one = read_python(source.tree)
        except (RecursionError, MemoryError):
            continue
        if one.endpoints:
            code[str(path)] = one
    code.update(read_cpp_files(found.cpp_files))
    launches = None
    if found.launch_files:
        launches = LaunchRun(
            found.launch_files, [*found.python_files, *found.summary_files]
        )
    return check_graph(code, launches, config)
