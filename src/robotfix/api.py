"""The public entry points: `check_source` for one text, `check_paths` for a run.

Here the layers meet: files are found and read, the catalog is built, the analysis
runs with a solver callback (z3 is imported only when a first VC needs it), and
diagnostics are filtered by suppressions, sorted and de-duplicated.
"""

from __future__ import annotations

import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path

from robotfix import messages, rules
from robotfix.analysis.vc import VC, Verdict
from robotfix.config import Config
from robotfix.diagnostics import Diagnostic, Severity
from robotfix.ros.catalog import MsgCatalog
from robotfix.source import SourceFile

INTERFACE_SUFFIXES = (".msg", ".srv", ".action")


@dataclass
class InternalError:
    path: str
    summary: str  # one line: the exception
    detail: str  # the traceback, shown only on request


@dataclass
class Result:
    diagnostics: list[Diagnostic] = field(default_factory=list)
    files: int = 0
    seconds: float = 0.0
    internal_errors: list[InternalError] = field(default_factory=list)

    def count(self, severity: Severity) -> int:
        return sum(1 for d in self.diagnostics if d.severity is severity)


def discharge(vc: VC) -> Verdict:
    from robotfix.smt.solver import check  # z3 costs ~70 ms: only when needed

    return check(vc)


def check_source(
    text: str,
    path: str,
    config: Config | None = None,
    catalog: MsgCatalog | None = None,
) -> list[Diagnostic]:
    """Diagnostics for one Python source text (no file system access but .msg files)."""
    config = config or Config()
    if catalog is None:
        catalog = MsgCatalog(
            interface_files(list(config.msg_paths)), rep103=config.rep103
        )
    return _finish(_check(SourceFile.from_text(path, text), catalog))


def check_paths(paths: list[Path], config: Config) -> Result:
    """Check every Python file under `paths`; interface files come from the msg paths
    and from the msg/srv/action folders of ROS packages under `paths`."""
    started = time.perf_counter()
    result = Result()
    folders = list(config.msg_paths) + ros_interface_folders(paths)
    catalog = MsgCatalog(interface_files(folders), rep103=config.rep103)
    for problem in catalog_problems(catalog):
        result.diagnostics.append(problem)
    for file in python_files(paths):
        result.files += 1
        try:
            data = file.read_bytes()
        except OSError as err:
            result.diagnostics.append(
                messages.unreadable(str(file), f"cannot read: {err.strerror}")
            )
            continue
        try:
            result.diagnostics.extend(
                _check(SourceFile.from_bytes(str(file), data), catalog)
            )
        except (
            Exception
        ) as err:  # a fault of ours: report it, go on with the other files
            summary = f"{type(err).__name__}: {err}"
            result.internal_errors.append(
                InternalError(str(file), summary, traceback.format_exc())
            )
    result.diagnostics = _finish(result.diagnostics)
    _save_caches(catalog)
    result.seconds = time.perf_counter() - started
    return result


def _check(source: SourceFile, catalog: MsgCatalog) -> list[Diagnostic]:
    from robotfix.analysis.context import FileContext
    from robotfix.analysis.interpreter import analyze_module

    if source.problem is not None:
        return [source.problem]
    ctx = FileContext(source, catalog, discharge)
    analyze_module(ctx)
    return [d for d in ctx.diagnostics if not source.is_suppressed(d)]


def catalog_problems(catalog: MsgCatalog) -> list[Diagnostic]:
    catalog.lookup("std_msgs/Header")  # loads the interface files
    return [
        messages.annotation_problem(p.path, p.line, p.col, p.rule, p.message)
        for p in catalog.problems
    ]


def _finish(diagnostics: list[Diagnostic]) -> list[Diagnostic]:
    """Sorted, without exact duplicates, and one RF508 note per message type per run."""
    unique = {(d.sort_key(), d.notes): d for d in diagnostics}
    result: list[Diagnostic] = []
    noted: set[str] = set()
    for key in sorted(unique, key=lambda k: k[0]):
        diag = unique[key]
        if diag.rule is rules.UNKNOWN_MESSAGE_CLASS:
            if diag.message in noted:
                continue
            noted.add(diag.message)
        result.append(diag)
    return result


def _save_caches(catalog: MsgCatalog) -> None:
    from robotfix.annotations.units import save_cache

    save_cache()
    catalog.save()


def python_files(paths: list[Path]) -> list[Path]:
    found: list[Path] = []
    for path in paths:
        if path.is_dir():
            found.extend(
                p
                for p in sorted(path.rglob("*.py"))
                if (p.is_file() or p.is_symlink()) and not _hidden(p.relative_to(path))
            )
        else:
            found.append(path)
    return sorted(dict.fromkeys(found))


def interface_files(folders: list[Path]) -> list[Path]:
    found: list[Path] = []
    for folder in folders:
        if folder.is_file() and folder.suffix in INTERFACE_SUFFIXES:
            found.append(folder)
        elif folder.is_dir():
            found.extend(
                p
                for p in sorted(folder.rglob("*"))
                if p.suffix in INTERFACE_SUFFIXES and p.is_file()
            )
    return found


def ros_interface_folders(paths: list[Path]) -> list[Path]:
    """The msg/, srv/, action/ folders of ROS packages (folders with package.xml)."""
    folders: list[Path] = []
    for path in paths:
        root = path if path.is_dir() else path.parent
        candidates = [root, *root.parents] if path.is_file() else [root]
        packages = [c for c in candidates if (c / "package.xml").is_file()][:1]
        if path.is_dir():
            packages += [
                p.parent
                for p in sorted(path.rglob("package.xml"))
                if not _hidden(p.relative_to(path))
            ]
        for package in packages:
            folders.extend(
                package / name
                for name in ("msg", "srv", "action")
                if (package / name).is_dir()
            )
    return sorted(dict.fromkeys(folders))


def _hidden(relative: Path) -> bool:
    return any(
        part.startswith(".") or part in ("__pycache__", "node_modules")
        for part in relative.parts[:-1]
    )
