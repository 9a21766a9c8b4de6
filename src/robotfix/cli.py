"""The command line: `robotfix check`, `robotfix rules`, `robotfix --version`.

Exit status: 0 no errors (warnings allowed unless --strict), 1 errors found,
2 bad usage, unreadable input or an internal failure.
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from robotfix import __version__

EXIT_OK, EXIT_FOUND, EXIT_FAILURE = 0, 1, 2


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="robotfix",
        description="Check units, frames and refinements in ROS Python code.",
    )
    parser.add_argument(
        "--version", action="version", version=f"robotfix {__version__}"
    )
    commands = parser.add_subparsers(dest="command", metavar="COMMAND")
    check = commands.add_parser("check", help="check Python files and folders")
    check.add_argument(
        "paths",
        nargs="*",
        type=Path,
        metavar="PATH",
        help="files or folders (default: the current folder)",
    )
    check.add_argument(
        "--msg-path",
        action="append",
        type=Path,
        default=[],
        metavar="DIR",
        help="a folder (or file) of .msg/.srv/.action files; repeatable",
    )
    check.add_argument("--format", choices=("text", "json"), default=None)
    check.add_argument(
        "--strict",
        action="store_true",
        default=None,
        help="warnings also make the exit status 1",
    )
    check.add_argument(
        "--no-rep103",
        dest="rep103",
        action="store_false",
        default=None,
        help="do not assume the REP 103 units of standard messages",
    )
    commands.add_parser("rules", help="list every diagnostic code")
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        if args.command == "check":
            return run_check(args)
        if args.command == "rules":
            return run_rules()
    except KeyboardInterrupt:
        return EXIT_FAILURE
    build_parser().print_help()
    return EXIT_FAILURE


def run_rules() -> int:
    from robotfix.rules import ALL_RULES

    for rule in ALL_RULES.values():
        print(f"{rule.code}  {rule.name:<28} {rule.severity.value:<8} {rule.title}")
    return EXIT_OK


def run_check(args: argparse.Namespace) -> int:
    from dataclasses import replace

    from robotfix import api, config
    from robotfix.diagnostics import Severity

    paths: list[Path] = args.paths or [Path(".")]
    missing = [p for p in paths if not p.exists()]
    if missing:
        for path in missing:
            print(
                f"robotfix: error: {path}: no such file or directory", file=sys.stderr
            )
        return EXIT_FAILURE
    try:
        settings = config.load(paths[0])
    except config.ConfigError as err:
        print(f"robotfix: error: {err}", file=sys.stderr)
        return EXIT_FAILURE
    settings = replace(
        settings,
        msg_paths=tuple(args.msg_path) + settings.msg_paths,
        strict=settings.strict if args.strict is None else args.strict,
        rep103=settings.rep103 if args.rep103 is None else args.rep103,
        output_format=args.format or settings.output_format,
    )
    result = api.check_paths(paths, settings)
    errors, warnings = result.count(Severity.ERROR), result.count(Severity.WARNING)
    _print(result, settings.output_format, errors, warnings)
    for failure in result.internal_errors:
        print(
            f"robotfix: internal error while checking {failure.path}: "
            f"{failure.summary}",
            file=sys.stderr,
        )
        if os.environ.get("ROBOTFIX_DEBUG"):
            print(failure.detail, file=sys.stderr)
    if result.internal_errors and not os.environ.get("ROBOTFIX_DEBUG"):
        print(
            "robotfix: the other files were checked; set ROBOTFIX_DEBUG=1 for the "
            "traceback, and please report it",
            file=sys.stderr,
        )
    unreadable = any(d.code == "RF003" for d in result.diagnostics)
    if result.internal_errors or unreadable:
        return EXIT_FAILURE
    if errors or (settings.strict and warnings):
        return EXIT_FOUND
    return EXIT_OK


def _print(result: object, fmt: str, errors: int, warnings: int) -> None:
    from robotfix.api import Result

    assert isinstance(result, Result)
    if fmt == "json":
        from robotfix.report import json as json_report

        sys.stdout.write(
            json_report.render(
                result.diagnostics, result.files, errors, warnings, result.seconds
            )
        )
        return
    from robotfix.report import text

    lines: dict[str, list[str]] = {}

    def source_line(path: str, line: int) -> str | None:
        if path not in lines:
            try:
                lines[path] = (
                    Path(path)
                    .read_text(encoding="utf-8", errors="replace")
                    .splitlines()
                )
            except OSError:
                lines[path] = []
        found = lines[path]
        return found[line - 1] if 0 < line <= len(found) else None

    sys.stdout.write(
        text.render(result.diagnostics, source_line, result.files, errors, warnings)
    )
