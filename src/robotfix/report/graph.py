"""`robotfix graph`: a run's static ROS graph as text, JSON, Graphviz DOT or
Mermaid, the way `rqt_graph` shows a running system: nodes, and the topics,
services and actions between them; an edge whose endpoint has a finding is marked
with its code (red in DOT and Mermaid).
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

from robotfix.report.escape import shown_path
from robotfix.ros.graph.build import OFFERS

if TYPE_CHECKING:
    from robotfix.graphcheck import GraphResult
    from robotfix.ros.graph.build import End, Graph

FORMATS = ("text", "json", "dot", "mermaid")
VERBS = {
    "publisher": "publishes",
    "subscription": "subscribes",
    "service": "serves",
    "client": "calls",
    "action_server": "serves action",
    "action_client": "calls action",
    "parameter": "declares parameter",
}


def render(result: GraphResult, form: str) -> str:
    if form == "json":
        return json.dumps(_data(result), indent=2, ensure_ascii=True) + "\n"
    if form == "dot":
        return _dot(result)
    if form == "mermaid":
        return _mermaid(result)
    return _text(result)


def _marks(result: GraphResult) -> dict[int, list[str]]:
    """End index -> the codes of the findings at it (or at its other side)."""
    found: dict[int, list[str]] = {}
    for finding in result.findings:
        for index in (finding.end, finding.other):
            if index is not None:
                codes = found.setdefault(index, [])
                if finding.diagnostic.code not in codes:
                    codes.append(finding.diagnostic.code)
    return found


def _node_label(graph: Graph, index: int) -> str:
    return graph.nodes[index].qualified


def _where(end: End) -> str:
    return f"{shown_path(end.path)}:{end.endpoint.line}"


def _types(end: End) -> str:
    types = end.endpoint.types
    return " | ".join(types) if types else "?"


def _text(result: GraphResult) -> str:
    graph = result.graph
    marks = _marks(result)
    lines: list[str] = []
    by_node: dict[int, list[int]] = {}
    for index, end in enumerate(graph.ends):
        by_node.setdefault(end.node, []).append(index)
    lines.append(f"nodes ({len(graph.nodes)}):")
    for index, node in enumerate(graph.nodes):
        started = (
            f"  (launched at {shown_path(node.launch.path)}:{node.launch.line})"
            if node.launch is not None
            else ""
        )
        lines.append(f"  {_node_label(graph, index)}{started}")
        for end_index in by_node.get(index, []):
            end = graph.ends[end_index]
            name = end.resolved or f"? ({end.endpoint.name or 'computed'})"
            qos = f" [{end.endpoint.qos.shown()}]" if end.endpoint.qos else ""
            value = f" = {end.endpoint.value}" if end.endpoint.value is not None else ""
            if end.endpoint.contract is not None:
                value += f" assumes `{end.endpoint.contract}`"
            mark = f"  !{','.join(marks[end_index])}" if end_index in marks else ""
            lines.append(
                f"    {VERBS[end.endpoint.kind]} {name} {_types(end)}{qos}{value}"
                f"  {_where(end)}{mark}"
            )
    channels = result.graph.channels()
    lines.append(f"channels ({len(channels)}):")
    for (family, name), ends in channels.items():
        offered = sorted({_node_label(graph, e.node) for e in ends if _offers(e)})
        taken = sorted({_node_label(graph, e.node) for e in ends if not _offers(e)})
        types = sorted({t for e in ends for t in e.endpoint.types})
        lines.append(
            f"  {family} {name} {' | '.join(types) or '?'}: "
            f"{', '.join(offered) or '-'} -> {', '.join(taken) or '-'}"
        )
    if result.findings:
        lines.append(f"findings ({len(result.findings)}):")
        for finding in result.findings:
            d = finding.diagnostic
            lines.append(
                f"  {shown_path(d.path)}:{d.span.line}:{d.span.col + 1}: "
                f"{d.severity.value}[{d.code}]: {d.message}"
            )
    return "\n".join(lines) + "\n"


def _offers(end: End) -> bool:
    return end.endpoint.kind in OFFERS


def _edges(
    graph: Graph, ids: dict[tuple[str, str], str]
) -> Iterator[tuple[int, str, str]]:
    """(end index, from, to) of each endpoint on a channel: a node offers to its
    channel, a channel to a node that takes."""
    for index, end in enumerate(graph.ends):
        if end.resolved is None or end.family == "parameter" or not end.certain:
            continue
        channel = ids.get((end.family, end.resolved))
        if channel is not None:
            node = f"n{end.node}"
            yield (index, node, channel) if _offers(end) else (index, channel, node)


def _data(result: GraphResult) -> dict[str, Any]:
    graph = result.graph
    marks = _marks(result)
    return {
        "nodes": [
            {
                "id": index,
                "name": node.name,
                "namespace": node.namespace,
                "qualified": node.qualified,
                "package": node.package,
                "executable": node.executable,
                "launch": None
                if node.launch is None
                else {"path": node.launch.path, "line": node.launch.line},
            }
            for index, node in enumerate(graph.nodes)
        ],
        "endpoints": [
            {
                "id": index,
                "node": end.node,
                "kind": end.endpoint.kind,
                "family": end.family,
                "ros": end.endpoint.ros,
                "name": end.endpoint.name,
                "resolved": end.resolved,
                "certain": end.certain,
                "types": list(end.endpoint.types),
                "qos": None
                if end.endpoint.qos is None
                else {
                    "reliability": end.endpoint.qos.reliability,
                    "durability": end.endpoint.qos.durability,
                    "depth": end.endpoint.qos.depth,
                    "certain": end.endpoint.qos.certain,
                },
                "default": end.endpoint.value,
                "contract": end.endpoint.contract,
                "path": end.path,
                "line": end.endpoint.line,
                "column": end.endpoint.col + 1,
                "findings": marks.get(index, []),
            }
            for index, end in enumerate(graph.ends)
        ],
        "findings": [
            {
                "code": f.diagnostic.code,
                "severity": f.diagnostic.severity.value,
                "path": f.diagnostic.path,
                "line": f.diagnostic.span.line,
                "column": f.diagnostic.span.col + 1,
                "message": f.diagnostic.message,
                "endpoint": f.end,
                "other": f.other,
            }
            for f in result.findings
        ],
    }


def _escaped(text: str) -> str:
    return text.replace("\\", "\\\\").replace('"', '\\"')


def _quote(text: str) -> str:
    return '"' + _escaped(text) + '"'


def _dot(result: GraphResult) -> str:
    graph = result.graph
    marks = _marks(result)
    out = ["digraph ros_graph {", "  rankdir=LR;", "  node [fontsize=10];"]
    used = sorted({e.node for e in graph.ends if e.family != "parameter"})
    for index in used:
        out.append(
            f"  n{index} [label={_quote(_node_label(graph, index))}, shape=box];"
        )
    channels = list(graph.channels().items())
    ids: dict[tuple[str, str], str] = {}
    for number, ((family, name), ends) in enumerate(channels):
        ids[(family, name)] = f"c{number}"
        types = sorted({t for e in ends for t in e.endpoint.types})
        shape = {"topic": "ellipse", "service": "diamond", "action": "hexagon"}[family]
        label = _escaped(name) + ("\\n" + _escaped(" | ".join(types)) if types else "")
        out.append(f'  c{number} [label="{label}", shape={shape}];')
    for index, a, b in _edges(graph, ids):
        style = ""
        if index in marks:
            style = (
                f" [color=red, fontcolor=red, label={_quote(','.join(marks[index]))}]"
            )
        out.append(f"  {a} -> {b}{style};")
    out.append("}")
    return "\n".join(dict.fromkeys(out)) + "\n"


def _mermaid_text(text: str) -> str:
    return '"' + text.replace('"', "#quot;") + '"'


def _mermaid(result: GraphResult) -> str:
    graph = result.graph
    marks = _marks(result)
    out = ["flowchart LR"]
    used = sorted({e.node for e in graph.ends if e.family != "parameter"})
    for index in used:
        out.append(f"  n{index}[{_mermaid_text(_node_label(graph, index))}]")
    ids: dict[tuple[str, str], str] = {}
    for number, ((family, name), ends) in enumerate(graph.channels().items()):
        ids[(family, name)] = f"c{number}"
        types = sorted({t for e in ends for t in e.endpoint.types})
        label = _mermaid_text(name + (" " + " | ".join(types) if types else ""))
        shape = {
            "topic": f"([{label}])",
            "service": f"{{{label}}}",
            "action": f"{{{{{label}}}}}",
        }[family]
        out.append(f"  c{number}{shape}")
    edges = 0
    red: list[int] = []
    for index, a, b in _edges(graph, ids):
        line = f"  {a} --> {b}"
        if index in marks:
            line = f"  {a} -- {_mermaid_text(','.join(marks[index]))} --> {b}"
        if line in out:
            continue
        out.append(line)
        if index in marks:
            red.append(edges)
        edges += 1
    for edge in red:
        out.append(f"  linkStyle {edge} stroke:red,stroke-width:2px")
    return "\n".join(out) + "\n"
