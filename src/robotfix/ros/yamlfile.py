"""YAML files as a small tree of our own, with the line and column of every node.
The only module that imports PyYAML.

Only the event stream is read (`yaml.parse` with the safe loader): no Python object
is ever constructed, and an alias is kept as a reference to the node its anchor
names, never expanded, so "billion laughs" costs nothing; `walk_budget` bounds what
a reader may visit through aliases. Files are read through `robotfix.fs` with a size
limit, and the number of nodes and the nesting depth are bounded too.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

from robotfix.fs import UnreadableError, read_text

MAX_YAML_BYTES = 4 * 1024 * 1024  # parameter files are a few kB
MAX_NODES = 200_000
MAX_DEPTH = 200
WALK_BUDGET = 400_000  # nodes a reader may visit, aliases counted each time

STR_TAG = "tag:yaml.org,2002:str"


@dataclass(frozen=True)
class Scalar:
    text: str
    plain: bool  # not quoted, not a block scalar
    tag: str | None  # an explicit tag (`!!str 5`), else None
    line: int  # 1-based
    col: int  # 0-based

    def yaml11_tag(self) -> str:
        """The type YAML 1.1 (PyYAML, rosparam) gives this scalar."""
        if self.tag is not None:
            return self.tag
        import yaml

        return str(_resolver().resolve(yaml.ScalarNode, self.text, (self.plain, True)))


@dataclass(frozen=True)
class Sequence:
    items: list[Node] = field(default_factory=list)
    line: int = 1
    col: int = 0


@dataclass(frozen=True)
class Mapping:
    items: list[tuple[Node, Node]] = field(default_factory=list)
    line: int = 1
    col: int = 0

    def get(self, key: str) -> Node | None:
        for k, v in self.items:
            if isinstance(k, Scalar) and k.text == key:
                return v
        return None


@dataclass(frozen=True)
class Alias:
    """`*name`: the node its anchor names (None when no anchor had that name)."""

    target: Node | None
    line: int
    col: int


Node = Scalar | Sequence | Mapping | Alias


@dataclass(frozen=True)
class YamlProblem:
    message: str
    line: int
    col: int


def read(path: str | os.PathLike[str]) -> Node | YamlProblem | None:
    """The first document of a YAML file (None when empty), or why it is not read."""
    try:
        text = read_text(path, MAX_YAML_BYTES)
    except UnreadableError as err:
        return YamlProblem(f"cannot read: {err.reason}", 1, 0)
    return parse(text)


@lru_cache(maxsize=1)
def _resolver() -> Any:
    import yaml

    return yaml.resolver.Resolver()


def parse(text: str) -> Node | YamlProblem | None:
    import yaml  # here, not at the top: most runs read no YAML (about 15 ms)

    try:
        loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
        return _build(yaml.parse(text, Loader=loader))
    except yaml.MarkedYAMLError as err:
        mark = err.problem_mark or err.context_mark
        line, col = (mark.line + 1, mark.column) if mark is not None else (1, 0)
        return YamlProblem(f"not valid YAML: {err.problem or err.context}", line, col)
    except yaml.YAMLError as err:
        return YamlProblem(f"not valid YAML: {err}", 1, 0)
    except _TooLargeError as err:
        return YamlProblem(str(err), err.line, 0)


class _TooLargeError(Exception):
    def __init__(self, message: str, line: int) -> None:
        super().__init__(message)
        self.line = line


def _build(events: object) -> Node | None:
    """Nodes from the event stream, iteratively; stops after the first document."""
    import yaml

    anchors: dict[str, Node] = {}
    stack: list[tuple[Sequence | Mapping, list[Node]]] = []
    count = 0
    root: Node | None = None
    for event in events:  # type: ignore[attr-defined]
        mark = event.start_mark
        line, col = mark.line + 1, mark.column
        node: Node | None = None
        if isinstance(event, yaml.ScalarEvent):
            plain = event.style in (None, "") and bool(event.implicit[0])
            tag = event.tag if event.tag not in (None, "!") else None
            node = Scalar(event.value, plain, tag, line, col)
        elif isinstance(event, yaml.AliasEvent):
            node = Alias(anchors.get(event.anchor), line, col)
        elif isinstance(event, (yaml.SequenceStartEvent, yaml.MappingStartEvent)):
            if len(stack) >= MAX_DEPTH:
                raise _TooLargeError(f"nested deeper than {MAX_DEPTH} levels", line)
            container: Sequence | Mapping = (
                Sequence(line=line, col=col)
                if isinstance(event, yaml.SequenceStartEvent)
                else Mapping(line=line, col=col)
            )
            if event.anchor:
                anchors[event.anchor] = container
            stack.append((container, []))
            count += 1
            continue
        elif isinstance(event, (yaml.SequenceEndEvent, yaml.MappingEndEvent)):
            container, pending = stack.pop()
            if isinstance(container, Sequence):
                container.items.extend(pending)
            else:
                container.items.extend(zip(pending[::2], pending[1::2], strict=False))
            node = container
        elif isinstance(event, yaml.DocumentEndEvent):
            break
        else:
            continue
        if isinstance(event, yaml.ScalarEvent) and event.anchor:
            anchors[event.anchor] = node
        count += 1
        if count > MAX_NODES:
            raise _TooLargeError(f"more than {MAX_NODES} YAML nodes", line)
        if stack:
            stack[-1][1].append(node)
        else:
            root = node
    return root


_YAML11 = {
    "tag:yaml.org,2002:int",
    "tag:yaml.org,2002:float",
    "tag:yaml.org,2002:bool",
    "tag:yaml.org,2002:null",
}


def yaml11_value(node: Scalar, tag: str) -> object:
    """The Python value PyYAML's safe loader makes of a plain scalar of `tag`
    (int, float, bool, null); None for any other tag or a value it refuses."""
    if tag not in _YAML11:
        return None
    import yaml

    try:
        return yaml.constructor.SafeConstructor().construct_object(
            yaml.ScalarNode(tag, node.text)
        )
    except (yaml.YAMLError, ValueError, OverflowError):
        return None


def resolve(node: Node | None, budget: list[int]) -> Node | None:
    """An alias's target (aliases of aliases followed); `budget` is a one-item
    counter shared by a whole walk, so aliases cannot make a walk explode."""
    hops = 0
    while isinstance(node, Alias) and hops < 100:
        node = node.target
        hops += 1
    budget[0] -= 1
    if budget[0] < 0 or isinstance(node, Alias):
        return None
    return node
