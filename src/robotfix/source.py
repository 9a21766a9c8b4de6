"""SourceFile: one Python file's text, its AST, columns in characters, suppressions.

Reading and parsing never raise for a fault in the user's file: an unreadable file is
RF003, a Python 2 file RF002, any other syntax error RF001, a text too long to
parse (`budget.MAX_PARSED_CHARS`) RF902.
"""

from __future__ import annotations

import ast
import codecs
import io
import os
import re
import sys
import tokenize
import warnings
from dataclasses import dataclass, field

from robotfix import messages, rules
from robotfix.budget import MAX_PARSED_CHARS
from robotfix.diagnostics import Diagnostic, Edit, Span
from robotfix.fs import UnreadableError, read_regular
from robotfix.lazyre import lazy


def _code_chars(lines: list[str]) -> int:
    """Characters outside comment lines: what the parser's memory follows (a comment
    makes no node; a 5 MB licence or data comment parses in a few MB)."""
    return sum(len(line) for line in lines if not line.lstrip().startswith("#"))


_SUPPRESS = lazy(r"#\s*robotfix:\s*ignore(?:\[(?P<codes>[^\]]*)\])?", re.IGNORECASE)


def suppresses(line: str, diag: Diagnostic) -> bool:
    """Whether a `# robotfix: ignore[...]` comment on `line` silences `diag` (for
    a file RobotFix reads by lines: parameter, launch, C++ files)."""
    match = _SUPPRESS.search(line)
    if match is None:
        return False
    codes = match["codes"]
    listed = {c.strip() for c in codes.split(",")} if codes is not None else None
    return listed is None or bool({diag.code, diag.rule.name} & listed)


# CPython's own words for Python 2 constructs (print and exec statements, `except
# X, e`, `0777`, backticks, `<>`, `ur''`).
_PY2_HINTS = (
    "Missing parentheses in call to",  # print x, exec "code"
    "multiple exception types must be parenthesized",  # except X, e:
    "leading zeros in decimal integer literals",  # 0777
    "invalid syntax. Perhaps you forgot a comma?",
    "parameters cannot be parenthesized",  # def f(a, (x, y)), lambda (x, y): x
)
# Python 2 forms on the failing line that CPython reports only as "invalid syntax":
# print/exec statements, `raise E, "why"`, backticks, `<>`, ur'' strings, 10L.
# PEP 695 (Python 3.12, ROS 2 Jazzy's Python): `type X = ...`, `def f[T](...)`,
# `class C[T]:`; an older parser stops at them.
_PY312_FORMS = lazy(
    r"\s*(type\s+[A-Za-z_]\w*\s*(\[.*\])?\s*="
    r"|(async\s+)?def\s+[A-Za-z_]\w*\s*\[|class\s+[A-Za-z_]\w*\s*\[)"
)
_PY2_TOKENS = lazy(
    r"^\s*(print\s+[\"'\w]|exec\s+[\"']|raise\s+[\w.]+\s*,)|`|<>"
    r"|\b[uU][rR][\"']|\b\d+[lL]\b",
    re.M,
)
# Python 3.10 says only "invalid syntax" at the `(` of a tuple parameter
# (`def f(a, (x, y))`, `lambda (k, v): v`); 3.11 and later name it (_PY2_HINTS).
_BEFORE_TUPLE_PARAMETER = lazy(
    r"(\bdef\s+\w+\s*\((?:[^()=]*,)?|\blambda(?:[^():=]*,)?)\s*$"
)


@dataclass
class SourceFile:
    """A Python file's path and text, and its syntax tree once parsed."""

    path: str
    text: str
    tree: ast.Module | None = None
    problem: Diagnostic | None = None
    lines: list[str] = field(default_factory=list)
    # line -> (column of the comment, the codes or names listed; None for a bare ignore)
    suppressions: dict[int, tuple[int, frozenset[str] | None]] = field(
        default_factory=dict
    )

    @staticmethod
    def from_bytes(path: str, data: bytes) -> SourceFile:
        try:
            text = _decode(data)
        except (SyntaxError, UnicodeDecodeError, LookupError) as err:
            return SourceFile(
                path, "", problem=messages.unreadable(path, f"cannot decode: {err}")
            )
        return SourceFile.from_text(path, text)

    @staticmethod
    def from_text(path: str, text: str) -> SourceFile:
        source = SourceFile(path, text, lines=split_lines(text))
        if len(text) > MAX_PARSED_CHARS and (code := _code_chars(source.lines)) > (
            MAX_PARSED_CHARS
        ):
            source.problem = messages.analysis_budget(
                path,
                1,
                f"{code:,} characters of code, over the {MAX_PARSED_CHARS:,} "
                "RobotFix parses",
            )
            return source
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # SyntaxWarning in user code is theirs
                source.tree = ast.parse(text, filename=path)
        except (SyntaxError, ValueError) as err:
            source.problem = _syntax_problem(path, text, err)
            return source
        except (RecursionError, MemoryError):
            # CPython 3.11 reports "parser stack overflow" as a MemoryError
            source.problem = messages.syntax_error(
                path,
                Span.point(1),
                "nesting too deep for Python's parser",
                rules.PYTHON_SYNTAX_ERROR,
            )
            return source
        source.suppressions = _suppressions(text)
        return source

    def char_col(self, line: int, byte_col: int) -> int:
        """ast gives UTF-8 byte offsets; diagnostics use characters."""
        if 1 <= line <= len(self.lines):
            text = self.lines[line - 1]
            if text.isascii():
                return byte_col
            return len(
                text.encode("utf-8")[:byte_col].decode("utf-8", errors="replace")
            )
        return byte_col

    def span(self, node: ast.AST) -> Span:
        line = getattr(node, "lineno", 1)
        col = self.char_col(line, getattr(node, "col_offset", 0))
        end_line = getattr(node, "end_lineno", None) or line
        end_col = getattr(node, "end_col_offset", None)
        end = self.char_col(end_line, end_col) if end_col is not None else col + 1
        return Span(line, col, end_line, end)

    def segment(self, node: ast.AST) -> str | None:
        """The source text of a node (as ast.get_source_segment, without re-splitting
        the whole file on every call)."""
        line, end_line = (
            getattr(node, "lineno", None),
            getattr(node, "end_lineno", None),
        )
        col, end_col = (
            getattr(node, "col_offset", None),
            getattr(node, "end_col_offset", None),
        )
        if line is None or end_line is None or col is None or end_col is None:
            return None
        if not 1 <= line <= end_line <= len(self.lines):
            return None
        if line == end_line:
            return _byte_slice(self.lines[line - 1], col, end_col)
        first = _byte_slice(self.lines[line - 1], col, None)
        last = _byte_slice(self.lines[end_line - 1], 0, end_col)
        return "\n".join([first, *self.lines[line : end_line - 1], last])

    def statement_text(self, node: ast.AST) -> str:
        """A statement's source on one line, for messages (a compound statement's
        first line); an annotated assignment is shown without its annotation
        (`x = 200`)."""
        if isinstance(node, ast.AnnAssign) and node.value is not None:
            target, value = self.segment(node.target), self.segment(node.value)
            text = f"{target} = {value}" if target and value else ""
        else:
            text = self.segment(node) or ""
        if isinstance(node, ast.stmt) and hasattr(node, "body"):
            one = text.splitlines()[0] if text else ""  # `if x:`, not its body
        else:
            one = _one_line(text)
        return one if len(one) <= 80 else one[:77] + "..."

    def is_suppressed(self, diag: Diagnostic) -> bool:
        if diag.span.line not in self.suppressions:
            return False
        codes = self.suppressions[diag.span.line][1]
        return codes is None or diag.code in codes or diag.rule.name in codes


LINE_BREAK = lazy(r"\r\n|\r|\n")  # the line breaks ast counts
_OPENED = lazy(r"([(\[{]) ")
_CLOSED = lazy(r",? ([)\]}])")


def _one_line(text: str) -> str:
    """A statement written over several lines, on one (`f(\n  x,\n)` is
    `f(x)`), so a message shows all of it and not `f(`."""
    lines = text.splitlines()
    if len(lines) <= 1:
        return lines[0].strip() if lines else ""
    try:  # comments inside the statement are left out
        for tok in tokenize.generate_tokens(io.StringIO(text).readline):
            if tok.type == tokenize.COMMENT:
                row, col = tok.start
                lines[row - 1] = lines[row - 1][:col]
    except (tokenize.TokenError, SyntaxError):
        pass
    lines = [line.strip().removesuffix("\\").rstrip() for line in lines]
    joined = " ".join(line for line in lines if line)
    return _CLOSED.sub(r"\1", _OPENED.sub(r"\1", joined))


def suppression(line_text: str, line: int, code: str) -> Edit:
    """The edit that silences `code` on a line: the code added to the line's
    `# robotfix: ignore[...]`, else that comment put at the line's end."""
    match = _SUPPRESS.search(line_text)
    if match is not None and match["codes"] is not None:
        at = match.end("codes")
        listed = match["codes"].strip()
        return Edit(Span(line, at, line, at), f", {code}" if listed else code)
    end = len(line_text.rstrip())
    return Edit(Span(line, end, line, len(line_text)), f"  # robotfix: ignore[{code}]")


def split_lines(text: str) -> list[str]:
    """The lines as `ast` numbers them: a form feed or U+2028 is not a line break.
    A text without `\r` is split at each `\n` by `str.split`, five times faster
    than the pattern (every parsed file's lines are split)."""
    return LINE_BREAK.split(text) if "\r" in text else text.split("\n")


def decode(data: bytes) -> str:
    """A Python file's text as Python reads it (PEP 263 cookie, BOM); raises
    SyntaxError, UnicodeDecodeError or LookupError when it cannot be decoded."""
    return _decode(data)


def _byte_slice(line: str, start: int, end: int | None) -> str:
    if line.isascii():
        return line[start:end]
    return line.encode("utf-8")[start:end].decode("utf-8", errors="replace")


def _decode(data: bytes) -> str:
    # PEP 263: only a coding cookie on one of the first two lines, or a BOM, makes
    # a file anything but UTF-8; without either, tokenize's answer is UTF-8 and the
    # text is `data.decode()` (its Python code was 25 k instructions a file). A
    # text that does not decode is left to it, for the same error.
    if not data.startswith(codecs.BOM_UTF8) and b"coding" not in _two_lines(data):
        try:
            return data.decode("utf-8")
        except UnicodeDecodeError:
            pass
    encoding, _ = tokenize.detect_encoding(io.BytesIO(data).readline)
    text = data.decode(encoding)
    return text[1:] if text.startswith("\ufeff") else text


def _two_lines(data: bytes) -> bytes:
    """The first two lines, as `tokenize.detect_encoding` reads them (split at
    each `\\n` alone), or the whole of a shorter text."""
    end = data.find(b"\n")
    if end >= 0:
        end = data.find(b"\n", end + 1)
    return data if end < 0 else data[:end]


def _syntax_problem(path: str, text: str, err: SyntaxError | ValueError) -> Diagnostic:
    if isinstance(err, ValueError):  # e.g. NUL bytes
        return messages.syntax_error(
            path, Span.point(1), str(err), rules.PYTHON_SYNTAX_ERROR
        )
    line = err.lineno or 1
    col = max((err.offset or 1) - 1, 0)
    lines = split_lines(text)
    failing = lines[line - 1] if 0 < line <= len(lines) else ""
    if sys.version_info < (3, 12) and _PY312_FORMS.match(failing):
        return messages.syntax_error(
            path, Span.point(line, col), "3.12", rules.NEWER_PYTHON_SOURCE
        )
    rule = rules.PYTHON2_SOURCE if _is_python2(text, err) else rules.PYTHON_SYNTAX_ERROR
    return messages.syntax_error(path, Span.point(line, col), err.msg, rule)


def _is_python2(text: str, err: SyntaxError, retabbed: bool = False) -> bool:
    """Whether the syntax error is Python 2 that CPython 3 rejects. Only the failing
    line is looked at (backticks in a docstring elsewhere say nothing). Python 2 read a
    tab as the next multiple of 8 columns: a TabError of a file that parses, or fails
    for a Python 2 reason, once its indentation tabs are expanded is Python 2."""
    if any(hint in err.msg for hint in _PY2_HINTS):
        return True
    lines = split_lines(text)
    line = err.lineno or 1
    if 0 < line <= len(lines) and _PY2_TOKENS.search(lines[line - 1]):
        return True
    if 0 < line <= len(lines) and _tuple_parameter(lines[line - 1], err.offset):
        return True
    if not isinstance(err, TabError) or retabbed:
        return False
    expanded = "\n".join(_expand_indent(text_line) for text_line in lines)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            ast.parse(expanded)
    except SyntaxError as again:
        return _is_python2(expanded, again, retabbed=True)
    except (ValueError, RecursionError, MemoryError):
        return False
    return True


def _tuple_parameter(line: str, offset: int | None) -> bool:
    """Whether the error is at the `(` that opens a tuple parameter."""
    at = (offset or 0) - 1
    return (
        0 <= at < len(line)
        and line[at] == "("
        and _BEFORE_TUPLE_PARAMETER.search(line[:at]) is not None
    )


def _expand_indent(line: str) -> str:
    body = line.lstrip(" \t")
    return line[: len(line) - len(body)].expandtabs(8) + body


def _suppressions(text: str) -> dict[int, tuple[int, frozenset[str] | None]]:
    found: dict[int, tuple[int, frozenset[str] | None]] = {}
    if "robotfix" not in text.lower():
        return found
    try:
        for tok in tokenize.generate_tokens(io.StringIO(text).readline):
            if tok.type == tokenize.COMMENT:
                match = _SUPPRESS.search(tok.string)
                if match:
                    codes = match["codes"]
                    listed = (
                        None
                        if codes is None
                        else frozenset(c.strip() for c in codes.split(",") if c.strip())
                    )
                    found[tok.start[0]] = (tok.start[1] + match.start(), listed)
    except (tokenize.TokenError, SyntaxError):
        pass
    return found


def read_mentioning(
    path: str | os.PathLike[str], words: tuple[bytes, ...]
) -> SourceFile | None:
    """A Python file parsed when its bytes name one of `words` (a quick filter
    before the parse: the parameter check's declaring files, the graph's endpoint
    files); None when it names none, cannot be read, or does not parse."""
    try:
        data = read_regular(path)
    except UnreadableError:
        return None
    if not any(word in data for word in words):
        return None
    source = SourceFile.from_bytes(os.fspath(path), data)
    return source if source.tree is not None else None
