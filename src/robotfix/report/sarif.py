"""SARIF 2.1.0: one run, the rules from the registry, one result per diagnostic.
Plain dicts for `json.dumps`; validated against the official schema in the tests."""

from __future__ import annotations

import json
from typing import Any

from robotfix import __version__
from robotfix.diagnostics import Diagnostic, Rule, Severity

SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
LEVELS = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.NOTE: "note"}


def render(diagnostics: list[Diagnostic], rules: list[Rule]) -> str:
    index = {rule.code: i for i, rule in enumerate(rules)}
    run = {
        "tool": {
            "driver": {
                "name": "RobotFix",
                "version": __version__,
                "informationUri": "https://robotfix.dev",
                "rules": [_rule(rule) for rule in rules],
            }
        },
        "results": [_result(d, index[d.code]) for d in diagnostics],
        "columnKind": "unicodeCodePoints",
    }
    payload = {"$schema": SCHEMA, "version": "2.1.0", "runs": [run]}
    return json.dumps(payload, indent=2) + "\n"


def _rule(rule: Rule) -> dict[str, Any]:
    return {
        "id": rule.code,
        "name": rule.name,
        "shortDescription": {"text": rule.title},
        "helpUri": rule.docs_url,
        "defaultConfiguration": {"level": LEVELS[rule.severity]},
    }


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
        "message": {"text": d.message},
        "locations": [_location(d.path, region)],
    }
    related = [n for n in d.notes if n.path is not None and n.line is not None]
    if related:
        result["relatedLocations"] = [
            {
                **_location(n.path or "", {"startLine": n.line}),
                "id": i,
                "message": {"text": n.message},
            }
            for i, n in enumerate(related)
        ]
    return result


def _location(path: str, region: dict[str, Any]) -> dict[str, Any]:
    return {
        "physicalLocation": {
            "artifactLocation": {"uri": path.replace("\\", "/")},
            "region": region,
        }
    }
