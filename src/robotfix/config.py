"""Config: the settings of a run, from flags and `[tool.robotfix]` in pyproject.toml.

`pyproject.toml` is found by walking up from the first checked path. Keys use the
flags' spelling: `msg-paths` (relative to that file), `strict`, `rep103`, `format`.
"""

from __future__ import annotations

import re
import sys
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

KEYS = {"msg-paths", "strict", "rep103", "format"}
FORMATS = ("text", "json")


class ConfigError(Exception):
    """A pyproject.toml that cannot be used; the message names file and line."""


@dataclass(frozen=True)
class Config:
    msg_paths: tuple[Path, ...] = ()
    strict: bool = False
    rep103: bool = True
    output_format: str = "text"
    source: Path | None = field(default=None, compare=False)


def find_pyproject(start: Path) -> Path | None:
    here = start.resolve()
    if here.is_file() or not here.exists():
        here = here.parent
    for folder in (here, *here.parents):
        candidate = folder / "pyproject.toml"
        if candidate.is_file():
            return candidate
    return None


def load(start: Path, base: Config | None = None) -> Config:
    """Settings from the nearest pyproject.toml with a [tool.robotfix] table."""
    config = base or Config()
    path = find_pyproject(start)
    if path is None:
        return config
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as err:
        line = re.search(r"line (\d+)", str(err))
        where = f"{path}:{line.group(1)}" if line else str(path)
        raise ConfigError(f"{where}: cannot parse TOML: {err}") from None
    except (OSError, UnicodeDecodeError) as err:
        raise ConfigError(f"{path}: cannot read: {err}") from None
    table = data.get("tool", {}).get("robotfix")
    if table is None:
        return config
    return _apply(config, table, path)


def _apply(config: Config, table: Any, path: Path) -> Config:
    if not isinstance(table, dict):
        raise ConfigError(f"{path}: [tool.robotfix] must be a table")
    unknown = sorted(set(table) - KEYS)
    if unknown:
        raise ConfigError(
            f"{path}: unknown [tool.robotfix] setting `{unknown[0]}` "
            f"(known: {', '.join(sorted(KEYS))})"
        )
    msg_paths = table.get("msg-paths", [])
    if not isinstance(msg_paths, list) or not all(
        isinstance(p, str) for p in msg_paths
    ):
        raise ConfigError(f"{path}: `msg-paths` must be a list of folder names")
    for key in ("strict", "rep103"):
        if key in table and not isinstance(table[key], bool):
            raise ConfigError(f"{path}: `{key}` must be true or false")
    fmt = table.get("format", config.output_format)
    if fmt not in FORMATS:
        raise ConfigError(f"{path}: `format` must be one of {', '.join(FORMATS)}")
    return replace(
        config,
        msg_paths=config.msg_paths + tuple(path.parent / p for p in msg_paths),
        strict=table.get("strict", config.strict),
        rep103=table.get("rep103", config.rep103),
        output_format=fmt,
        source=path,
    )
