"""Which files still to check import a module, guessed from the files' bytes before
a sequential run's checks (`Project.expect(..., release=True)`), so that a module
checked before its first importer has its summary built from the parse of its own
check (`Project.take`) rather than parsing the file again for that importer (90
modules, 373 K characters of corpus25 were). A guess only: a miss costs that parse
again, a wrong guess a summary nobody asks for; the output never depends on it (a
summary depends on the import graph alone, not on when it is built).

Only the import statements' first lines are read (`from a.b import c, d` names
`a.b`, `a.b.c` and `a.b.d`; relative ones made absolute in the file's package), and
only where `import` is written: no file is parsed here."""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from pathlib import Path

from robotfix.fs import UnreadableError, read_regular
from robotfix.project.modules import ModuleIndex

# an import statement from the start of its line: `from .x import (a, b as c` or
# `import a.b as c, d`; what follows a line's end, `#`, `;` or `\` is not read
_STATEMENT = re.compile(
    rb"[ \t]*(?:from[ \t]+(\.*)[ \t]*([\w.]*)[ \t]+import[ \t]*\(?([^)#\n;\\]*)"
    rb"|import[ \t]+([^#\n;\\]*))"
)


def named_modules(data: bytes, package: str | None) -> set[str]:
    """The absolute names the import statements of a file's bytes mention."""
    from robotfix.analysis.imported import absolute

    found: set[str] = set()
    at = data.find(b"import")
    while at >= 0:
        start = data.rfind(b"\n", 0, at) + 1
        match = _STATEMENT.match(data, start)
        if match is not None and match.end() > at:
            dots, module, names, plain = match.groups()
            try:
                if plain is not None:
                    for part in plain.decode("ascii").split(","):
                        found.add(part.split(" as ")[0].strip())
                else:
                    text = module.decode("ascii")
                    base = absolute(package, len(dots), text) if dots else text
                    if base:
                        found.add(base)
                        for part in names.decode("ascii").split(","):
                            name = part.split(" as ")[0].strip()
                            if name and name != "*":
                                found.add(f"{base}.{name}")
            except UnicodeDecodeError:  # a name Python normalizes: not guessed
                pass
        end = data.find(b"\n", at)
        at = data.find(b"import", end) if end >= 0 else -1
    found.discard("")
    return found


def imported_later(
    index: ModuleIndex, paths: Sequence[Path], key: Callable[[Path], str]
) -> dict[str, Path]:
    """Each of `paths` (in the order they are checked) that a later one imports, by
    `key` (how the project compares files, `summary._key`): the module file as the
    index spells it for that importer (the project keeps its summary under that
    spelling). Decided before the checks, so that only these few are held while
    they run, not what each file imports."""
    importers: dict[str, list[int]] = {}  # module name -> places of its importers
    for place, path in enumerate(paths):
        try:
            data = read_regular(path)
        except UnreadableError:
            continue
        number = index.search_id(path)
        for name in named_modules(data, index.package_of(path)):
            if index.offers(number, name.partition(".")[0]):  # not rclpy's
                importers.setdefault(name, []).append(place)
    found: dict[str, Path] = {}
    for place, path in enumerate(paths):
        name = index.module_name(path)
        for later in importers.get(name, ()):
            if later > place:
                module = index.find(name, paths[later])
                if module is not None and key(module) == key(path):
                    found[key(path)] = module
                    break
    return found
