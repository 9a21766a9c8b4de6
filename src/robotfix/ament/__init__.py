"""`ament_robotfix`: RobotFix with the interface of the ament linters (ament_flake8,
ament_mypy), for `colcon test` through a pytest file or ament_cmake's `ament_lint_auto`.

    ament_robotfix [PATH ...] [--exclude PATTERN ...] [--config FILE]
                   [--xunit-file FILE] [--msg-path DIR] [--strict]
                   [--cache-dir DIR | --no-cache] [--template]

`main(argv) -> int` and `main_with_errors(argv) -> (int, [problem lines])` are what a
package's `test/test_robotfix.py` calls (`ament_robotfix --template` prints one). The
paths default to the current folder, which `colcon test` sets to the package's source
folder. Folders holding an `AMENT_IGNORE` file are skipped. The per-file cache never
goes into the package: it is `--cache-dir` (the CMake function passes a folder of the
build space), else a folder of the user cache (`~/.cache/robotfix/ament/`, or under
`$ROBOTFIX_CACHE_DIR`) named after the checked paths.

Exit status as `robotfix check`: 0 no errors, 1 errors (warnings too with --strict),
2 bad usage, nothing to check, unreadable input or an internal failure. The xUnit
file, when asked for, says the same (see `robotfix.report.junit`).
"""

from __future__ import annotations

import argparse
import hashlib
import os
import sys
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from robotfix.api import Result
    from robotfix.config import Config

EXIT_OK, EXIT_FOUND, EXIT_FAILURE = 0, 1, 2
IGNORE_MARKER = "AMENT_IGNORE"
TEMPLATE = "data/test_robotfix.py"  # in this package


def main(argv: list[str] | None = None) -> int:
    """The console script: the exit status only."""
    status, _ = main_with_errors(argv)
    return status


def main_with_errors(argv: list[str] | None = None) -> tuple[int, list[str]]:
    """The exit status, and one line per problem that fails the check."""
    args = _parser().parse_args(argv)
    if args.template:
        sys.stdout.write(template())
        return EXIT_OK, []
    try:
        return _run(args)
    except KeyboardInterrupt:
        return EXIT_FAILURE, ["interrupted"]


def template() -> str:
    """The `test/test_robotfix.py` that users copy next to `test_flake8.py`."""
    from importlib import resources

    return resources.files(__name__).joinpath(TEMPLATE).read_text(encoding="utf-8")


def _parser() -> argparse.ArgumentParser:
    from robotfix.cli import add_msg_path_argument

    parser = argparse.ArgumentParser(
        prog="ament_robotfix",
        description="Check units, frames and refinements in ROS Python code "
        "(RobotFix, with the interface of the ament linters).",
    )
    parser.add_argument(
        "paths",
        nargs="*",
        default=[os.curdir],
        metavar="PATH",
        help="files or folders to check (default: the current folder)",
    )
    parser.add_argument(
        "--exclude",
        nargs="*",
        action="extend",
        default=[],
        dest="excludes",
        metavar="PATTERN",
        help="file names or gitignore-style patterns to skip",
    )
    parser.add_argument(
        "--config",
        type=Path,
        default=None,
        metavar="FILE",
        help="a TOML file with a [tool.robotfix] table "
        "(default: the nearest pyproject.toml)",
    )
    parser.add_argument(
        "--xunit-file",
        type=Path,
        default=None,
        metavar="FILE",
        help="also write the results as xUnit XML (a test case per file)",
    )
    add_msg_path_argument(parser)
    parser.add_argument(
        "--strict", action="store_true", help="warnings fail the check too"
    )
    cache = parser.add_mutually_exclusive_group()
    cache.add_argument(
        "--cache-dir",
        type=Path,
        default=None,
        metavar="DIR",
        help="the per-file cache folder (default: in the user cache, never in "
        "the package)",
    )
    cache.add_argument(
        "--no-cache", action="store_true", help="neither read nor write a cache"
    )
    parser.add_argument(
        "--template",
        action="store_true",
        help="print a test/test_robotfix.py for an ament_python package and exit",
    )
    return parser


def _run(args: argparse.Namespace) -> tuple[int, list[str]]:
    from robotfix import api, cli, config
    from robotfix.run import default_jobs

    paths = [Path(p) for p in args.paths]
    missing = [p for p in paths if not p.exists() and not p.is_symlink()]
    if missing:
        return _fail([f"{p}: no such file or directory" for p in missing])
    try:
        if args.config is not None:
            if not args.config.is_file():
                return _fail([f"{args.config}: no such config file"])
            settings = config.load_file(args.config)
            if settings.source is None:
                return _fail([f"{args.config}: has no [tool.robotfix] table"])
        else:
            settings = config.load(paths[0])
    except config.ConfigError as err:
        return _fail([str(err)])
    named = paths
    paths, ignored = ament_ignored(paths, settings.root)
    for path in named:
        if path not in paths:
            print(
                f"ament_robotfix: skipped {path}: in a folder with {IGNORE_MARKER}",
                file=sys.stderr,
            )
    flags = config.Flags(
        msg_paths=tuple(args.msg_path),
        strict=args.strict or None,
        output_format="text",
        exclude=tuple(args.excludes) + ignored,
        cache_dir=args.cache_dir or default_cache_dir(paths),
    )
    settings = flags.apply(settings)
    if args.config is not None:  # its settings for every file, as ruff's --config
        settings = replace(settings, flags=None)
    try:
        result = api.check_paths(
            paths, settings, jobs=default_jobs(), use_cache=not args.no_cache
        )
    except config.ConfigError as err:  # a nested package's configuration
        return _fail([str(err)])
    if not result.checked:
        return _fail(["no Python files found in " + ", ".join(map(str, named))])
    status = cli.report(result, settings)
    print("\nChecked files:\n" + "\n".join(f"* {f}" for f in result.checked))
    if args.xunit_file is not None:
        try:
            write_xunit(args.xunit_file, result, settings)
        except OSError as err:
            return _fail([f"{args.xunit_file}: cannot write: {err.strerror}"])
    return status, problems(result, settings.strict)


def _fail(lines: list[str]) -> tuple[int, list[str]]:
    for line in lines:
        print(f"ament_robotfix: error: {line}", file=sys.stderr)
    return EXIT_FAILURE, lines


def problems(result: Result, strict: bool) -> list[str]:
    """The lines that fail the check: diagnostics, then files RobotFix failed on."""
    from robotfix.report import junit
    from robotfix.report.text import render_concise

    failing = [
        d for d in result.diagnostics if junit.fails(d, strict) or d.code == "RF003"
    ]
    crashed = [f"{e.path}: internal error: {e.summary}" for e in result.internal_errors]
    return render_concise(failing).splitlines() + crashed


def write_xunit(path: Path, result: Result, settings: Config) -> None:
    """The results as xUnit XML, named as ament names its linters' results:
    `<folder>.<file>` from `.../<folder>/<file>.xunit.xml`."""
    from robotfix import fs
    from robotfix.report import junit

    name = path.name.removesuffix(".xml").removesuffix(".xunit")
    suite = f"{path.absolute().parent.name}.{name}"
    xml = junit.render(
        result.diagnostics,
        result.checked,
        settings.strict,
        result.seconds,
        suite=suite,
        internal_errors=[(e.path, e.summary) for e in result.internal_errors],
    )
    path.absolute().parent.mkdir(parents=True, exist_ok=True)
    fs.atomic_write(path, xml.encode("utf-8"))


def ament_ignored(paths: list[Path], root: Path) -> tuple[list[Path], tuple[str, ...]]:
    """The paths without those inside a folder holding AMENT_IGNORE, and exclude
    patterns (relative to `root`, as Config matches them) for such folders below."""
    kept: list[Path] = []
    patterns: list[str] = []
    for path in paths:
        if any((p / IGNORE_MARKER).exists() for p in _folders_up_to(path, root)):
            continue
        kept.append(path)
        if not path.is_dir():
            continue
        for folder, names, files in os.walk(path):
            names[:] = sorted(
                n for n in names if not n.startswith(".") and n != "__pycache__"
            )
            if IGNORE_MARKER in files and Path(folder) != path:
                patterns.append(_anchored(Path(folder), root))
                names[:] = []
    return kept, tuple(patterns)


def _folders_up_to(path: Path, root: Path) -> list[Path]:
    """`path` (if a folder) and its parents, as far as `root` or the filesystem root."""
    here = path.resolve()
    folders = [here] if here.is_dir() else []
    top = root.resolve()
    for parent in here.parents:
        if top not in (parent, *parent.parents):
            break
        folders.append(parent)
    return folders


def _anchored(folder: Path, root: Path) -> str:
    """A pattern for everything under `folder`, from `root` (`a/b/**` matches only
    there, unlike `b/`, which matches at any depth)."""
    try:
        relative = folder.resolve().relative_to(root.resolve()).as_posix()
    except ValueError:
        relative = folder.as_posix()
    return f"{relative}/**"


def default_cache_dir(paths: list[Path]) -> Path:
    """A folder of the user cache for these paths: never the package's own folder."""
    from robotfix.disk_cache import cache_dir

    key = "\n".join(sorted(os.path.abspath(p) for p in paths))
    return cache_dir() / "ament" / hashlib.sha256(key.encode()).hexdigest()[:16]
