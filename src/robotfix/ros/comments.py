"""Units written in interface file comments, by rosidl's rule.

rosidl (`rosidl_adapter`, which turns `.msg` files into `.idl`) gives every field and
constant the comment lines that belong to it, and emits `@unit` for the field when
those lines, joined, hold exactly one `[...]` with no comma and no `]` inside
(`float32 range_min  # minimum range value [m]`). Which comment lines belong to a
field or constant:

- the leading lines of a message (each `.srv`/`.action` part on its own) that start
  with `#` in the first column describe the message, not a field; a blank line ends
  them;
- any other comment line that starts in the first column waits for the next field or
  constant (blank lines in between do not matter), and that element's own trailing
  comment comes after them;
- an indented comment line (only blanks before its `#`) belongs to the field or
  constant above it, and to nothing before the first one;
- comment lines after the last element belong to nothing.

A comment is what follows the first `#` of a line (quotes are not special), without
its leading `#`s; tabs count as spaces. Pure text processing: whether the text
between the brackets is a unit is for the catalog to decide (pint).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

_UNIT = re.compile(r"\s*\[([^,\]]+)\]")


@dataclass(frozen=True)
class CommentUnit:
    """A unit written in a field's comment (`# range [m]`)."""

    field: str
    text: str  # between the brackets, stripped
    line: int  # the line holding the brackets
    col: int = 0
    strict: bool = False  # written as a unit (IDL `@unit`): a typo is reported


@dataclass
class _Element:
    """A line of an interface file with the comments that belong to it."""

    name: str | None  # None for a constant or a line that is not a field
    comments: list[tuple[int, str]]


def comment_units(lines: Sequence[tuple[int, str]]) -> tuple[CommentUnit, ...]:
    """The unit of each field of one message, from its numbered lines."""
    found = []
    for element in _elements(lines):
        if element.name is None:
            continue
        unit = unit_in(element.comments)
        if unit is not None:
            found.append(CommentUnit(element.name, unit[1], unit[0]))
    return tuple(found)


def unit_in(comments: Sequence[tuple[int, str]]) -> tuple[int, str] | None:
    """(line, unit) when the comment lines hold exactly one `[unit]`."""
    joined = "\n".join(text for _, text in comments)
    matches = list(_UNIT.finditer(joined))
    if len(matches) != 1:
        return None
    before = joined[: matches[0].start(1)].count("\n")
    text = matches[0].group(1).strip()
    return (comments[before][0], text) if text else None


def _elements(lines: Sequence[tuple[int, str]]) -> list[_Element]:
    elements: list[_Element] = []
    waiting: list[tuple[int, str]] = []
    body = list(lines)
    while body and body[0][1].replace("\t", " ").startswith("#"):
        body.pop(0)  # the message's own comment
    for number, raw in body:
        line = raw.replace("\t", " ").rstrip()
        if not line:
            continue
        code, hash_, comment = line.partition("#")
        comment = comment.lstrip("#") if hash_ else ""
        if hash_ and code and not code.strip():  # indented: the element above
            if elements:
                elements[-1].comments.append((number, comment))
            continue
        if hash_:
            waiting.append((number, comment))
        if not code.strip():
            continue
        elements.append(_Element(_field_name(code), waiting))
        waiting = []
    return elements


def _field_name(code: str) -> str | None:
    """The name a field line declares; None for a constant or anything else."""
    parts = code.split()
    if code.lstrip().startswith("@optional"):
        parts = parts[1:]
    if len(parts) < 2 or "=" in code.partition(parts[0])[2]:
        return None
    return parts[1]
