"""ModuleIndex: which file of the tree a dotted module name is, seen from one file.

Python's own search, without running anything: for a file, the folders searched are
the `python-paths` setting, then the folder above the file's top package (for a
script, its own folder: `sys.path[0]`), then the root of the ROS package around it
(the folder with `package.xml`; a ROS 2 `pkg/pkg/` or a ROS 1 `src/` layout) and
its `src/`, then the checked roots. A name is a module there as `a/b.py` or
`a/b/__init__.py`. Only existence is tested here (no file is read); every lookup is
remembered for the run.
"""

from __future__ import annotations

import ast
import os
from collections.abc import Sequence
from pathlib import Path

from robotfix.analysis.imported import absolute

_UNKNOWN = Path("\0")  # not looked up yet
MAX_DEPTH = 32  # folders climbed looking for a package top or a package.xml


class ModuleIndex:
    def __init__(
        self, roots: Sequence[Path] = (), python_paths: Sequence[Path] = ()
    ) -> None:
        self.python_paths = tuple(_absolute(Path(p)) for p in python_paths)
        self.roots = tuple(
            _absolute(Path(r) if _is_dir(Path(r)) else Path(r).parent) for r in roots
        )
        self._search: dict[Path, tuple[Path, ...]] = {}
        self._folders: dict[str, Path] = {}  # a folder as spelled -> absolute
        self._found: dict[tuple[Path, str], Path | None] = {}
        self._packages: dict[Path, str | None] = {}

    def find(self, name: str, importer: Path) -> Path | None:
        """The file of module `name` (absolute, dotted) as `importer` imports it."""
        if not name or not all(part.isidentifier() for part in name.split(".")):
            return None
        for root in self.search_path(importer):
            key = (root, name)
            found = self._found.get(key, _UNKNOWN)
            if found is _UNKNOWN:
                found = self._found[key] = _module_file(root, name)
            if found is not None:
                return found if importer.is_absolute() else _relative(found)
        return None

    def candidates(self, name: str, importer: Path) -> list[Path]:
        """Every file `name` could be for `importer`, existing or not (absolute)."""
        if not name or not all(part.isidentifier() for part in name.split(".")):
            return []
        found = []
        for root in self.search_path(importer):
            base = root.joinpath(*name.split("."))
            found += [base.with_name(base.name + ".py"), base / "__init__.py"]
        return found

    def search_path(self, importer: Path) -> tuple[Path, ...]:
        """Absolute folders, in the order they are searched."""
        spelled = os.path.dirname(importer)
        folder = self._folders.get(spelled)
        if folder is None:
            folder = self._folders[spelled] = _absolute(importer.parent)
        if folder not in self._search:
            found: list[Path] = [*self.python_paths, self._top_parent(folder)]
            package = _ros_package(folder)
            if package is not None:
                found.append(package)
                if _is_dir(package / "src"):
                    found.append(package / "src")
            found += self.roots
            self._search[folder] = tuple(dict.fromkeys(found))
        return self._search[folder]

    def package_of(self, path: Path) -> str | None:
        """The dotted package `path` is a module of; None when its folder is no
        package (a script's folder: relative imports do not work there)."""
        folder = _absolute(path.parent)
        if folder not in self._packages:
            parts: list[str] = []
            current = folder
            for _ in range(MAX_DEPTH):
                if not os.path.isfile(current / "__init__.py"):
                    break
                parts.append(current.name)
                if current.parent == current:
                    break
                current = current.parent
            valid = parts and all(p.isidentifier() for p in parts)
            self._packages[folder] = ".".join(reversed(parts)) if valid else None
        return self._packages[folder]

    def module_name(self, path: Path) -> str:
        """The dotted name `path` has as a module (`my_pkg.util`)."""
        package = self.package_of(path)
        if path.name == "__init__.py":
            return package or _absolute(path.parent).name
        return f"{package}.{path.stem}" if package else path.stem

    def _top_parent(self, folder: Path) -> Path:
        """The folder above the top package that holds `folder` (or `folder`)."""
        current = folder
        for _ in range(MAX_DEPTH):
            if not os.path.isfile(current / "__init__.py") or current.parent == current:
                return current
            current = current.parent
        return current


def _absolute(path: Path) -> Path:
    try:
        return Path(os.path.abspath(path))
    except OSError:  # the cwd was deleted
        return path


def _relative(path: Path) -> Path:
    """A found module as a relative importer's run spells paths."""
    try:
        return Path(os.path.relpath(path))
    except (OSError, ValueError):
        return path


def _module_file(root: Path, name: str) -> Path | None:
    base = root.joinpath(*name.split("."))
    for candidate in (base.with_name(base.name + ".py"), base / "__init__.py"):
        if os.path.isfile(candidate):
            return candidate
    return None


def _ros_package(folder: Path) -> Path | None:
    current = folder
    for _ in range(MAX_DEPTH):
        if os.path.isfile(current / "package.xml"):
            return current
        if current.parent == current:
            return None
        current = current.parent
    return None


def _is_dir(path: Path) -> bool:
    try:
        return path.is_dir()
    except OSError:
        return False


def imported_names(tree: ast.Module, package: str | None) -> list[str]:
    """Every module name a file's import statements mention (absolute)."""
    found: list[str] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = (
                absolute(package, node.level, node.module)
                if node.level
                else node.module
            )
            if base:
                found.append(base)
                found += [f"{base}.{a.name}" for a in node.names if a.name != "*"]
    return found
