"""The editor's open documents, kept as the client edits them (incremental sync),
and the conversions between LSP positions (UTF-16 code units) and ours (characters).

Incremental sync, not Full: an editor then sends the few characters a keystroke
changed instead of the whole file, so a 5 MB document costs a splice per keystroke,
not 5 MB of JSON to read and decode. A change without a `range` replaces the whole
text (clients may send either). Lines end at `\\n`, `\\r\\n` or `\\r`, as LSP says; a
position past the end of a line means the end of that line, past the last line the
end of the text.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from urllib.parse import unquote, urlparse

_EOL = re.compile(r"\r\n|\r|\n")
_DRIVE = re.compile(r"^/[a-zA-Z]:")


@dataclass
class Document:
    """An open document: its URI, text and version."""

    uri: str  # as the client wrote it
    text: str
    version: int | None = None


class InvalidChangeError(ValueError):
    """A content change whose shape is not LSP's."""


def key(uri: str) -> str:
    """The same document however its URI is quoted."""
    return unquote(uri)


def to_path(uri: str) -> Path | None:
    """The file of a `file:` URI (None for another scheme)."""
    try:
        parsed = urlparse(uri)
    except ValueError:
        return None
    if parsed.scheme != "file":
        return None
    path = unquote(parsed.path)
    if parsed.netloc:
        return Path(f"//{unquote(parsed.netloc)}{path}")  # a UNC share
    if _DRIVE.match(path):
        return Path(path[1].lower() + path[2:])
    return Path(path)


def path_of(uri: str) -> Path:
    """The path a document is checked as (its URI when it is no file)."""
    return to_path(uri) or Path(uri)


class Documents:
    def __init__(self) -> None:
        self._open: dict[str, Document] = {}

    def open(self, uri: str, text: str, version: int | None) -> None:
        self._open[key(uri)] = Document(uri, text, version)

    def close(self, uri: str) -> None:
        self._open.pop(key(uri), None)

    def get(self, uri: str) -> Document | None:
        return self._open.get(key(uri))

    def all(self) -> list[Document]:
        return sorted(self._open.values(), key=lambda d: d.uri)

    def change(self, uri: str, version: int | None, changes: list[object]) -> None:
        document = self._open.get(key(uri))
        if document is None:
            return  # a change of a document never opened: nothing to apply it to
        text = document.text
        for change in changes:
            text = apply(text, change)
        document.text = text
        document.version = version


def apply(text: str, change: object) -> str:
    """`text` after one TextDocumentContentChangeEvent."""
    if not isinstance(change, dict) or not isinstance(change.get("text"), str):
        raise InvalidChangeError("a content change needs a text")
    new: str = change["text"]
    where = change.get("range")
    if where is None:
        return new
    first, last = _position(where, "start"), _position(where, "end")
    if last < first:
        first, last = last, first
    lines = _Lines(text)
    start_line = lines.start(first[0], 0)
    start = lines.index(start_line, first[1])
    end = lines.index(lines.start(last[0] - first[0], start_line), last[1])
    return text[:start] + new + text[end:]


def _position(where: object, name: str) -> tuple[int, int]:
    point = where.get(name) if isinstance(where, dict) else None
    if not isinstance(point, dict):
        raise InvalidChangeError(f"a range needs a {name} position")
    line, character = point.get("line"), point.get("character")
    if not isinstance(line, int) or not isinstance(character, int):
        raise InvalidChangeError("a position needs an integer line and character")
    return max(0, line), max(0, character)


def offset(text: str, position: tuple[int, int]) -> int:
    """The index in `text` of an LSP (0-based line, UTF-16 character) position."""
    lines = _Lines(text)
    return lines.index(lines.start(position[0], 0), position[1])


class _Lines:
    """Line starts and ends of a text, found by memchr (`str.find`) when it has
    no `\r`, else by a regex."""

    def __init__(self, text: str) -> None:
        self.text = text
        self.plain = "\r" not in text

    def start(self, lines: int, start: int) -> int:
        """Where the line `lines` lines after the one beginning at `start` begins;
        -1 past the last line."""
        text = self.text
        for _ in range(lines):
            if start < 0:
                return start
            if self.plain:
                found_at = text.find("\n", start)
                start = found_at + 1 if found_at >= 0 else -1
            else:
                found = _EOL.search(text, start)
                start = found.end() if found is not None else -1
        return start

    def index(self, start: int, units: int) -> int:
        """The index of UTF-16 column `units` of the line beginning at `start`
        (the end of the text for -1)."""
        text = self.text
        if start < 0:
            return len(text)
        if self.plain:
            end = text.find("\n", start)
        else:
            found = _EOL.search(text, start)
            end = found.start() if found is not None else -1
        if end < 0:
            end = len(text)
        return start + char_index(text[start:end], units)


def char_index(line: str, utf16: int) -> int:
    """The character index of a UTF-16 column of `line` (its end when past it)."""
    if line.isascii():
        return min(utf16, len(line))
    units = 0
    for index, char in enumerate(line):
        if units >= utf16:
            return index
        units += 2 if ord(char) > 0xFFFF else 1
    return len(line)


def utf16(lines: list[str], line: int, col: int) -> int:
    """LSP columns count UTF-16 code units; ours count characters."""
    if not 1 <= line <= len(lines):
        return col
    prefix = lines[line - 1][:col]
    return len(prefix.encode("utf-16-le")) // 2 + max(0, col - len(lines[line - 1]))


def char(lines: list[str], line: int, units: int) -> int:
    """Our character column of an LSP column on 1-based `line`."""
    if not 1 <= line <= len(lines):
        return units
    return char_index(lines[line - 1], units)
