"""ModuleIndex: which file of the tree a dotted module name is, seen from one file.

Python's own search, without running anything: for a file, the folders searched are
the `python-paths` setting, then the folder above the file's top package (for a
script, its own folder: `sys.path[0]`), then the root of the ROS package around it
(the folder with `package.xml`; a ROS 2 `pkg/pkg/` or a ROS 1 `src/` layout) and
its `src/`, then the checked roots. A name is a module there as `a/b.py` or
`a/b/__init__.py`. Only existence is tested here (no file is read); every lookup is
remembered for the run.

A cached run (the result cache) keeps the answers between runs (`keep`, `restore`)
as `discovery.Trace` keeps the walk: with the stamp (os.stat, taken before the
listing) of every folder listed and the answer of every existence probe
(`__init__.py`, `package.xml`, `src/`; one in a folder listed before it is
answered by that folder's stamp). When a probe answers otherwise, nothing is
reused; when a folder's stamp changed, the answers that may have listed it are
dropped (every answer of a search path holding it; below one, the names under it)
and the others reused. A symlink a listing met is kept with what the listing made
of it (a Python file, a folder, neither: what it reaches is not in its folder's
stamp), checked like a probe; a folder whose stamp is younger than `RACY_NS` counts
as changed in the next run.
"""

from __future__ import annotations

import ast
import functools
import json
import os
import sys
import time
from bisect import bisect_left, bisect_right
from collections import deque
from collections.abc import Callable, Iterable, Sequence
from itertools import islice, repeat
from pathlib import Path
from typing import Any

from robotfix.fs import RACY_NS, stamp

_UNKNOWN = Path("\0")  # not looked up yet
MAX_DEPTH = 32  # folders climbed looking for a package top or a package.xml
KEPT_FORMAT = 2  # 2: symlinks listed kept with their answers
MAX_CHANGED = 64  # folders changed since the answers were kept: beyond, none is


class ModuleIndex:
    def __init__(
        self, roots: Sequence[Path] = (), python_paths: Sequence[Path] = ()
    ) -> None:
        self.python_paths = tuple(_absolute(Path(p)) for p in python_paths)
        self.roots = tuple(
            _absolute(Path(r) if _is_dir(Path(r)) else Path(r).parent) for r in roots
        )
        self._search: dict[Path, tuple[Path, ...]] = {}
        self._by_spelling: dict[str, tuple[Path, ...]] = {}  # folder as spelled ->
        self._resolved: dict[tuple[int, str], Path | None] = {}
        self._ids: dict[str, int] = {}  # folder as spelled -> its search path's id
        self._numbers: dict[tuple[str, ...], int] = {}
        # search paths by number (None: restored, not needed as Paths yet)
        self._paths: list[tuple[Path, ...] | None] = []
        self._spelled: list[tuple[str, ...]] = []  # the same, as strings
        # (root, name) -> its file, for names whose top a root's listing offers
        # (a root without it answers None from its listing: not kept, 31,078 of
        # 35,549 entries on corpus25)
        self._found: dict[tuple[str, str], Path | None] = {}
        self._packages: dict[Path, str | None] = {}
        self._package_by_spelling: dict[str, str | None] = {}  # a folder as spelled
        # each search path's folders' listings (by number), once listed: `_lookup`
        # reads them for every name no module of the tree answers (rclpy, numpy)
        self._offering: dict[int, tuple[dict[str, bool], ...]] = {}
        # (search path's number, top-level name) -> its folders that offer the
        # name: 2,152 on corpus25 for 11,466 names looked up (`rclpy.node`,
        # `rclpy.qos` ask the same folders)
        self._tops: dict[tuple[int, str], tuple[str, ...]] = {}
        self._listings: dict[str, dict[str, bool]] = {}
        # folders in which a file's existence was tested (`__init__.py`,
        # `package.xml`, `src/`): a change there can change an answer too
        self._probed: set[str] = set()
        # for `keep`: each listed folder's stamp, taken before it was listed, and
        # each probe's answer (path -> (is a folder?, exists?))
        self._stamps: dict[str, list[int] | None] = {}
        self._probes: dict[str, tuple[bool, bool]] = {}
        # probes in a folder stamped before them: the stamp answers for them
        self._covered: set[str] = set()
        # each symlink a listing met -> what the listing made of it (`_list`)
        self._links: dict[str, bool | None] = {}
        self._spoiled = False  # a worker's answer differed (`merge`)
        self._now = time.time_ns()
        self._restored: tuple[dict[str, Any], tuple[int, ...]] | None = None
        self._handed = (0, 0, 0)  # `fresh`: the stamps, probes, answers handed out

    def listed_folders(self) -> set[str]:
        """Every folder this index listed or probed (for the language server: a
        module added or removed in one of them changes what a name is)."""
        probed = {os.path.dirname(name) for name in self._probes}
        return {*self._listings, *self._probed, *self._stamps, *probed}

    def _listing(self, folder: str) -> dict[str, bool]:
        found = self._listings.get(folder)
        if found is None:
            if folder not in self._stamps:
                stamped = stamp(folder)
                if stamped is not None and self._now - max(stamped[:2]) < RACY_NS:
                    # too recent to vouch for (the next change could land in
                    # the same tick): the next run counts the folder as changed
                    stamped = [-1] * len(stamped)
                self._stamps[folder] = stamped
            found = _list(folder, self._links)
            self._listings[folder] = found
        return found

    def _isfile(self, path: Path) -> bool:
        name = str(path)
        self._probed.add(os.path.dirname(name))
        found = self._probes.get(name)
        if found is None:
            self._cover(name)
            found = self._probes[name] = (False, os.path.isfile(name))
        return found[1]

    def _cover(self, name: str) -> None:
        if self._stamps.get(os.path.dirname(name)) is not None:
            self._covered.add(name)

    def _isdir(self, path: Path) -> bool:
        name = str(path)
        found = self._probes.get(name)
        if found is None:
            self._cover(name)
            found = self._probes[name] = (True, _is_dir(path))
        return found[1]

    # -- kept between runs ----------------------------------------------------
    def _key(self) -> str | None:
        """What the answers depend on besides the disk: the current folder (for
        relative spellings), the python paths and the roots."""
        try:
            cwd = os.getcwd()
        except OSError:
            return None
        parts = [KEPT_FORMAT, cwd, [str(p) for p in self.python_paths]]
        return json.dumps([*parts, [str(r) for r in self.roots]])

    def keep(self) -> dict[str, Any] | None:
        """The answers so far and what they depend on, for the next run's
        `restore`; None when they cannot be vouched for."""
        key = self._key()
        if key is None or self._spoiled:
            return None
        if self._restored is not None and self._restored[1] == self._sizes():
            return self._restored[0]  # nothing new: the same object
        # sorted (search paths renumbered in their order): the order things were
        # asked in follows the hash seed (`Project._ranked` walks sets of imports)
        spelled = sorted(self._spelled)
        spelled_as = [self._numbers[roots] for roots in spelled]  # new -> old
        renumber = {old: new for new, old in enumerate(spelled_as)}
        # by search path: the names, and each one's file (1-based in "files"; 0:
        # no module of the tree)
        asked: dict[int, list[str]] = {}
        for number, name in self._resolved:
            asked.setdefault(renumber[number], []).append(name)
        files: dict[Path, int] = {}
        groups: dict[int, tuple[list[str], list[int]]] = {}
        for number in sorted(asked):
            names = sorted(asked[number])
            old = spelled_as[number]
            found_ids = [
                0 if found is None else files.setdefault(found, len(files) + 1)
                for found in (self._resolved[old, name] for name in names)
            ]
            groups[number] = (names, found_ids)
        # a probe in a folder listed before it is answered by the folder's stamp
        # (no symlink there, else nothing is kept): checked only if that changed
        covered = self._covered
        probes = [(k, self._probes[k]) for k in sorted(self._probes)]
        return {
            "key": key,
            "stamps": self._stamps,
            "probes": [[k, d, e] for k, (d, e) in probes if k not in covered],
            "covered": [[k, d, e] for k, (d, e) in probes if k in covered],
            "links": self._links,
            "paths": spelled,
            "ids": {k: renumber[n] for k, n in self._ids.items()},
            "files": [str(f) for f in files],
            "resolved": [[n, names, ids] for n, (names, ids) in groups.items()],
        }

    def restore(self, raw: Any) -> bool:
        """Take over what an earlier run's `keep` wrote when every probe answers
        as it did then, without the answers that listed a folder whose stamp
        changed since (they are worked out again); False when nothing is taken
        over. Only on a fresh index."""
        if not (isinstance(raw, dict) and raw.get("key") == self._key()):
            return False
        if self._resolved or self._ids or self._stamps or self._probes:
            return False
        try:
            stamps = raw["stamps"]
            probes = {str(k): (bool(d), bool(e)) for k, d, e in raw["probes"]}
            covered = {str(k): (bool(d), bool(e)) for k, d, e in raw["covered"]}
            links = {str(k): v for k, v in raw["links"].items()}
            if not set(map(type, links.values())) <= {bool, type(None)}:
                return False
            paths = [tuple(str(p) for p in roots) for roots in raw["paths"]]
            ids = {str(k): int(v) for k, v in raw["ids"].items()}
            table: list[Path | None] = [None, *map(Path, raw["files"])]
            resolved: dict[tuple[int, str], Path | None] = {}
            for number, names, found_ids in raw["resolved"]:
                if not (
                    type(number) is int
                    and 0 <= number < len(paths)
                    and len(names) == len(found_ids)
                    and set(map(type, names)) <= {str}
                    and set(map(type, found_ids)) <= {int}
                    and min(found_ids, default=0) >= 0
                ):
                    return False
                found = map(table.__getitem__, found_ids)
                resolved.update(zip(zip(repeat(number), names), found, strict=True))
            if not isinstance(stamps, dict):
                return False
            if any(n < 0 or n >= len(paths) for n in ids.values()):
                return False
        except (KeyError, TypeError, ValueError, IndexError, AttributeError):
            return False
        changed = {str(f) for f, known in stamps.items() if stamp(f) != known}
        if len(changed) > MAX_CHANGED:
            return False
        # the probes a changed folder's stamp no longer answers for are checked
        recheck = {k for k in covered if os.path.dirname(k) in changed}
        for name, (folder_probe, answer) in [
            *probes.items(),
            *((k, covered[k]) for k in recheck),
        ]:
            now = _is_dir(Path(name)) if folder_probe else os.path.isfile(name)
            if now != answer:
                return False
        if any(_reached(name) != answer for name, answer in links.items()):
            return False
        if changed:
            resolved = _without(resolved, paths, changed)
        self._stamps = {str(k): v for k, v in stamps.items() if k not in changed}
        self._probes = {**probes, **covered}
        self._covered = set(covered) - recheck
        self._links = links
        self._spelled = paths
        self._paths = [None] * len(paths)
        self._numbers = {roots: n for n, roots in enumerate(paths)}
        self._ids = ids
        self._resolved = resolved
        self._restored = (raw, self._sizes()) if not changed else None
        self.handed_out()
        return True

    # -- a worker's answers, for the main process's `keep` ----------------------
    def fresh(self) -> dict[str, Any] | None:
        """What this index found since the last call (or since `restore`, or since
        a fork handed it its parent's), in `merge`'s terms; None when nothing."""
        stamps, probes, resolved = self._handed
        self._handed = (len(self._stamps), len(self._probes), len(self._resolved))
        if self._handed == (stamps, probes, resolved) and not self._spoiled:
            return None
        numbers: dict[int, int] = {}  # this index's search-path numbers -> the delta's
        answers = []
        for (number, name), found in islice(self._resolved.items(), resolved, None):
            local = numbers.setdefault(number, len(numbers))
            answers.append((local, name, None if found is None else str(found)))
        return {
            "spoiled": self._spoiled,
            "paths": [self._spelled[n] for n in numbers],
            "ids": {k: numbers[n] for k, n in self._ids.items() if n in numbers},
            "stamps": dict(islice(self._stamps.items(), stamps, None)),
            "links": self._links,  # few: all of them
            "probes": [
                (k, d, e, k in self._covered)
                for k, (d, e) in islice(self._probes.items(), probes, None)
            ],
            "resolved": answers,
        }

    def handed_out(self) -> None:
        """What this index holds now is its parent's: `fresh` leaves it out (a
        forked worker's index, which the main process has already)."""
        self._handed = (len(self._stamps), len(self._probes), len(self._resolved))

    def merge(self, fresh: dict[str, Any]) -> None:
        """Take a worker's `fresh` answers, so that `keep` holds what the workers
        found too; an answer or a stamp that differs from this index's (the disk
        changed while the run went on) keeps nothing."""
        spoiled = bool(fresh["spoiled"])
        for folder, stamped in fresh["stamps"].items():
            known = self._stamps.setdefault(folder, stamped)
            spoiled = spoiled or known != stamped
        for name, reached in fresh["links"].items():
            spoiled = spoiled or self._links.setdefault(name, reached) != reached
        for name, folder_probe, answer, covered in fresh["probes"]:
            known_probe = self._probes.setdefault(name, (folder_probe, answer))
            spoiled = spoiled or known_probe != (folder_probe, answer)
            if covered:
                self._covered.add(name)
        numbers = [self._number(tuple(roots)) for roots in fresh["paths"]]
        for spelled, local in fresh["ids"].items():
            self._ids.setdefault(spelled, numbers[local])
        for local, name, found in fresh["resolved"]:
            answer = None if found is None else Path(found)
            known_answer = self._resolved.setdefault((numbers[local], name), answer)
            spoiled = spoiled or known_answer != answer
        self._spoiled = self._spoiled or spoiled

    def _number(self, spelled: tuple[str, ...]) -> int:
        found = self._numbers.setdefault(spelled, len(self._numbers))
        if found == len(self._spelled):
            self._paths.append(None)
            self._spelled.append(spelled)
        return found

    def _sizes(self) -> tuple[int, ...]:
        """How much `keep` would write (it only grows)."""
        return (
            len(self._stamps),
            len(self._probes),
            len(self._paths),
            len(self._ids),
            len(self._resolved),
            len(self._links),
        )

    def find(self, name: str, importer: Path | str) -> Path | None:
        """The file of module `name` (absolute, dotted) as `importer` imports it."""
        return self.find_in(self.search_id(importer), name, importer)

    def find_in(self, number: int, name: str, importer: Path | str) -> Path | None:
        """`find`, with `number` the `search_id` of `importer`."""
        key = (number, name)
        found = self._resolved.get(key, _UNKNOWN)
        if found is _UNKNOWN:
            found = self._lookup(number, name)
            # one string per name, not per asking: each call spells it anew
            # (10,716 strings for 4,556 names on corpus25)
            self._resolved[(number, sys.intern(name))] = found
        if found is None or os.path.isabs(importer):
            return found
        return _relative(found)

    def offers(self, number: int, top: str) -> bool:
        """Whether a folder of the search path `number` (`search_id`) holds `top` as
        a module or a folder: no name under a top it does not hold is found."""
        return bool(self._roots_of(number, top))

    def _roots_of(self, number: int, top: str) -> tuple[str, ...]:
        roots = self._tops.get((number, top))
        if roots is None:
            module = top + ".py"
            roots = self._tops[(number, top)] = tuple(
                root
                for root, entries in zip(
                    self._spelled[number], self._offering_of(number), strict=True
                )
                if top in entries or module in entries
            )  # a root without it answers from its listing: nothing to keep
        return roots

    def _lookup(self, number: int, name: str) -> Path | None:
        roots = self._roots_of(number, name.partition(".")[0])
        if not roots:
            return None  # rclpy, numpy: not in any folder searched
        if not name or not all(part.isidentifier() for part in name.split(".")):
            return None
        for root in roots:
            key = (root, name)
            found = self._found.get(key, _UNKNOWN)
            if found is _UNKNOWN:
                found = self._found[key] = _module_file(root, name, self._listing)
            if found is not None:
                return found
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

    def _offering_of(self, number: int) -> tuple[dict[str, bool], ...]:
        """The listings of the folders of a search path, which say whether one
        offers a top-level name (a module or a folder). Every folder is listed: a
        miss holds while none changes. Read from the listings, not kept as a set
        of names per search path (1.3 MB on corpus25, each folder's names again in
        every path)."""
        listings = self._offering.get(number)
        if listings is None:
            listed = map(self._listing, self._spelled[number])
            listings = self._offering[number] = tuple(listed)
        return listings

    def search_id(self, importer: Path | str) -> int:
        """A number for the search path of `importer` (files with the same one
        resolve every name alike)."""
        spelled = os.path.dirname(importer)
        found = self._ids.get(spelled)
        if found is None:
            roots = self.search_path(importer)
            found = self._number(tuple(map(str, roots)))
            if self._paths[found] is None:
                self._paths[found] = roots
            self._ids[spelled] = found
        return found

    def search_path(self, importer: Path | str) -> tuple[Path, ...]:
        """Absolute folders, in the order they are searched."""
        spelled = os.path.dirname(importer)
        known = self._by_spelling.get(spelled)
        if known is not None:
            return known
        number = self._ids.get(spelled)
        if number is not None:  # restored (`restore`)
            known = self._by_spelling[spelled] = self._path(number)
            return known
        folder = _absolute(Path(spelled or "."))
        if folder not in self._search:
            found: list[Path] = [*self.python_paths, self._top_parent(folder)]
            package = self._ros_package(folder)
            if package is not None:
                found.append(package)
                if self._isdir(package / "src"):
                    found.append(package / "src")
            found += self.roots
            self._search[folder] = tuple(dict.fromkeys(found))
        self._by_spelling[spelled] = self._search[folder]
        return self._search[folder]

    def _path(self, number: int) -> tuple[Path, ...]:
        found = self._paths[number]
        if found is None:
            found = self._paths[number] = tuple(map(Path, self._spelled[number]))
        return found

    def package_of(self, path: Path) -> str | None:
        """The dotted package `path` is a module of; None when its folder is no
        package (a script's folder: relative imports do not work there)."""
        spelled = os.path.dirname(path)
        if spelled in self._package_by_spelling:
            return self._package_by_spelling[spelled]
        folder = _absolute(path.parent)
        if folder not in self._packages:
            parts: list[str] = []
            current = folder
            for _ in range(MAX_DEPTH):
                if not self._isfile(current / "__init__.py"):
                    break
                parts.append(current.name)
                if current.parent == current:
                    break
                current = current.parent
            valid = parts and all(p.isidentifier() for p in parts)
            self._packages[folder] = ".".join(reversed(parts)) if valid else None
        found = self._package_by_spelling[spelled] = self._packages[folder]
        return found

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
            if not self._isfile(current / "__init__.py") or current.parent == current:
                return current
            current = current.parent
        return current

    def _ros_package(self, folder: Path) -> Path | None:
        current = folder
        for _ in range(MAX_DEPTH):
            if self._isfile(current / "package.xml"):
                return current
            if current.parent == current:
                return None
            current = current.parent
        return None


def _without(
    resolved: dict[tuple[int, str], Path | None],
    paths: list[tuple[str, ...]],
    changed: set[str],
) -> dict[tuple[int, str], Path | None]:
    """`resolved` without the answers that may have listed a `changed` folder:
    for a search path, every answer when one of its folders changed (the names it
    offers), else the names under a changed folder below one of them
    (`root/a/b` changed: `a.b` and `a.b.*`, which listed it)."""
    everything: set[int] = set()
    below: dict[int, tuple[str, ...]] = {}
    for number, roots in enumerate(paths):
        prefixes: list[str] = []
        for root in roots:
            if root in changed:
                everything.add(number)
                break
            inside = root.rstrip(os.sep) + os.sep
            for folder in changed:
                if folder.startswith(inside):
                    prefixes.append(folder[len(inside) :].replace(os.sep, "."))
        if prefixes:
            below[number] = tuple(prefixes)
    kept: dict[tuple[int, str], Path | None] = {}
    for (number, name), found in resolved.items():
        if number in everything:
            continue
        prefixes_here = below.get(number)
        if prefixes_here is not None and any(
            name == p or name.startswith(p + ".") for p in prefixes_here
        ):
            continue
        kept[(number, name)] = found
    return kept


def _absolute(path: Path) -> Path:
    try:
        return Path(os.path.abspath(path))
    except OSError:  # the cwd was deleted
        return path


@functools.lru_cache(maxsize=4096)
def _relative(path: Path) -> Path:
    """A found module as a relative importer's run spells paths."""
    try:
        return Path(os.path.relpath(path))
    except (OSError, ValueError):
        return path


def _module_file(
    root: str, name: str, listing: Callable[[str], dict[str, bool]]
) -> Path | None:
    """`root/a/b.py` or `root/a/b/__init__.py`, looked up in folder listings: an
    absent top-level name (rclpy, numpy) costs one listing of the root per run."""
    *packages, last = name.split(".")
    folder = root
    for part in packages:
        if listing(folder).get(part) is not True:
            return None
        folder = os.path.join(folder, part)
    entries = listing(folder)
    if entries.get(last + ".py") is False:
        return Path(folder, last + ".py")
    if (
        entries.get(last) is True
        and listing(os.path.join(folder, last)).get("__init__.py") is False
    ):
        return Path(folder, last, "__init__.py")
    return None


def _list(folder: str, links: dict[str, bool | None]) -> dict[str, bool]:
    """A folder's sub-folders (True) and Python files (False); `links` learns
    what each symlink among its entries is of these (None: neither)."""
    found: dict[str, bool] = {}
    try:
        with os.scandir(folder) as entries:
            for entry in entries:
                try:
                    link = entry.is_symlink()
                    if entry.name.endswith(".py") and entry.is_file():
                        found[entry.name] = False
                    elif entry.is_dir():
                        found[entry.name] = True
                    if link:
                        links[entry.path] = found.get(entry.name)
                except OSError:
                    continue
    except OSError:
        pass
    return found


def _reached(path: str) -> bool | None:
    """What `_list` makes of the symlink `path` now (following it)."""
    try:
        if os.path.basename(path).endswith(".py") and os.path.isfile(path):
            return False
        return True if os.path.isdir(path) else None
    except (OSError, ValueError):
        return None


def _is_dir(path: Path) -> bool:
    try:
        return path.is_dir()
    except OSError:
        return False


def imported_names(
    tree: ast.Module, package: str | None, text: str | None = None
) -> list[str]:
    """Every module name a file's import statements mention (absolute). `text`, the
    source `tree` was parsed from, spares the walk the compound statements whose
    lines hold no `import` (the keyword has that one spelling)."""
    return import_names(_import_statements(tree, text), package)


def import_names(nodes: Iterable[ast.AST], package: str | None) -> list[str]:
    """The module names the import statements among `nodes` mention, in order."""
    from robotfix.analysis.imported import absolute

    found: list[str] = []
    for node in nodes:
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


def _import_statements(tree: ast.Module, text: str | None) -> list[ast.AST]:
    """The import statements of `tree`, in `ast.walk`'s order (breadth first),
    visiting statements (and the handlers and match cases that hold some) only: on
    real files about a tenth of the nodes. With `text`, a compound statement none
    of whose lines holds `import` is not entered: none of its statements is one."""
    marks = _import_lines(text) if text is not None else None
    found: list[ast.AST] = []
    todo: deque[ast.AST] = deque(tree.body)
    while todo:
        node = todo.popleft()
        kind = node.__class__
        if kind is ast.Import or kind is ast.ImportFrom:
            found.append(node)
            continue
        names = _BODIES.get(kind)
        if names is None:
            names = _BODIES[kind] = tuple(f for f in kind._fields if f in _BODY_FIELDS)
        if not names:
            continue
        end = getattr(node, "end_lineno", None)  # (a match case has none)
        if marks is not None and end is not None:
            start: int = node.lineno  # type: ignore[attr-defined]
            if bisect_left(marks, start) == bisect_right(marks, end):
                continue  # none of its lines holds `import`
        for name in names:
            todo.extend(getattr(node, name))
    return found


def _import_lines(text: str) -> list[int] | None:
    """The numbers of the lines of `text` that hold `import`, ascending; None when
    counting line feeds does not number the lines as the parser does (a carriage
    return, which it reads as a line end too)."""
    if "\r" in text:
        return None
    found: list[int] = []
    line, counted = 1, 0
    at = text.find("import")
    while at >= 0:
        line += text.count("\n", counted, at)
        counted = at
        if not found or found[-1] != line:
            found.append(line)
        at = text.find("import", at + 6)
    return found


# the fields that hold statements (or handlers, or match cases), in `_fields` order
_BODY_FIELDS = frozenset({"body", "orelse", "finalbody", "handlers", "cases"})
_BODIES: dict[type, tuple[str, ...]] = {}
