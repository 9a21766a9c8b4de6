"""SARIF 2.1.0: one run, the rules from the registry, one result per diagnostic.
Plain dicts for `json.dumps`; validated against the official schema in the tests.
Locations are URI references (RFC 3986): relative paths percent-encoded, absolute
paths as `file://` URIs; files that could not be checked are tool notifications."""

from __future__ import annotations

import json
import os
from collections.abc import Sequence
from pathlib import PurePath, PurePosixPath
from typing import Any
from urllib.parse import quote_from_bytes

from robotfix import __version__, rulepages
from robotfix.diagnostics import Diagnostic, Rule, Severity
from robotfix.report.escape import clean_text

SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
LEVELS = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.NOTE: "note"}


def render(
    diagnostics: list[Diagnostic],
    rules: list[Rule],
    unchecked: Sequence[tuple[str, str]] = (),
) -> str:
    """`unchecked`: (path, reason) of each file that had an internal error."""
    index = {rule.code: i for i, rule in enumerate(rules)}
    run: dict[str, Any] = {
        "tool": {
            "driver": {
                "name": "RobotFix",
                "version": __version__,
                "rules": [_rule(rule) for rule in rules],
            }
        },
        "results": [_result(d, index[d.code]) for d in diagnostics],
        "columnKind": "unicodeCodePoints",
    }
    if unchecked:
        run["invocations"] = [
            {
                "executionSuccessful": False,
                "toolExecutionNotifications": [
                    {
                        "level": "error",
                        "message": {"text": clean_text(f"internal error: {reason}")},
                        "locations": [_location(path, None)],
                    }
                    for path, reason in unchecked
                ],
            }
        ]
    payload = {"$schema": SCHEMA, "version": "2.1.0", "runs": [run]}
    return json.dumps(payload, indent=2) + "\n"


def _rule(rule: Rule) -> dict[str, Any]:
    found: dict[str, Any] = {
        "id": rule.code,
        "name": rule.name,
        "shortDescription": {"text": rule.title},
        "defaultConfiguration": {"level": LEVELS[rule.severity]},
    }
    page = rulepages.uri(rule.code)  # the installed rule page: RobotFix has no site
    if page is not None:
        found["helpUri"] = page
    return found


def _result(d: Diagnostic, rule_index: int) -> dict[str, Any]:
    region = {
        "startLine": d.span.line,
        "startColumn": d.span.col + 1,
        "endLine": d.span.end_line,
        "endColumn": d.span.end_col + 1,
    }
    result: dict[str, Any] = {
        "ruleId": d.code,
        "ruleIndex": rule_index,
        "level": LEVELS[d.severity],
        "message": {"text": clean_text(d.message)},
        "locations": [_location(d.path, region)],
    }
    related = [n for n in d.notes if n.path is not None and n.line is not None]
    if related:
        result["relatedLocations"] = [
            {
                **_location(n.path or "", {"startLine": n.line}),
                "id": i,
                "message": {"text": clean_text(n.message)},
            }
            for i, n in enumerate(related)
        ]
    return result


def _location(path: str, region: dict[str, Any] | None) -> dict[str, Any]:
    physical: dict[str, Any] = {"artifactLocation": {"uri": uri(path)}}
    if region is not None:
        physical["region"] = region
    return {"physicalLocation": physical}


def uri(path: str) -> str:
    """A path as a URI reference: the file name's bytes percent-encoded (space, `#`,
    `%`, `:`, control characters, non-UTF-8 bytes), absolute paths as `file://`."""
    pure = PurePath(path)
    if pure.is_absolute() and not isinstance(pure, PurePosixPath):
        return pure.as_uri()  # Windows: file:///C:/...
    text = pure.as_posix()
    try:
        data = os.fsencode(text)
    except UnicodeEncodeError:  # a surrogate no file system produced
        data = text.encode("utf-8", "backslashreplace")
    encoded = quote_from_bytes(data, safe="/")
    return "file://" + encoded if pure.is_absolute() else encoded
