"""`robotfix suggest`: propose `Annotated[..., "Unit('...')"]` for unannotated
variables whose unit the analysis can pin down, as a unified diff; `--apply` writes
it, only if the file has not changed since it was read.
"""

from __future__ import annotations

import ast
import difflib
import sys
from pathlib import Path

from robotfix import api
from robotfix.config import Config, ConfigError, load
from robotfix.discovery import install_space
from robotfix.ros.catalog import MsgCatalog


def run_suggest(paths: list[Path], msg_paths: list[Path], apply: bool) -> int:
    missing = [p for p in paths if not p.exists()]
    for path in missing:
        print(f"robotfix: error: {path}: no such file or directory", file=sys.stderr)
    if missing:
        return 2
    try:
        settings = load(paths[0])
    except ConfigError as err:
        print(f"robotfix: error: {err}", file=sys.stderr)
        return 2
    catalog = _catalog(paths, msg_paths, settings)
    status = 0
    for file in api.python_files(paths, settings):
        original = file.read_bytes()
        try:
            text = original.decode("utf-8")
        except UnicodeDecodeError:
            continue
        changed = annotate(text, str(file), catalog)
        if changed == text:
            continue
        sys.stdout.writelines(
            difflib.unified_diff(
                text.splitlines(keepends=True),
                changed.splitlines(keepends=True),
                f"a/{file}",
                f"b/{file}",
            )
        )
        if apply:
            if file.read_bytes() != original:
                print(
                    f"robotfix: {file} changed while it was read; not written",
                    file=sys.stderr,
                )
                status = 1
                continue
            file.write_text(changed, encoding="utf-8")
    return status


def _catalog(paths: list[Path], msg_paths: list[Path], settings: Config) -> MsgCatalog:
    folders = (
        list(msg_paths) + list(settings.msg_paths) + api.ros_interface_folders(paths)
    )
    return MsgCatalog(
        api.interface_files(folders),
        rep103=settings.rep103,
        distro=settings.ros_distro,
        installed=install_space(),
    )


def annotate(text: str, path: str, catalog: MsgCatalog) -> str:
    """The text with every suggestion applied, and `Annotated` imported if needed."""
    suggestions = api.unit_suggestions(text, path, catalog)
    if not suggestions:
        return text
    lines = text.splitlines(keepends=True)
    for s in sorted(suggestions, key=lambda s: (s.line, s.col), reverse=True):
        line = lines[s.line - 1]
        start = len(line.encode("utf-8")[: s.col].decode("utf-8", errors="replace"))
        end = start + len(s.name)
        if line[start:end] != s.name:
            continue
        annotation = f": Annotated[{s.kind}, \"Unit('{s.unit}')\"]"
        lines[s.line - 1] = line[:end] + annotation + line[end:]
    result = "".join(lines)
    if "Annotated" not in _imported_names(text):
        result = _add_import(result)
    return result


def _imported_names(text: str) -> set[str]:
    names: set[str] = set()
    for node in ast.parse(text).body:
        if isinstance(node, ast.ImportFrom):
            names.update(a.asname or a.name for a in node.names)
    return names


def _add_import(text: str) -> str:
    """`from typing import Annotated` after the docstring and `__future__` imports."""
    tree = ast.parse(text)
    after = 0
    for node in tree.body:
        docstring = (
            isinstance(node, ast.Expr)
            and isinstance(node.value, ast.Constant)
            and isinstance(node.value.value, str)
            and after == 0
            and node is tree.body[0]
        )
        future = isinstance(node, ast.ImportFrom) and node.module == "__future__"
        if docstring or future:
            after = node.end_lineno or after
        else:
            break
    lines = text.splitlines(keepends=True)
    lines.insert(after, "from typing import Annotated\n")
    return "".join(lines)
