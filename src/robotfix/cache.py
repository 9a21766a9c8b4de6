"""Per-file results under `.robotfix_cache/`, as ruff and mypy keep them.

An entry is reused only when the file's bytes, its per-file ignores, the run key
(RobotFix's version, the settings that change results, the unit and message
libraries) and the definition of every message type the file looked up are all
unchanged: changing one `.msg` re-checks exactly the files that use it. A missing,
corrupt or foreign cache is ignored and rebuilt; a cache that cannot be written only
costs speed.
"""

from __future__ import annotations

import hashlib
import json
import os
import sys
from pathlib import Path
from typing import Any

from robotfix import __version__, rules
from robotfix.config import Config
from robotfix.diagnostics import Diagnostic, Note, Span
from robotfix.disk_cache import install_key
from robotfix.ros.catalog import MsgCatalog

FORMAT = 1


def run_key(config: Config) -> str:
    parts = [
        f"robotfix {__version__}",
        f"format {FORMAT}",
        f"python {sys.version_info[0]}.{sys.version_info[1]}",
        f"rep103 {config.rep103}",
        f"distro {config.ros_distro}",
        install_key("pint", ""),
        install_key("rosbags", ""),
        install_key("z3", ""),
    ]
    return hashlib.sha256("\n".join(parts).encode()).hexdigest()


class ResultCache:
    def __init__(self, folder: Path, key: str) -> None:
        self.path = folder / "results.json"
        self.key = key
        self._entries: dict[str, Any] = {}
        self._dirty = False
        try:
            data = json.loads(self.path.read_text(encoding="utf-8"))
            if isinstance(data, dict) and data.get("key") == key:
                self._entries = dict(data["entries"])
        except (OSError, ValueError, KeyError, TypeError):
            pass

    def get(
        self, path: Path, data: bytes, config: Config, catalog: MsgCatalog
    ) -> list[Diagnostic] | None:
        entry = self._entries.get(str(path))
        if not isinstance(entry, dict) or entry.get("file") != _file_key(
            data, path, config
        ):
            return None
        try:
            deps = entry["types"]
            if any(catalog.fingerprint(name) != fp for name, fp in deps.items()):
                return None
            return [_load(d) for d in entry["diagnostics"]]
        except (KeyError, TypeError, ValueError, IndexError):
            return None

    def put(
        self,
        path: Path,
        data: bytes,
        config: Config,
        catalog: MsgCatalog,
        diagnostics: list[Diagnostic],
        types: list[str],
    ) -> None:
        self._entries[str(path)] = {
            "file": _file_key(data, path, config),
            "types": {name: catalog.fingerprint(name) for name in types},
            "diagnostics": [_dump(d) for d in diagnostics],
        }
        self._dirty = True

    def save(self) -> None:
        if not self._dirty:
            return
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            gitignore = self.path.parent / ".gitignore"
            if not gitignore.exists():
                gitignore.write_text("# Created by robotfix\n*\n", encoding="utf-8")
            tmp = self.path.with_name(f"results.{os.getpid()}.tmp")
            payload = {"key": self.key, "entries": self._entries}
            tmp.write_text(json.dumps(payload, sort_keys=True), encoding="utf-8")
            tmp.replace(self.path)
        except OSError:
            pass


def _file_key(data: bytes, path: Path, config: Config) -> str:
    ignored = ",".join(sorted(config.ignored_codes(path)))
    return hashlib.sha256(data + b"\0" + ignored.encode()).hexdigest()


def _dump(d: Diagnostic) -> list[Any]:
    span = [d.span.line, d.span.col, d.span.end_line, d.span.end_col]
    return [
        d.code,
        d.path,
        span,
        d.message,
        [[n.message, n.path, n.line] for n in d.notes],
    ]


def _load(raw: list[Any]) -> Diagnostic:
    code, path, span, message, notes = raw
    return Diagnostic(
        rules.ALL_RULES[code],
        path,
        Span(*span),
        message,
        tuple(Note(m, p, line) for m, p, line in notes),
    )
