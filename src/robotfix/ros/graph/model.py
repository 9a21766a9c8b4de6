"""The graph's data: endpoints as a file's code makes them, pure data.

An `Endpoint` is one call that makes a publisher, subscription, service, client,
action server or client (or, in C++, declares a parameter), with the name as the
code writes it (None: computed), the interface types it may have (empty: unknown;
two or more: chosen at run time, as a parameter picks `Twist` or `TwistStamped`)
and its ROS 2 QoS profile where it is a constant. `owner` says which node object
made it (a class, or a variable at module level) so the node's name can be found:
`nodes` maps an owner to the node names its code gives it.

`dump`/`load` are the JSON form the result cache keeps with a file's entry.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

# endpoint kinds; which are topics, services, actions
PUBLISHER = "publisher"
SUBSCRIPTION = "subscription"
SERVICE = "service"
CLIENT = "client"
ACTION_SERVER = "action_server"
ACTION_CLIENT = "action_client"
PARAMETER = "parameter"
# C++ code that may declare parameters the file does not name (`value`: the word,
# `cpp.OPENING`, or another package's node class): for `cppparams`, not the graph
OPENS = "opens"
KINDS = (
    PUBLISHER,
    SUBSCRIPTION,
    SERVICE,
    CLIENT,
    ACTION_SERVER,
    ACTION_CLIENT,
    PARAMETER,
    OPENS,
)
# the middle of a type's name (`pkg/msg/Name`) each kind's interface has
MIDDLE = {
    PUBLISHER: "msg",
    SUBSCRIPTION: "msg",
    SERVICE: "srv",
    CLIENT: "srv",
    ACTION_SERVER: "action",
    ACTION_CLIENT: "action",
    PARAMETER: "",
    OPENS: "",
}
# the kind on the other side of an edge
PEER = {
    PUBLISHER: SUBSCRIPTION,
    SUBSCRIPTION: PUBLISHER,
    SERVICE: CLIENT,
    CLIENT: SERVICE,
    ACTION_SERVER: ACTION_CLIENT,
    ACTION_CLIENT: ACTION_SERVER,
}


@dataclass(frozen=True)
class Qos:
    """The policies RobotFix compares; None: not known (computed, or the RMW's
    system default)."""

    reliability: str | None = None  # "reliable" | "best_effort"
    durability: str | None = None  # "volatile" | "transient_local"
    depth: int | None = None
    certain: bool = True  # False: the profile may be overridden or chosen at run time

    def shown(self) -> str:
        parts = [
            self.reliability or "reliability ?",
            self.durability or "durability ?",
        ]
        if self.depth is not None:
            parts.append(f"depth {self.depth}")
        return ", ".join(parts)


@dataclass(frozen=True)
class Endpoint:
    """A publisher, subscription, service, action or parameter in the code."""

    kind: str
    name: str | None  # as written: `cmd_vel`, `/scan`, `~/out`, `~out`; None computed
    types: tuple[str, ...]  # `pkg/msg/Name`; () unknown; 2+ chosen at run time
    line: int
    col: int
    owner: str = ""  # the node object's class or variable ("" the file's only node)
    qos: Qos | None = None  # ROS 2 topics only; None unknown
    ros: int = 2
    handle: str = ""  # ROS 1 C++: the NodeHandle's namespace ("~" private)
    value: str | None = None  # a parameter's default, as written (C++)
    # what a subscription's callback assumes of the message: the refinement of
    # its parameter (`msg: Annotated[Twist, "abs(linear.x) <= 0.5"]`), as written;
    # a service's callback, of the request; a Python client, of the response
    # (`resp: Annotated[SetSpeed.Response, "actual <= 2"] = self.cli.call(req)`)
    contract: str | None = None
    # where the code keeps a Python publisher or client (`self.pub =
    # create_publisher(...)` in class Planner: "Planner:self.pub"), for what its
    # subscribers or server assume of `self.pub.publish(m)`, `self.cli.call(r)`
    holder: str = ""
    # a Python service's callback, as the analysis keys it (`Server.handle`,
    # `handle`): what it returns is the response its clients' contracts meet
    returns: str = ""


@dataclass
class FileGraph:
    """What one file's code says of the graph."""

    endpoints: list[Endpoint] = field(default_factory=list)
    nodes: dict[str, list[str]] = field(default_factory=dict)  # owner -> names
    ros: int = 2


def dump(found: FileGraph) -> list[Any]:
    """A JSON-able form, for the result cache."""
    return [
        found.ros,
        {k: list(v) for k, v in sorted(found.nodes.items())},
        [
            [
                e.kind,
                e.name,
                list(e.types),
                e.line,
                e.col,
                e.owner,
                None
                if e.qos is None
                else [e.qos.reliability, e.qos.durability, e.qos.depth, e.qos.certain],
                e.ros,
                e.handle,
                e.value,
                e.contract,
                e.holder,
                e.returns,
            ]
            for e in found.endpoints
        ],
    ]


def _text(value: Any) -> bool:
    return isinstance(value, str)


def _opt(value: Any) -> bool:
    return value is None or isinstance(value, str)


def _int(value: Any) -> bool:
    return type(value) is int and 0 <= value < 2**31


def load(raw: Any) -> FileGraph | None:
    """What `dump` wrote; None when `raw` is not exactly that."""
    if not (isinstance(raw, list) and len(raw) == 3 and raw[0] in (1, 2)):
        return None
    ros, nodes, endpoints = raw
    if not (
        isinstance(nodes, dict)
        and all(
            _text(k) and isinstance(v, list) and all(_text(n) for n in v)
            for k, v in nodes.items()
        )
        and isinstance(endpoints, list)
    ):
        return None
    found = FileGraph([], {k: list(v) for k, v in nodes.items()}, ros)
    for item in endpoints:
        if not (isinstance(item, list) and len(item) == 13):
            return None
        kind, name, types, line, col, owner, qos, eros, handle, value = item[:10]
        contract, holder, returns = item[10:]
        if not (
            kind in KINDS
            and _opt(name)
            and isinstance(types, list)
            and all(_text(t) for t in types)
            and _int(line)
            and _int(col)
            and _text(owner)
            and eros in (1, 2)
            and _text(handle)
            and _opt(value)
            and _opt(contract)
            and _text(holder)
            and _text(returns)
        ):
            return None
        profile = None
        if qos is not None:
            if not (
                isinstance(qos, list)
                and len(qos) == 4
                and _opt(qos[0])
                and _opt(qos[1])
                and (qos[2] is None or _int(qos[2]))
                and type(qos[3]) is bool
            ):
                return None
            profile = Qos(*qos)
        found.endpoints.append(
            Endpoint(
                kind,
                name,
                tuple(types),
                line,
                col,
                owner,
                profile,
                eros,
                handle,
                value,
                contract,
                holder,
                returns,
            )
        )
    return found
