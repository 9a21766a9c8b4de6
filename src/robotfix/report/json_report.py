"""JSON output: one object with `diagnostics` and `summary` (SPEC §5).
Lines and columns are 1-based, as in the text output; end columns are exclusive.
`summary.unchecked` (files that had an internal error) appears only when there are
some. Paths that are not printable UTF-8 are quoted as in the text output."""

from __future__ import annotations

import json
from typing import Any

from robotfix.diagnostics import Diagnostic
from robotfix.report.escape import clean_text, shown_path


def render(
    diagnostics: list[Diagnostic],
    files: int,
    errors: int,
    warnings: int,
    seconds: float,
    unchecked: int = 0,
) -> str:
    summary: dict[str, Any] = {
        "files": files,
        "errors": errors,
        "warnings": warnings,
        "seconds": round(seconds, 3),
    }
    if unchecked:
        summary["unchecked"] = unchecked
    payload = {"diagnostics": [_diagnostic(d) for d in diagnostics], "summary": summary}
    return json.dumps(payload, indent=2) + "\n"


def _diagnostic(d: Diagnostic) -> dict[str, Any]:
    return {
        "path": shown_path(d.path),
        "line": d.span.line,
        "column": d.span.col + 1,
        "end_line": d.span.end_line,
        "end_column": d.span.end_col + 1,
        "severity": d.severity.value,
        "code": d.code,
        "message": clean_text(d.message),
        "notes": [
            {
                "path": None if n.path is None else shown_path(n.path),
                "line": n.line,
                "message": clean_text(n.message),
            }
            for n in d.notes
        ],
    }
