"""Text output: `path:line:col: severity[CODE]: message`, then notes and the source line
with carets under the span, then a summary line."""

from __future__ import annotations

from collections.abc import Callable

from robotfix.diagnostics import Diagnostic
from robotfix.report.escape import clean_text, shown_path


def render_concise(diagnostics: list[Diagnostic]) -> str:
    """One line per diagnostic, for editors, grep and quick scans."""
    return "".join(
        f"{shown_path(d.path)}:{d.span.line}:{d.span.col + 1}: "
        f"{d.severity.value}[{d.code}]: {clean_text(d.message)}\n"
        for d in diagnostics
    )


def render(
    diagnostics: list[Diagnostic],
    source_line: Callable[[str, int], str | None],
    summary_line: str,
) -> str:
    """The default: each diagnostic, its notes, and its source line with carets."""
    out: list[str] = []
    for d in diagnostics:
        out.append(
            f"{shown_path(d.path)}:{d.span.line}:{d.span.col + 1}: "
            f"{d.severity.value}[{d.code}]: {clean_text(d.message)}"
        )
        for note in d.notes:
            where = f" --> {shown_path(note.path)}:{note.line}" if note.path else ""
            out.append(f"  note: {clean_text(note.message)}{where}")
        line = source_line(d.path, d.span.line)
        if line is not None:
            out.extend(_excerpt(line, d))
    out.append(summary_line)
    return "\n".join(out) + "\n"


def _excerpt(line: str, d: Diagnostic, width: int = 100) -> list[str]:
    """The source line with carets under the span; a long line is cut to a window
    around the span."""
    number = str(d.span.line)
    gutter = " " * len(number)
    # one column per character: a form feed or U+2028 inside the line shows as a space
    text = "".join(c if c.isprintable() else " " for c in line.rstrip())
    start = min(d.span.col, len(text))
    end = d.span.end_col if d.span.end_line == d.span.line else len(text)
    end = max(start + 1, min(end, len(text)))
    if len(text) > width:
        left = max(0, min(start - 20, len(text) - width))
        prefix = "..." if left else ""
        suffix = "..." if left + width < len(text) else ""
        shown = prefix + text[left : left + width] + suffix
        start, end = start - left + len(prefix), min(end - left, width) + len(prefix)
        text = shown
    carets = "^" * max(1, end - start)
    return [f"  {number} | {text}", f"  {gutter} | {' ' * start}{carets}"]


def summary(
    files: int,
    errors: int,
    warnings: int,
    seconds: float | None = None,
    unchecked: int = 0,
) -> str:
    """The last line. Files that had an internal error were not checked: then it
    never says "No problems found"."""

    def plural(n: int, word: str) -> str:
        return f"{n} {word}{'' if n == 1 else 's'}"

    timing = f" ({seconds:.2f} s)" if seconds is not None else ""
    if unchecked:
        return (
            f"Could not check {unchecked} of {plural(files, 'file')} (internal "
            f"error); found {plural(errors, 'error')} and "
            f"{plural(warnings, 'warning')}{timing}."
        )
    if not files and not errors and not warnings:
        return f"No Python files were found to check{timing}."
    if not errors and not warnings:
        return f"No problems found in {plural(files, 'file')}{timing}."
    return (
        f"Found {plural(errors, 'error')} and {plural(warnings, 'warning')} "
        f"in {plural(files, 'file')}{timing}."
    )
