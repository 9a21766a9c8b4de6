"""InstallSpace: where the sourced ROS installations keep their interface files.

ROS 2 (`AMENT_PREFIX_PATH`) and ROS 1 (`CMAKE_PREFIX_PATH`) list prefixes whose
`share/<pkg>/msg|srv|action` folders hold the `.msg`, `.srv` and `.action` files
of the installed packages; ROS 1's `ROS_PACKAGE_PATH` lists folders that are
searched for packages (folders with a package.xml, named by its `<name>`). Earlier
entries win, as in an overlay. Files are found by name when a type is looked up,
never listed: a `.idl` beside them is never read, nor is anything a check does not
ask for. Only the environment given is read; nothing here runs or imports ROS.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path

from robotfix.ros.package import package_name

SUFFIXES = {  # a type name's ending -> the interface kind holding it
    "_Request": "srv",
    "_Response": "srv",
    "_Goal": "action",
    "_Result": "action",
    "_Feedback": "action",
}
IGNORE_MARKERS = ("COLCON_IGNORE", "AMENT_IGNORE", "CATKIN_IGNORE")
MAX_CRAWLED_FOLDERS = 20_000  # ROS_PACKAGE_PATH folders searched for packages


class InstallSpace:
    """The interface files of installed packages, found by type name (`pkg/Name`,
    `pkg/Name_Request`, `pkg/Name_Goal`); each answer is remembered."""

    def __init__(
        self, shares: Sequence[Path], package_roots: Sequence[Path] = ()
    ) -> None:
        self.shares = list(shares)  # <prefix>/share folders
        self.package_roots = list(package_roots)  # ROS_PACKAGE_PATH entries
        self._files: dict[str, Path | None] = {}
        self._packages: dict[str, Path | None] = {}
        self._crawled: dict[str, Path] | None = None

    @classmethod
    def from_environment(
        cls, environ: Mapping[str, str] | None = None
    ) -> InstallSpace | None:
        """The install space the environment has sourced; None when none is."""
        env = os.environ if environ is None else environ
        shares = _unique(
            Path(prefix) / "share"
            for name in ("AMENT_PREFIX_PATH", "CMAKE_PREFIX_PATH")
            for prefix in _entries(env.get(name, ""))
        )
        roots = _unique(
            Path(entry) for entry in _entries(env.get("ROS_PACKAGE_PATH", ""))
        )
        if not shares and not roots:
            return None
        return cls(shares, roots)

    def __eq__(self, other: object) -> bool:
        return (
            isinstance(other, InstallSpace)
            and self.shares == other.shares
            and self.package_roots == other.package_roots
        )

    def __hash__(self) -> int:
        return hash((tuple(self.shares), tuple(self.package_roots)))

    def find(self, key: str) -> Path | None:
        """The file that defines the type `key` (`pkg/Name`), or None."""
        if key not in self._files:
            self._files[key] = self._find(key)
        return self._files[key]

    def has_package(self, package: str) -> bool:
        return self._package(package) is not None

    def _find(self, key: str) -> Path | None:
        package, _, name = key.partition("/")
        if not package or not name or "/" in name:
            return None
        folder = self._package(package)
        if folder is None:
            return None
        candidates = [("msg", name)]
        for suffix, kind in SUFFIXES.items():
            if name.endswith(suffix) and len(name) > len(suffix):
                candidates.append((kind, name[: -len(suffix)]))
        for kind, stem in candidates:
            path = folder / kind / f"{stem}.{kind}"
            if os.path.isfile(path):
                return path
        for kind, stem in candidates:  # a package written in IDL
            path = folder / kind / f"{stem}.idl"
            if os.path.isfile(path):
                return path
        return None

    def _package(self, package: str) -> Path | None:
        """The installed folder of `package`: `<share>/<package>` of the first share
        that has one, else a package of that name under ROS_PACKAGE_PATH."""
        if package not in self._packages:
            found = next(
                (
                    share / package
                    for share in self.shares
                    if _has_interfaces(share / package)
                ),
                None,
            )
            if found is None and self.package_roots:
                found = self._crawl().get(package)
            self._packages[package] = found
        return self._packages[package]

    def _crawl(self) -> dict[str, Path]:
        """Packages under ROS_PACKAGE_PATH, as rospack finds them: a folder with a
        package.xml is a package (not searched further), hidden folders and
        folders with an ignore marker are skipped; the first of a name wins."""
        if self._crawled is None:
            self._crawled = {}
            seen: set[str] = set()
            budget = MAX_CRAWLED_FOLDERS
            for root in self.package_roots:
                stack = [root]
                while stack and budget > 0:
                    folder = stack.pop()
                    real = os.path.realpath(folder)
                    if real in seen:
                        continue
                    seen.add(real)
                    budget -= 1
                    try:
                        names = sorted(os.listdir(folder))
                    except OSError:
                        continue
                    if any(marker in names for marker in IGNORE_MARKERS):
                        continue
                    if "package.xml" in names:
                        name = package_name(folder) or folder.name
                        self._crawled.setdefault(name, folder)
                        continue
                    stack.extend(
                        folder / name
                        for name in reversed(names)
                        if not name.startswith(".") and os.path.isdir(folder / name)
                    )
        return self._crawled


def _has_interfaces(folder: Path) -> bool:
    return any(os.path.isdir(folder / kind) for kind in ("msg", "srv", "action"))


def _entries(value: str) -> list[str]:
    return [entry for entry in value.split(os.pathsep) if entry.strip()]


def _unique(paths: Iterable[Path]) -> list[Path]:
    found: dict[str, Path] = {}
    for path in paths:
        found.setdefault(os.path.realpath(path), path)
    return list(found.values())
