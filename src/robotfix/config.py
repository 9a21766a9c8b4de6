"""Config: the settings of a run, from flags and `[tool.robotfix]` in pyproject.toml.

`pyproject.toml` is found by walking up from the first checked path. Keys use the
flags' spelling: `msg-paths` and `stub-paths` (relative to that file), `strict`,
`rep103`, `format`, `unit-suffixes`.
"""

from __future__ import annotations

import fnmatch
import os
import re
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from robotfix import tomlfile
from robotfix.fs import UnreadableError, read_text

KEYS = {
    "msg-paths",
    "stub-paths",
    "strict",
    "rep103",
    "format",
    "exclude",
    "per-file-ignores",
    "python-paths",
    "ros-distro",
    "unit-suffixes",
}
FORMATS = ("text", "concise", "json", "sarif", "github", "junit")
MAX_PYPROJECT_BYTES = 4 * 1024 * 1024  # a real pyproject.toml is a few kB
DISTROS = ("ros2", "ros1", "jazzy", "humble", "iron", "kilted", "rolling", "noetic")


class ConfigError(Exception):
    """A pyproject.toml that cannot be used; the message names file and line."""


@dataclass(frozen=True)
class Config:
    msg_paths: tuple[Path, ...] = ()
    # folders of `.pyi` stubs (`robotfix.stubs`), searched before the shipped ones
    stub_paths: tuple[Path, ...] = ()
    # folders where imported modules are looked for, before the checked file's own
    python_paths: tuple[Path, ...] = ()
    strict: bool = False
    rep103: bool = True
    output_format: str = "text"
    exclude: tuple[str, ...] = ()  # gitignore-style patterns
    per_file_ignores: tuple[tuple[str, frozenset[str]], ...] = ()  # (pattern, codes)
    ros_distro: str = "ros2"
    unit_suffixes: bool = False  # interface fields named `*_ms`, `*_deg` have units
    root: Path = field(
        default_factory=Path.cwd, compare=False
    )  # patterns are relative to it
    source: Path | None = field(default=None, compare=False)
    # where per-file results are cached (None: `.robotfix_cache/` in `root`)
    cache_dir: Path | None = field(default=None, compare=False)

    def excluded(self, path: Path, folder: bool = False) -> bool:
        """Whether an `exclude` pattern matches the file (or, with folder=True, the
        folder and so everything below it)."""
        if not self.exclude:
            return False
        relative = self._relative(path)
        return any(matches(pattern, relative, folder) for pattern in self.exclude)

    def ignored_codes(self, path: Path) -> frozenset[str]:
        if not self.per_file_ignores:
            return frozenset()  # no path to work out: a cached run asks per file
        relative = self._relative(path)
        found: frozenset[str] = frozenset()
        for pattern, codes in self.per_file_ignores:
            if matches(pattern, relative):
                found |= codes
        return found

    def _relative(self, path: Path) -> str:
        """The path as seen from the root: as spelled first (a folder reached
        through a symlink keeps the link's name), else with symlinks resolved."""
        for here, root in (
            (os.path.abspath(path), os.path.abspath(self.root)),
            (os.path.realpath(path), os.path.realpath(self.root)),
        ):
            try:
                return Path(here).relative_to(root).as_posix()
            except ValueError:
                continue
        return path.as_posix()


def matches(pattern: str, relative: str, folder: bool = False) -> bool:
    """gitignore-style: `name` matches at any depth, `a/b` from the root, `dir/` a
    folder and all below it, `*` within a name, `**` across folders.

    The pattern is matched segment by segment against the path's folders, keeping
    the set of positions reached: linear in the number of segments whatever the
    pattern (repeated `**/` cannot backtrack), and `*` within a segment is
    fnmatch's, which does not backtrack either. `relative` is a file's path, or a
    folder's with folder=True (then `dir/` matches the folder itself)."""
    pattern = pattern.strip()
    directory = pattern.endswith("/")
    pattern = pattern.strip("/")
    if not pattern:
        return False
    parts = relative.split("/")
    # how many leading segments may form a match: a `dir/` pattern needs a folder
    last = len(parts) if folder or not directory else len(parts) - 1
    if "/" not in pattern:
        return any(fnmatch.fnmatchcase(part, pattern) for part in parts[:last])
    segments = [s for s in pattern.split("/") if s]
    collapsed = [
        s
        for i, s in enumerate(segments)
        if not (s == "**" and segments[i - 1 : i] == ["**"])
    ]
    reached = {0}  # how many path segments the pattern's prefix can consume
    for index, segment in enumerate(collapsed):
        if segment == "**":
            # across folders: zero or more, but a trailing `**` needs one at least
            least = min(reached) + (1 if index == len(collapsed) - 1 else 0)
            reached = set(range(least, len(parts) + 1))
        else:
            reached = {
                at + 1
                for at in reached
                if at < len(parts) and fnmatch.fnmatchcase(parts[at], segment)
            }
        if not reached:
            return False
    return any(1 <= at <= last for at in reached)


def find_pyproject(start: Path) -> Path | None:
    here = Path(os.path.realpath(start))
    if not os.path.isdir(here):  # os.path never raises (a path too long, a loop)
        here = here.parent
    for folder in (here, *here.parents):
        candidate = folder / "pyproject.toml"
        if os.path.isfile(candidate):
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
        data = tomlfile.loads(read_text(path, MAX_PYPROJECT_BYTES))
    except tomlfile.TomlError as err:
        line = re.search(r"line (\d+)", str(err))
        where = f"{path}:{line.group(1)}" if line else str(path)
        raise ConfigError(f"{where}: cannot parse TOML: {err}") from None
    except RecursionError:
        raise ConfigError(f"{path}: cannot parse TOML: nested too deeply") from None
    except UnreadableError as err:
        raise ConfigError(f"{path}: cannot read: {err.reason}") from None
    tool = data.get("tool")
    if tool is None:
        return config
    if not isinstance(tool, dict):
        raise ConfigError(f"{path}: `tool` must be a table ([tool.robotfix])")
    table = tool.get("robotfix")
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
    stub_paths = _strings(table, "stub-paths", path)
    python_paths = _strings(table, "python-paths", path)
    exclude = _strings(table, "exclude", path)
    for key in ("strict", "rep103", "unit-suffixes"):
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
        stub_paths=config.stub_paths + tuple(path.parent / p for p in stub_paths),
        python_paths=config.python_paths + tuple(path.parent / p for p in python_paths),
        strict=table.get("strict", config.strict),
        rep103=table.get("rep103", config.rep103),
        output_format=fmt,
        exclude=config.exclude + tuple(exclude),
        per_file_ignores=config.per_file_ignores
        + tuple((k, frozenset(v)) for k, v in ignores.items()),
        ros_distro=distro,
        unit_suffixes=table.get("unit-suffixes", config.unit_suffixes),
        root=path.parent,
        source=path,
    )


def _strings(table: dict[str, Any], key: str, path: Path) -> list[str]:
    value = table.get(key, [])
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise ConfigError(f"{path}: `{key}` must be a list of strings")
    return value
