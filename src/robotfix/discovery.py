"""Which files a run reads: the Python files under the checked paths, the interface
files of the msg paths and of the ROS packages there, and what was left out (RF004).

The paths named on the command line (and the msg paths) are roots. Folders are
walked with os.scandir, without recursion, so a folder that vanishes during the
walk is skipped and one that cannot be read (no permission, a path longer than the
system allows) is an RF004 warning, never a crash. A symlink is followed when its
target lies inside a root, once: every real folder is walked once and every real
file is listed once, whatever the spellings that reach it. A symlink whose target
leaves every root is not read; an RF004 warning names it and its target. Files keep
the spelling of the path that reached them (`ws/src/pkg/node.py`).

Below the roots, hidden folders, `__pycache__` and `node_modules` are skipped, and
so are build and install output (`build/`, `install/`, `log/`, `devel/`, `dist/`,
`venv/`, ... as ruff skips them) unless the folder is a Python package of that name
(it holds `__init__.py`), and every folder holding COLCON_IGNORE, AMENT_IGNORE or
CATKIN_IGNORE. At a colcon or catkin workspace root (a folder with `src/` beside
`build/`, `install/`, `log/` or `devel/`) those are skipped whatever they hold, so
a workspace's packages are checked once, from `src/`. Python files are `*.py` and
files without an extension whose first line is a Python shebang (ROS 1 `scripts/`
and `nodes/`). The install space the environment has sourced is where interface
files missing from the run are looked up (`ros/install.py`).
"""

from __future__ import annotations

import os
import re
import time
from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from robotfix import messages
from robotfix.config import Config
from robotfix.diagnostics import Diagnostic
from robotfix.fs import (
    RACY_NS,
    Noted,
    UnreadableError,
    asked,
    read_head,
    read_text,
    stamp,
    within,
)
from robotfix.lazyre import lazy
from robotfix.ros.executables import CPP_SOURCE_SUFFIXES
from robotfix.ros.install import IGNORE_MARKERS, InstallSpace
from robotfix.ros.launch.names import YAML_SUFFIXES, is_launch_file

INTERFACE_SUFFIXES = (".msg", ".srv", ".action", ".idl")
INTERFACE_FOLDERS = ("msg", "srv", "action")
PARAMETER_FOLDERS = ("config", "params", "param")  # a package's parameter files
MAX_BUILD_FILE_BYTES = 1024 * 1024  # CMakeLists.txt, setup.py
_GPL_CMAKE = lazy(r"generate_parameter_library\s*\(([^)]*)\)")
_YAML_NAME = lazy(r"""["']?([^\s"'()]+\.ya?ml)["']?""")
SKIPPED_FOLDERS = ("__pycache__", "node_modules")  # and every hidden folder
WORKSPACE_OUTPUT = ("build", "install", "log", "logs", "devel")  # colcon, catkin
OUTPUT_FOLDERS = (  # skipped unless they hold __init__.py (ruff's defaults, and ROS's)
    *WORKSPACE_OUTPUT,
    "dist",
    "venv",
    "_build",
    "buck-out",
    "__pypackages__",
    "site-packages",
)
WORKSPACE_MARKERS = (".catkin_workspace", ".catkin_tools")
SHEBANG_BYTES = 256  # a kernel reads at most this much of a `#!` line
_SHEBANG = lazy(
    rb"#![ \t]*(?:\S*/)?(?:env[ \t]+(?:-\S+[ \t]+)*)?python[0-9.]*(?:[ \t]|\r|\n|$)"
)


@dataclass
class Discovery:
    """What a run found to check under the paths it was given."""

    python_files: list[Path] = field(default_factory=list)
    interface_files: list[Path] = field(default_factory=list)
    notices: list[Diagnostic] = field(default_factory=list)  # RF004 warnings
    package_interface_files: list[Path] = field(default_factory=list)  # they win
    installed: InstallSpace | None = None  # where other types are looked up
    # parameter files: found in packages' config/, params/, param/, or named
    parameter_files: list[Path] = field(default_factory=list)
    named_parameter_files: list[Path] = field(default_factory=list)
    parameter_definitions: list[Path] = field(default_factory=list)  # gen. param lib
    summary_files: list[Path] = field(default_factory=list)  # their packages' code
    # launch files: in a `launch/` folder, or named `*.launch.py`, `*_launch.xml`...
    launch_files: list[Path] = field(default_factory=list)
    # C++ sources and headers of ROS packages, for the graph (`graphcheck.py`)
    cpp_files: list[Path] = field(default_factory=list)


def discover(
    paths: list[Path],
    config: Config,
    environ: Mapping[str, str] | None = None,
    trace: Trace | None = None,
) -> Discovery:
    """Everything a run over `paths` reads, and the RF004 notices of what it left
    out. Interface files come from the msg paths and from the msg/, srv/, action/
    folders of the ROS packages under `paths`, or around a path inside a package;
    those of the packages win over the msg paths' (`package_interface_files`), and
    both over the install space of `environ` (by default the process's). With
    `trace`, what it looked at on disk is noted there (`Trace`)."""
    global _TRACE
    _TRACE = trace
    try:
        found = _discover(paths, config)
    finally:
        _TRACE = None
    found.installed = install_space(environ)
    return found


def _discover(paths: list[Path], config: Config) -> Discovery:
    found = Discovery()
    named_yaml = [p for p in paths if _is_yaml(p.name) and not _isdir(p)]
    python_paths = [p for p in paths if p not in named_yaml]
    reals: dict[Path, str] = {}  # real paths the walks found: not resolved again
    files, packages = _python_files(
        python_paths, config, found.notices, reals, found.launch_files, found.cpp_files
    )
    found.python_files = files
    folders = [p for p in python_paths if _isdir(p)]
    scanned = _around(packages, folders, reals)
    _parameter_files(found, named_yaml, scanned, [*paths, *packages], config, reals)
    roots = [*paths, *config.msg_paths, *packages]
    folders = list(config.msg_paths) + _interface_folders(packages)
    found.interface_files = _interface_files(folders, roots, found.notices, reals)
    found.package_interface_files = _inside(found.interface_files, packages, reals)
    return found


def _inside(
    files: list[Path], folders: list[Path], reals: Mapping[Path, str]
) -> list[Path]:
    """The files that lie in one of `folders`, symlinks resolved (as `fs.within`),
    with each folder resolved once: a tree of many packages stays linear."""
    real: set[Path] = set()
    for folder in folders:
        found_real = _real(folder, reals)
        if found_real is not None:
            real.add(found_real)
    found = []
    for file in files:
        resolved = _real(file, reals)
        if resolved is not None and (
            resolved in real or not real.isdisjoint(resolved.parents)
        ):
            found.append(file)
    return found


def _around(
    packages: list[Path], folders: list[Path], reals: Mapping[Path, str]
) -> list[Path]:
    """The packages under one of `folders` or holding one of them (as `fs.within`
    both ways), each path resolved once."""
    roots = [r for r in (_real(f, reals) for f in folders) if r is not None]
    found = []
    for package in packages:
        real = _real(package, reals)
        if real is not None and any(
            real == root or root in real.parents or real in root.parents
            for root in roots
        ):
            found.append(package)
    return found


def _real(path: Path, reals: Mapping[Path, str]) -> Path | None:
    """`path` with every symlink resolved (a walk may know it already); None when
    it cannot be resolved."""
    known = reals.get(path)
    if known is not None:
        return Path(known)
    try:
        return Path(_realpath(path))
    except (OSError, ValueError):
        return None


def _parameter_files(
    found: Discovery,
    named: list[Path],
    packages: list[Path],
    roots: list[Path],
    config: Config,
    reals: Mapping[Path, str] | None = None,
) -> None:
    """Parameter YAML files: those named, and those in the config/, params/ and
    param/ folders of the packages under (or around) the folders named;
    generate_parameter_library definitions named by those packages' (and named
    files' packages') CMakeLists.txt or setup.py; and the Python files of the
    packages around named files, whose declarations they are checked against."""
    around = [p for p in (_package_around(n) for n in named) if p is not None]
    folders = [
        package / name
        for package in packages
        for name in PARAMETER_FOLDERS
        if _isdir(package / name)
    ]
    walker = _Walker(roots + around, found.notices, reals)
    chosen = _OnePathEach()
    for path in named:
        chosen.add(path, _realpath(path), False)
    pruned = lambda folder, real: config.excluded(folder, True, real)  # noqa: E731
    for _, _, entries in walker.walk(folders, _is_yaml, pruned):
        for entry in entries:
            if (
                _is_yaml(entry.name)
                and entry.regular
                and not config.excluded(entry.path)
            ):
                chosen.add(entry.path, entry.real, entry.link)
    found.parameter_files = chosen.paths()
    found.named_parameter_files = list(named)
    found.parameter_definitions = sorted(
        {d for package in [*packages, *around] for d in _definitions_of(package)}
    )
    if around:
        found.summary_files = _python_files(
            sorted(set(around)), None, [], launch=found.launch_files
        )[0]
    found.launch_files = sorted(set(found.launch_files))


def _definitions_of(package: Path) -> list[Path]:
    """generate_parameter_library definition files a package's build names:
    `generate_parameter_library(name path.yaml)` in CMakeLists.txt, or a `.yaml`
    string in a setup.py that calls generate_parameter_module."""
    names: list[str] = []
    for build in ("CMakeLists.txt", "setup.py"):
        if _TRACE is not None:
            _TRACE.stamp(package / build)
        try:
            text = read_text(package / build, MAX_BUILD_FILE_BYTES)
        except UnreadableError:
            continue
        if build == "setup.py":
            if "generate_parameter_module" in text:
                names += re.findall(r"""["']([^"'\n]+\.ya?ml)["']""", text)
            continue
        for call in _GPL_CMAKE.finditer(text):
            names += _YAML_NAME.findall(call.group(1))
    found = []
    for name in names:
        name = name.replace("${CMAKE_CURRENT_SOURCE_DIR}/", "")
        path = package / name
        if "$" not in name and _isfile(path) and _within(path, [package]):
            found.append(path)
    return found


def _is_yaml(name: str) -> bool:
    return name.endswith(YAML_SUFFIXES)


def install_space(environ: Mapping[str, str] | None = None) -> InstallSpace | None:
    """The install space sourced in `environ` (by default the process's): where
    types that no checked package or msg path defines are looked up."""
    return InstallSpace.from_environment(environ)


def python_files(paths: list[Path], config: Config | None = None) -> list[Path]:
    """Files named on the command line, and `*.py` under folders (less excludes)."""
    return _python_files(paths, config, [])[0]


def ros_interface_folders(paths: list[Path]) -> list[Path]:
    """The msg/, srv/, action/ folders of ROS packages (folders with package.xml)
    under `paths`, or holding one of them."""
    return _interface_folders(_python_files(paths, None, [])[1])


def interface_files(folders: list[Path]) -> list[Path]:
    """The .msg/.srv/.action files in `folders` (or named by them), each once; a
    symlink leaving the folders is not followed."""
    return _interface_files(folders, folders, [])


def _hidden(relative: Path) -> bool:
    return any(_skipped(part) for part in relative.parts[:-1])


def _skipped(name: str) -> bool:
    return name.startswith(".") or name in SKIPPED_FOLDERS


def _output(folder: Path, in_workspace: bool) -> bool:
    """Build or install output: at a workspace root by name alone, elsewhere unless
    it is a Python package of that name (`mypkg/log/__init__.py`)."""
    if in_workspace and folder.name in WORKSPACE_OUTPUT:
        return True
    return folder.name in OUTPUT_FOLDERS and not _isfile(folder / "__init__.py")


def _workspace_root(names: set[str]) -> bool:
    """Whether a folder holding `names` is a colcon or catkin workspace root."""
    return ("src" in names and not names.isdisjoint(WORKSPACE_OUTPUT)) or not (
        names.isdisjoint(WORKSPACE_MARKERS)
    )


# -- the walk ---------------------------------------------------------------


class _Entry:
    """A file entry of a walked folder; its path and real path are made only when
    asked for (a tree has many more files than the few a run keeps)."""

    __slots__ = ("folder", "link", "name", "prefix", "regular", "target")

    def __init__(
        self,
        folder: Path,
        name: str,
        prefix: str,
        target: str,
        regular: bool,
        link: bool,
    ) -> None:
        self.folder = folder
        self.name = name
        self.prefix = prefix  # the folder's real path, ending with a separator
        self.target = target  # a symlink's target, every symlink resolved ("" if none)
        self.regular = regular  # a regular file, or a symlink to one
        self.link = link

    @property
    def path(self) -> Path:
        """As reached: the root's spelling, then the names walked."""
        return self.folder / self.name

    @property
    def real(self) -> str:
        """Every symlink resolved."""
        return self.target or self.prefix + self.name


class _Walker:
    """Walks folders under a set of roots; remembers the real folders it has
    walked, so a loop or a second spelling is walked once."""

    def __init__(
        self,
        roots: Iterable[Path],
        notices: list[Diagnostic],
        reals: Mapping[Path, str] | None = None,
    ) -> None:
        """`reals`: real paths of some roots, already known (not resolved again)."""
        known = reals or {}
        self.roots = [known.get(root) or _realpath(root) for root in roots]
        self.notices = notices
        self.walked: set[str] = set()

    def inside(self, real: str) -> bool:
        return _within(real, self.roots)

    def walk(
        self,
        tops: list[Path],
        wanted: Callable[[str], bool],
        pruned: Callable[[Path, str | None], bool],
    ) -> Iterator[tuple[Path, str, list[_Entry]]]:
        """Each folder under `tops` (themselves included) with its real path and its
        entries that are not folders; `wanted` names the files whose leaving links
        deserve a notice, `pruned` the folders not to enter (with their real path
        when the walk knows it). Folders reached through a symlink are walked
        last, so a folder also reachable without one keeps that spelling."""
        stack = [(top, _realpath(top), False, True) for top in reversed(tops)]
        linked: list[tuple[Path, str, bool, bool]] = []
        walked = self.walked
        while stack or linked:
            if not stack:
                stack, linked = linked[::-1], []
            folder, real, via_link, top = stack.pop()
            if real in walked:
                continue
            walked.add(real)
            if _TRACE is not None:
                _TRACE.stamp(folder)
            try:
                with os.scandir(folder) as listing:
                    entries = sorted(listing, key=_entry_name)
            except (FileNotFoundError, NotADirectoryError):
                continue  # gone while we walked (a concurrent build)
            except OSError as err:
                self.notices.append(messages.folder_not_read(str(folder), _reason(err)))
                continue
            names = {entry.name for entry in entries}
            if not top and not names.isdisjoint(IGNORE_MARKERS):
                walked.discard(real)  # still walked if named as a root
                continue  # COLCON_IGNORE, AMENT_IGNORE, CATKIN_IGNORE
            workspace = _workspace_root(names)
            prefix = real if real.endswith(os.sep) else real + os.sep
            files: list[_Entry] = []
            below: list[tuple[Path, str, bool, bool]] = []
            for entry in entries:
                name = entry.name
                link = _test(entry.is_symlink)
                if link and _TRACE is not None:
                    _TRACE.link(folder / name)
                is_folder = _test(entry.is_dir)  # follows a symlink; False if broken
                path: Path | None = None
                if is_folder:
                    if _skipped(name):
                        continue
                    path = folder / name
                    # (a folder that is no link is real under its parent's real path)
                    if _output(path, workspace) or pruned(
                        path, None if link else prefix + name
                    ):
                        continue
                target = ""
                if link:
                    path = path or folder / name
                    target = os.path.realpath(path)
                    if not self.inside(target):
                        if is_folder or wanted(name):
                            self.notices.append(
                                messages.outside_link(str(path), target)
                            )
                        continue
                if is_folder:
                    assert path is not None
                    (linked if link else below).append(
                        (path, target or prefix + name, via_link or link, False)
                    )
                else:
                    regular = _test(entry.is_file)
                    files.append(
                        _Entry(folder, name, prefix, target, regular, via_link or link)
                    )
            yield folder, real, files
            stack.extend(reversed(below))


def _entry_name(entry: os.DirEntry[str]) -> str:
    return entry.name


def _python_files(
    paths: list[Path],
    config: Config | None,
    notices: list[Diagnostic],
    reals: dict[Path, str] | None = None,
    launch: list[Path] | None = None,
    cpp: list[Path] | None = None,
) -> tuple[list[Path], list[Path]]:
    """Python files (each real file once) and ROS package folders under `paths`,
    or holding one of them; `reals` learns the packages' real paths, `launch`
    the launch files found on the way."""
    walker = _Walker(paths, notices)
    chosen = _OnePathEach()
    sources: list[tuple[Path, str]] = []  # C++ files, with their real paths
    packages: dict[str, Path] = {}

    def pruned(folder: Path, real: str | None) -> bool:
        return config is not None and config.excluded(folder, True, real)

    for path in paths:
        package = _package_around(path)
        if package is not None:
            packages.setdefault(_realpath(package), package)
        if not _isdir(path):
            chosen.add(path, _realpath(path), False)  # named: always checked
    tops = [path for path in paths if _isdir(path)]
    for folder, real, entries in walker.walk(tops, _is_python, pruned):
        for entry in entries:
            if entry.name == "package.xml" and entry.regular:
                packages.setdefault(real, folder)
            if (
                launch is not None
                and entry.regular
                and is_launch_file(folder.name, entry.name)
                and not (config is not None and config.excluded(entry.path))
            ):
                launch.append(entry.path)
            if (
                cpp is not None
                and entry.regular
                and entry.name.endswith(CPP_SOURCE_SUFFIXES)
                and not (config is not None and config.excluded(entry.path))
            ):
                sources.append((entry.path, entry.real))
            # a Python launch file is Python code too (RF301 in a launch helper)
            if (_is_python(entry.name) and (entry.regular or entry.link)) or (
                entry.regular and "." not in entry.name and _is_script(entry.path)
            ):  # a broken link to a `.py`: RF003
                path = entry.path
                if not (config is not None and config.excluded(path)):
                    chosen.add(path, entry.real, entry.link)
    if reals is not None:
        reals.update((folder, real) for real, folder in packages.items())
    if cpp is not None:  # only those in a ROS package: a vendored library's are not
        inside = tuple(real + os.sep for real in packages)
        cpp += sorted(p for p, real in sources if real.startswith(inside))
    return chosen.paths(ordered=False), sorted(packages.values())


def _package_around(path: Path) -> Path | None:
    """The ROS package a path lies in (its own folder included), found by walking
    up; spelled relative to the current folder when `path` was relative."""
    absolute = Path(os.path.abspath(path))
    start = absolute if _isdir(absolute) else absolute.parent
    for folder in (start, *start.parents):
        if _isfile(folder / "package.xml"):
            if path.is_absolute():
                return folder
            try:
                return Path(os.path.relpath(folder))
            except ValueError:  # another drive
                return folder
    return None


def _interface_folders(packages: Iterable[Path]) -> list[Path]:
    return [
        package / name
        for package in packages
        for name in INTERFACE_FOLDERS
        if _isdir(package / name) or _islink(package / name)
    ]


def _interface_files(
    folders: list[Path],
    roots: Iterable[Path],
    notices: list[Diagnostic],
    reals: dict[Path, str] | None = None,
) -> list[Path]:
    """`reals`: real paths known (of roots), then learnt (of the files found)."""
    walker = _Walker(roots, notices, reals)
    chosen = _OnePathEach()
    tops = []
    for folder in folders:
        real = _realpath(folder)
        if not walker.inside(real):  # a package's msg/ linked elsewhere
            notices.append(messages.outside_link(str(folder), real))
        elif _isdir(folder):
            tops.append(folder)
        elif _is_interface(folder.name) and _isfile(folder):
            chosen.add(folder, real, False)
    for _, _, entries in walker.walk(tops, _is_interface, lambda _, __: False):
        for entry in entries:
            if _is_interface(entry.name) and entry.regular:
                chosen.add(entry.path, entry.real, entry.link)
    if reals is not None:
        reals.update(chosen.reals())
    return chosen.paths(ordered=False)


class _OnePathEach:
    """One path per real file: the first reached without a symlink, if any."""

    def __init__(self) -> None:
        self._chosen: dict[str, tuple[bool, Path]] = {}

    def add(self, path: Path, real: str, link: bool) -> None:
        if real not in self._chosen or (self._chosen[real][0] and not link):
            self._chosen[real] = (link, path)

    def paths(self, ordered: bool = True) -> list[Path]:
        """Sorted; or, with ordered=False, in the order first reached (msg-path
        order, then path order: which of two definitions of a type wins)."""
        found = [path for _, path in self._chosen.values()]
        return sorted(found) if ordered else found

    def reals(self) -> dict[Path, str]:
        return {path: real for real, (_, path) in self._chosen.items()}


def _is_python(name: str) -> bool:
    return name.endswith(".py")


def _is_script(path: Path) -> bool:
    """A file without an extension whose first line is a Python shebang
    (`#!/usr/bin/env python3`, `#!/usr/bin/python2.7`); only that line is read."""
    if "." in path.name:
        return False
    if _TRACE is not None:
        _TRACE.stamp(path)
    try:
        head = read_head(path, SHEBANG_BYTES)
    except UnreadableError:
        return False
    return _SHEBANG.match(head) is not None


def _is_interface(name: str) -> bool:
    return name.endswith(INTERFACE_SUFFIXES)


def _test(test: Callable[[], bool]) -> bool:
    """A DirEntry test; an entry that cannot be looked at (a symlink loop, gone)
    is none of the things tested."""
    try:
        return test()
    except OSError:
        return False


def _reason(err: OSError) -> str:
    return err.strerror or type(err).__name__


# -- what a discovery looked at, for a cached run ----------------------------


class Trace(Noted):
    """What a discovery looked at on disk: the stamp (os.stat, taken before the
    read) of each folder it listed and file it read, and the answer of every other
    probe (isdir, isfile, islink, realpath). A discovery is a function of
    these answers, of the paths and settings and of the current folder (the
    caller's key holds those), so when every stamp and answer is the same again it
    finds the same: a cached run checks them (`holds`) instead of walking again.

    A symlink the walk meets is noted by what it reaches (`link`), which is not
    in its folder's stamp. Not kept (`spoiled`) when a stamp is younger than
    `RACY_NS` (the next change could land in the same tick, as git's racily clean
    files). A stamp holds the mtime and the ctime (a `touch -d` or a chmod, say a
    folder made unreadable, changes it), the inode, device, size and mode."""

    def __init__(self) -> None:
        super().__init__()
        self.spoiled = False
        self.renewed = False  # `holds` renewed a stamp: to be kept again
        self._now = time.time_ns()

    def stamp(self, path: str | os.PathLike[str]) -> None:
        name = os.fspath(path)
        if name not in self.stamps:
            found = stamp(name)
            if found is not None and self._now - max(found[0], found[1]) < RACY_NS:
                self.spoiled = True
            self.stamps[name] = found

    def link(self, path: Path) -> None:
        """A symlink among a listed folder's entries (the folder's stamp says it
        is there, a link): what it reaches, its real path (a probe), and the stamp
        of that (through any chain of links; None when broken), which says whether
        it is a folder or a file, and for a file its head, as the walk reads them
        through the link (a folder it reaches is listed, and stamped, by the walk)."""
        name = os.fspath(path)
        real = os.path.realpath(name)
        self.probes[("realpath", name)] = real
        self.stamp(real)

    def take(self, other: Noted) -> None:
        """What another computation noted (`fs.remembered`), as if noted here."""
        self.spoiled = self.spoiled or getattr(other, "spoiled", False)
        for name, found in other.stamps.items():
            if name not in self.stamps:
                racy = found is not None and self._now - max(found[:2]) < RACY_NS
                self.spoiled = self.spoiled or racy
                self.stamps[name] = found
        self.probes.update(other.probes)

    def folded(self, least: int = 3) -> Trace:
        """This trace with fewer probes, to keep: `isfile` of a file it stamped
        (the stamp says it) goes, and the `isfile` answers False that share the
        deepest existing folder above them, `least` of them or more (a node's
        imports looked for in its package), become that folder's stamp (a file
        made below it adds an entry to that folder, which changes its stamp);
        a lone one stays a probe (`package.xml` looked for up to `/`: a folder
        such as `/tmp` or a home changes all the time)."""
        out = Trace()
        out._now, out.spoiled = self._now, self.spoiled
        out.stamps = dict(self.stamps)
        folders: dict[str, bool] = {}  # isdir, asked once
        missing: dict[str, list[str]] = {}
        for (kind, arg), answer in self.probes.items():
            if kind != "isfile" or (answer and arg not in self.stamps):
                out.probes[(kind, arg)] = answer
            elif not answer:
                folder = os.path.dirname(arg)
                while folder:
                    if folder not in folders:
                        folders[folder] = os.path.isdir(folder)
                    if folders[folder]:
                        break
                    folder = os.path.dirname(folder)
                missing.setdefault(folder or ".", []).append(arg)
        for folder, paths in missing.items():
            if len(paths) >= least:
                out.stamp(folder)
            else:
                out.probes.update({("isfile", p): False for p in paths})
        return out

    def holds(
        self,
        same: Callable[[str, list[int], list[int]], list[int] | None] | None = None,
    ) -> bool:
        """Whether every stamp and probe answers as it did. With `same`, a file
        whose stamp changed holds while `same(name, was, now)` says it holds the
        bytes it held (a `touch`, a checkout or a restored CI cache that wrote
        it alike; `ResultCache.same_bytes`), and which stamp to keep for it: a
        new one is renewed here (`renewed`), for the caller to keep."""
        if self.spoiled:
            return False
        renewed: dict[str, list[int] | None] = {}
        for name, known in self.stamps.items():
            now = stamp(name)
            if now != known:
                if same is None or known is None or now is None:
                    return False
                kept = same(name, known, now)
                if kept is None:
                    return False
                if kept != known:
                    renewed[name] = kept
        for (kind, arg), answer in self.probes.items():
            if _probe(kind, arg) != answer:
                return False
        self.stamps.update(renewed)
        self.renewed = bool(renewed)
        return True

    def to_json(self) -> dict[str, Any]:
        """Without the probes of a folder's entries when the folder's own stamp is
        kept: with no symlink met, the stamp decides what they answer."""
        stamped = self.stamps
        return {
            "stamps": stamped,
            "probes": [
                [kind, arg, answer]
                for (kind, arg), answer in self.probes.items()
                if kind == "realpath" or stamped.get(os.path.dirname(arg)) is None
            ],
        }

    @classmethod
    def from_json(cls, raw: Any) -> Trace | None:
        """The trace `to_json` wrote; None when `raw` is not exactly that."""
        if not isinstance(raw, dict):
            return None
        stamps, probes = raw.get("stamps"), raw.get("probes")
        if not (isinstance(stamps, dict) and isinstance(probes, list)):
            return None
        trace = cls()
        for name, kept in stamps.items():
            if kept is not None and not (
                isinstance(kept, list)
                and len(kept) == 6
                and all(type(n) is int for n in kept)
            ):
                return None
            trace.stamps[name] = kept
        for item in probes:
            if not (
                isinstance(item, list)
                and len(item) == 3
                and item[0] in _PROBES
                and isinstance(item[1], str)
                and type(item[2]) in (bool, str)
            ):
                return None
            trace.probes[(item[0], item[1])] = item[2]
        return trace


_TRACE: Trace | None = None  # the running discovery's, if it keeps one


_PROBES: dict[str, Callable[[str], Any]] = {
    "isdir": os.path.isdir,
    "isfile": os.path.isfile,
    "islink": os.path.islink,
    "realpath": os.path.realpath,
}


def _probe(kind: str, arg: str) -> Any:
    try:
        if kind in ("isfile", "realpath"):  # the run's answer (`fs.answering`):
            return asked(kind, arg)  # 470 launch files' traces ask many alike
        return _PROBES[kind](arg)
    except (OSError, ValueError):
        return None  # never equal to an answer noted


def _noted(kind: str, arg: str) -> Any:
    # a real path or a file asked once in a run, as the later stages ask them
    answer = asked(kind, arg) if kind in ("isfile", "realpath") else _PROBES[kind](arg)
    if _TRACE is not None:
        _TRACE.probes[(kind, arg)] = answer
    return answer


def _isdir(path: str | os.PathLike[str]) -> bool:
    return bool(_noted("isdir", os.fspath(path)))


def _isfile(path: str | os.PathLike[str]) -> bool:
    return bool(_noted("isfile", os.fspath(path)))


def _islink(path: str | os.PathLike[str]) -> bool:
    return bool(_noted("islink", os.fspath(path)))


def _realpath(path: str | os.PathLike[str]) -> str:
    return str(_noted("realpath", os.fspath(path)))


def _within(
    path: str | os.PathLike[str], roots: Iterable[str | os.PathLike[str]]
) -> bool:
    return within(path, roots, _realpath)
