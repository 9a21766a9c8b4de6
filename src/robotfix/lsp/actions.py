"""Quick fixes as LSP code actions: the fixes a diagnostic carries
(`Diagnostic.fixes`, made where its message is), a suppression comment for its
line, and the `Unit(...)` annotations `robotfix suggest` proposes for the lines
asked about. Each one is applied to the text in memory and checked again (parse
and analysis, with the document's catalog and summaries); it is offered only when
the diagnostic it targets is gone from its line and no diagnostic is added (an
error or a warning of a code the text did not have as often before). Verdicts are
kept per text, so a client that asks at every cursor move pays once.
"""

from __future__ import annotations

import difflib
from collections import Counter
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from robotfix import source
from robotfix.diagnostics import Diagnostic, Edit, Fix, Severity, Span
from robotfix.lsp.documents import apply, utf16

if TYPE_CHECKING:
    from robotfix.api import Suggestion

Checker = Callable[[str], list[Diagnostic]]


MAX_TRIED = 16  # fixes checked for one request; the others wait for the next one


@dataclass
class Verdicts:
    """What was found for one text of a document: its verdict on each fix tried."""

    text: str
    fixes: dict[tuple[object, ...], bool] = field(default_factory=dict)
    suggested: list[Suggestion] | None = None  # what suggest proposes in the text
    edits: dict[tuple[object, ...], Fix] = field(default_factory=dict)  # suggest's
    budget: int = MAX_TRIED  # of the request being answered

    def holds(self, key: tuple[object, ...], check: Callable[[], bool]) -> bool:
        """The verdict kept under `key`, else `check()`'s while this request may
        still try fixes (a request over a whole file with many diagnostics does
        not check them all at once); False when it may not."""
        if key not in self.fixes:
            if self.budget <= 0:
                return False
            self.budget -= 1
            self.fixes[key] = check()
        return self.fixes[key]


def applied(text: str, edits: Iterable[Edit]) -> str:
    """`text` with `edits` (ours: 1-based lines, character columns) made, last
    first so that each edit's place is still where it was."""
    lines = source.split_lines(text)
    changes = [
        {"range": lsp_range(lines, edit.span), "text": edit.text}
        for edit in sorted(edits, key=lambda e: e.span, reverse=True)
    ]
    for change in changes:
        text = apply(text, change)
    return text


def lsp_range(lines: list[str], span: Span) -> dict[str, object]:
    return {
        "start": {
            "line": span.line - 1,
            "character": utf16(lines, span.line, span.col),
        },
        "end": {
            "line": span.end_line - 1,
            "character": utf16(lines, span.end_line, span.end_col),
        },
    }


def candidates(text: str, target: Diagnostic) -> list[Fix]:
    """The fixes of a diagnostic, then the comment that silences it on its line."""
    lines = source.split_lines(text)
    line = target.span.line
    found = list(target.fixes)
    if 1 <= line <= len(lines):
        edit = source.suppression(lines[line - 1], line, target.code)
        found.append(Fix(f"Silence {target.code} on this line", (edit,)))
    return found


def verified(
    text: str,
    before: list[Diagnostic],
    fix: Fix,
    check: Checker,
    target: Diagnostic | None,
) -> bool:
    """Whether `fix`, applied to `text`, removes `target` (from its line, moved by
    the edits) and adds no error or warning that `before` did not have."""
    after = check(applied(text, fix.edits))
    if target is not None:
        line = moved(target.span.line, fix.edits)
        if any(d.code == target.code and d.span.line == line for d in after):
            return False
    kept = Counter(d.code for d in before if d is not target)
    added = Counter(d.code for d in after if d.severity != Severity.NOTE) - kept
    return not added


def moved(line: int, edits: Iterable[Edit]) -> int:
    """Where `line` is once the edits are made (lines added or removed above it)."""
    shift = 0
    for edit in edits:
        if edit.span.end_line < line:
            shift += edit.text.count("\n") - (edit.span.end_line - edit.span.line)
    return line + shift


def diff_edits(old: str, new: str) -> tuple[Edit, ...]:
    """The line edits that turn `old` into `new` (keeping the rest of the buffer,
    and the editor's marks in it, where they are)."""
    a, b = old.splitlines(keepends=True), new.splitlines(keepends=True)
    edits = []
    matcher = difflib.SequenceMatcher(None, a, b, autojunk=False)
    for tag, i1, i2, j1, j2 in matcher.get_opcodes():
        if tag != "equal":
            span = Span(i1 + 1, 0, i2 + 1, 0)
            edits.append(Edit(span, "".join(b[j1:j2])))
    return tuple(edits)
