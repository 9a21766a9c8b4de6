"""The command line: `check`, `rules`, `explain`, `suggest`, `lsp`, `--version`.

Exit status: 0 no errors (warnings allowed unless --strict), 1 errors found,
2 bad usage, unreadable input or an internal failure. Heavy modules are imported
inside the commands, so `robotfix --version` starts fast.
"""

from __future__ import annotations

import argparse
import atexit
import contextlib
import errno
import functools
import gc
import io
import os
import sys
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, NoReturn, TypeVar, cast

from robotfix import GC_THRESHOLDS, __version__
from robotfix.config import FORMATS  # light: stdlib only, tomllib imported there

if TYPE_CHECKING:
    from collections.abc import Callable

    from robotfix.api import Result
    from robotfix.config import Config

EXIT_OK, EXIT_FOUND, EXIT_FAILURE = 0, 1, 2
EXIT_INTERRUPTED = 130  # 128 + SIGINT, as shells report Ctrl-C


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
    add_msg_path_argument(check)
    check.add_argument(
        "--stub-path",
        action="append",
        type=Path,
        default=[],
        metavar="DIR",
        help="a folder of .pyi stubs with Annotated signatures (before the shipped "
        "ones); repeatable",
    )
    check.add_argument(
        "--python-path",
        action="append",
        type=Path,
        default=[],
        metavar="DIR",
        help="a folder where imported modules are looked for (as mypy_path); "
        "repeatable",
    )
    check.add_argument(
        "--format",
        choices=FORMATS,
        default=None,
        help="text (default: with source lines), concise, json, sarif, github, "
        "junit (xUnit XML: a test case per file)",
    )
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
    check.add_argument(
        "--unit-suffixes",
        action="store_true",
        default=None,
        help="interface fields named *_ms, *_deg, *_kmph, ... have those units",
    )
    check.add_argument(
        "--exclude",
        action="append",
        default=[],
        metavar="PATTERN",
        help="gitignore-style pattern of files to skip; repeatable",
    )
    check.add_argument(
        "--ros-distro",
        default=None,
        metavar="NAME",
        help="standard message definitions: ros2 (default), ros1, jazzy, "
        "humble, iron, kilted, rolling, noetic",
    )
    check.add_argument(
        "-j",
        "--jobs",
        type=int,
        default=None,
        metavar="N",
        help=(
            "check files in N processes (default and cap: the cores this process "
            "may use, its CPU quota counted)"
        ),
    )
    check.add_argument(
        "--no-cache",
        dest="cache",
        action="store_false",
        help="neither read nor write .robotfix_cache/",
    )
    check.add_argument(
        "--cache-dir",
        type=Path,
        default=None,
        metavar="DIR",
        help="keep the per-file cache in DIR instead of .robotfix_cache/ "
        "(e.g. a build folder)",
    )
    commands.add_parser("rules", help="list every diagnostic code")
    explain = commands.add_parser("explain", help="what a code means, and the fix")
    explain.add_argument("code", metavar="CODE", help="a code (RF101) or a name")
    suggest = commands.add_parser("suggest", help="propose Unit() annotations")
    suggest.add_argument("paths", nargs="+", type=Path, metavar="PATH")
    add_msg_path_argument(suggest)
    suggest.add_argument(
        "--apply", action="store_true", help="write the proposals into the files"
    )
    commands.add_parser("lsp", help="language server on stdin/stdout")
    graph = commands.add_parser(
        "graph", help="print the static ROS graph (nodes, topics, services, actions)"
    )
    graph.add_argument(
        "paths",
        nargs="*",
        type=Path,
        metavar="PATH",
        help="files or folders (default: the current folder)",
    )
    graph.add_argument(
        "--format",
        choices=("text", "json", "dot", "mermaid"),
        default="text",
        help="text (default), json, dot (Graphviz), mermaid",
    )
    graph.add_argument(
        "--exclude",
        action="append",
        default=[],
        metavar="PATTERN",
        help="gitignore-style pattern of files to skip; repeatable",
    )
    return parser


def add_msg_path_argument(parser: argparse.ArgumentParser) -> None:
    """`--msg-path DIR`, the same for `check`, `suggest` and `ament_robotfix`."""
    parser.add_argument(
        "--msg-path",
        action="append",
        type=Path,
        default=[],
        metavar="DIR",
        help="a folder (or file) of .msg/.srv/.action files; repeatable",
    )


_Main = TypeVar("_Main", bound=Callable[..., int])


def _guard_output(command: _Main) -> _Main:
    """A closed, full or broken stdout ends the command with status 2: one line on
    stderr (none for a broken pipe, as `cat` or `grep`), never a traceback."""

    @functools.wraps(command)
    def guarded(argv: list[str] | None = None) -> int:
        try:
            try:
                return command(argv)
            finally:
                flush_stdout()
        except BrokenPipeError:
            _discard_stdout()
            return EXIT_FAILURE
        except OutputError as err:
            _discard_stdout()
            print(f"robotfix: error: cannot write the output: {err}", file=sys.stderr)
            return EXIT_FAILURE

    return cast("_Main", guarded)


@_guard_output
def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        if args.command == "check":
            return run_check(args)
        if args.command == "rules":
            return run_rules()
        if args.command == "explain":
            return run_explain(args.code)
        if args.command == "suggest":
            from robotfix.suggest import run_suggest

            return run_suggest(args.paths, args.msg_path, args.apply)
        if args.command == "lsp":
            return run_lsp()
        if args.command == "graph":
            return run_graph(args)
    except KeyboardInterrupt:
        return EXIT_INTERRUPTED
    build_parser().print_help()
    return EXIT_FAILURE


def run() -> NoReturn:
    """The `robotfix` command and `python -m robotfix`: `main`, then the process
    ends without freeing its heap, as mypy's does (Python's teardown frees every
    module, class and cached object: 1.5% of the instructions of a check of three
    repositories, and work nobody sees). What is buffered is written and the
    `atexit` handlers run first, as at any exit (z3 registers one; a pool's
    workers are joined before `main` returns).

    A one-shot command (all but `lsp`) runs at the check's collector thresholds
    from here on, its imports included, and never back: at Python's 700 the
    imports made about 30 young collections that found next to nothing, and the
    threshold restored after a check (`run.check_paths`, for in-process callers)
    made one more of all the run had allocated since its last (together 14 M
    instructions of a check of three repositories)."""
    if sys.argv[1:2] != ["lsp"]:  # the editor's server keeps Python's
        gc.set_threshold(*GC_THRESHOLDS)
    status = main()
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(AttributeError, OSError, ValueError):  # None, closed
            stream.flush()
    atexit._run_exitfuncs()  # what the interpreter's exit runs first
    os._exit(status)


def run_rules() -> int:
    from robotfix.rules import ALL_RULES

    write_stdout(
        "".join(
            f"{rule.code}  {rule.name:<24} {rule.severity.value:<8} {rule.title}\n"
            for rule in ALL_RULES.values()
        )
    )
    return EXIT_OK


def run_explain(code: str) -> int:
    from robotfix.rules import ALL_RULES, RULES_BY_NAME

    rule = ALL_RULES.get(code.upper()) or RULES_BY_NAME.get(code)
    if rule is None:
        print(
            f"robotfix: error: `{code}` is not a RobotFix code or rule name; "
            "`robotfix rules` lists them",
            file=sys.stderr,
        )
        return EXIT_FAILURE
    from robotfix import rulepages

    page = rulepages.text(rule.code)
    write_stdout(page or f"{rule.code} {rule.name}: {rule.title}\n")
    return EXIT_OK


def run_lsp() -> int:
    try:
        from robotfix.lsp.server import serve
    except ImportError as err:
        print(
            f"robotfix: error: the language server cannot start ({err})",
            file=sys.stderr,
        )
        return EXIT_FAILURE
    return serve()  # 1 when the client exits without asking to shut down


def _settings(paths: list[Path], merge: Callable[[Config], Config]) -> Config | None:
    """The settings for a run over `paths` (the first one's config, `merge`d with
    the command's flags); None, and why on stderr, for a missing path or a bad
    config."""
    from robotfix import config

    missing = [(p, why) for p in paths if (why := _missing(p))]
    for path, why in missing:
        print(f"robotfix: error: {path}: {why}", file=sys.stderr)
    if missing:
        return None
    try:
        return merge(config.load(paths[0]))
    except config.ConfigError as err:
        print(f"robotfix: error: {err}", file=sys.stderr)
        return None


def run_graph(args: argparse.Namespace) -> int:
    """`robotfix graph`: exit 0, or 1 when the graph has an error finding."""
    from dataclasses import replace

    from robotfix.graphcheck import graph_paths
    from robotfix.report.graph import render as render_graph

    paths: list[Path] = args.paths or [Path(".")]
    settings = _settings(
        paths, lambda found: replace(found, exclude=found.exclude + tuple(args.exclude))
    )
    if settings is None:
        return EXIT_FAILURE
    result = graph_paths(paths, settings)
    write_stdout(render_graph(result, args.format))
    errors = any(f.diagnostic.severity.value == "error" for f in result.findings)
    return EXIT_FOUND if errors else EXIT_OK


def run_check(args: argparse.Namespace) -> int:
    from robotfix import api, config

    paths: list[Path] = args.paths or [Path(".")]
    settings = _settings(paths, lambda found: merge_flags(found, args))
    if settings is None:
        return EXIT_FAILURE
    for folder in settings.msg_paths:
        why = _missing(folder)
        if why:
            where = "--msg-path" if folder in args.msg_path else "msg-paths"
            print(f"robotfix: error: {where} {folder}: {why}", file=sys.stderr)
            return EXIT_FAILURE
    for folder in settings.stub_paths:
        why = _missing(folder) or (None if os.path.isdir(folder) else "not a folder")
        if why:
            where = "--stub-path" if folder in args.stub_path else "stub-paths"
            print(f"robotfix: error: {where} {folder}: {why}", file=sys.stderr)
            return EXIT_FAILURE
    from robotfix.run import default_jobs

    if args.jobs is not None and args.jobs < 1:
        print(
            "robotfix: error: -j needs a number of processes, 1 or more",
            file=sys.stderr,
        )
        return EXIT_FAILURE
    progress = Progress() if sys.stderr.isatty() else None
    jobs = args.jobs or default_jobs()
    try:
        result = api.check_paths(
            paths, settings, progress=progress, jobs=jobs, use_cache=args.cache
        )
    except config.ConfigError as err:  # a package's own configuration
        print(f"robotfix: error: {err}", file=sys.stderr)
        return EXIT_FAILURE
    if progress is not None:
        progress.done()
    if not result.files:
        print(
            f"robotfix: warning: no Python files found in {' '.join(map(str, paths))}",
            file=sys.stderr,
        )
    return report(result, settings)


def _excerpts(
    result: Result, lines: Callable[[str, int], str | None]
) -> Callable[[str, int], str | None]:
    """Source lines for excerpts, but none of a file that was not read (RF003) or
    not checked (RF004): a FIFO would block, and the content of a symlink leaving
    the checked paths must not be shown."""
    unread = {d.path for d in result.diagnostics if d.code in ("RF003", "RF004")}
    return lambda path, line: None if path in unread else lines(path, line)


def _missing(path: Path) -> str | None:
    """Why a path named by the user is not there (None when it is; a dangling
    symlink is there, and gets RF003)."""
    try:
        os.lstat(path)
    except OSError as err:
        if err.errno == errno.ENOENT:
            return "no such file or directory"
        return err.strerror or type(err).__name__
    return None


def merge_flags(settings: Config, args: argparse.Namespace) -> Config:
    """The flags over the settings; kept in them (`Config.flags`) for the files
    whose nearest configuration is another (`Config.for_file`)."""
    from robotfix.config import DISTROS, ConfigError, Flags

    if args.ros_distro is not None and args.ros_distro not in DISTROS:
        raise ConfigError(f"--ros-distro must be one of {', '.join(DISTROS)}")
    flags = Flags(
        msg_paths=tuple(args.msg_path),
        stub_paths=tuple(getattr(args, "stub_path", ())),
        python_paths=tuple(getattr(args, "python_path", None) or ()),
        exclude=tuple(args.exclude),
        strict=args.strict,
        rep103=args.rep103,
        output_format=args.format,
        ros_distro=args.ros_distro,
        unit_suffixes=bool(getattr(args, "unit_suffixes", None)),
        cache_dir=args.cache_dir,
    )
    return flags.apply(settings)


def report(result: Result, settings: Config) -> int:
    from robotfix.diagnostics import Severity
    from robotfix.report.escape import shown_path

    errors, warnings = result.count(Severity.ERROR), result.count(Severity.WARNING)
    write_stdout(
        render(result, settings.output_format, errors, warnings, settings.strict)
    )
    for failure in result.internal_errors:
        print(
            f"robotfix: internal error while checking {shown_path(failure.path)}: "
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
    if result.internal_errors or any(d.code == "RF003" for d in result.diagnostics):
        return EXIT_FAILURE
    if errors or (settings.strict and warnings):
        return EXIT_FOUND
    return EXIT_OK


def render(
    result: Result, fmt: str, errors: int, warnings: int, strict: bool = False
) -> str:
    # each format's renderer is imported when asked for (sarif's imports
    # importlib.resources: 4 M instructions of every text run)
    from robotfix.report import text
    from robotfix.rules import ALL_RULES

    unchecked = len(result.internal_errors)
    if fmt == "json":
        from robotfix.report import json_report

        return json_report.render(
            result.diagnostics,
            result.files,
            errors,
            warnings,
            result.seconds,
            unchecked,
        )
    if fmt == "sarif":
        from robotfix.report import sarif

        failed = [(f.path, f.summary) for f in result.internal_errors]
        return sarif.render(result.diagnostics, list(ALL_RULES.values()), failed)
    if fmt == "github":
        from robotfix.report import github

        return github.render(result.diagnostics)
    if fmt == "junit":
        from robotfix.report import junit

        return junit.render(
            result.diagnostics,
            result.checked,
            strict,
            result.seconds,
            internal_errors=[(e.path, e.summary) for e in result.internal_errors],
        )
    # The summary is timed only on a terminal: piped output stays byte-identical.
    terminal = sys.stdout is not None and sys.stdout.isatty()
    seconds = result.seconds if terminal else None
    summary = text.summary(result.files, errors, warnings, seconds, unchecked)
    if fmt == "concise":
        return text.render_concise(result.diagnostics) + summary + "\n"
    return text.render(result.diagnostics, _excerpts(result, SourceLines()), summary)


class SourceLines:
    """Source lines for excerpts, read once per file and numbered as the checker
    numbered them: Python files decoded and split as `ast` does (a PEP 263 cookie
    is honoured; a form feed or U+2028 is not a line break), interface files as
    `ros/msg.py` reads them."""

    def __init__(self) -> None:
        self._files: dict[str, list[str]] = {}

    def __call__(self, path: str, line: int) -> str | None:
        if path not in self._files:
            self._files[path] = _lines_of(path)
        found = self._files[path]
        return found[line - 1] if 0 < line <= len(found) else None


def _lines_of(path: str) -> list[str]:
    from robotfix import fs, source
    from robotfix.api import INTERFACE_SUFFIXES

    try:
        data = fs.read_regular(path)
    except fs.UnreadableError:
        return []
    if path.endswith(INTERFACE_SUFFIXES):
        return data.decode("utf-8", errors="replace").splitlines()
    try:
        return source.split_lines(source.decode(data))
    except (SyntaxError, UnicodeDecodeError, LookupError):
        return []


class OutputError(Exception):
    """Standard output is closed or cannot be written (a full disk)."""


def write_stdout(text: str) -> None:
    """Write and flush; OutputError when stdout is closed or fails, BrokenPipeError
    when the reader went away. A character the terminal's encoding lacks is
    written as an escape, never an error."""
    stream = sys.stdout
    if stream is None:
        raise OutputError("standard output is closed")
    if isinstance(stream, io.TextIOWrapper) and stream.errors == "strict":
        stream.reconfigure(errors="backslashreplace")
    try:
        stream.write(text)
        stream.flush()
    except BrokenPipeError:
        raise
    except (OSError, ValueError) as err:  # ValueError: the stream object is closed
        raise OutputError(_why(err)) from None


def flush_stdout() -> None:
    """Flush what print() left buffered; OutputError or BrokenPipeError as above.
    A stream our own code closed (the language server closes stdout when the client
    says `exit`) has nothing left to flush."""
    if sys.stdout is not None and not sys.stdout.closed:
        write_stdout("")


def _why(err: BaseException) -> str:
    if isinstance(err, OSError) and err.strerror:
        return err.strerror
    return str(err) or type(err).__name__


def _discard_stdout() -> None:
    """Point stdout at /dev/null, so the interpreter's flush at exit cannot fail
    again (and print "Exception ignored")."""
    stream = sys.stdout
    if stream is None:
        return
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        try:
            os.dup2(devnull, stream.fileno())
        finally:
            os.close(devnull)
    except (OSError, ValueError):
        sys.stdout = None


class Progress:
    """A one-line progress bar on stderr, shown only when stderr is a terminal."""

    def __init__(self) -> None:
        self._shown = False

    def __call__(self, done: int, total: int, path: str) -> None:
        if total < 20:
            return
        width = 30
        filled = width * done // total
        name = path if len(path) < 40 else "..." + path[-37:]
        sys.stderr.write(
            f"\r[{'#' * filled}{'.' * (width - filled)}] {done}/{total} {name:<40}"
        )
        sys.stderr.flush()
        self._shown = True

    def done(self) -> None:
        if self._shown:
            sys.stderr.write("\r" + " " * 80 + "\r")
            sys.stderr.flush()
