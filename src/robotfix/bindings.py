"""What the names an edit of `robotfix suggest` writes stand for in the module:
`Annotated` must be typing's, `typing` the typing module, `float` the builtin, at
every place the edit writes them.

Decided syntactically, from the compiler's own scopes (`symtable`: nothing is run or
imported). A name is taken to mean what the edit means when no scope of the module
binds it (assignment, `def`, `class`, `del`, loop, `with`, `except`, walrus, match,
parameter, `global` from a function) other than a module-level import that means it
(`from typing import Annotated`, `from typing_extensions import Annotated`,
`import typing`); a builtin may not be bound at all. A star import is taken to bind
nothing (what it binds is not in the text).
"""

from __future__ import annotations

import ast
import symtable

TYPING_MODULES = ("typing", "typing_extensions")
# the names an edit writes that an import must bind, and that import's text
IMPORTS = {"Annotated": "from typing import Annotated", "typing": "import typing"}


class Bindings:
    """One module's scopes, for questions about the names an edit writes. Raises
    SyntaxError (and RecursionError, MemoryError on absurd nesting) when the text
    does not compile."""

    def __init__(self, text: str, tree: ast.Module) -> None:
        self.tree = tree
        top = symtable.symtable(text, "<module>", "exec")
        self.module = top
        self.scopes: list[symtable.SymbolTable] = []
        stack = [top]
        while stack:
            table = stack.pop()
            self.scopes.append(table)
            stack.extend(table.get_children())

    def rebound(self, name: str) -> bool:
        """Whether `name` may stand, somewhere in the module, for something other
        than what the edit means by it."""
        for table in self.scopes:
            try:
                symbol = table.lookup(name)
            except KeyError:
                continue
            if symbol.is_assigned() or (
                table is not self.module
                and (symbol.is_imported() or symbol.is_parameter())
            ):
                return True
        return any(
            _bound(node, alias) == name and not _means(node, alias, name)
            for node in ast.walk(self.tree)
            if isinstance(node, (ast.Import, ast.ImportFrom))
            for alias in node.names
        )

    def imported_at(self, name: str) -> int | None:
        """The line of the first top-level statement that imports `name` as the
        edit means it (None if none does, or if `name` needs no import)."""
        for node in self.tree.body:
            if isinstance(node, (ast.Import, ast.ImportFrom)) and any(
                _bound(node, alias) == name and _means(node, alias, name)
                for alias in node.names
            ):
                return node.lineno
        return None


def _bound(node: ast.Import | ast.ImportFrom, alias: ast.alias) -> str:
    """The name an import binds (`import a.b` binds `a`; `*` binds no name here)."""
    if alias.asname:
        return alias.asname
    return alias.name if isinstance(node, ast.ImportFrom) else alias.name.split(".")[0]


def _means(node: ast.Import | ast.ImportFrom, alias: ast.alias, name: str) -> bool:
    if name == "Annotated":
        return (
            isinstance(node, ast.ImportFrom)
            and node.level == 0
            and node.module in TYPING_MODULES
            and alias.name == "Annotated"
        )
    if name == "typing":
        return isinstance(node, ast.Import) and (
            alias.name == "typing"
            or (alias.asname is None and alias.name.startswith("typing."))
        )
    return False  # a builtin: no import means it
