"""Config: the settings of a run, from flags and `[tool.robotfix]` in pyproject.toml.

`pyproject.toml` is found by walking up from the first checked path. Keys use the
flags' spelling: `msg-paths` (relative to that file), `strict`, `rep103`, `format`.
"""

from __future__ import annotations

import fnmatch
import re
import sys
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

KEYS = {
    "msg-paths",
    "strict",
    "rep103",
    "format",
    "exclude",
    "per-file-ignores",
    "ros-distro",
}
FORMATS = ("text", "concise", "json", "sarif", "github", "junit")
DISTROS = ("ros2", "ros1", "jazzy", "humble", "iron", "kilted", "rolling", "noetic")


class ConfigError(Exception):
    """A pyproject.toml that cannot be used; the message names file and line."""


@dataclass(frozen=True)
class Config:
    msg_paths: tuple[Path, ...] = ()
    strict: bool = False
    rep103: bool = True
    output_format: str = "text"
    exclude: tuple[str, ...] = ()  # gitignore-style patterns
    per_file_ignores: tuple[tuple[str, frozenset[str]], ...] = ()  # (pattern, codes)
    ros_distro: str = "ros2"
    root: Path = field(
        default_factory=Path.cwd, compare=False
    )  # patterns are relative to it
    source: Path | None = field(default=None, compare=False)
    # where per-file results are cached (None: `.robotfix_cache/` in `root`)
    cache_dir: Path | None = field(default=None, compare=False)

    def excluded(self, path: Path) -> bool:
        return any(matches(pattern, self._relative(path)) for pattern in self.exclude)

    def ignored_codes(self, path: Path) -> frozenset[str]:
        relative = self._relative(path)
        found: frozenset[str] = frozenset()
        for pattern, codes in self.per_file_ignores:
            if matches(pattern, relative):
                found |= codes
        return found

    def _relative(self, path: Path) -> str:
        try:
            return path.resolve().relative_to(self.root.resolve()).as_posix()
        except ValueError:
            return path.as_posix()


def matches(pattern: str, relative: str) -> bool:
    """gitignore-style: `name` matches at any depth, `a/b` from the root, `dir/` a
    folder and all below it, `*` within a name, `**` across folders."""
    pattern = pattern.strip()
    directory = pattern.endswith("/")
    pattern = pattern.strip("/")
    parts = relative.split("/")
    candidates = ["/".join(parts[: i + 1]) for i in range(len(parts))]
    if directory:
        candidates = candidates[:-1] if len(candidates) > 1 else []
    if "/" not in pattern:
        return any(
            fnmatch.fnmatchcase(c.rsplit("/", 1)[-1], pattern) for c in candidates
        )
    regex = re.escape(pattern).replace(r"\*\*/", "(?:.*/)?").replace(r"\*\*", ".*")
    regex = regex.replace(r"\*", "[^/]*").replace(r"\?", "[^/]")
    return any(re.fullmatch(regex, c) for c in candidates)


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
    return load_file(path, config)


def load_file(path: Path, base: Config | None = None) -> Config:
    """Settings from the [tool.robotfix] table of one TOML file (`--config FILE`);
    patterns and msg-paths are relative to its folder."""
    config = base or Config()
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
    msg_paths = _strings(table, "msg-paths", path)
    exclude = _strings(table, "exclude", path)
    for key in ("strict", "rep103"):
        if key in table and not isinstance(table[key], bool):
            raise ConfigError(f"{path}: `{key}` must be true or false")
    fmt = table.get("format", config.output_format)
    if fmt not in FORMATS:
        raise ConfigError(f"{path}: `format` must be one of {', '.join(FORMATS)}")
    distro = table.get("ros-distro", config.ros_distro)
    if distro not in DISTROS:
        raise ConfigError(f"{path}: `ros-distro` must be one of {', '.join(DISTROS)}")
    ignores = table.get("per-file-ignores", {})
    if not isinstance(ignores, dict) or not all(
        isinstance(v, list) and all(isinstance(c, str) for c in v)
        for v in ignores.values()
    ):
        raise ConfigError(
            f"{path}: `per-file-ignores` must map patterns to code lists, "
            f'e.g. {{"tests/**" = ["RF102"]}}'
        )
    return replace(
        config,
        msg_paths=config.msg_paths + tuple(path.parent / p for p in msg_paths),
        strict=table.get("strict", config.strict),
        rep103=table.get("rep103", config.rep103),
        output_format=fmt,
        exclude=config.exclude + tuple(exclude),
        per_file_ignores=config.per_file_ignores
        + tuple((k, frozenset(v)) for k, v in ignores.items()),
        ros_distro=distro,
        root=path.parent,
        source=path,
    )


def _strings(table: dict[str, Any], key: str, path: Path) -> list[str]:
    value = table.get(key, [])
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise ConfigError(f"{path}: `{key}` must be a list of strings")
    return value
