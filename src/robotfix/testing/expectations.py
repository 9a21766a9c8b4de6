"""Read `# error: RF201 "text"` assertions out of a test case's comments.

A trailing assertion targets its own line; assertions on lines of their own stack up
and target the next line of code. Matching is strict: every diagnostic must be
expected and every expectation met. Comments are read with `tokenize`, so an
assertion inside a string never counts.
"""

from __future__ import annotations

import io
import re
import tokenize
from dataclasses import dataclass

from robotfix.diagnostics import Diagnostic

_PREFIX = re.compile(r"#\s*(error|warning|note)\s*:")
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


def read_expectations(source: str) -> list[Expectation]:
    expectations: list[Expectation] = []
    pending: list[re.Match[str]] = []
    for tok in tokenize.generate_tokens(io.StringIO(source).readline):
        if tok.type == tokenize.COMMENT and _PREFIX.match(tok.string):
            match = _ASSERTION.fullmatch(tok.string)
            if match is None:
                raise ValueError(
                    f"line {tok.start[0]}: malformed assertion {tok.string!r}"
                )
            if tok.line.lstrip().startswith("#"):
                pending.append(match)
            else:
                expectations.append(_expectation(tok.start[0], match))
        elif tok.type not in _SKIP:
            expectations.extend(_expectation(tok.start[0], m) for m in pending)
            pending.clear()
    return expectations


def _expectation(line: int, match: re.Match[str]) -> Expectation:
    return Expectation(line, match["kind"], match["code"], match["text"])


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
