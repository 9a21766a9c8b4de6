"""MsgCatalog: every message type a check can meet, with its units and refinements.

Three sources, later ones adding to earlier ones:
1. the standard ROS 2 (Jazzy) and ROS 1 (Noetic) definitions bundled with `rosbags`
   (the only module that imports rosbags), converted once into a JSON cache;
2. REP 103 units (`rep103.toml`), unless turned off;
3. the user's `.msg`/`.srv`/`.action` files, whose `#RobotFix#` lines add units and
   invariants. A user file that redeclares a standard message adds its refinements to
   it; its own field list wins where it has one.

Problems in interface files come back as `CatalogProblem`s (rule, path, line, col),
never as exceptions.
"""

from __future__ import annotations

import hashlib
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from robotfix import rules
from robotfix.annotations import ast as A
from robotfix.annotations.parser import AnnotationSyntaxError, parse_predicate
from robotfix.annotations.units import UnitError, resolve
from robotfix.diagnostics import Rule
from robotfix.disk_cache import JsonCache, install_key
from robotfix.ros.msg import InterfaceFile, Section, read_interface

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

INT_TYPES = frozenset(
    [
        "byte",
        "char",
        "int8",
        "uint8",
        "int16",
        "uint16",
        "int32",
        "uint32",
        "int64",
        "uint64",
    ]
)
FLOAT_TYPES = frozenset({"float32", "float64"})
BASE_KINDS = {"bool": "bool", "string": "str", "wstring": "str"}
ALIASES = {
    "Header": "std_msgs/Header",
    "time": "builtin_interfaces/Time",
    "duration": "builtin_interfaces/Duration",
}


@dataclass(frozen=True)
class Origin:
    path: str
    line: int


@dataclass(frozen=True)
class FieldSpec:
    name: str
    kind: str  # int, float, bool, str, msg
    msg_type: str | None = None  # pkg/Name when kind == "msg"
    array: bool = False
    loose: bool = False  # char/byte: ROS 1 takes str or int there; no base-type check


@dataclass(frozen=True)
class Invariant:
    predicate: A.Expr  # names are field paths relative to the message
    paths: frozenset[str]
    text: str
    origin: Origin


@dataclass(frozen=True)
class FieldUnit:
    text: str
    origin: Origin | None  # None for REP 103 (see `source`)
    source: str = ""


@dataclass
class MsgSpec:
    name: str
    fields: dict[str, FieldSpec]
    units: dict[str, FieldUnit] = field(default_factory=dict)
    invariants: list[Invariant] = field(default_factory=list)
    constants: dict[str, tuple[str, Any]] = field(default_factory=dict)
    declared_at: dict[str, Origin] = field(default_factory=dict)  # user files' fields


@dataclass(frozen=True)
class CatalogProblem:
    rule: Rule
    path: str
    line: int
    col: int
    message: str


def normalize(name: str) -> str:
    """`geometry_msgs/msg/Twist` and `geometry_msgs/Twist` name the same type."""
    parts = name.split("/")
    if len(parts) == 3 and parts[1] in ("msg", "srv", "action"):
        return f"{parts[0]}/{parts[2]}"
    return name


class MsgCatalog:
    def __init__(
        self, interface_files: list[Path], *, rep103: bool = True, distro: str = "ros2"
    ) -> None:
        self._std: dict[str, Any] | None = None
        self._specs: dict[str, MsgSpec] = {}
        self._files = sorted(set(interface_files))
        self._rep103 = rep103
        self._distro = distro
        self._loaded = False
        self.problems: list[CatalogProblem] = []
        self.touched: set[str] | None = None  # names looked up, while a file is checked
        self._defined_by: dict[
            str, str
        ] = {}  # type -> hash of the file that defines it

    # -- public --------------------------------------------------------------
    def lookup(self, name: str) -> MsgSpec | None:
        self.load()
        key = normalize(name)
        if self.touched is not None:
            self.touched.add(key)
        spec = self._specs.get(key)
        if spec is None and key in self._standard():
            spec = self._specs[key] = self._from_standard(key)
        return spec

    def has_package(self, package: str) -> bool:
        self.load()
        prefix = package + "/"
        return any(k.startswith(prefix) for k in (*self._specs, *self._standard()))

    def field_at(self, msg_type: str, path: str) -> FieldSpec | None:
        """The field at a dotted path (`linear.x`) inside `msg_type`."""
        spec = self.lookup(msg_type)
        parts = path.split(".")
        for index, part in enumerate(parts):
            if spec is None or part not in spec.fields:
                return None
            found = spec.fields[part]
            if index == len(parts) - 1:
                return found
            if found.kind != "msg" or found.array or found.msg_type is None:
                return None
            spec = self.lookup(found.msg_type)
        return None

    def fingerprint(self, name: str) -> str:
        """What a type's definition depends on: its interface file's content, the
        standard store, or its absence."""
        self.load()
        if name in self._defined_by:
            return self._defined_by[name]
        return "std" if name in self._standard() else "missing"

    def save(self) -> None:
        _std_cache(self._distro).save()

    def refined_specs(self) -> list[MsgSpec]:
        """The message types with invariants (all from interface files), by name."""
        self.load()
        return [spec for _, spec in sorted(self._specs.items()) if spec.invariants]

    def self_containing(self) -> list[CatalogProblem]:
        """Fields of interface files that make a type contain itself by value (not
        through an array): ROS rejects such a type, its size would be infinite."""
        self.load()
        found = []
        for name, spec in sorted(self._specs.items()):
            for fname, origin in sorted(spec.declared_at.items()):
                fs = spec.fields.get(fname)
                if fs is None or fs.kind != "msg" or fs.array or fs.msg_type is None:
                    continue
                loop = self._path_to(fs.msg_type, name, set())
                if loop is None:
                    continue
                chain = " -> ".join([name, *loop])
                short = fs.msg_type.split("/")[-1]
                found.append(
                    CatalogProblem(
                        rules.MALFORMED_INTERFACE,
                        origin.path,
                        origin.line,
                        0,
                        f"field `{fname}` makes {name} contain itself ({chain}): ROS "
                        f"cannot build such a type; hold it in an array "
                        f"(`{short}[] {fname}`)",
                    )
                )
        return found

    def _path_to(self, start: str, target: str, seen: set[str]) -> list[str] | None:
        """The types from `start` to `target` through fields held by value."""
        if start == target:
            return [start]
        if start in seen:
            return None
        seen.add(start)
        spec = self.lookup(start)
        for fs in spec.fields.values() if spec is not None else ():
            if fs.kind == "msg" and not fs.array and fs.msg_type is not None:
                rest = self._path_to(fs.msg_type, target, seen)
                if rest is not None:
                    return [start, *rest]
        return None

    # -- loading -------------------------------------------------------------
    def load(self) -> None:
        """Read the interface files (once); their problems land in `problems`."""
        if self._loaded:
            return
        self._loaded = True
        files: list[InterfaceFile] = []
        for path in self._files:
            try:
                text = path.read_text(encoding="utf-8")
            except (OSError, UnicodeDecodeError) as err:
                self._problem(
                    rules.MALFORMED_INTERFACE,
                    str(path),
                    1,
                    0,
                    f"cannot read interface file: {err}",
                )
                continue
            parsed = read_interface(path, text)
            digest = hashlib.sha1(text.encode("utf-8")).hexdigest()
            for section in parsed.sections:
                self._defined_by[section.name] = digest
            files.append(parsed)
        for file in files:  # declare every type before resolving any field
            for problem in file.problems:
                self._problem(
                    rules.MALFORMED_INTERFACE,
                    file.path,
                    problem.line,
                    problem.col,
                    problem.message,
                )
            for section in file.sections:
                self._declare(section)
        if self._rep103:
            self._add_rep103()
        for file in files:
            for section in file.sections:
                self._resolve_fields(file, section)
        for file in files:
            for section in file.sections:
                self._add_annotations(file.path, section)

    def _declare(self, section: Section) -> None:
        base = self._specs.get(section.name)
        if base is None and section.name in self._standard():
            base = self._from_standard(section.name)
        self._specs[section.name] = base or MsgSpec(section.name, {})

    def _resolve_fields(self, file: InterfaceFile, section: Section) -> None:
        if not section.fields:
            return
        package = section.name.split("/")[0]
        spec = self._specs[section.name]
        resolved: dict[str, FieldSpec] = {}
        for decl in section.fields:
            fs = self._field(decl.name, decl.type, decl.array, package)
            if fs is None:
                self._problem(
                    rules.UNKNOWN_MESSAGE_TYPE,
                    file.path,
                    decl.line,
                    0,
                    f"unknown message type `{decl.type}` of field `{decl.name}`",
                )
                fs = FieldSpec(decl.name, "unknown", None, decl.array)
            resolved[decl.name] = fs
            spec.declared_at[decl.name] = Origin(file.path, decl.line)
        spec.fields = resolved

    def _field(
        self, name: str, type_: str, array: bool, package: str
    ) -> FieldSpec | None:
        if type_ in INT_TYPES:
            return FieldSpec(name, "int", None, array, loose=type_ in ("char", "byte"))
        if type_ in FLOAT_TYPES:
            return FieldSpec(name, "float", None, array)
        if type_ in BASE_KINDS:
            return FieldSpec(name, BASE_KINDS[type_], None, array)
        target = self._resolve_type(type_, package)
        return None if target is None else FieldSpec(name, "msg", target, array)

    def _resolve_type(self, type_: str, package: str) -> str | None:
        if type_ in ALIASES:
            return ALIASES[type_]
        if "/" in type_:
            key = normalize(type_)
            return key if self._known(key) else None
        local = f"{package}/{type_}"
        if self._known(local):
            return local
        matches = sorted(
            k for k in (*self._specs, *self._standard()) if k.endswith("/" + type_)
        )
        return matches[0] if matches else None

    def _known(self, key: str) -> bool:
        return key in self._specs or key in self._standard()

    def _add_annotations(self, path: str, section: Section) -> None:
        spec = self._specs[section.name]
        field_lines = {decl.line: decl.name for decl in section.fields}
        for note in section.annotations:
            try:
                predicate = parse_predicate(note.text)
            except AnnotationSyntaxError as err:
                self._problem(
                    rules.ANNOTATION_SYNTAX,
                    path,
                    note.line,
                    note.col + err.offset,
                    err.message,
                )
                continue
            own = field_lines.get(note.line)
            self._add_predicate(spec, predicate, own, Origin(path, note.line), note)

    def _add_predicate(
        self,
        spec: MsgSpec,
        predicate: A.Expr,
        own: str | None,
        origin: Origin,
        note: Any,
    ) -> None:
        rename = {"_": own} if own else {}
        for part in A.conjuncts(predicate):
            if isinstance(part, A.UnitIs):
                target = part.target or own
                if target is None:
                    self._problem(
                        rules.MISPLACED_UNIT,
                        origin.path,
                        origin.line,
                        note.col + part.pos,
                        f"{part.kind.capitalize()}('{part.text}') in an "
                        "interface file needs a field: write "
                        f'{part.kind.capitalize()}(field) == "{part.text}"',
                    )
                elif self._check_path(spec, target, origin, note.col + part.pos):
                    self._add_unit(spec, target, part, origin, note.col)
                continue
            if any(isinstance(n, A.UnitIs) for n in A.walk(part)):
                self._problem(
                    rules.MISPLACED_UNIT,
                    origin.path,
                    origin.line,
                    note.col,
                    "Unit(), Frame() and Tag() must be top-level `and` parts",
                )
                continue
            part = A.substitute(part, {k: A.Name(v) for k, v in rename.items() if v})
            paths = {n.name for n in A.names(part)}
            if all(
                self._check_path(spec, p, origin, note.col + n.pos)
                for n in A.names(part)
                for p in [n.name]
            ):
                spec.invariants.append(
                    Invariant(part, frozenset(paths), A.show(part), origin)
                )

    def _add_unit(
        self, spec: MsgSpec, target: str, part: A.UnitIs, origin: Origin, col: int
    ) -> None:
        text = part.text if part.kind == "unit" else f"{part.kind}:{part.text}"
        if part.kind == "unit":
            try:
                resolve(part.text)
            except UnitError as err:
                self._problem(
                    rules.UNKNOWN_UNIT,
                    origin.path,
                    origin.line,
                    col + part.pos,
                    err.message,
                )
                return
        spec.units[target] = FieldUnit(text, origin)

    def _check_path(self, spec: MsgSpec, path: str, origin: Origin, col: int) -> bool:
        found = self.field_at(spec.name, path)
        if found is None or found.kind == "msg":
            what = "is a message, not a value" if found else "is not a field"
            self._problem(
                rules.UNKNOWN_FIELD,
                origin.path,
                origin.line,
                col,
                f"`{path}` {what} of {spec.name}",
            )
            return False
        return True

    def _add_rep103(self) -> None:
        data = tomllib.loads(
            (Path(__file__).with_name("rep103.toml")).read_text(encoding="utf-8")
        )
        for entry in data["message"]:
            spec = self.lookup(entry["type"])
            if spec is None:
                continue
            for path, unit in entry["units"].items():
                if self.field_at(spec.name, path) is not None:
                    spec.units.setdefault(path, FieldUnit(unit, None, entry["source"]))

    def _problem(
        self, rule: Rule, path: str, line: int, col: int, message: str
    ) -> None:
        self.problems.append(CatalogProblem(rule, path, line, col, message))

    # -- standard definitions ------------------------------------------------
    def _standard(self) -> dict[str, Any]:
        if self._std is None:
            self._std = _standard_definitions(self._distro)
        return self._std

    def _from_standard(self, key: str) -> MsgSpec:
        entry = self._standard()[key]
        fields = {}
        for name, type_, array in entry["fields"]:
            package = key.split("/")[0]
            fs = self._field(name, type_, array, package)
            fields[name] = fs or FieldSpec(name, "unknown", None, array)
        consts = {name: (type_, value) for name, type_, value in entry["consts"]}
        return MsgSpec(key, fields, constants=consts)


# ros2 and ros1 are the newest LTS of each generation; the other store wins for
# types one generation lacks, so ROS 1 code still knows ROS 2-only types and back.
STORES = {
    "ros2": ("ros2_jazzy", "ros1_noetic"),
    "ros1": ("ros1_noetic", "ros2_jazzy"),
    "jazzy": ("ros2_jazzy", "ros1_noetic"),
    "humble": ("ros2_humble", "ros1_noetic"),
    "iron": ("ros2_iron", "ros1_noetic"),
    "kilted": ("ros2_kilted", "ros1_noetic"),
    "rolling": ("latest", "ros1_noetic"),
    "noetic": ("ros1_noetic", "ros2_jazzy"),
}
_STD_CACHES: dict[str, JsonCache] = {}


def _std_cache(distro: str) -> JsonCache:
    if distro not in _STD_CACHES:
        key = install_key("rosbags", f"msgs-v2-{distro}")
        _STD_CACHES[distro] = JsonCache(f"ros-messages-{distro}", key)
    return _STD_CACHES[distro]


def _standard_definitions(distro: str) -> dict[str, Any]:
    cache = _std_cache(distro)
    if not cache.entries:
        for key, value in _convert_rosbags(STORES.get(distro, STORES["ros2"])).items():
            cache.put(key, value)
    return cache.entries


def _convert_rosbags(stores: tuple[str, str]) -> dict[str, Any]:
    import importlib

    out: dict[str, Any] = {}
    for store in reversed(stores):  # the first store wins
        fielddefs = importlib.import_module(f"rosbags.typesys.stores.{store}").FIELDDEFS
        for name, (consts, fields) in fielddefs.items():
            out[normalize(name)] = {
                "fields": [_rosbags_field(n, d) for n, d in fields],
                "consts": [
                    [n, t, v]
                    for n, t, v in consts
                    if isinstance(v, (int, float, str, bool))
                ],
            }
    return out


def _rosbags_field(name: str, desc: Any) -> list[Any]:
    nodetype, detail = desc
    kind = int(nodetype)
    if kind in (3, 4):  # ARRAY, SEQUENCE: detail is (element, size)
        element = _rosbags_field(name, detail[0])
        return [name, element[1], True]
    if kind == 1:  # BASE: (type, string bound)
        return [name, str(detail[0]), False]
    return [name, normalize(str(detail)), False]  # NAME
