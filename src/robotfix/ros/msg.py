"""Read `.msg`, `.srv`, `.action` text into `InterfaceFile`, with `#RobotFix#` lines.

Pure text processing: no ROS install, no catalog. Field types stay as written
(`Vector3`, `float64[]`); the catalog resolves them. Constants (`uint8 MODE_A=1`) and
default values (`float64 w 1`) are read into Python values here, by the rules rosidl
applies to them. Problems are returned as `Problem`s with 1-based lines and 0-based
columns, never raised.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass, replace
from fractions import Fraction
from pathlib import Path

from robotfix.annotations.ast import excerpt
from robotfix.ros.comments import CommentUnit, comment_units
from robotfix.ros.package import package_name

MARKER = re.compile(r"#\s*robotfix\s*#", re.IGNORECASE)
_HEADER_PATH = re.compile(
    r"^\s*([A-Za-z_][\w]*)/([A-Za-z_]\w*)(?:\.(?:msg|srv|action))?\s*$"
)
_HEADER_BRACKET = re.compile(r"^\s*\[\s*([A-Za-z_]\w*)/([A-Za-z_]\w*)\s*\]\s*:?\s*$")
_FIELD = re.compile(
    r"^(?P<type>[A-Za-z_][\w/]*)(?P<bound><=\d+)?(?P<array>\[(?:<=)?\d*\])?"
    r"\s+(?P<name>[A-Za-z_]\w*)\s*(?P<rest>.*)$"
)
_OPTIONAL = re.compile(r"^\s*@optional\s+(?=[A-Za-z_])")
SECTIONS = {
    ".msg": ("",),
    ".srv": ("_Request", "_Response"),
    ".action": ("_Goal", "_Result", "_Feedback"),
}


Literal = bool | int | Fraction | str


@dataclass(frozen=True)
class FieldDecl:
    """A field line of an interface file."""

    name: str
    type: str  # as written: float64, Vector3, geometry_msgs/Vector3
    array: bool
    line: int
    default: Literal | None = None  # `float64 w 1`: the value of a field never set
    size: int | None = None  # `float64[9]`: a fixed-size array
    bound: int | None = None  # `float64[<=9]`: an array of at most that many


@dataclass(frozen=True)
class ConstantDecl:
    """A constant line of an interface file."""

    name: str
    type: str  # a primitive type: uint8, float64, string, bool, ...
    value: Literal
    line: int


@dataclass(frozen=True)
class AnnotationLine:
    """A `#RobotFix#` line of an interface file."""

    text: str  # the predicate after the marker
    line: int
    col: int  # where the predicate starts on its line
    field: str | None = None  # the field `_` names, when not the one on `line`


@dataclass(frozen=True)
class Section:
    """One message: the whole `.msg`, or one part of a `.srv`/`.action`."""

    name: str  # pkg/Name, pkg/Name_Request, ...
    fields: tuple[FieldDecl, ...]
    annotations: tuple[AnnotationLine, ...]
    constants: tuple[ConstantDecl, ...] = ()
    units: tuple[CommentUnit, ...] = ()  # `[m]` in comments, by rosidl's rule


@dataclass(frozen=True)
class Problem:
    """A line of an interface file that cannot be read."""

    line: int
    col: int
    message: str


@dataclass(frozen=True)
class InterfaceFile:
    """A `.msg`, `.srv` or `.action` file, read."""

    path: str
    package: str
    sections: tuple[Section, ...]
    problems: tuple[Problem, ...]


def read_interface(path: Path, text: str) -> InterfaceFile:
    if path.suffix == ".idl":
        from robotfix.ros.idl import read_idl  # idl builds on this module

        return read_idl(path, text)
    lines = text.removeprefix("\ufeff").splitlines()
    package, name, first_body = _name_of(path, lines)
    suffixes = SECTIONS.get(path.suffix, ("",))
    problems: list[Problem] = []
    chunks: list[list[tuple[int, str]]] = [[]]
    for number, line in enumerate(lines[first_body:], start=first_body + 1):
        if line.strip() == "---" and len(chunks) < len(suffixes):
            chunks.append([])
        else:
            chunks[-1].append((number, line))
    sections = tuple(
        replace(
            _read_section(f"{package}/{name}{suffix}", _plain(chunk), problems),
            units=comment_units(chunk),
        )
        for suffix, chunk in zip(suffixes, chunks, strict=False)
    )
    return InterfaceFile(str(path), package, sections, tuple(problems))


def _plain(chunk: list[tuple[int, str]]) -> list[tuple[int, str]]:
    """The lines with what a field line may carry before its type blanked out
    (rosidl's `@optional string s`), so columns stay where they are."""
    out = []
    for number, line in chunk:
        match = _OPTIONAL.match(line)
        if match is not None:
            line = " " * match.end() + line[match.end() :]
        out.append((number, line))
    return out


def _name_of(path: Path, lines: list[str]) -> tuple[str, str, int]:
    """Package and type name from a header line (`pkg/Name.msg`, `[pkg/Name]:`),
    else from the path: the package is the `<name>` in the package.xml of the
    folder holding msg/ (or the file), else that folder's name."""
    for index, line in enumerate(lines):
        stripped = line.strip()
        if not stripped or (stripped.startswith("#") and not MARKER.match(stripped)):
            continue
        match = _HEADER_BRACKET.match(line) or _HEADER_PATH.match(line)
        if match:
            return match.group(1), match.group(2), index + 1
        break
    parent = Path(os.path.abspath(path)).parent  # `.` has no name; its folder has
    if parent.name in ("msg", "srv", "action"):
        parent = parent.parent
    return package_name(parent) or parent.name or "unknown", path.stem, 0


def _read_section(
    name: str, chunk: list[tuple[int, str]], problems: list[Problem]
) -> Section:
    fields: list[FieldDecl] = []
    notes: list[AnnotationLine] = []
    constants: list[ConstantDecl] = []
    for number, raw in chunk:
        code, annotation = _split_comment(raw)
        if annotation is not None:
            notes.append(AnnotationLine(annotation[1], number, annotation[0]))
        code = code.strip()
        if not code:
            continue
        column = len(raw) - len(raw.lstrip())
        match = _FIELD.match(code)
        if match is None:
            problems.append(Problem(number, column, _bad_line(code)))
            continue
        rest, array = match["rest"].strip(), match["array"] is not None
        if rest.startswith("="):
            value = _value(match["type"], rest[1:].strip(), code, "constant")
            if isinstance(value, Problem):
                problems.append(replace(value, line=number, col=column))
            elif value is not None and not array:
                constants.append(
                    ConstantDecl(match["name"], match["type"], value, number)
                )
            continue
        default = None
        if rest and not array:  # array defaults are not modelled (arrays are unknown)
            found = _value(match["type"], rest, code, "default")
            if isinstance(found, Problem):
                problems.append(replace(found, line=number, col=column))
            else:
                default = found
        size, bound = _array_size(match["array"])
        fields.append(
            FieldDecl(match["name"], match["type"], array, number, default, size, bound)
        )
    return Section(name, tuple(fields), tuple(notes), tuple(constants))


def _array_size(text: str | None) -> tuple[int | None, int | None]:
    """(fixed size, upper bound) of `[9]`, `[<=9]`, `[]`."""
    digits = (text or "").strip("[]<=")
    if not digits:
        return None, None
    return (None, int(digits)) if "<=" in (text or "") else (int(digits), None)


INTEGERS = frozenset(
    {"byte", "char", "int8", "uint8", "int16", "uint16", "int32", "uint32"}
    | {"int64", "uint64"}
)
FLOATS = frozenset({"float32", "float64"})
PRIMITIVES = INTEGERS | FLOATS | {"bool", "string", "wstring"}


def literal_of(type_: str, text: str) -> Literal | None:
    """The value of a constant or default written `text`, for a primitive `type_`:
    None when `type_` is not primitive or the value is not modelled (`inf`); raises
    ValueError when the text is not a value of the type. Reals are read exactly
    (`0.1` is 1/10, as in annotations)."""
    if type_ in INTEGERS:
        try:
            return int(text)
        except ValueError:
            return int(text, 0)  # 0x1F
    if type_ in FLOATS:
        try:
            return Fraction(text)
        except (ValueError, ZeroDivisionError):
            float(text)  # inf and nan are valid, but not modelled
            return None
    if type_ == "bool":
        found = {"true": True, "1": True, "false": False, "0": False}.get(text.lower())
        if found is None:
            raise ValueError(text)
        return found
    if type_ in ("string", "wstring"):
        if len(text) >= 2 and text[0] == text[-1] and text[0] in "'\"":
            return text[1:-1]
        return text  # ROS 1 writes string constants unquoted
    return None


def _value(type_: str, text: str, code: str, what: str) -> Literal | Problem | None:
    try:
        return literal_of(type_, text)
    except ValueError:
        return Problem(0, 0, f"cannot read the {what} value of `{code}` as {type_}")


def _split_comment(line: str) -> tuple[str, tuple[int, str] | None]:
    """The code part of a line, and the `#RobotFix#` predicate (column, text) if any."""
    marker = MARKER.search(line)
    hash_at = line.find("#")
    if marker is not None and marker.start() == hash_at:
        start = marker.end()
        while start < len(line) and line[start] in " \t":
            start += 1
        return line[:hash_at], (start, _until_comment(line[start:]).rstrip())
    return (line if hash_at < 0 else line[:hash_at]), None


def _until_comment(text: str) -> str:
    """A predicate ends where an ordinary `# comment` starts (outside quotes)."""
    quote = ""
    for index, char in enumerate(text):
        if quote:
            quote = "" if char == quote else quote
        elif char in "'\"":
            quote = char
        elif char == "#":
            return text[:index]
    return text


def _bad_line(code: str) -> str:
    hint = ""
    if any(op in code for op in ("<", ">", "==", " and ", " or ")):
        hint = " (a #RobotFix# annotation must fit on one line)"
    return f"cannot read `{excerpt(code)}` as a field `type name`{hint}"
