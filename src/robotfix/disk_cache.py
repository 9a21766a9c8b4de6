"""Machine-local JSON caches: unit resolutions, the standard message catalog.

The folder is `ROBOTFIX_CACHE_DIR`, else `$XDG_CACHE_HOME/robotfix` or
`~/.cache/robotfix`. Each cache is one JSON file stamped with a key (the install of
the library whose answers it stores), and the file's name carries a hash of that key,
so two installs on one machine (two venvs, a venv and pipx) each keep their own file
instead of overwriting each other's on every run. A missing, stale or corrupt file
is ignored, and a folder that cannot be written only costs speed. The file is read
only when it is a regular file (a FIFO or a device there is ignored, never waited
on) and replaced atomically through a fresh temporary file, never written through a
symlink.

A cache holds data only: it is read with `json.loads` into plain values (the units
cache checks each entry before use, `units._is_resolution`); nothing in the folder
is unpickled, imported or run. (pint's own registry cache is a pickle: RobotFix does
not use it, and never reads the `pint/` folder older versions left here.)
"""

from __future__ import annotations

import hashlib
import json
import os
from importlib.util import find_spec
from pathlib import Path
from typing import Any

from robotfix import fs

MAX_BYTES = 64 * 1024 * 1024  # the standard message catalog is ~50 kB


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


def is_text(value: Any, errors: str = "strict") -> bool:
    """Whether a value read from a cache is a str that encodes as UTF-8, as every
    string RobotFix writes there does (a lone surrogate would raise where the string
    is hashed or printed). errors="surrogateescape": a path, which may also hold the
    bytes of a non-UTF-8 name as `os.fsdecode` gives them."""
    if not isinstance(value, str):
        return False
    if value.isascii():
        return True
    try:
        value.encode("utf-8", errors)
    except UnicodeEncodeError:
        return False
    return True


class JsonCache:
    """A dict persisted as `<cache_dir>/<name>-<hash of key>.json`, valid while `key`
    matches (the key is stored in the file too)."""

    def __init__(self, name: str, key: str) -> None:
        self.name = name
        self.key = key
        self._entries: dict[str, Any] | None = None
        self._dirty = False

    @property
    def path(self) -> Path:
        digest = hashlib.sha256(self.key.encode("utf-8", "replace")).hexdigest()
        return cache_dir() / f"{self.name}-{digest[:16]}.json"

    @property
    def entries(self) -> dict[str, Any]:
        if self._entries is None:
            self._entries = {}
            try:
                data = json.loads(fs.read_regular(self.path, MAX_BYTES, follow=False))
            except (fs.UnreadableError, ValueError, RecursionError):
                data = None
            if (
                isinstance(data, dict)
                and data.get("key") == self.key
                and isinstance(data.get("entries"), dict)
            ):
                self._entries = data["entries"]
        return self._entries

    def put(self, key: str, value: Any) -> None:
        self.entries[key] = value
        self._dirty = True

    def save(self) -> None:
        if not self._dirty:
            return
        path = self.path
        payload = {"key": self.key, "entries": self._entries}
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            fs.atomic_write(path, json.dumps(payload, sort_keys=True).encode())
            self._dirty = False
        except (OSError, ValueError):
            pass
