"""Pure data that crosses layers: severities, spans, rules and diagnostics.

Imports nothing of ours, so every layer may use it.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field


class Severity(enum.Enum):
    ERROR = "error"
    WARNING = "warning"
    NOTE = "note"  # information only: never changes the exit status


@dataclass(frozen=True)
class Rule:
    """One stable, documented kind of diagnostic."""

    code: str  # "RF201": never reused, never renumbered
    name: str  # "unit-mismatch": kebab-case, names the problem
    title: str  # one line
    severity: Severity = Severity.ERROR


@dataclass(frozen=True, order=True)
class Span:
    """1-based lines, 0-based character columns, end exclusive."""

    line: int
    col: int
    end_line: int
    end_col: int

    @staticmethod
    def point(line: int, col: int = 0) -> Span:
        return Span(line, col, line, col + 1)


@dataclass(frozen=True)  # never ordered: `api.finish` sorts by `sort_key` alone
class Note:
    """Extra context for a diagnostic; a location when `path` is set."""

    message: str
    path: str | None = None
    line: int | None = None


@dataclass(frozen=True)
class Edit:
    """Replace the text at `span` with `text`."""

    span: Span
    text: str


@dataclass(frozen=True)
class Fix:
    """A change of the source the message proposes (`title` says which), as edits:
    an editor offers it as a quick fix once it has checked the result."""

    title: str
    edits: tuple[Edit, ...]


@dataclass(frozen=True)
class Diagnostic:
    """A finding: its rule, place, message, notes and fixes."""

    rule: Rule
    path: str
    span: Span
    message: str
    notes: tuple[Note, ...] = ()
    level: Severity | None = None  # when not the rule's own severity
    # proposed changes; not part of what a diagnostic is (a cached run has none)
    fixes: tuple[Fix, ...] = field(default=(), compare=False)

    @property
    def code(self) -> str:
        return self.rule.code

    @property
    def severity(self) -> Severity:
        return self.rule.severity if self.level is None else self.level

    def sort_key(self) -> tuple[str, Span, str, str]:
        return (self.path, self.span, self.code, self.message)
