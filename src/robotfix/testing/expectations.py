"""Read `# error: RF201 "text"` assertions out of a test case's comments.

A trailing assertion targets its own line; assertions on lines of their own stack up
and target the next line of code. Matching is strict: every diagnostic must be
expected and every expectation met. Comments are read with `tokenize`, so an
assertion inside a string never counts. So that no expectation vanishes unnoticed,
reading raises ValueError for a comment that looks like an assertion but is not
written as one (`# Error: RF101`, `# error RF101`, `# error: rf101`) and for
assertions after the last line of code, which target nothing.
"""

from __future__ import annotations

import io
import re
import tokenize
from dataclasses import dataclass, replace
from pathlib import Path

from robotfix.diagnostics import Diagnostic

_PREFIX = re.compile(r"#\s*(error|warning|note)\s*:")
# any spelling of an assertion: a kind (any case, plural, no colon) and a code
_NEAR = re.compile(r"#\s*(error|warning|note)s?\b\W*RF\s*\d", re.IGNORECASE)
_ASSERTION = re.compile(
    r'#\s*(?P<kind>error|warning|note):\s*(?P<code>RF\d{3})(?:\s+"(?P<text>[^"]*)")?\s*'
)
_SKIP = (
    tokenize.NL,
    tokenize.NEWLINE,
    tokenize.COMMENT,
    tokenize.INDENT,
    tokenize.DEDENT,
    tokenize.ENDMARKER,
)


@dataclass(frozen=True)
class Expectation:
    """An expected diagnostic written in a test file."""

    line: int
    kind: str
    code: str
    text: str | None = None

    def matches(self, diag: Diagnostic) -> bool:
        return (
            diag.span.line == self.line
            and diag.severity.value == self.kind
            and diag.code == self.code
            and (self.text is None or self.text in diag.message)
        )


def assertion(comment: str, line: int) -> Expectation | None:
    """The expectation `comment` (from `#` on) states about `line`; None when it is
    not an assertion. ValueError when it looks like one but is not written as one."""
    if not (_PREFIX.match(comment) or _NEAR.match(comment)):
        return None
    match = _ASSERTION.fullmatch(comment.rstrip())
    if match is None:
        raise ValueError(
            f"line {line}: malformed assertion {comment!r} (written "
            '`# error: RF101` or `# warning: RF201 "part of the message"`)'
        )
    return Expectation(line, match["kind"], match["code"], match["text"])


def read_expectations(source: str) -> list[Expectation]:
    expectations: list[Expectation] = []
    pending: list[Expectation] = []
    for tok in tokenize.generate_tokens(io.StringIO(source).readline):
        if tok.type == tokenize.COMMENT:
            found = assertion(tok.string, tok.start[0])
            if found is not None and tok.line.lstrip().startswith("#"):
                pending.append(found)
            elif found is not None:
                expectations.append(found)
        elif tok.type not in _SKIP:
            line = tok.start[0]
            expectations.extend(replace(e, line=line) for e in pending)
            pending.clear()
    if pending:
        raise ValueError(
            f"line {pending[0].line}: assertion after the last line of code "
            "(an assertion on a line of its own is about the next line of code)"
        )
    return expectations


def read_line_expectations(text: str) -> list[Expectation]:
    """Assertions at the end of the lines they are about, in a file that is not
    Python (a YAML parameter file: `max_speed: 3.0  # error: RF101`). A `#` starts
    a comment at the start of a line or after a space, as in YAML."""
    expectations = []
    for number, line in enumerate(text.splitlines(), 1):
        starts = [m.start() for m in re.finditer(r"(?:^|(?<=\s))#", line)]
        read = (assertion(line[i:], number) for i in starts)
        found = [e for e in read if e is not None]
        if found and line.lstrip().startswith("#"):
            raise ValueError(
                f"line {number}: an assertion goes at the end of the line it is about"
            )
        expectations += found
    return expectations


# an XML comment that holds an assertion (`<!-- error: RF101 -->`)
_XML_ASSERTION = re.compile(r"<!--\s*((?:error|warning|note)s?\b[^>]*?)\s*-->", re.I)
XML_SUFFIXES = (".xml", ".launch")
# a C++ comment that holds an assertion (`// error: RF603`)
_CPP_ASSERTION = re.compile(r"//\s*((?:error|warning|note)s?\b.*)$", re.I | re.M)
CPP_SUFFIXES = (".cpp", ".cc", ".cxx", ".hpp", ".hh", ".hxx", ".h")


def file_expectations(path: Path) -> list[Expectation]:
    """A Python file's assertions, or those at the ends of another file's lines
    (in an XML file, each in a comment of its own: `<!-- error: RF101 -->`; in a
    C++ file, in a `//` comment: `// error: RF603`)."""
    text = path.read_text(encoding="utf-8")
    if path.suffix == ".py":
        return read_expectations(text)
    if path.name.endswith(XML_SUFFIXES):
        text = _XML_ASSERTION.sub(r"# \1", text)
    if path.name.endswith(CPP_SUFFIXES):
        text = _CPP_ASSERTION.sub(r"# \1", text.replace("#", " "))
    return read_line_expectations(text)


def compare_files(files: list[Path], actual: list[Diagnostic]) -> list[str]:
    """`compare` for each file of a run, against its assertions; a diagnostic in any
    other file is unexpected too."""
    by_file: dict[Path, list[Diagnostic]] = {}
    for diag in actual:
        by_file.setdefault(Path(diag.path).resolve(), []).append(diag)
    problems = []
    for path in files:
        found = by_file.pop(path.resolve(), [])
        problems += [f"{path}: {p}" for p in compare(file_expectations(path), found)]
    problems += [
        f"{d.path}:{d.span.line}: unexpected {d.severity.value} {d.code} {d.message}"
        for diags in by_file.values()
        for d in diags
    ]
    return problems


def compare(expected: list[Expectation], actual: list[Diagnostic]) -> list[str]:
    """One line per mismatch; an empty list means the case passes."""
    unmatched = list(actual)
    problems = []
    for exp in expected:
        hit = next((d for d in unmatched if exp.matches(d)), None)
        if hit is None:
            problems.append(
                f"line {exp.line}: expected {exp.kind} {exp.code}, got none"
            )
        else:
            unmatched.remove(hit)
    problems += [
        f"line {d.span.line}: unexpected {d.severity.value} {d.code} {d.message}"
        for d in unmatched
    ]
    return problems
