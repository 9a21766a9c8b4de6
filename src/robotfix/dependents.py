"""Which documents depend on a changed file, for the language server: a Python
module that imports a changed module, a Python module that uses a type of a changed
interface file.

A syntactic scan of `import` statements, with the catalog to follow message fields
into nested types, and the module index of whole-package analysis to follow imports
through the tree. Over-approximate on purpose (an extra re-check costs time, a
missing one shows stale diagnostics).
"""

from __future__ import annotations

import ast
import os
from pathlib import Path

from robotfix.fs import UnreadableError, read_regular
from robotfix.interface_names import INTERFACE_MODULES
from robotfix.project.modules import ModuleIndex, imported_names
from robotfix.ros.catalog import MsgCatalog, normalize
from robotfix.ros.msg import read_interface
from robotfix.source import SourceFile

SECTIONS = ("", "_Request", "_Response", "_Goal", "_Result", "_Feedback")
ROS1_SUFFIXES = ("Request", "Response", "Goal", "Result", "Feedback", "Action")
MAX_TYPES = 2000  # nested types followed per document
MAX_MODULES = 200  # modules of the tree followed per document


def interface_types(path: Path, text: str) -> set[str]:
    """The types an interface file defines (`pkg/Name`, `pkg/Name_Request`, ...);
    from its path alone when the file is gone (`text` empty)."""
    return {section.name for section in read_interface(path, text).sections}


def uses_interface(text: str, path: Path, catalog: MsgCatalog, types: set[str]) -> bool:
    """Whether Python `text` imports one of `types`, a message that contains one,
    or the whole interface module of their package (`import pkg.msg`)."""
    tree = SourceFile.from_text(str(path), text).tree
    if tree is None:
        return False
    packages = {t.split("/")[0] for t in types}
    named: set[str] = set()
    for package, name in _imported_interfaces(tree):
        if name == "*":
            if package in packages:
                return True
            continue
        named.update(f"{package}/{base}{s}" for base in _bases(name) for s in SECTIONS)
    return not types.isdisjoint(_closure(catalog, named))


def imports_module(
    text: str, path: Path, module: Path, index: ModuleIndex | None = None
) -> bool:
    """Whether Python `text` (the file at `path`) imports the module file `module`,
    directly or through modules of its tree that import it (whose summaries it
    sees): names are found as a check finds them (`project.modules.ModuleIndex`)."""
    tree = SourceFile.from_text(str(path), text).tree
    if tree is None:
        return False
    index = index or ModuleIndex()
    goal = _real(module)
    seen: set[str] = set()
    todo = [(path, tree)]
    while todo and len(seen) < MAX_MODULES:
        importer, current = todo.pop()
        package = index.package_of(importer)
        for name in imported_names(current, package):
            parts = name.split(".")
            for cut in range(len(parts), 0, -1):
                prefix = ".".join(parts[:cut])
                if any(_real(c) == goal for c in index.candidates(prefix, importer)):
                    return True  # also when the module was just deleted
                found = index.find(prefix, importer)
                if found is None:
                    continue
                real = _real(found)
                if real == goal:
                    return True
                if real not in seen:
                    seen.add(real)
                    parsed = _parse(found)
                    if parsed is not None:
                        todo.append((found, parsed))
    return False


def _real(path: Path) -> str:
    try:
        return os.path.realpath(path)
    except OSError:
        return str(path)


def _parse(path: Path) -> ast.Module | None:
    try:
        data = read_regular(path)
    except UnreadableError:
        return None
    return SourceFile.from_bytes(str(path), data).tree


def _imported_interfaces(tree: ast.Module) -> list[tuple[str, str]]:
    """(package, name) for `from pkg.msg import Name` and the seed's bare
    `from pkg import Name`; (package, "*") for a whole interface module."""
    found: list[tuple[str, str]] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                parts = alias.name.split(".")
                if len(parts) >= 2 and parts[1] in INTERFACE_MODULES:
                    found.append((parts[0], "*"))
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            parts = node.module.split(".")
            interface = len(parts) == 2 and parts[1] in INTERFACE_MODULES
            if not interface and len(parts) != 1:
                continue
            for alias in node.names:
                whole = alias.name == "*" or (
                    len(parts) == 1 and alias.name in INTERFACE_MODULES
                )
                found.append((parts[0], "*" if whole else alias.name))
    return found


def _bases(name: str) -> set[str]:
    """`AddTwoInts`, and the ROS 1 and action class names it may stand for
    (`AddTwoIntsRequest`, `FibonacciAction`)."""
    found = {name}
    for suffix in ROS1_SUFFIXES:
        if name.endswith(suffix) and len(name) > len(suffix):
            found.add(name[: -len(suffix)].rstrip("_"))
    return found


def _closure(catalog: MsgCatalog, names: set[str]) -> set[str]:
    """`names` and the message types of their fields, transitively."""
    seen = {normalize(n) for n in names}
    todo = sorted(seen)
    while todo and len(seen) < MAX_TYPES:
        spec = catalog.lookup(todo.pop())
        if spec is None:
            continue
        for info in spec.fields.values():
            if info.msg_type and normalize(info.msg_type) not in seen:
                seen.add(normalize(info.msg_type))
                todo.append(normalize(info.msg_type))
    return seen
