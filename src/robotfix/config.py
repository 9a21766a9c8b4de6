"""Config: the settings of a run, from flags and configuration files.

A configuration is the `[tool.robotfix]` table of a `pyproject.toml`, or the top
level of a `robotfix.toml` (which wins over a `pyproject.toml` in the same folder);
a `pyproject.toml` without the table is not one. Keys use the flags' spelling:
`msg-paths` and `stub-paths` (relative to that file), `strict`, `rep103`, `format`,
`unit-suffixes`; `extend` names another configuration whose settings this one
starts from (as ruff's `extend`).

Settings are resolved per file, as ruff resolves them: each file's are those of the
nearest configuration above it, with the flags over them (`Config.for_file`), so a
file gets the same findings whichever folder a run starts from. What is a setting
of the run, not of a file (`format`, `strict`, where the cache is, and `exclude`
patterns, which add up), comes from the configuration nearest the first path.
"""

from __future__ import annotations

import fnmatch
import os
import re
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from robotfix import tomlfile
from robotfix.fs import UnreadableError, asked, read_text, stamp

KEYS = {
    "extend",
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
CONFIG_FILES = ("robotfix.toml", "pyproject.toml")  # in one folder, the first wins
MAX_EXTENDS = 16  # `extend` chains deeper than this are a mistake (or a cycle)


class ConfigError(Exception):
    """A pyproject.toml that cannot be used; the message names file and line."""


@dataclass(frozen=True)
class Config:
    """The settings of a run, or of the files under one configuration."""

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
    # the command line's settings: with them, each file's settings are its nearest
    # configuration's, these over them (`for_file`); None: these settings for all
    flags: Flags | None = field(default=None, compare=False)
    # the configuration `extend` names: its patterns match from its own folder
    extends: Config | None = field(default=None, compare=False, repr=False)
    _nearest: dict[str, Config] = field(default_factory=dict, compare=False, repr=False)
    _found: dict[str, Path | None] = field(  # folder -> its nearest configuration
        default_factory=dict, compare=False, repr=False
    )
    _spelled: dict[str, Path | None] = field(  # the same, by the folder as spelled
        default_factory=dict, compare=False, repr=False
    )
    _folders: dict[str, str] = field(  # a path asked of `for_file` -> its folder
        default_factory=dict, init=False, compare=False, repr=False
    )

    def for_file(
        self, path: Path, folder: bool | None = None, real: str | None = None
    ) -> Config:
        """The settings of one file (or, with `folder`, a folder; None: either):
        those of the nearest configuration above it with the flags over them, or
        these when that is this run's own. `real`: a folder's real path, when
        the caller knows it (a walk does: not resolved again)."""
        if self.flags is None:
            return self
        raw = os.fspath(path)  # the folder as spelled: no realpath, no stat
        # a file's or a folder's: asked of the disk once a path (a run asks
        # again of every file: the cache's key, its check, its findings)
        folder_name = self._folders.get(raw) if folder is None else None
        if folder_name is None:
            if folder is None:
                folder = os.path.isdir(raw)
            folder_name = raw if folder else os.path.dirname(raw) or "."
            self._folders[raw] = folder_name
        if folder_name in self._spelled:
            found = self._spelled[folder_name]
        else:
            found = find(folder_name, self._found, real if folder else None)
            self._spelled[folder_name] = found
        if found == self.source:
            return self
        key = str(found)
        known = self._nearest.get(key)
        if known is None:
            loaded = load_file(found) if found is not None else Config()
            known = self._nearest[key] = self.flags.apply(loaded)
        return known

    def nested_sources(self) -> list[str]:
        """The configuration files `for_file` has read (for a cached discovery's
        trace: their `exclude` decides what it finds)."""
        return [key for key in self._nearest if key != "None"]

    def excluded(
        self, path: Path, folder: bool = False, real: str | None = None
    ) -> bool:
        """Whether an `exclude` pattern matches the file (or, with folder=True, the
        folder and so everything below it): this run's patterns, and those of the
        nearest configuration (each from its own folder; `real`: `for_file`'s)."""
        if self._excluded(path, folder):
            return True
        nearest = self.for_file(path, folder, real)
        return nearest is not self and nearest._excluded(path, folder)

    def _excluded(self, path: Path, folder: bool) -> bool:
        if self.extends is not None and self.extends._excluded(path, folder):
            return True
        if not self.exclude:
            return False
        relative = self._relative(path)
        return any(matches(pattern, relative, folder) for pattern in self.exclude)

    def silences(self, path: str | Path, *codes: str) -> bool:
        """Whether `per-file-ignores` silences one of `codes` (a rule's code, its
        name) in the file."""
        return not self.ignored_codes(Path(path)).isdisjoint(codes)

    def ignored_codes(self, path: Path) -> frozenset[str]:
        """The codes `per-file-ignores` silences in the file, by its nearest
        configuration (and those it extends)."""
        nearest = self.for_file(path)
        found = (
            frozenset()
            if nearest.extends is None
            else nearest.extends.ignored_codes(path)
        )
        if not nearest.per_file_ignores:
            return found  # no path to work out: a cached run asks per file
        relative = nearest._relative(path)
        for pattern, codes in nearest.per_file_ignores:
            if matches(pattern, relative):
                found |= codes
        return found

    def _relative(self, path: Path) -> str:
        """The path as seen from the root: as spelled first (a folder reached
        through a symlink keeps the link's name), else with symlinks resolved."""
        for resolve in (os.path.abspath, os.path.realpath):  # realpath: if need be
            try:
                return Path(resolve(path)).relative_to(resolve(self.root)).as_posix()
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


def find(
    start: str | os.PathLike[str],
    memo: dict[str, Path | None] | None = None,
    real: str | None = None,
) -> Path | None:
    """The nearest configuration at or above `start` (a file: its folder): a
    `robotfix.toml`, or a `pyproject.toml` with a [tool.robotfix] table. `real`:
    `start`'s real path, when known. The folders are real paths, walked up as
    text: only a configuration found is made a Path (a walk asks for every
    folder, whose parent `memo` knows)."""
    # in a run, a folder's real path is its parent's, once asked (`fs.asked`)
    folder = real if real is not None else asked("realpath", os.fspath(start))
    if not os.path.isdir(folder):  # os.path never raises (a path too long, a loop)
        folder = os.path.dirname(folder)
    seen: list[str] = []  # the folders looked at, each with the answer
    found: Path | None = None
    while True:
        if memo is not None and folder in memo:
            found = memo[folder]
            break
        seen.append(folder)
        candidates = [os.path.join(folder, name) for name in CONFIG_FILES]
        config = next((c for c in candidates if _is_config(c)), None)
        if config is not None:
            found = Path(config)
            break
        parent = os.path.dirname(folder)
        if parent == folder:
            break
        folder = parent
    if memo is not None:
        memo.update(dict.fromkeys(seen, found))
    return found


def _is_config(path: str) -> bool:
    return os.path.isfile(path) and _table(Path(path)) is not None


def load(start: Path, base: Config | None = None) -> Config:
    """Settings from the nearest configuration at or above `start` (`find`)."""
    config = base or Config()
    path = find(start)
    if path is None:
        return config
    return load_file(path, config)


def load_file(path: Path, base: Config | None = None) -> Config:
    """Settings from one configuration file (`--config FILE`): the [tool.robotfix]
    table of a pyproject.toml, the top level of any other TOML file; patterns and
    msg-paths are relative to its folder."""
    return _load(path, base or Config(), ())


def _load(path: Path, config: Config, chain: tuple[str, ...]) -> Config:
    table = _table(path)
    if table is None:
        return config
    extend = table.get("extend")
    if extend is None:
        return _apply(config, table, path)
    if not isinstance(extend, str):
        raise ConfigError(f"{path}: `extend` must be the path of a configuration")
    target = path.parent / extend
    if os.path.realpath(target) in chain or len(chain) >= MAX_EXTENDS:
        raise ConfigError(f"{path}: `extend` makes a cycle or a chain too long")
    if not os.path.isfile(target):
        raise ConfigError(f"{path}: `extend`: {target}: no such file")
    chain = (*chain, os.path.realpath(path))
    parent = _load(target, config, chain)
    # the extended file's patterns match from its own folder (`Config.extends`)
    start = replace(parent, exclude=config.exclude, per_file_ignores=(), extends=parent)
    return _apply(start, table, path)


# file -> (its stamp, its table)
_tables: dict[str, tuple[list[int] | None, dict[str, Any] | None]] = {}


def _table(path: Path) -> dict[str, Any] | None:
    """The settings table of a configuration file (None: it has none), read once
    while its stamp holds (`fs.stamp`)."""
    key = os.path.realpath(path)
    found = stamp(key)
    known = _tables.get(key)
    if known is not None and known[0] == found and found is not None:
        return known[1]
    table = _read_table(path)
    _tables[key] = (found, table)
    return table


def _read_table(path: Path) -> dict[str, Any] | None:
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
    if tool is not None and not isinstance(tool, dict):
        raise ConfigError(f"{path}: `tool` must be a table ([tool.robotfix])")
    if tool is None and path.name != "pyproject.toml":
        return dict(data)  # robotfix.toml: the settings at the top level
    table = None if tool is None else tool.get("robotfix")
    if table is None:
        return None
    if not isinstance(table, dict):
        raise ConfigError(f"{path}: [tool.robotfix] must be a table")
    return dict(table)


@dataclass(frozen=True)
class Flags:
    """What the command line sets, over every file's configuration: lists go
    first, a value given replaces the configuration's."""

    msg_paths: tuple[Path, ...] = ()
    stub_paths: tuple[Path, ...] = ()
    python_paths: tuple[Path, ...] = ()
    exclude: tuple[str, ...] = ()
    strict: bool | None = None
    rep103: bool | None = None
    output_format: str | None = None
    ros_distro: str | None = None
    unit_suffixes: bool = False
    cache_dir: Path | None = None

    def apply(self, config: Config) -> Config:
        return replace(
            config,
            msg_paths=self.msg_paths + config.msg_paths,
            stub_paths=self.stub_paths + config.stub_paths,
            python_paths=self.python_paths + config.python_paths,
            strict=config.strict if self.strict is None else self.strict,
            rep103=config.rep103 if self.rep103 is None else self.rep103,
            output_format=self.output_format or config.output_format,
            exclude=config.exclude + self.exclude,
            ros_distro=self.ros_distro or config.ros_distro,
            unit_suffixes=config.unit_suffixes or self.unit_suffixes,
            cache_dir=self.cache_dir or config.cache_dir,
            flags=self,
        )


def _apply(config: Config, table: dict[str, Any], path: Path) -> Config:
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


def by_settings(files: list[Path], config: Config) -> list[tuple[Config, list[Path]]]:
    """The files whose settings are not `config`'s (`Config.for_file`: their
    nearest configuration is another), grouped by those settings, in the order
    first met."""
    groups: dict[int, tuple[Config, list[Path]]] = {}
    for file in files:
        settings = config.for_file(file, folder=False)
        if settings is not config:
            groups.setdefault(id(settings), (settings, []))[1].append(file)
    return list(groups.values())
