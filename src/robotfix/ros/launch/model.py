"""What a launch file says, as data: the launch entries a reader finds.

A launch file is read, never run (`robotfix.ros.launch.read`), so any value may be
unknown: a substitution computed at launch time (`$(env X)`, a `Command`, a
`LaunchConfiguration` nobody declares a default for) is `None` here, never an
error. Launch arguments take the value the including file passes, else their
declared default: the configuration a plain `ros2 launch` / `roslaunch` starts.

Every entry carries its place (`path`, 1-based `line`, 0-based `col`), so a check
reports at the launch file, and a later graph module can build on the node entries
(package, executable, name, namespace, parameters, remappings, arguments).
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields
from typing import Any

from robotfix.ros.paramfile import Typed, Unread


@dataclass(frozen=True)
class Place:
    """Where something is written: file, line, column."""

    path: str
    line: int
    col: int


@dataclass(frozen=True)
class InlineParam:
    """`{'max_speed': 0.5}` in a Python launch file, `<param name= value=>`."""

    name: str  # ROS 2: dotted (`limits.max`); ROS 1: as written (`~rate`, `rate`)
    value: Typed | Unread | None  # None: computed at launch time, or of no
    # checkable type; Unread: PyYAML refuses it (launch fails)
    place: Place  # of the value
    key: Place | None = None  # of the name, where it is written apart


@dataclass(frozen=True)
class FileParam:
    """A parameter file an entry names (`parameters=[path]`, `<param from=>`,
    `<rosparam command="load" file=>`)."""

    path: str | None  # the file in the checked tree; None: not found or computed
    shown: str  # as the launch file spells it, substitutions kept
    place: Place
    namespace: str = ""  # ROS 1 `<rosparam ns=>`: where its keys go


@dataclass(frozen=True)
class Remap:
    """A remapping rule of a launch entry."""

    source: str | None
    target: str | None
    place: Place


@dataclass
class NodeEntry:
    """One node a launch file starts (`Node(...)`, `<node>`, `- node:`)."""

    ros: int  # 1 (roslaunch) or 2
    place: Place
    package: str | None
    executable: str | None  # ROS 2 `executable`/`exec`; ROS 1 `type`
    name: str | None  # the name the launch file gives it; None: none or unknown
    namespace: str | None  # "" the root; None unknown
    parameters: list[InlineParam | FileParam] = field(default_factory=list)
    remappings: list[Remap] = field(default_factory=list)
    arguments: list[str | None] = field(default_factory=list)
    plugin: str | None = None  # a ComposableNode's class (C++)


@dataclass(frozen=True)
class Include:
    """A launch file another one includes; `path` None when it is not in the tree."""

    path: str | None
    shown: str
    place: Place


@dataclass
class LaunchFile:
    """A launch file's node entries, includes and global parameters."""

    path: str
    ros: int  # 2 for Python, ROS 2 XML and YAML; 1 for roslaunch XML
    entries: list[NodeEntry] = field(default_factory=list)
    includes: list[Include] = field(default_factory=list)
    # ROS 1 `<param>`s outside any `<node>` (global), by resolved name
    global_params: list[InlineParam] = field(default_factory=list)
    problem: tuple[str, int, int] | None = None  # why it was not read: text, l, c
    launch: bool = True  # False: a Python file that is no launch file at all


# -- the JSON form of node entries, for the result cache -------------------------
_KINDS = {
    cls.__name__: cls
    for cls in (Place, InlineParam, FileParam, Remap, NodeEntry, Typed, Unread)
}
# each kind's field names, in order (`fields` made a tuple of Field objects for
# every value loaded: 83,338 of them when 470 kept launch readings are used)
_FIELDS = {name: tuple(f.name for f in fields(cls)) for name, cls in _KINDS.items()}


def dump(value: object) -> object:
    """Node entries (and what they hold) as JSON data: a dataclass as a list of
    its class name and its fields' values in order."""
    name = type(value).__name__
    if _KINDS.get(name) is type(value):
        return [name, *(dump(getattr(value, f)) for f in _FIELDS[name])]
    if isinstance(value, list):
        return [[dump(v) for v in value]]
    if value is None or type(value) in (bool, int, float, str):
        return value
    if isinstance(value, str):  # a launch argument's text (`python._ArgText`):
        return str(value)  # read, an entry's strings are text, equal and alike
    raise ValueError(f"no JSON form for {name}")  # a tuple would come back a list


def load(raw: object) -> object:
    """What `dump` wrote; ValueError when `raw` is not that (the caller checks
    that the result's `repr` is the original's)."""
    if not isinstance(raw, list):
        if raw is None or type(raw) in (bool, int, float, str):
            return raw
        raise ValueError("not a dumped value")
    if len(raw) == 1 and isinstance(raw[0], list):
        return [load(v) for v in raw[0]]
    if not raw or not isinstance(raw[0], str) or raw[0] not in _KINDS:
        raise ValueError("not a dumped value")
    cls = _KINDS[raw[0]]
    names = _FIELDS[raw[0]]
    if len(raw) != len(names) + 1:
        raise ValueError("not a dumped value")
    values: dict[str, Any] = {n: load(v) for n, v in zip(names, raw[1:], strict=True)}
    return cls(**values)
