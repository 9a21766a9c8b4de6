"""YAML files as a small tree of our own, with the line and column of every node.
The only module that imports PyYAML.

Only the event stream is read (`yaml.parse` with the safe loader): no Python object
is ever constructed, and an alias is kept as a reference to the node its anchor
names, never expanded, so "billion laughs" costs nothing; `walk_budget` bounds what
a reader may visit through aliases. Files are read through `robotfix.fs` with a size
limit, and the number of nodes and the nesting depth are bounded too. `pairs` reads a
mapping as PyYAML's loader does (merge keys applied, alias keys resolved), once per
mapping however often it is merged, so merge bombs cost what the file holds.
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
MAX_MERGE_DEPTH = 50  # mappings merged into mappings merged into ...

STR_TAG = "tag:yaml.org,2002:str"
INT_TAG = "tag:yaml.org,2002:int"


@dataclass(frozen=True)
class Scalar:
    """A YAML scalar as written, with its place."""

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
    """A YAML sequence with its place."""

    items: list[Node] = field(default_factory=list)
    line: int = 1
    col: int = 0


@dataclass(frozen=True)
class Mapping:
    """A YAML mapping (pairs in order) with its place."""

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
    """What PyYAML would refuse, at its place."""

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
    except _RefusedError as err:
        return YamlProblem(str(err), err.line, err.col)


class _RefusedError(Exception):
    """A document this reader does not take (too large, an undefined alias)."""

    def __init__(self, message: str, line: int, col: int = 0) -> None:
        super().__init__(message)
        self.line = line
        self.col = col


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
            if event.anchor not in anchors:  # as PyYAML's composer refuses it
                raise _RefusedError(
                    f"found undefined alias `{event.anchor}`", line, col
                )
            node = Alias(anchors[event.anchor], line, col)
        elif isinstance(event, (yaml.SequenceStartEvent, yaml.MappingStartEvent)):
            if len(stack) >= MAX_DEPTH:
                raise _RefusedError(f"nested deeper than {MAX_DEPTH} levels", line)
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
            raise _RefusedError(f"more than {MAX_NODES} YAML nodes", line)
        if stack:
            stack[-1][1].append(node)
        else:
            root = node
    return root


_YAML11 = {
    INT_TAG,
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


def is_merge(key: Node) -> bool:
    """The merge key `<<` (plain, untagged: YAML 1.1 resolves it so)."""
    return (
        isinstance(key, Scalar) and key.plain and key.tag is None and key.text == "<<"
    )


@dataclass(frozen=True)
class Pair:
    """One entry of a mapping as a loader reads it."""

    key: str | None  # the key's text (an alias key: its target's); None: not a scalar
    where: Node  # the key as written: where the entry is (an alias key: the alias)
    value: Node | None  # aliases resolved


@dataclass
class _Flattening:
    """The state of flattening a file's merge keys: budget, problems, memo."""

    budget: list[int]
    problems: list[YamlProblem]
    done: dict[int, list[Pair]] = field(default_factory=dict)
    busy: set[int] = field(default_factory=set)  # being flattened


def pairs(
    node: Mapping, budget: list[int], problems: list[YamlProblem] | None = None
) -> list[Pair]:
    """A mapping's entries as PyYAML's loader reads them (so rosparam and tools
    that rewrite a file with PyYAML): a merge key (`<<: *base`, `<<: [*a, *b]`)
    brings in the merged mappings' entries (merged first, recursively) that the
    mapping does not set itself, and of several merged mappings the first wins; an
    alias key stands for its target. What PyYAML would refuse (merging a scalar, a
    mapping that merges itself, merges nested deeper than MAX_MERGE_DEPTH) is put
    in `problems` and left out."""
    return _flatten(node, _Flattening(budget, [] if problems is None else problems), 0)


def _flatten(node: Mapping, walk: _Flattening, depth: int) -> list[Pair]:
    known = walk.done.get(id(node))
    if known is not None:
        return known
    walk.busy.add(id(node))
    merged: list[Pair] = []  # PyYAML's order: later ones win
    own: list[Pair] = []
    for key, raw in node.items:
        if not is_merge(key):
            target = resolve(key, walk.budget)
            text = target.text if isinstance(target, Scalar) else None
            own.append(Pair(text, key, resolve(raw, walk.budget)))
            continue
        sources = _merged(raw, key, walk, depth)
        for source in reversed(sources):
            merged += _flatten(source, walk, depth + 1)
    found = own
    if merged:  # most mappings merge nothing
        kept: dict[str, Pair] = {}
        for pair in merged:
            if pair.key is not None:
                kept[pair.key] = pair
        mine = {pair.key for pair in own}
        found = [p for k, p in kept.items() if k not in mine] + own
    walk.done[id(node)] = found
    walk.busy.discard(id(node))
    return found


def _merged(raw: Node, key: Node, walk: _Flattening, depth: int) -> list[Mapping]:
    """The mappings a merge key brings in, or a problem and none."""
    value = resolve(raw, walk.budget)
    items = value.items if isinstance(value, Sequence) else [value]
    sources = [resolve(item, walk.budget) for item in items]
    line, col = key.line, key.col
    if walk.budget[0] < 0:
        return []  # the walk's budget is spent: nothing more is read, as elsewhere
    if not all(isinstance(s, Mapping) for s in sources):
        walk.problems.append(
            YamlProblem(
                "a merge key (`<<`) takes a mapping or a list of them", line, col
            )
        )
        return []
    if depth >= MAX_MERGE_DEPTH:
        walk.problems.append(
            YamlProblem(f"merge keys nested deeper than {MAX_MERGE_DEPTH}", line, col)
        )
        return []
    if any(id(s) in walk.busy for s in sources):
        walk.problems.append(YamlProblem("a mapping that merges itself", line, col))
    return [s for s in sources if isinstance(s, Mapping) and id(s) not in walk.busy]


def first_reference(root: Node | None) -> Node | None:
    """The first alias (`*base`) of a document in reading order, else its first
    merge key (`<<`), else None. Aliases are not followed: one pass."""
    todo: list[Node] = [] if root is None else [root]
    merge: Node | None = None
    while todo:
        node = todo.pop()
        if isinstance(node, Alias):
            return node
        if merge is None and is_merge(node):
            merge = node
        if isinstance(node, Sequence):
            todo.extend(reversed(node.items))
        elif isinstance(node, Mapping):
            todo.extend(n for pair in reversed(node.items) for n in reversed(pair))
    return merge
