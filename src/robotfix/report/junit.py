"""JUnit/xUnit XML, as `colcon test-result`, ament's run_test.py, Jenkins and GitLab
read it: one test case per checked file, a `<failure>` per diagnostic that fails the
run (errors; warnings too under --strict), an `<error>` per file that could not be
checked. Diagnostics that do not fail the run (warnings, notes) are the test case's
`<system-out>`, so the file's verdict always agrees with the exit status.

Characters XML 1.0 cannot carry (control characters, lone surrogates from
undecodable file names) are written as `\\xNN`/`\\uNNNN` escapes, so the file always
parses.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from collections.abc import Iterable

from robotfix.diagnostics import Diagnostic, Severity

UNCHECKED = "RF003"  # the file could not be read: the test could not run
_NOT_XML = re.compile("[^\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")


def render(
    diagnostics: list[Diagnostic],
    files: list[str],
    strict: bool,
    seconds: float,
    suite: str = "robotfix",
    internal_errors: Iterable[tuple[str, str]] = (),
) -> str:
    """`files` are the checked files as the diagnostics spell their paths;
    `internal_errors` are (path, summary) pairs of files RobotFix failed on."""
    order = list(dict.fromkeys([*files, *(d.path for d in diagnostics)]))
    by_file: dict[str, list[Diagnostic]] = {path: [] for path in order}
    for d in diagnostics:
        by_file[d.path].append(d)
    crashed: dict[str, list[str]] = {}
    for path, summary in internal_errors:
        crashed.setdefault(path, []).append(summary)
        by_file.setdefault(path, [])
    testsuite = ET.Element("testsuite", name=_clean(suite))
    failures = errors = 0
    for path, found in by_file.items():
        case = ET.SubElement(
            testsuite, "testcase", classname=_clean(suite), name=_clean(path)
        )
        case.set("file", _clean(path))
        failed = errored = False
        quiet: list[str] = []
        for d in found:
            if d.code == UNCHECKED:
                _child(case, "error", d.code, _line(d), _full(d))
                errored = True
            elif fails(d, strict):
                _child(case, "failure", d.code, _line(d), _full(d))
                failed = True
            else:
                quiet.append(_full(d))
        for summary in crashed.get(path, []):
            text = f"{path}: internal error: {summary}"
            _child(case, "error", "internal-error", text, text)
            errored = True
        if quiet:
            ET.SubElement(case, "system-out").text = _clean("\n".join(quiet) + "\n")
        errors += errored
        failures += failed and not errored
    counts = {
        "tests": str(len(by_file)),
        "failures": str(failures),
        "errors": str(errors),
        "skipped": "0",
        "time": f"{seconds:.3f}",
    }
    for key, value in counts.items():
        testsuite.set(key, value)
    root = ET.Element("testsuites", name=_clean(suite))
    for key in ("tests", "failures", "errors", "time"):
        root.set(key, counts[key])
    root.append(testsuite)
    ET.indent(root)
    body = ET.tostring(root, encoding="unicode")
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + body + "\n"


def fails(d: Diagnostic, strict: bool) -> bool:
    """Whether a diagnostic fails the run (and so the test case)."""
    return d.severity is Severity.ERROR or (strict and d.severity is Severity.WARNING)


def _child(case: ET.Element, tag: str, kind: str, message: str, text: str) -> None:
    element = ET.SubElement(case, tag, type=_clean(kind), message=_clean(message))
    element.text = _clean(text)


def _line(d: Diagnostic) -> str:
    return (
        f"{d.path}:{d.span.line}:{d.span.col + 1}: "
        f"{d.severity.value}[{d.code}]: {d.message}"
    )


def _full(d: Diagnostic) -> str:
    lines = [_line(d)]
    for note in d.notes:
        where = f" --> {note.path}:{note.line}" if note.path else ""
        lines.append(f"  note: {note.message}{where}")
    return "\n".join(lines)


def _clean(text: str) -> str:
    def escape(match: re.Match[str]) -> str:
        code = ord(match.group())
        return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}"

    return _NOT_XML.sub(escape, text)
