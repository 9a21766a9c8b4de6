"""Paths and texts made safe to print: every file keeps one unambiguous name, and no
output carries a lone surrogate (a non-UTF-8 file name, decoded with
surrogateescape), which strict JSON readers and UTF-8 terminals reject."""

from __future__ import annotations

_ESCAPES = {
    "\\": "\\\\",
    '"': '\\"',
    "\a": "\\a",
    "\b": "\\b",
    "\t": "\\t",
    "\n": "\\n",
    "\v": "\\v",
    "\f": "\\f",
    "\r": "\\r",
}


def shown_path(path: str) -> str:
    """The path itself when it is printable and does not start with `"`; otherwise
    double-quoted with C escapes, as git quotes paths: the bytes of a non-UTF-8 name
    in octal (`"bad\\377.py"`), other unprintable characters as `\\uXXXX`. A plain
    path never starts with `"`, so the two forms cannot be confused."""
    if path.isprintable() and not path.startswith('"'):
        return path
    out = ['"']
    for char in path:
        code = ord(char)
        if char in _ESCAPES:
            out.append(_ESCAPES[char])
        elif 0xDC80 <= code <= 0xDCFF:  # a byte that is not UTF-8 (surrogateescape)
            out.append(f"\\{code - 0xDC00:03o}")
        elif char.isprintable():
            out.append(char)
        elif code <= 0xFFFF:
            out.append(f"\\u{code:04x}")
        else:
            out.append(f"\\U{code:08x}")
    out.append('"')
    return "".join(out)


def clean_text(text: str) -> str:
    """A message without lone surrogates (each becomes the text `\\udcff`)."""
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        return text.encode("utf-8", "backslashreplace").decode("utf-8")
    return text
