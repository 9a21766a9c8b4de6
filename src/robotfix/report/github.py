"""GitHub Actions workflow commands: each diagnostic becomes an annotation on the
pull request (`::error file=...,line=...::message`)."""

from __future__ import annotations

from robotfix.diagnostics import Diagnostic, Severity
from robotfix.report.escape import clean_text, shown_path

COMMANDS = {
    Severity.ERROR: "error",
    Severity.WARNING: "warning",
    Severity.NOTE: "notice",
}


def render(diagnostics: list[Diagnostic]) -> str:
    lines = []
    for d in diagnostics:
        props = ",".join(
            [
                f"file={_property(shown_path(d.path))}",
                f"line={d.span.line}",
                f"col={d.span.col + 1}",
                f"endLine={d.span.end_line}",
                f"endColumn={d.span.end_col + 1}",
                f"title={_property(f'{d.code} {d.rule.name}')}",
            ]
        )
        lines.append(
            f"::{COMMANDS[d.severity]} {props}::{_data(clean_text(d.message))}"
        )
    return "".join(line + "\n" for line in lines)


def _data(text: str) -> str:
    return text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def _property(text: str) -> str:
    return _data(text).replace(":", "%3A").replace(",", "%2C")
