"""Machine-local JSON caches: unit resolutions, the standard message catalog.

The folder is `ROBOTFIX_CACHE_DIR`, else `$XDG_CACHE_HOME/robotfix` or
`~/.cache/robotfix`. Each cache is one JSON file stamped with a key (the install of
the library whose answers it stores); a missing, stale or corrupt file is ignored, and
a folder that cannot be written only costs speed.
"""

from __future__ import annotations

import json
import os
from importlib.util import find_spec
from pathlib import Path
from typing import Any


def cache_dir() -> Path:
    explicit = os.environ.get("ROBOTFIX_CACHE_DIR")
    if explicit:
        return Path(explicit)
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(
        os.path.expanduser("~"), ".cache"
    )
    return Path(base) / "robotfix"


def install_key(module: str, version: str) -> str:
    """Identifies an installed library without importing it (find_spec is ~1 ms)."""
    spec = find_spec(module)
    origin = spec.origin if spec is not None and spec.origin else "?"
    try:
        stamp = Path(origin).stat().st_mtime_ns
    except OSError:
        stamp = 0
    return f"{origin}:{stamp}:{version}"


class JsonCache:
    """A dict persisted as `<cache_dir>/<name>.json`, valid while `key` matches."""

    def __init__(self, name: str, key: str) -> None:
        self.name = name
        self.key = key
        self._entries: dict[str, Any] | None = None
        self._dirty = False

    @property
    def path(self) -> Path:
        return cache_dir() / f"{self.name}.json"

    @property
    def entries(self) -> dict[str, Any]:
        if self._entries is None:
            self._entries = {}
            try:
                data = json.loads(self.path.read_text(encoding="utf-8"))
                if isinstance(data, dict) and data.get("key") == self.key:
                    self._entries = dict(data["entries"])
            except (OSError, ValueError, KeyError, TypeError):
                pass
        return self._entries

    def put(self, key: str, value: Any) -> None:
        self.entries[key] = value
        self._dirty = True

    def save(self) -> None:
        if not self._dirty:
            return
        path = self.path
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            tmp = path.with_name(f"{path.name}.{os.getpid()}.tmp")
            payload = {"key": self.key, "entries": self._entries}
            tmp.write_text(json.dumps(payload, sort_keys=True), encoding="utf-8")
            tmp.replace(path)
            self._dirty = False
        except OSError:
            pass
