"""The graph of a run: node instances, their endpoints' resolved names, channels.

A node instance is a launch entry's (its name, namespace and remappings over the
code of the executable it starts: one instance per node object of that code), or,
for code no launch entry of the run starts, the code as `ros2 run` / `rosrun`
starts it: in the root namespace with the name its code gives. Each endpoint's
name is resolved for its instance (`names.py`); a channel is one resolved name of
one family (topics, services, actions) with every endpoint on it.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from robotfix.ros.graph.model import (
    ACTION_CLIENT,
    ACTION_SERVER,
    CLIENT,
    OPENS,
    PARAMETER,
    PUBLISHER,
    SERVICE,
    SUBSCRIPTION,
    Endpoint,
    FileGraph,
)
from robotfix.ros.graph.names import expand, namespace_of, remap_rule

if TYPE_CHECKING:  # annotations only: a check without launch files never loads them
    from robotfix.ros.launch.model import NodeEntry, Place

FAMILY = {
    PUBLISHER: "topic",
    SUBSCRIPTION: "topic",
    SERVICE: "service",
    CLIENT: "service",
    ACTION_SERVER: "action",
    ACTION_CLIENT: "action",
    PARAMETER: "parameter",
}
# the side that offers (publishes, serves) in each family
OFFERS = frozenset({PUBLISHER, SERVICE, ACTION_SERVER})


@dataclass
class Instance:
    """A node of the graph: its name, namespace, launch entry and code."""

    name: str | None  # the node's name; None unknown
    namespace: str | None  # absolute; None unknown
    launch: Place | None = None  # the launch entry that starts it
    package: str | None = None
    executable: str | None = None
    remaps: list[tuple[str | None, str | None]] = field(default_factory=list)
    code: str = ""  # the file of its code, shown when its name is not known
    remapped_at: list[Place] = field(default_factory=list)  # each rule's place

    @property
    def qualified(self) -> str:
        shown = self.name or f"?({os.path.basename(self.code)})"
        if self.namespace is None:
            return f"?/{shown}"
        return f"{self.namespace.rstrip('/')}/{shown}"


@dataclass
class End:
    """One endpoint of one instance, with its name resolved."""

    node: int  # index in Graph.nodes
    path: str
    endpoint: Endpoint
    resolved: str | None
    certain: bool  # the name is known for sure (no remapping rule left unread)
    remapped: Place | None = None  # the launch file's rule that renamed it

    @property
    def family(self) -> str:
        return FAMILY[self.endpoint.kind]


@dataclass
class Graph:
    """A run's nodes and their endpoints."""

    nodes: list[Instance] = field(default_factory=list)
    ends: list[End] = field(default_factory=list)
    # (name, namespace, remappings, file, owner) -> its instance: the same code
    # started alike by two launch files (a demo's .py, .xml and .yaml) is one node
    known: dict[tuple[object, ...], int] = field(default_factory=dict)

    def channels(self) -> dict[tuple[str, str], list[End]]:
        """(family, resolved name) -> its endpoints, sorted by place."""
        found: dict[tuple[str, str], list[End]] = {}
        for end in self.ends:
            if end.resolved is not None and end.family != "parameter":
                found.setdefault((end.family, end.resolved), []).append(end)
        return {k: found[k] for k in sorted(found)}


@dataclass
class Started:
    """A launch entry with the code files it runs (paths as the run spells them)
    and, for a composable node, the class it loads."""

    entry: NodeEntry
    files: list[str]
    plugin: str | None = None


def code_name(found: FileGraph, owner: str) -> str | None:
    """The node name the code gives the node object `owner`."""
    names = found.nodes.get(owner)
    if names:
        return names[0]
    if "." in owner or names is not None:
        # a member holding a node made elsewhere, or a node class whose name is
        # computed (C++ `: Node(node_name)`): not the name of another node
        return None
    every = {n for listed in found.nodes.values() for n in listed}
    return every.pop() if len(every) == 1 else None


def _owners(found: FileGraph, plugin: str | None) -> list[str]:
    seen: list[str] = []
    for endpoint in found.endpoints:
        owner = endpoint.owner
        if endpoint.kind == OPENS:
            continue  # not in the graph
        if (
            plugin is not None
            and owner != plugin
            and not owner.startswith(plugin + ".")
        ):
            continue
        if owner not in seen:
            seen.append(owner)
    return seen


def build(code: dict[str, FileGraph], started: list[Started]) -> Graph:
    """The graph of `code` (path -> its file's graph) run as `started` says."""
    graph = Graph()
    covered: set[tuple[str, str]] = set()
    for one in started:
        entry = one.entry
        namespace = namespace_of(entry.namespace)
        remaps = [(r.source, r.target) for r in entry.remappings]
        for path in one.files:
            found = code.get(path)
            if found is None:
                continue
            for owner in _owners(found, one.plugin):
                covered.add((path, owner))
                name = (
                    entry.name.rsplit("/", 1)[-1]
                    if entry.name
                    else code_name(found, owner)
                )
                if entry.name and ("$" in entry.name or "{" in entry.name):
                    name = None
                instance = Instance(
                    name,
                    namespace,
                    entry.place,
                    entry.package,
                    entry.executable,
                    remaps,
                    remapped_at=[r.place for r in entry.remappings],
                )
                _add(graph, instance, path, found, owner)
    for path in sorted(code):
        found = code[path]
        for owner in _owners(found, None):
            if (path, owner) in covered:
                continue
            instance = Instance(code_name(found, owner), "/")
            _add(graph, instance, path, found, owner)
    return graph


def _add(
    graph: Graph, instance: Instance, path: str, found: FileGraph, owner: str
) -> None:
    key = (instance.name, instance.namespace, tuple(instance.remaps), path, owner)
    if key in graph.known:
        return
    index = graph.known[key] = len(graph.nodes)
    instance.code = path
    graph.nodes.append(instance)
    for endpoint in found.endpoints:
        if endpoint.owner != owner:
            continue
        if endpoint.kind == OPENS:
            continue
        if endpoint.kind == PARAMETER:  # a node's own: not a graph name
            graph.ends.append(End(index, path, endpoint, endpoint.name, True))
            continue
        named = expand(
            endpoint.name, instance.namespace, instance.name, endpoint.handle
        )
        resolved, uncertain, rule = remap_rule(
            named, instance.remaps, instance.namespace, instance.name
        )
        # where the launch file's rule that renamed it is written (`remapped_at`
        # is parallel to `remaps`)
        renamed = rule is not None and resolved != named
        place = instance.remapped_at[rule] if renamed and rule is not None else None
        graph.ends.append(End(index, path, endpoint, resolved, not uncertain, place))
