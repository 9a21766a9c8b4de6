"""JSON output: one object with `diagnostics` and `summary` (SPEC §5).
Lines and columns are 1-based, as in the text output; end columns are exclusive."""

from __future__ import annotations

import json
from typing import Any

from robotfix.diagnostics import Diagnostic


def render(
    diagnostics: list[Diagnostic],
    files: int,
    errors: int,
    warnings: int,
    seconds: float,
) -> str:
    payload: dict[str, Any] = {
        "diagnostics": [_diagnostic(d) for d in diagnostics],
        "summary": {
            "files": files,
            "errors": errors,
            "warnings": warnings,
            "seconds": round(seconds, 3),
        },
    }
    return json.dumps(payload, indent=2) + "\n"


def _diagnostic(d: Diagnostic) -> dict[str, Any]:
    return {
        "path": d.path,
        "line": d.span.line,
        "column": d.span.col + 1,
        "end_line": d.span.end_line,
        "end_column": d.span.end_col + 1,
        "severity": d.severity.value,
        "code": d.code,
        "message": d.message,
        "notes": [
            {"path": n.path, "line": n.line, "message": n.message} for n in d.notes
        ],
    }
