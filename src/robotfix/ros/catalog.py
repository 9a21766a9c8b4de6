"""MsgCatalog: every message type a check can meet, with its units and refinements.

Three sources, later ones adding to earlier ones:
1. the standard ROS 2 (Jazzy) and ROS 1 (Noetic) definitions bundled with `rosbags`
   (the only module that imports rosbags), converted once into a JSON cache;
2. REP 103 units (`rep103.toml`), unless turned off;
3. the user's `.msg`/`.srv`/`.action` files, whose `#RobotFix#` lines add units and
   invariants. A user file that redeclares a standard message adds its refinements to
   it; its own field list wins where it has one.

A type is taken from the first source that defines it: the interface files of the
checked packages (`preferred`), then the other user files (msg paths), then the
sourced install space (`InstallSpace`, read when a type is looked up), then the
bundled standard definitions. A user file shadows the install space's copy of its
type; problems in installed files are kept apart (`installed_problems`), and an
installed file with a line that does not parse is not used at all.
When two user files define one type, the first in that order wins and the other gets
RF510, unless both say the same (a copy, as in a colcon install/ tree). A section
without fields (an overlay: `[pkg/Type]:` and `#RobotFix#` lines) defines nothing:
its lines are added to its type's definition wherever that comes from, after the
definition's own, overlays in the order above.
Constants (`uint8 ULTRASOUND=0`) come from rosbags and from user files; default values
(`float64 w 1`) from user files and, for the standard messages, from `defaults.toml`
(rosbags drops them). `#RobotFix#` lines may name the message's constants and `pi`,
`math.pi`, `math.inf`...; their values are put in when the line is read.

Problems in interface files come back as `CatalogProblem`s (rule, path, line, col),
never as exceptions: one file or line RobotFix cannot process is reported there and
skipped, and the run goes on.
"""

from __future__ import annotations

import functools
import hashlib
import json
import os
from collections.abc import Collection, Mapping
from dataclasses import dataclass, field, replace
from fractions import Fraction
from functools import cache
from itertools import islice
from pathlib import Path
from typing import TYPE_CHECKING, Any

from robotfix import messages, rules, tomlfile
from robotfix.diagnostics import Diagnostic, Note, Rule, Span
from robotfix.disk_cache import JsonCache, install_key
from robotfix.fs import UnreadableError, read_text
from robotfix.ros.install import InstallSpace

if TYPE_CHECKING:  # a cached run asks only the digests: it reads no interface file
    # nor annotation, and loads none of these (each function that does imports them)
    from robotfix.annotations import ast as A
    from robotfix.ros.comments import CommentUnit
    from robotfix.ros.msg import InterfaceFile, Section

# `MsgCatalog.outline`: (file, sha1 of its text, [(type, has fields)]) per file used
Outline = list[tuple[str, str, list[tuple[str, bool]]]]

MAX_INTERFACE_BYTES = 4 * 1024 * 1024  # installed files are a few kB
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
# The values an integer field can hold (rosidl; `char` is uint8 in a .msg, in ROS 1
# too; `byte` is int8 in ROS 1 but `bytes` in ROS 2's Python: no range).
INT_RANGES = {
    "char": (0, 2**8 - 1),
    **{f"uint{n}": (0, 2**n - 1) for n in (8, 16, 32, 64)},
    **{f"int{n}": (-(2 ** (n - 1)), 2 ** (n - 1) - 1) for n in (8, 16, 32, 64)},
}
FLOAT_TYPES = frozenset({"float32", "float64"})
BASE_KINDS = {"bool": "bool", "string": "str", "wstring": "str"}
ALIASES = {
    "Header": "std_msgs/Header",
    "time": "builtin_interfaces/Time",
    "duration": "builtin_interfaces/Duration",
}
# A ROS 1 `time` or `duration` field holds genpy's Time or Duration, whose fields
# are `secs` and `nsecs` (rosbags' ROS 1 store spells them as ROS 2 does); a ROS 1
# distribution's catalog names them so (their units: rep103.toml).
GENPY_TIME = {
    "builtin_interfaces/Time": (("secs", "uint32"), ("nsecs", "uint32")),
    "builtin_interfaces/Duration": (("secs", "int32"), ("nsecs", "int32")),
}


@dataclass(frozen=True)
class Origin:
    """Where a definition is: file and line."""

    path: str
    line: int


@dataclass(frozen=True)
class FieldSpec:
    """A message field: its type, array shape, default and range."""

    name: str
    kind: str  # int, float, bool, str, msg
    msg_type: str | None = None  # pkg/Name when kind == "msg"
    array: bool = False
    loose: bool = False  # char/byte: ROS 1 takes str or int there; no base-type check
    default: Any = None  # the value of the field never set, when not 0/False/""
    std_default: bool = False  # from a ROS 2 standard definition: ROS 1 has none
    size: int | None = None  # an array of this fixed size (`float64[9]`)
    bound: int | None = None  # an array of at most this many elements (`[<=9]`)
    # an integer field's type range, `uint8` (0, 255): its elements' for an array
    values: tuple[int, int] | None = None


@dataclass(frozen=True)
class Invariant:
    """A `#RobotFix#` predicate of a message type, over its field paths."""

    predicate: A.Expr  # names are field paths relative to the message
    paths: frozenset[str]
    text: str
    origin: Origin


@dataclass(frozen=True)
class FieldUnit:
    """A field's unit, and where it was written."""

    text: str
    origin: Origin | None  # None for REP 103 (see `source`)
    source: str = ""


COMMENT = "comment"  # FieldUnit.source of a unit from a user file's comment
SUFFIX = "suffix"  # ... and of one from a field name's suffix (`unit_suffixes`)
# Autoware's message guidelines: the suffix of a field in a unit that is not SI's.
# `_min` (minute) and `_nm` (nanometre) are left out: `range_min` is a minimum and
# `torque_nm` is in newton metres far more often.
UNIT_SUFFIXES = {
    "_um": "um",
    "_mm": "mm",
    "_km": "km",
    "_deg": "degree",
    "_ns": "ns",
    "_us": "us",
    "_ms": "ms",
    "_hour": "hour",
    "_kmph": "km/h",
}


NUMBER_KINDS = ("int", "float")


def suffix_unit(name: str) -> str | None:
    """The unit a field's name ends in by Autoware's guidelines (`timeout_ms`)."""
    for suffix, unit in UNIT_SUFFIXES.items():
        if name.endswith(suffix) and len(name) > len(suffix):
            return unit
    return None


def is_comment_unit(text: str) -> bool:
    """Whether the text of a `[...]` in a comment is a unit pint reads (not a tag,
    not a typo, nothing pint should not evaluate)."""
    from robotfix.annotations.units import UnitError, resolve

    try:
        return not resolve(text).is_label
    except UnitError:
        return False


@dataclass
class MsgSpec:
    """A message type: fields, units, invariants, constants."""

    name: str
    fields: dict[str, FieldSpec]
    units: dict[str, FieldUnit] = field(default_factory=dict)
    invariants: list[Invariant] = field(default_factory=list)
    constants: dict[str, tuple[str, Any]] = field(default_factory=dict)
    declared_at: dict[str, Origin] = field(default_factory=dict)  # user files' fields


@dataclass(frozen=True)
class CatalogProblem:
    """A problem of an interface file, reported when a checked file uses its type."""

    rule: Rule
    path: str
    line: int
    col: int
    message: str
    notes: tuple[Note, ...] = ()
    absent_package: str | None = None  # RF504: a package with no type known at all


def constant_term(type_: str, value: Any) -> A.Expr | None:
    """The solver term of a constant or default value of a field type."""
    from robotfix.annotations import ast as A

    if isinstance(value, bool):
        return A.Bool(value)
    if isinstance(value, (int, float, Fraction)) and not isinstance(value, bool):
        exact = Fraction(value)
        return A.Num(exact, type_ not in FLOAT_TYPES and exact.denominator == 1)
    if isinstance(value, str):
        return A.Str(value)
    return None


def normalize(name: str) -> str:
    """`geometry_msgs/msg/Twist` and `geometry_msgs/Twist` name the same type."""
    if name.count("/") != 2:  # most names: no list made (40,000 a corpus run)
        return name
    package, middle, type_ = name.split("/")
    return f"{package}/{type_}" if middle in ("msg", "srv", "action") else name


class MsgCatalog:
    def __init__(
        self,
        interface_files: list[Path],
        *,
        rep103: bool = True,
        distro: str = "ros2",
        texts: Mapping[Path, str] | None = None,
        installed: InstallSpace | None = None,
        preferred: Collection[Path] = (),
        unit_suffixes: bool = False,
    ) -> None:
        """`texts`: the content of files an editor has open, for those files;
        `unit_suffixes`: a number field named `*_ms`, `*_deg`, ... has that unit."""
        self._std: dict[str, Any] | None = None
        self._specs: dict[str, MsgSpec] = {}
        # `_packages`: the packages of `_specs` and of the standard types, and how
        # many of `_specs` they were made from (names are only ever added)
        self._package_names: tuple[int, frozenset[str]] = (-1, frozenset())
        # order decides duplicates: the checked packages' files first, then the rest
        # in the order given (msg paths, then path order)
        chosen = {str(path) for path in preferred}
        self._given = [p for p in interface_files if str(p) in chosen] + [
            p for p in interface_files if str(p) not in chosen
        ]
        self._texts = dict(texts or {})
        self._rep103 = rep103
        self.unit_suffixes = unit_suffixes  # the analysis reads it for parameter names
        self._distro = distro
        self._loaded = False
        self.problems: list[CatalogProblem] = []
        self.touched: set[str] | None = None  # names looked up, while a file is checked
        self._defined_by: dict[
            str, str
        ] = {}  # type -> hash of the file that defines it
        self._installed = installed
        self._installed_keys: set[str] = set()  # types read from the install space
        self._installed_tried: set[str] = set()  # installed files read (or refused)
        self.installed_problems: list[CatalogProblem] = []  # never reported
        self._types_of: dict[str, tuple[str, ...]] = {}  # user file -> its types
        # fingerprint_types' memo: each type's message-typed fields
        self._children: dict[str, tuple[str, ...]] = {}
        self._digests_handed = 0  # `fresh_digests`: the table's entries handed out
        self._combined: dict[tuple[str, ...], str] = {}  # names asked -> digest
        # a name asked -> the types its digest covers (its own, its fields'...), and
        # each of those types' line of the digest (`_closure`): the many files of a
        # run that share types walk each type's fields once
        self._closures: dict[str, frozenset[str]] = {}
        self._lines: dict[str, str] = {}
        # the lazy load (`preload_outline`): each used file in order, its digest and
        # its sections (name, has fields); files not read yet, by type they define
        self._outline: Outline | None = None
        self._lazy = False  # the types are declared from the outline, not read
        # type -> indices in the outline of the files that define or overlay it
        # (the definition first); `_read`: those read since
        self._unread: dict[str, list[int]] = {}
        self._read_indices: set[int] = set()
        self._overlaid: set[tuple[str, tuple[Any, ...]]] = set()  # `_duplicate`
        self._no_reads = False  # REP 103 is applied before any file is resolved

    # -- public --------------------------------------------------------------
    def lookup(self, name: str) -> MsgSpec | None:
        key = normalize(name)
        if not self._loaded or self._lazy:  # else every file is read already
            if self._outline is None:
                self.load()
            else:
                self._declare_outline()
                if key in self._unread and not self._no_reads:
                    self._read_type(key)
        if self.touched is not None:
            self.touched.add(key)
        spec = self._specs.get(key)
        if spec is None and self._installed is not None:
            spec = self._from_installed(key)
        if spec is None and key in self._standard():
            spec = self._specs[key] = self._from_standard(key)
        return spec

    def types_in(self, path: str) -> tuple[str, ...]:
        """The types a user interface file defines (as spelled in `problems`)."""
        self.load()
        return self._types_of.get(path, ())

    def _user_package(self, package: str) -> bool:
        """Whether the user's interface files (or the install space) define types
        of `package`, as opposed to the bundled standard definitions only."""
        prefix = package + "/"
        return any(k.startswith(prefix) for k in self._defined_by) or (
            self._installed is not None and self._installed.has_package(package)
        )

    def _near_miss(self, package: str, name: str) -> bool:
        """Whether a type of `package` is spelled almost like `name` (a typo)."""
        prefix = package + "/"
        names = [
            k[len(prefix) :]
            for k in (*self._specs, *self._standard())
            if k.startswith(prefix)
        ]
        import difflib  # only for a type that is not found: 2 ms of every start

        return bool(difflib.get_close_matches(name, names, n=1, cutoff=0.8))

    def has_package(self, package: str) -> bool:
        if self._outline is None or (self._loaded and not self._lazy):
            self.load()
        else:  # every type is declared: the names are all it needs
            self._declare_outline()
        if "/" in package:  # no package name: the names' prefixes, as spelled
            prefix = package + "/"
            names = (*self._specs, *self._standard())
            found = any(k.startswith(prefix) for k in names)
        else:
            found = package in self._packages()
        return found or (
            self._installed is not None and self._installed.has_package(package)
        )

    def _packages(self) -> frozenset[str]:
        """The package (first part) of every declared and standard type's name:
        `has_package` is asked once per imported package, and the names number
        hundreds."""
        count, packages = self._package_names
        if count != len(self._specs):
            names = (*self._specs, *self._standard())
            packages = frozenset(k.partition("/")[0] for k in names if "/" in k)
            self._package_names = (len(self._specs), packages)
        return packages

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

    def unit_at(self, msg_type: str, path: str) -> str | None:
        """The unit an interface gives the field at a dotted path inside
        `msg_type` (REP 103, a comment, `#RobotFix#`), written on it or on a
        message type that holds it; None without one."""
        spec = self.lookup(msg_type)
        parts = path.split(".")
        for index, part in enumerate(parts):
            if spec is None:
                return None
            declared = spec.units.get(".".join(parts[index:]))
            if declared is not None:
                return declared.text
            found = spec.fields.get(part)
            if found is None or found.kind != "msg" or found.array:
                return None
            spec = self.lookup(found.msg_type or "")
        return None

    _resolved_digests: dict[str, str] | None = None  # fingerprint_types' memo

    def fingerprint_types(self, names: list[str]) -> str:
        """A digest of everything a check can read about the types `names`: each
        type's resolved definition (fields with the types they resolve to, units,
        invariants, constants, and the path and line each was declared at, from
        every file that declares it), then the same for the message types of its
        fields, transitively; a type that is not found counts as missing, so a file
        that later resolves it changes the digest."""
        asked = tuple(sorted(set(names)))
        known = self._combined.get(asked)
        if known is not None:  # many files use the same few types
            return known
        covered: set[str] = set()
        saved, self.touched = self.touched, None  # not a lookup of the checked file
        try:
            for name in asked:
                covered |= self._closures.get(name) or self._closure(name)
        finally:
            self.touched = saved
        lines = sorted(map(self._lines.__getitem__, covered))
        combined = hashlib.sha256("\n".join(lines).encode()).hexdigest()
        self._combined[asked] = combined  # the digests it is made of never change
        return combined

    def _closure(self, name: str) -> frozenset[str]:
        """The types `fingerprint_types` covers for `name`: its own, its fields'
        message types, transitively, each with its line of the digest (kept once a
        run, so a cached run's many files that share types walk each type's fields
        once). A type's digest and fields come from `preload_digests` when an
        earlier run knew them (its file is not read), else from its definition."""
        if self._resolved_digests is None:
            self._resolved_digests = {}
        digests, children, lines = self._resolved_digests, self._children, self._lines
        seen: set[str] = set()
        todo = [normalize(name)]
        while todo:
            key = todo.pop()
            if key in seen:
                continue
            seen.add(key)
            if key not in digests or key not in children:
                spec = self.lookup(key)
                text = "missing" if spec is None else _canonical(spec)
                digests[key] = hashlib.sha256(text.encode()).hexdigest()
                children[key] = tuple(
                    f.msg_type
                    for f in (spec.fields.values() if spec else ())
                    if f.msg_type
                )
            if key not in lines:
                lines[key] = f"{key} {digests[key]}"
            todo.extend(children[key])
        found = self._closures[name] = frozenset(seen)
        return found

    def digest_table(self) -> dict[str, tuple[str, tuple[str, ...]]]:
        """What `fingerprint_types` worked out so far: each type's digest and the
        message types of its fields (for a result cache to hand back)."""
        digests = self._resolved_digests or {}
        return {k: (v, self._children[k]) for k, v in digests.items()}

    def fresh_digests(self) -> dict[str, tuple[str, tuple[str, ...]]]:
        """`digest_table`'s entries since the last call: a worker hands them to the
        main process (`preload_digests`), whose result cache keeps them, so the next
        run reads no interface file a worker read for them."""
        digests = self._resolved_digests or {}
        fresh = {
            k: (v, self._children[k])
            for k, v in islice(digests.items(), self._digests_handed, None)
        }
        self._digests_handed = len(digests)
        return fresh

    def preload_digests(self, table: Mapping[str, tuple[str, tuple[str, ...]]]) -> None:
        """`digest_table` of an earlier run over the very same interface files (the
        caller's key says so: their stats, the settings, no install space), so that
        `fingerprint_types` need not read them."""
        if self._resolved_digests is None:
            self._resolved_digests = {}
        for key, (digest, fields) in table.items():
            self._resolved_digests.setdefault(key, digest)
            self._children.setdefault(key, tuple(fields))

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

    def prepare(self) -> None:
        """Read the interface files and the standard definitions now, before worker
        processes are forked, so that they share them instead of each reading them."""
        self.load()
        self._standard()

    # -- loading -------------------------------------------------------------
    def load(self) -> None:
        """Read the interface files (once); their problems land in `problems`."""
        if self._loaded and not self._lazy:
            return
        if self._lazy:  # a partial load: all of it again, as if never begun
            self._restart()
        self._loaded = True
        files: list[InterfaceFile] = []
        first: dict[str, tuple[InterfaceFile, tuple[Any, ...]]] = {}
        self._overlaid = set()  # (type, shape) of the overlays used, for copies
        outline: Outline = []
        # each file once, however spelled, and not rosidl's twin (`realpath` of
        # every file: a cached run with an outline does not need it)
        for path in _without_twins(_distinct(self._given)):
            read = self._read(path)
            if read is None or self._duplicate(read[0], first):
                continue
            parsed, digest = read
            for section in parsed.sections:
                if section.fields:  # an overlay defines nothing: it adds
                    first.setdefault(section.name, (parsed, _shape(section)))
                self._defined_by[section.name] = digest
            files.append(parsed)
            sections = [(x.name, bool(x.fields)) for x in parsed.sections]
            outline.append((os.fspath(path), digest, sections))
        self._outline = outline
        for file in files:
            self._types_of[file.path] = tuple(s.name for s in file.sections)
        for file in files:
            for problem in file.problems:
                self._problem(
                    rules.MALFORMED_INTERFACE,
                    file.path,
                    problem.line,
                    problem.col,
                    problem.message,
                )
        # every type declared before any field is resolved: definitions first, then
        # overlays (`_overlays_last`), which add to their type's definition wherever
        # that comes from (a file here, the install space, the standard set)
        for _, section in _overlays_last(files):
            self._declare(section)
        if self._rep103:
            self._add_rep103()
        for file in files:
            for section in file.sections:
                try:
                    self._resolve_fields(file, section)
                except Exception as err:  # one file never takes the run down
                    self._report(
                        messages.unprocessable_interface(file.path, 1, 0, "file", err)
                    )
        for file, section in _overlays_last(files):
            self._add_comment_units(file.path, section)
            self._add_annotations(file.path, section)

    # -- the lazy load ---------------------------------------------------------
    def outline(self) -> Outline | None:
        """Which files a full load used, in order, each with the digest of its text
        and its sections (name, whether it has fields); None when unknown."""
        return self._outline

    def preload_outline(self, outline: Outline) -> None:
        """`outline` of an earlier full load of the very same interface files (the
        caller's key says so: their stats, the settings, no install space): a type
        is then read from its own file when looked up, as the full load would have
        made it, and the other files are not read (`problems`, `refined_specs` and
        the like still load everything)."""
        if not self._loaded and self._installed is None and not self._texts:
            self._outline = outline

    def _declare_outline(self) -> None:
        """The first steps of `load` from the outline: every type declared (a
        section is all `_declare` reads: its name and whether it has fields), then
        REP 103 on the declared types, before any field is resolved."""
        if self._loaded:
            return
        assert self._outline is not None
        self._loaded = self._lazy = True
        for path, digest, sections in self._outline:
            self._types_of[path] = tuple(name for name, _ in sections)
            for name, _ in sections:
                self._defined_by[name] = digest
        named = [
            (name, has_fields, index)
            for index, (_, _, sections) in enumerate(self._outline)
            for name, has_fields in sections
        ]
        # as `load`: definitions first, then overlays (`_overlays_last`)
        for name, has_fields, index in sorted(named, key=lambda n: not n[1]):
            self._unread.setdefault(name, []).append(index)
            self._declare_name(name, has_fields)
        if self._rep103:
            self._no_reads = True
            try:
                self._add_rep103()
            finally:
                self._no_reads = False

    def _read_outlined(self, index: int) -> None:
        """The rest of `load` for one file of the outline: its fields resolved, its
        units and annotations added; the whole load when it no longer reads as the
        outline says."""
        assert self._outline is not None
        path, digest, sections = self._outline[index]
        self._read_indices.add(index)
        read = self._read(Path(path))
        if (
            read is None
            or read[1] != digest
            or [(x.name, bool(x.fields)) for x in read[0].sections] != sections
        ):
            self._outline = None
            self.load()
            return
        parsed = read[0]
        for section in parsed.sections:
            try:
                self._resolve_fields(parsed, section)
            except Exception as err:  # as `load`
                self._report(
                    messages.unprocessable_interface(parsed.path, 1, 0, "file", err)
                )
        for section in parsed.sections:
            if not section.fields:  # an overlay: its type's definition first
                self._read_type(section.name, definitions_only=True)
            if not self._lazy:  # a file read meanwhile fell back to the whole load
                return
            self._add_comment_units(parsed.path, section)
            self._add_annotations(parsed.path, section)

    def _read_type(self, name: str, definitions_only: bool = False) -> None:
        """Read the outline's files not read yet that define type `name` (and,
        unless `definitions_only`, those that overlay it), definition first."""
        outline = self._outline
        assert outline is not None
        todo = [
            index
            for index in self._unread.get(name, ())
            if index not in self._read_indices
            and not (definitions_only and (name, True) not in outline[index][2])
        ]
        self._read_indices.update(todo)  # a lookup while they are read reads none
        for index in todo:
            if self._lazy:  # else a file read fell back to the whole load
                self._read_outlined(index)

    def _restart(self) -> None:
        """Forget a partial load (what `__init__` set; the digests stay: they are
        the full load's too)."""
        self._specs = {}
        self._package_names = (-1, frozenset())
        self.problems = []
        self._defined_by = {}
        self._installed_keys = set()
        self._installed_tried = set()
        self.installed_problems = []
        self._types_of = {}
        self._unread = {}
        self._read_indices = set()
        self._lazy = False
        self._loaded = False

    def _read(self, path: Path) -> tuple[InterfaceFile, str] | None:
        """The parsed file and a digest of its text; None after reporting why not."""
        try:
            text = self._texts[path] if path in self._texts else read_text(path)
        except UnreadableError as err:
            self._problem(
                rules.MALFORMED_INTERFACE,
                str(path),
                1,
                0,
                f"cannot read interface file: {err.reason}",
            )
            return None
        from robotfix.ros.msg import read_interface

        try:
            parsed = read_interface(path, text)
        except Exception as err:  # one file never takes the run down
            self._report(messages.unprocessable_interface(str(path), 1, 0, "file", err))
            return None
        return parsed, hashlib.sha1(text.encode("utf-8")).hexdigest()

    def _duplicate(
        self,
        file: InterfaceFile,
        first: dict[str, tuple[InterfaceFile, tuple[Any, ...]]],
    ) -> bool:
        """Whether `file` defines a type an earlier file defines (RF510 unless it
        says the same), or holds only overlays an earlier file holds; such a file
        is not used. An overlay (a section without fields) never clashes: it adds
        its `#RobotFix#` lines to its type, wherever that is defined."""
        clashes = [
            (section, first[section.name])
            for section in file.sections
            if section.fields and section.name in first
        ]
        if not clashes:  # only overlays: a copy of earlier ones adds nothing
            overlays = [(s.name, _shape(s)) for s in file.sections if not s.fields]
            copy = bool(overlays) and len(overlays) == len(file.sections)
            if copy and all(o in self._overlaid for o in overlays):
                return True
            self._overlaid.update(overlays)
            return False
        if any(_shape(section) != shape for section, (_, shape) in clashes):
            section, (earlier, _) = clashes[0]
            name = _type_name(file, section.name)
            self._report(messages.duplicate_interface(file.path, name, earlier.path))
        return True

    def _declare(self, section: Section) -> None:
        self._declare_name(section.name, bool(section.fields))

    def _declare_name(self, name: str, has_fields: bool) -> None:
        base = self._specs.get(name)
        if name in self._installed_keys:  # a user file replaces it
            self._installed_keys.discard(name)
            base = None
            if not has_fields:  # refinements only: added to the installed type
                base = self._specs[name]
        if base is None and name in self._standard():
            base = self._from_standard(name)
        if base is None and not has_fields:
            base = self._from_installed(name)
            self._installed_keys.discard(name)
        self._specs[name] = base or MsgSpec(name, {})

    def _from_installed(self, key: str) -> MsgSpec | None:
        """The type `key` from the install space's file that defines it, read now;
        None when there is none, or it cannot be read or has a malformed line."""
        path = None if self._installed is None else self._installed.find(key)
        if path is None or str(path) in self._installed_tried:
            return None
        self._installed_tried.add(str(path))
        try:
            text = read_text(path, MAX_INTERFACE_BYTES)
        except UnreadableError:
            return None
        from robotfix.ros.msg import read_interface

        parsed = read_interface(path, text)
        names = [section.name for section in parsed.sections]
        if parsed.problems or key not in names:
            return None
        digest = hashlib.sha1(text.encode("utf-8")).hexdigest()
        saved, self.problems = self.problems, []
        try:
            for section in parsed.sections:
                name = section.name
                if name not in self._specs:  # a user file's type stays the user's
                    self._defined_by[name] = digest
                    self._installed_keys.add(name)
                    standard = name in self._standard()
                    self._specs[name] = (
                        self._from_standard(name) if standard else MsgSpec(name, {})
                    )
            for section in parsed.sections:
                if section.name in self._installed_keys:
                    self._resolve_fields(parsed, section)
            for section in parsed.sections:
                if section.name in self._installed_keys:
                    self._add_comment_units(parsed.path, section)
                    self._add_annotations(parsed.path, section)
        finally:
            self.installed_problems.extend(self.problems)
            self.problems = saved
        return self._specs.get(key)

    def _resolve_fields(self, file: InterfaceFile, section: Section) -> None:
        spec = self._specs[section.name]
        spec.constants.update({c.name: (c.type, c.value) for c in section.constants})
        if not section.fields:
            return
        package = section.name.split("/")[0]
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
                named = normalize(decl.type).split("/")
                if len(named) == 2 and not self.has_package(named[0]):
                    self.problems[-1] = replace(
                        self.problems[-1], absent_package=named[0]
                    )
                elif (
                    len(named) == 2
                    and not self._user_package(named[0])
                    and not self._near_miss(named[0], named[1])
                ):
                    # a standard package without that type, and nothing in it is
                    # spelled like it: a newer distribution's type (nav_msgs/Goals),
                    # so a warning; `PoseStampd` stays an error (a typo)
                    self.problems[-1] = replace(
                        self.problems[-1], absent_package="/".join(named)
                    )
                fs = FieldSpec(decl.name, "unknown", None, decl.array)
            elif decl.default is not None and fs.kind != "msg":
                fs = replace(fs, default=decl.default)
            if decl.size is not None or decl.bound is not None:
                fs = replace(fs, size=decl.size, bound=decl.bound)
            resolved[decl.name] = fs
            spec.declared_at[decl.name] = Origin(file.path, decl.line)
        spec.fields = resolved

    def _field(
        self, name: str, type_: str, array: bool, package: str
    ) -> FieldSpec | None:
        if type_ in INT_TYPES:
            loose = type_ in ("char", "byte")
            values = INT_RANGES.get(type_)
            return FieldSpec(name, "int", None, array, loose=loose, values=values)
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
        return (
            key in self._specs
            or key in self._standard()
            or (self._installed is not None and self._installed.find(key) is not None)
        )

    def _add_comment_units(self, path: str, section: Section) -> None:
        """Units of the section's number fields from their names' suffixes (if
        `unit_suffixes`), replaced by those in their comments (rosidl's `[m]`, where
        pint reads them as a unit); a `#RobotFix#` Unit() replaces both."""
        spec = self._specs[section.name]
        if self.unit_suffixes:
            for decl in section.fields:
                unit = suffix_unit(decl.name)
                field = spec.fields.get(decl.name)
                if (
                    unit is not None
                    and field is not None
                    and field.kind in NUMBER_KINDS
                ):
                    origin = Origin(path, decl.line)
                    spec.units[decl.name] = FieldUnit(unit, origin, SUFFIX)
        for found in section.units:
            field = spec.fields.get(found.field)
            if found.strict and not self._unit_ok(path, found):
                continue
            if (
                field is not None
                and field.kind in NUMBER_KINDS
                and is_comment_unit(found.text)
            ):
                origin = Origin(path, found.line)
                spec.units[found.field] = FieldUnit(found.text, origin, COMMENT)

    def _unit_ok(self, path: str, found: CommentUnit) -> bool:
        """An IDL `@unit` that is a typo of a unit (or unsafe for pint) is RF502;
        a word that is no unit at all (rosidl copies `[enum]`) is only ignored."""
        from robotfix.annotations.units import UnitError, resolve

        try:
            resolve(found.text)
        except UnitError as err:
            self._problem(rules.UNKNOWN_UNIT, path, found.line, found.col, err.message)
            return False
        return True

    def _add_annotations(self, path: str, section: Section) -> None:
        from robotfix.annotations.parser import AnnotationSyntaxError, parse_predicate

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
            except Exception as err:  # one line never takes the run down
                self._report(
                    messages.unprocessable_interface(
                        path, note.line, note.col, "annotation", err
                    )
                )
                continue
            own = note.field or field_lines.get(note.line)
            origin = Origin(path, note.line)
            try:
                self._add_predicate(spec, predicate, own, origin, note)
            except Exception as err:  # one line never takes the run down
                self._report(
                    messages.unprocessable_interface(
                        path, note.line, note.col, "annotation", err
                    )
                )

    def _add_predicate(
        self,
        spec: MsgSpec,
        predicate: A.Expr,
        own: str | None,
        origin: Origin,
        note: Any,
    ) -> None:
        from robotfix.annotations import ast as A

        for part in A.conjuncts(predicate):
            if isinstance(part, A.UnitIs):
                target = _own_path(part.target, own) if part.target else own
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
            if own:
                part = A.substitute(
                    part,
                    {
                        n.name: A.Name(_own_path(n.name, own), n.pos)
                        for n in A.names(part)
                    },
                )
            text = A.show(part)  # as written, with the constants' names
            part = self._put_constants(spec, part)
            paths = {n.name for n in A.names(part)}
            if not paths:
                continue  # names no field (`MODE_A < MODE_B`): nothing to check
            problem = self._array_problem(spec, part)
            if problem is not None:
                rule, message = problem
                self._problem(rule, origin.path, origin.line, note.col, message)
                continue
            if all(
                self._check_path(spec, p, origin, note.col + n.pos)
                for n in A.names(part)
                for p in [n.name]
            ):
                spec.invariants.append(Invariant(part, frozenset(paths), text, origin))

    def _array_problem(self, spec: MsgSpec, part: A.Expr) -> tuple[Rule, str] | None:
        """An annotation that names an array field is on its elements (the field's
        name, or `_` on its line) or on its length (`len(field)`); a part on the
        elements names no other field."""
        from robotfix.annotations import ast as A

        in_len: set[int] = set()
        for node in A.walk(part):
            if isinstance(node, A.Func) and node.name == "len":
                arg = node.args[0]
                found = (
                    self.field_at(spec.name, arg.name)
                    if isinstance(arg, A.Name)
                    else None
                )
                if found is None or not found.array:
                    shown = A.show(arg)
                    return rules.ANNOTATION_SYNTAX, (
                        f"len() takes an array field of {spec.name}, not `{shown}`"
                    )
                in_len.add(id(arg))
        bare = {n.name for n in A.names(part) if id(n) not in in_len}
        arrays = sorted(p for p in bare if _is_array(self.field_at(spec.name, p)))
        if arrays and len(bare) > 1:
            return rules.UNKNOWN_FIELD, (
                f"`{arrays[0]}` is an array: an annotation on its elements names no "
                "other field (write len(...) for its length)"
            )
        return None

    def _put_constants(self, spec: MsgSpec, predicate: A.Expr) -> A.Expr:
        """The message's constants and `pi`, `math.pi`... by value, where no field
        has that name."""
        from robotfix.annotations import ast as A
        from robotfix.annotations.numbers import NUMBERS, named_number

        values: dict[str, A.Expr] = {}
        for ref in A.names(predicate):
            name = ref.name
            if name in values or self.field_at(spec.name, name) is not None:
                continue
            term: A.Expr | None = None
            if name in spec.constants:
                term = constant_term(*spec.constants[name])
            elif name == "pi" or named_number(name) is not None:
                term = A.Num(named_number(name) or NUMBERS["pi"], False)
            if term is not None:
                values[name] = term
        return A.substitute(predicate, values) if values else predicate

    def _add_unit(
        self, spec: MsgSpec, target: str, part: A.UnitIs, origin: Origin, col: int
    ) -> None:
        from robotfix.annotations.units import UnitError, resolve

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
        old = spec.units.get(target)
        if (
            old is None
            or old.origin is None
            or old.source in (COMMENT, SUFFIX)
            or _kind(old.text) != part.kind
        ):
            spec.units[target] = FieldUnit(text, origin)  # REP 103 is overridden
        elif not _same_label(old.text, text):
            shown = old.text if part.kind == "unit" else old.text.partition(":")[2]
            self._report(
                messages.conflicting_label(
                    origin.path,
                    Span.point(origin.line, col + part.pos),
                    target,
                    part.kind,
                    (shown, old.origin.line),
                    part.text,
                )
            )

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
        for entry in table("rep103")["message"]:
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

    def _report(self, diag: Diagnostic) -> None:
        self.problems.append(
            CatalogProblem(
                diag.rule,
                diag.path,
                diag.span.line,
                diag.span.col,
                diag.message,
                diag.notes,
            )
        )

    # -- standard definitions ------------------------------------------------
    def _standard(self) -> dict[str, Any]:
        if self._std is None:
            self._std = _standard_definitions(self._distro)
        return self._std

    def _from_standard(self, key: str) -> MsgSpec:
        entry = self._standard()[key]
        fields = {}
        listed = entry["fields"]
        if key in GENPY_TIME and STORES.get(self._distro, ("",))[0].startswith("ros1"):
            listed = [[name, type_, False] for name, type_ in GENPY_TIME[key]]
        for name, type_, array, *size in listed:
            package = key.split("/")[0]
            fs = self._field(name, type_, array, package)
            fields[name] = fs or FieldSpec(name, "unknown", None, array)
            if size and size[0]:  # [fixed size, bound]
                fields[name] = replace(fields[name], size=size[0])
            if len(size) > 1 and size[1]:
                fields[name] = replace(fields[name], bound=size[1])
        for name, value in (
            _standard_defaults(STORES.get(self._distro, ("",))[0]).get(key, {}).items()
        ):
            if name in fields:
                fields[name] = replace(fields[name], default=value, std_default=True)
        consts = {name: (type_, value) for name, type_, value in entry["consts"]}
        units = {
            name: FieldUnit(unit, None, note)
            for name, (unit, note) in _standard_comment_units().get(key, {}).items()
            if name in fields and fields[name].kind in NUMBER_KINDS
        }
        return MsgSpec(key, fields, units, constants=consts)


# the TOML tables shipped beside this module (their source of truth), also shipped
# parsed, as JSON, by tools/build_package_data.py: read 10x faster, without
# importing tomllib (8 ms of a 150 ms one-file check)
TABLES = ("rep103", "comment_units", "defaults")
TABLE_DIR = Path(__file__).parent
TABLES_JSON = TABLE_DIR / "tables.json"


@functools.cache
def table(name: str) -> Any:
    """`ros/<name>.toml`, parsed: its JSON copy when that was made of these bytes,
    else the TOML itself (an edited table before the tool is run again)."""
    data = (TABLE_DIR / f"{name}.toml").read_bytes()
    try:
        shipped = _shipped_tables().get(name)
    except (OSError, ValueError, AttributeError):
        shipped = None
    if isinstance(shipped, dict) and shipped.get("sha256") == _sha256(data):
        return shipped["data"]
    return tomlfile.loads(data.decode("utf-8"))


@functools.cache
def _shipped_tables() -> Any:
    return json.loads(TABLES_JSON.read_bytes())


def _sha256(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


@functools.cache
def _standard_comment_units() -> dict[str, dict[str, tuple[str, str]]]:
    """type -> field -> (unit, where it is written) from `comment_units.toml`: the
    units rosidl reads from the comments of the standard interface files."""
    return {
        entry["type"]: {
            name: (unit, f"{entry['file']} comment: `{entry['comments'][name]}`")
            for name, unit in entry["units"].items()
        }
        for entry in table("comment_units")["message"]
    }


def _own_path(path: str, own: str | None) -> str:
    """A path of an annotation at the end of a field's line, where `_` is the field:
    `_` and `_.x` (of a message field) become `own` and `own.x`."""
    root, dot, rest = path.partition(".")
    return own + dot + rest if own and root == "_" else path


def _is_array(found: FieldSpec | None) -> bool:
    return found is not None and found.array


def _distinct(paths: list[Path]) -> list[Path]:
    """`paths` in order, each file once however it is spelled (a package found both
    under a msg-path and as a checked folder)."""
    seen: set[str] = set()
    out: list[Path] = []
    for path in paths:
        key = os.path.realpath(path)
        if key not in seen:
            seen.add(key)
            out.append(path)
    return out


def _without_twins(paths: list[Path]) -> list[Path]:
    """`paths` less each `.idl` that has a `.msg`/`.srv`/`.action` of its name in
    its folder (rosidl's output beside its input, as in an install space): they
    define one type, and the file the user writes is the one read."""
    given = {os.path.normcase(os.path.abspath(p)) for p in paths}

    def twin(path: Path) -> bool:
        stem = os.path.abspath(path.with_suffix(""))
        return any(
            os.path.normcase(stem + suffix) in given
            for suffix in (".msg", ".srv", ".action")
        )

    return [p for p in paths if p.suffix != ".idl" or not twin(p)]


def _overlays_last(files: list[InterfaceFile]) -> list[tuple[InterfaceFile, Section]]:
    """Every section of `files`, those with fields (definitions) first, then those
    without (overlays: `#RobotFix#` lines only, added to their type), each group in
    file order: the order in which a type's refinements are added."""
    sections = [(file, section) for file in files for section in file.sections]
    return [item for item in sections if item[1].fields] + [
        item for item in sections if not item[1].fields
    ]


def _shape(section: Section) -> tuple[Any, ...]:
    """What a definition says, without its line numbers: equal for copies."""
    fields = tuple((f.name, f.type, f.array) for f in section.fields)
    return fields, tuple(note.text for note in section.annotations)


def _type_name(file: InterfaceFile, section: str) -> str:
    """`pkg/Name` of a file from one of its sections (`pkg/Name_Request`)."""
    for suffix in ("_Request", "_Response", "_Goal", "_Result", "_Feedback"):
        if file.path.endswith((".srv", ".action")) and section.endswith(suffix):
            return section.removesuffix(suffix)
    return section


def _same_label(a: str, b: str) -> bool:
    """Two FieldUnit texts of one kind that mean the same (`m` and `meter`)."""
    from robotfix.annotations.units import resolve

    if a == b:
        return True
    return _kind(a) == "unit" and resolve(a).same_as(resolve(b))


def _kind(text: str) -> str:
    """unit, frame or tag, for the text of a FieldUnit."""
    kind, sep, _ = text.partition(":")
    return kind if sep and kind in ("frame", "tag") else "unit"


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


@cache
def _standard_defaults(store: str) -> dict[str, dict[str, Any]]:
    """type -> field -> the default a ROS 2 standard definition in `store` gives it."""
    found: dict[str, dict[str, Any]] = {}
    for entry in table("defaults")["default"]:
        if store in entry["stores"]:
            value = entry["value"]
            exact = Fraction(str(value)) if isinstance(value, float) else value
            found.setdefault(entry["type"], {})[entry["field"]] = exact
    return found


def _std_cache(distro: str) -> JsonCache:
    if distro not in _STD_CACHES:
        key = install_key("rosbags", f"msgs-v3-{distro}")
        _STD_CACHES[distro] = JsonCache(f"ros-messages-{distro}", key)
    return _STD_CACHES[distro]


def standard_format(distro: str) -> str:
    """The version of the conversion (`msgs-vN-<distro>`): the machine cache's key
    without the install of rosbags."""
    return _std_cache(distro).key.rsplit(":", 1)[-1]


@functools.cache
def _shipped_standard(distro: str) -> dict[str, Any] | None:
    """The converted definitions shipped in the package (`standard/<distro>.json`,
    written by tools/build_package_data.py), so that a first run converts nothing;
    ignored when written by another version of the conversion."""
    path = Path(__file__).with_name("standard") / f"{distro}.json"
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if not isinstance(data, dict) or data.get("format") != standard_format(distro):
        return None
    entries = data.get("entries")
    return entries if isinstance(entries, dict) else None


def _standard_definitions(distro: str) -> dict[str, Any]:
    shipped = _shipped_standard(distro)
    if shipped is not None:
        return shipped
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
    if kind in (3, 4):  # ARRAY, SEQUENCE: detail is (element, size or bound)
        element = _rosbags_field(name, detail[0])
        count = detail[1] if isinstance(detail[1], int) and detail[1] > 0 else 0
        if kind == 3:
            return [name, element[1], True, count, 0]
        return [name, element[1], True, 0, count]
    if kind == 1:  # BASE: (type, string bound)
        return [name, str(detail[0]), False]
    return [name, normalize(str(detail)), False]  # NAME


def _canonical(value: Any) -> str:
    """A text that is equal for equal definitions, in every process: dataclasses field
    by field, dicts in insertion order, sets sorted. Iterative, so deep predicates
    cannot exhaust the stack."""
    from dataclasses import fields, is_dataclass

    out: list[str] = []
    stack: list[Any] = [value]
    while stack:
        item = stack.pop()
        if isinstance(item, _Literal):
            out.append(item.text)
        elif is_dataclass(item) and not isinstance(item, type):
            stack.append(_Literal(")"))
            for f in reversed(fields(item)):
                stack.extend(
                    [_Literal(","), getattr(item, f.name), _Literal(f.name + "=")]
                )
            stack.append(_Literal(type(item).__name__ + "("))
        elif isinstance(item, dict):
            stack.append(_Literal("}"))
            for k, v in reversed(list(item.items())):
                stack.extend([_Literal(","), v, _Literal(":"), k])
            stack.append(_Literal("{"))
        elif isinstance(item, (list, tuple)):
            stack.append(_Literal("]"))
            for v in reversed(item):
                stack.extend([_Literal(","), v])
            stack.append(_Literal("["))
        elif isinstance(item, (set, frozenset)):
            out.append("{" + ",".join(sorted(_canonical(v) for v in item)) + "}")
        else:
            out.append(f"{type(item).__name__}:{item!r}")
    return "".join(out)


@dataclass(frozen=True)
class _Literal:
    """A constant's value as written."""

    text: str
