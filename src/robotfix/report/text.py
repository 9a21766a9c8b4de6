"""Text output: `path:line:col: severity[CODE]: message`, then notes and the source line
with carets under the span, then a summary line."""

from __future__ import annotations

from collections.abc import Callable

from robotfix.diagnostics import Diagnostic


def render(
    diagnostics: list[Diagnostic],
    source_line: Callable[[str, int], str | None],
    files: int,
    errors: int,
    warnings: int,
) -> str:
    out: list[str] = []
    for d in diagnostics:
        out.append(
            f"{d.path}:{d.span.line}:{d.span.col + 1}: "
            f"{d.severity.value}[{d.code}]: {d.message}"
        )
        for note in d.notes:
            where = f" --> {note.path}:{note.line}" if note.path else ""
            out.append(f"  note: {note.message}{where}")
        line = source_line(d.path, d.span.line)
        if line is not None:
            out.extend(_excerpt(line, d))
    out.append(summary(files, errors, warnings))
    return "\n".join(out) + "\n"


def _excerpt(line: str, d: Diagnostic) -> list[str]:
    number = str(d.span.line)
    gutter = " " * len(number)
    text = line.rstrip().expandtabs(1)
    start = min(d.span.col, len(text))
    end = d.span.end_col if d.span.end_line == d.span.line else len(text)
    width = max(1, min(end, len(text)) - start)
    return [f"  {number} | {text}", f"  {gutter} | {' ' * start}{'^' * width}"]


def summary(files: int, errors: int, warnings: int) -> str:
    def plural(n: int, word: str) -> str:
        return f"{n} {word}{'' if n == 1 else 's'}"

    if not errors and not warnings:
        return f"No problems found in {plural(files, 'file')}."
    return (
        f"Found {plural(errors, 'error')} and {plural(warnings, 'warning')} "
        f"in {plural(files, 'file')}."
    )
