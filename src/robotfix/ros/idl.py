"""Read `.idl` interface files (the OMG IDL subset rosidl emits) into `InterfaceFile`.

Understood: `#include` and other preprocessor lines (skipped), `//` and `/* */`
comments, nested `module`s, `struct`s with members (`double x;`, `double m[9];`,
`sequence<T>`, `sequence<T, N>`, `string<N>`, `pkg::msg::Type`), `typedef`s of
arrays and sequences, `const` declarations (in a `*_Constants` module, as rosidl
writes them: read and skipped, constants are the catalog's to give), and the
annotations rosidl and users write on members:

- `@unit (value="m")` -> the member's unit (`Section.units`, `strict`: a unit string
  that is a typo of a unit is RF502; a word that is no unit at all, which rosidl
  copies from a `[enum]` comment, is ignored);
- `@range (min=0, max=1)`, `@min (0)`, `@max (value=1)` -> refinements of the member;
- `@default (value=...)` -> the field's default, read as a `.msg` default is;
- `@verbatim (language="comment", text="RobotFix# ...")` -> a `#RobotFix#` line of the
  member it stands before (or of the struct);
- any other annotation (`@key`, `@optional`, `@deprecated`, ...) is accepted and
  ignored.

Each struct is a section named `pkg/Name` after its outermost module. Member types
are given in `.msg` spelling (`float64`, `pkg/Type`), so the catalog resolves them as
it does for `.msg` files. Problems are `Problem`s at the line and column where the
text stops making sense; the rest of the file is not read then.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace
from pathlib import Path

from robotfix.annotations.ast import excerpt
from robotfix.ros.comments import CommentUnit
from robotfix.ros.msg import (
    AnnotationLine,
    FieldDecl,
    InterfaceFile,
    Problem,
    Section,
    literal_of,
)

MARKER = re.compile(r"^\s*robotfix\s*#", re.IGNORECASE)
_TOKEN = re.compile(
    r"""(?P<space>[ \t\r\f\v]+|\n)
    |(?P<comment>//[^\n]*|/\*.*?\*/)
    |(?P<string>L?"(?:[^"\\\n]|\\.)*")
    |(?P<char>L?'(?:[^'\\\n]|\\.)+')
    |(?P<number>0[xX][0-9A-Fa-f]+
      |(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][-+]?[0-9]+)?[dD]?)
    |(?P<name>[A-Za-z_][A-Za-z0-9_]*)
    |(?P<scope>::)
    |(?P<punct>[{}()<>\[\];,=@\-+])
    """,
    re.VERBOSE | re.DOTALL,
)
PRIMITIVES = {
    "boolean": "bool",
    "octet": "byte",
    "char": "char",
    "wchar": "char",
    "float": "float32",
    "double": "float64",
    "short": "int16",
    "long": "int32",
    "int8": "int8",
    "uint8": "uint8",
    "int16": "int16",
    "uint16": "uint16",
    "int32": "int32",
    "uint32": "uint32",
    "int64": "int64",
    "uint64": "uint64",
    "string": "string",
    "wstring": "wstring",
}
MAX_TOKENS = 200_000  # a real .idl has a few hundred


@dataclass(frozen=True)
class Token:
    """A token of an `.idl` file."""

    kind: str  # string, number, name, scope, punct, end
    text: str
    line: int
    col: int


@dataclass(frozen=True)
class _Type:
    """A member's type, spelt as in a `.msg` file."""

    name: str  # .msg spelling: float64, pkg/Type
    array: bool


@dataclass
class _Annotation:
    """An `@annotation(...)` of an `.idl` member or struct."""

    name: str
    args: dict[str, Token | str]  # keyword -> value; a lone value is "value"
    token: Token


@dataclass
class _Struct:
    """An `.idl` struct, read into a section's parts."""

    name: str
    fields: list[FieldDecl] = field(default_factory=list)
    notes: list[AnnotationLine] = field(default_factory=list)
    units: list[CommentUnit] = field(default_factory=list)
    defaults: list[tuple[str, str]] = field(default_factory=list)


class IdlError(Exception):
    def __init__(self, token: Token, message: str) -> None:
        super().__init__(message)
        self.token = token
        self.message = message


def read_idl(path: Path, text: str) -> InterfaceFile:
    """The structs of an `.idl` file, as sections; never raises."""
    reader = _Reader(path, text.removeprefix("\ufeff"))
    problems: list[Problem] = []
    try:
        reader.specification()
    except IdlError as err:
        problems.append(Problem(err.token.line, err.token.col, err.message))
    sections = tuple(
        Section(
            s.name,
            _with_defaults(s, problems),
            tuple(s.notes),
            units=tuple(s.units),
        )
        for s in reader.structs
    )
    package = reader.package or _package_of(path)
    return InterfaceFile(str(path), package, sections, tuple(problems))


def _package_of(path: Path) -> str:
    parent = path.resolve().parent
    if parent.name in ("msg", "srv", "action"):
        parent = parent.parent
    return parent.name or "unknown"


def tokens(text: str) -> list[Token]:
    """The tokens of `text`, preprocessor lines and comments left out."""
    out: list[Token] = []
    line, start, pos = 1, 0, 0
    at_line_start = True
    while pos < len(text):
        if at_line_start and text[pos] == "#":
            end = text.find("\n", pos)
            pos = len(text) if end < 0 else end
            continue
        match = _TOKEN.match(text, pos)
        if match is None:
            raise IdlError(
                Token("end", text[pos], line, pos - start),
                f"cannot read `{excerpt(text[pos : pos + 20])}` in an IDL file",
            )
        kind = match.lastgroup or ""
        value = match.group()
        if kind not in ("space", "comment"):
            out.append(Token(kind, value, line, pos - start))
            at_line_start = False
            if len(out) > MAX_TOKENS:
                raise IdlError(out[-1], "the IDL file is too large to read")
        newlines = value.count("\n")
        if newlines:
            line += newlines
            start = pos + value.rindex("\n") + 1
            at_line_start = True
        pos = match.end()
    out.append(Token("end", "", line, pos - start))
    return out


class _Reader:
    def __init__(self, path: Path, text: str) -> None:
        self.path = path
        self.text = text
        self.toks: list[Token] = []
        self.index = 0
        self.modules: list[str] = []
        self.package: str | None = None
        self.typedefs: dict[str, tuple[_Type, int | None]] = {}
        self.structs: list[_Struct] = []

    # -- tokens --------------------------------------------------------------
    @property
    def tok(self) -> Token:
        return self.toks[self.index]

    def take(self) -> Token:
        token = self.toks[self.index]
        if token.kind != "end":
            self.index += 1
        return token

    def at(self, text: str) -> bool:
        return self.tok.kind in ("punct", "name", "scope") and self.tok.text == text

    def expect(self, text: str) -> Token:
        if not self.at(text):
            raise IdlError(self.tok, f"expected `{text}`, found {_shown(self.tok)}")
        return self.take()

    def name(self) -> Token:
        if self.tok.kind != "name":
            raise IdlError(self.tok, f"expected a name, found {_shown(self.tok)}")
        return self.take()

    # -- declarations ----------------------------------------------------------
    def specification(self) -> None:
        self.toks = tokens(self.text)
        while self.tok.kind != "end":
            self.definition()

    def definition(self) -> None:
        notes = self.annotations()
        token = self.tok
        if self.at("module"):
            self.module()
        elif self.at("struct"):
            self.struct(notes)
        elif self.at("typedef"):
            self.typedef()
        elif self.at("const"):
            self.const()
        elif self.at(";"):
            self.take()
            return
        else:
            what = "is not read by RobotFix" if token.kind == "name" else "unexpected"
            raise IdlError(token, f"{_shown(token)} {what} in an IDL file")
        if self.at(";"):
            self.take()

    def module(self) -> None:
        self.expect("module")
        name = self.name().text
        if not self.modules and self.package is None:
            self.package = name
        self.modules.append(name)
        self.expect("{")
        while not self.at("}"):
            if self.tok.kind == "end":
                raise IdlError(self.tok, f"module `{name}` is not closed")
            self.definition()
        self.expect("}")
        self.modules.pop()

    def struct(self, notes: list[_Annotation]) -> None:
        self.expect("struct")
        name = self.name()
        package = self.modules[0] if self.modules else _package_of(self.path)
        struct = _Struct(f"{package}/{name.text}")
        for note in notes:
            self.verbatim(struct, note, None)
        if self.at(";"):  # a forward declaration
            return
        self.expect("{")
        while not self.at("}"):
            if self.tok.kind == "end":
                raise IdlError(
                    self.tok, f"struct `{name.text}` is not closed with `}}`"
                )
            self.member(struct)
        self.expect("}")
        self.structs.append(struct)

    def member(self, struct: _Struct) -> None:
        notes = self.annotations()
        type_ = self.type_spec()
        while True:
            name = self.name()
            array = type_.array or self.array_sizes() is not None
            struct.fields.append(FieldDecl(name.text, type_.name, array, name.line))
            for note in notes:
                self.member_note(struct, note, name.text)
            if not self.at(","):
                break
            self.take()
        self.expect(";")

    def typedef(self) -> None:
        self.expect("typedef")
        type_ = self.type_spec()
        name = self.name()
        size = self.array_sizes()
        array = type_.array or size is not None
        self.typedefs[name.text] = (_Type(type_.name, array), size)
        self.expect(";")

    def const(self) -> None:
        self.expect("const")
        self.type_spec()
        self.name()
        self.expect("=")
        self.expression()
        self.expect(";")

    # -- types -------------------------------------------------------------------
    def type_spec(self) -> _Type:
        token = self.tok
        if self.at("sequence"):
            self.take()
            self.expect("<")
            element = self.type_spec()
            if self.at(","):
                self.take()
                self.expression()
            self.expect(">")
            return _Type(element.name, True)
        if self.at("unsigned"):
            self.take()
            base = self.integer_words()
            return _Type("u" + base, False)
        if self.at("long") or self.at("short"):
            return _Type(self.integer_words(), False)
        scoped = self.scoped_name()
        if scoped in ("string", "wstring") and self.at("<"):
            self.take()
            self.expression()
            self.expect(">")
        if scoped in PRIMITIVES:
            return _Type(PRIMITIVES[scoped], False)
        if scoped in self.typedefs:
            return self.typedefs[scoped][0]
        parts = scoped.split("::")
        if len(parts) == 1:
            return _Type(parts[0], False)
        if len(parts) == 3 and parts[1] in ("msg", "srv", "action"):
            return _Type(f"{parts[0]}/{parts[2]}", False)
        if len(parts) == 2:
            return _Type(f"{parts[0]}/{parts[1]}", False)
        raise IdlError(token, f"cannot read the type `{scoped}`")

    def integer_words(self) -> str:
        if self.at("short"):
            self.take()
            return "int16"
        self.expect("long")
        if self.at("long"):
            self.take()
            return "int64"
        if self.at("double"):
            self.take()
            return "float64"
        return "int32"

    def scoped_name(self) -> str:
        parts = []
        if self.at("::"):
            self.take()
        parts.append(self.name().text)
        while self.at("::"):
            self.take()
            parts.append(self.name().text)
        return "::".join(parts)

    def array_sizes(self) -> int | None:
        size = None
        while self.at("["):
            self.take()
            token = self.expression()
            size = (
                int(token.text)
                if token.kind == "number" and token.text.isdigit()
                else 0
            )
            self.expect("]")
        return size

    # -- values and annotations --------------------------------------------------
    def expression(self) -> Token:
        """A constant value: a number (signed), a string (adjacent ones joined), a
        name (`TRUE`); simple arithmetic of those is accepted, its value not kept."""
        first = self.term()
        while self.tok.kind == "punct" and self.tok.text in "+-":
            self.take()
            first = Token("expr", "", first.line, first.col)
            self.term()
        return first

    def term(self) -> Token:
        token = self.tok
        if self.at("-") or self.at("+"):
            sign = self.take().text
            number = self.term()
            text = number.text if sign == "+" else "-" + number.text
            return Token(number.kind, text, token.line, token.col)
        if self.at("("):
            self.take()
            inner = self.expression()
            self.expect(")")
            return inner
        if token.kind == "string":
            parts = []
            while self.tok.kind == "string":
                parts.append(_unquote(self.take().text))
            return Token("string", "".join(parts), token.line, token.col)
        if token.kind in ("number", "char"):
            return self.take()
        if token.kind == "name":
            return Token("name", self.scoped_name(), token.line, token.col)
        raise IdlError(token, f"expected a value, found {_shown(token)}")

    def annotations(self) -> list[_Annotation]:
        found = []
        while self.at("@"):
            at = self.take()
            name = self.scoped_name()
            args: dict[str, Token | str] = {}
            if self.at("("):
                self.take()
                while not self.at(")"):
                    key = "value"
                    if (
                        self.tok.kind == "name"
                        and self.toks[self.index + 1].text == "="
                    ):
                        key = self.take().text
                        self.take()
                    args[key] = self.expression()
                    if not self.at(","):
                        break
                    self.take()
                self.expect(")")
            found.append(_Annotation(name, args, at))
        return found

    def member_note(self, struct: _Struct, note: _Annotation, name: str) -> None:
        value = note.args.get("value")
        at = note.token
        if note.name == "unit" and isinstance(value, Token) and value.kind == "string":
            struct.units.append(
                CommentUnit(name, value.text.strip(), at.line, at.col, strict=True)
            )
        elif note.name in ("range", "min", "max"):
            bounds = {
                ">=": note.args.get("min", value if note.name == "min" else None),
                "<=": note.args.get("max", value if note.name == "max" else None),
            }
            parts = [
                f"{name} {op} {_number(bound.text)}"
                for op, bound in bounds.items()
                if isinstance(bound, Token) and bound.kind == "number"
            ]
            if parts:
                struct.notes.append(
                    AnnotationLine(" and ".join(parts), at.line, at.col, field=name)
                )
        elif note.name == "default" and isinstance(value, Token):
            struct.defaults.append((name, _default_text(value)))
        else:
            self.verbatim(struct, note, name)

    def verbatim(self, struct: _Struct, note: _Annotation, name: str | None) -> None:
        """A `@verbatim` comment whose text (any line of it) starts `RobotFix#`."""
        text = note.args.get("text")
        if note.name != "verbatim" or not isinstance(text, Token):
            return
        for line in text.text.split("\n"):
            marker = MARKER.match(line)
            if marker is not None:
                predicate = line[marker.end() :].strip()
                col = text.col if text.line != note.token.line else note.token.col
                struct.notes.append(
                    AnnotationLine(predicate, text.line, col, field=name)
                )


def _default_text(token: Token) -> str:
    """A default in `.msg` spelling: `TRUE` -> true, a string quoted, an array
    (rosidl writes `"(1, 2)"`) in brackets."""
    if token.kind == "name":
        return token.text.lower()
    if token.kind == "string":
        text = token.text
        if text.startswith("(") and text.endswith(")"):
            return "[" + text[1:-1].rstrip(", ") + "]"
        return '"' + text.replace('"', '\\"') + '"'
    return _number(token.text) if token.kind == "number" else token.text


def _number(text: str) -> str:
    """An IDL number as Python writes it: `1.` -> 1.0, `.5d` -> 0.5, `0x1F` -> 31."""
    sign, digits = ("-", text[1:]) if text.startswith("-") else ("", text)
    if digits[:2] in ("0x", "0X"):
        return sign + str(int(digits, 16))
    digits = digits.rstrip("dD")
    if digits.startswith("."):
        digits = "0" + digits
    if digits.endswith("."):
        digits += "0"
    return sign + digits.replace(".e", ".0e").replace(".E", ".0E")


def _unquote(text: str) -> str:
    body = text[2:-1] if text.startswith("L") else text[1:-1]
    return re.sub(r"\\(.)", lambda m: {"n": "\n", "t": "\t"}.get(m[1], m[1]), body)


def _shown(token: Token) -> str:
    return "the end of the file" if token.kind == "end" else f"`{excerpt(token.text)}`"


def _with_defaults(struct: _Struct, problems: list[Problem]) -> tuple[FieldDecl, ...]:
    """The struct's fields with their `@default` values, read as a `.msg` default is
    (a value that does not fit the field's type is RF506 at the field)."""
    given = dict(struct.defaults)
    fields = []
    for decl in struct.fields:
        text = given.get(decl.name)
        if text is not None and not decl.array:
            try:
                decl = replace(decl, default=literal_of(decl.type, text))
            except ValueError:
                problems.append(
                    Problem(decl.line, 0, f"`{text}` is not a {decl.type} default")
                )
        fields.append(decl)
    return tuple(fields)
