"""Fast traversal of the stdlib AST (about twice as fast as `ast.walk`).

`ast.walk` goes through generator-based `iter_child_nodes`; on real ROS trees the
analysis walks every node several times, so the plain loop here matters. It also
leaves out the fields that never hold a node worth visiting: names and other
strings, and the singleton contexts and operators (`Load`, `Add`, `Eq`), which no
walker looks for (they are read from their parent: `node.ctx`, `node.op`).
"""

from __future__ import annotations

import ast
import re
from collections.abc import Callable, Collection, Iterable, Iterator
from typing import Any

# `try` statements: `try ... except*` (`ast.TryStar`) is Python 3.11's; the package
# runs on 3.10 (ROS 2 Humble), where naming it at import failed
TRIES: tuple[type, ...] = (ast.Try, getattr(ast, "TryStar", ast.Try))
# fields that hold a str, a number, or a context or operator singleton
LEAF_FIELDS = frozenset(
    {"ctx", "op", "ops", "id", "attr", "arg", "name", "asname", "module", "level"}
    | {"kind", "conversion", "is_async", "simple", "type_comment", "tag"}
)
_FIELDS: dict[type, tuple[str, ...]] = {}
FIELDS = _FIELDS  # read-only for hot loops: `FIELDS.get(kind) or fields(kind)`


def fields(kind: type) -> tuple[str, ...]:
    """The fields of a node class that may hold nodes worth visiting."""
    found = _FIELDS.get(kind)
    if found is not None:
        return found
    found = tuple(f for f in kind._fields if f not in LEAF_FIELDS)  # type: ignore[attr-defined]
    _FIELDS[kind] = found
    return found


# Node classes each of whose `fields` always holds a node or a list of nodes (never
# None or a string), the single nodes before the lists: (single fields, list
# fields), in the order of `fields`. A walk that must be fast pushes their
# children without a test per child (`paths.PathWalker.havoc_sums`).
SHAPES: dict[type, tuple[tuple[str, ...], tuple[str, ...]]] = {
    ast.Compare: (("left",), ("comparators",)),
    ast.If: (("test",), ("body", "orelse")),
    ast.BinOp: (("left", "right"), ()),
    ast.For: (("target", "iter"), ("body", "orelse")),
    ast.AsyncFor: (("target", "iter"), ("body", "orelse")),
    ast.Subscript: (("value", "slice"), ()),
    ast.Tuple: ((), ("elts",)),
    ast.List: ((), ("elts",)),
    ast.Set: ((), ("elts",)),
    ast.keyword: (("value",), ()),
    ast.UnaryOp: (("operand",), ()),
    ast.BoolOp: ((), ("values",)),
    ast.While: (("test",), ("body", "orelse")),
    ast.Try: ((), ("body", "handlers", "orelse", "finalbody")),
    ast.AugAssign: (("target", "value"), ()),
    ast.comprehension: (("target", "iter"), ("ifs",)),
    ast.ListComp: (("elt",), ("generators",)),
    ast.SetComp: (("elt",), ("generators",)),
    ast.GeneratorExp: (("elt",), ("generators",)),
    ast.DictComp: (("key", "value"), ("generators",)),
    ast.Starred: (("value",), ()),
    ast.IfExp: (("test", "body", "orelse"), ()),
    ast.JoinedStr: ((), ("values",)),
    ast.With: ((), ("items", "body")),
    ast.AsyncWith: ((), ("items", "body")),
    ast.Await: (("value",), ()),
    ast.Delete: ((), ("targets",)),
}


_NODE = ast.AST  # (a global read, not `ast.AST`'s two lookups, per child)


def children(node: ast.AST) -> list[ast.AST]:
    found: list[ast.AST] = []
    kind = type(node)
    names = _FIELDS.get(kind)
    if names is None:
        names = fields(kind)
    for name in names:
        value = getattr(node, name, None)
        if type(value) is list:
            for v in value:
                if isinstance(v, _NODE):
                    found.append(v)
        elif isinstance(value, _NODE):
            found.append(value)
    return found


def walk(roots: ast.AST | Iterable[ast.AST]) -> Iterator[ast.AST]:
    """Every node under `roots` (roots included), in no particular order; parents
    come before their children. Contexts and operators are not visited."""
    todo = [roots] if isinstance(roots, ast.AST) else list(roots)
    pop, extend = todo.pop, todo.extend
    while todo:
        node = pop()
        yield node
        kind = type(node)
        if kind is not ast.Name and kind is not ast.Constant:  # they have none
            extend(children(node))


def select(
    roots: Iterable[ast.AST],
    kinds: frozenset[type],
    skip: frozenset[type] = frozenset(),
) -> list[ast.AST]:
    """The nodes under `roots` (roots included) of a class in `kinds`, as `walk`
    meets them, not entering those of a class in `skip` (nor returning them).
    Names and constants are never stacked, so `kinds` holds neither; nor are
    attributes, unless asked for: a chain `a.b().c` is read down to what its
    last attribute holds, which takes the chain's place on the stack (an
    attribute holds no other node, so the order is `walk`'s)."""
    found: list[ast.AST] = []
    todo = list(roots)
    pop, append = todo.pop, todo.append
    leaves, node_class, known = (ast.Name, ast.Constant), ast.AST, _FIELDS
    chain = ast.Attribute if ast.Attribute not in kinds | skip else None
    child: Any
    while todo:
        node = pop()
        kind = type(node)
        if kind in skip:
            continue
        if kind in kinds:
            found.append(node)
        for name in known.get(kind) or fields(kind):
            value = getattr(node, name, None)
            for child in value if type(value) is list else (value,):
                while type(child) is chain:
                    child = child.value
                if type(child) not in leaves and isinstance(child, node_class):
                    append(child)
    return found


def names_under(
    root: ast.AST, keep: Callable[[ast.AST], bool] | None = None
) -> list[tuple[ast.AST, ast.Name]]:
    """Every name under `root`, with its parent (names and constants are never
    stacked: they hold no node). Given `keep` (a `Mentions`), only under the
    statements it keeps."""
    found: list[tuple[ast.AST, ast.Name]] = []
    todo = [root]
    pop, append, add = todo.pop, todo.append, found.append
    name_class, constant_class, node_class, known = (
        ast.Name,
        ast.Constant,
        ast.AST,
        _FIELDS,
    )
    child: Any
    while todo:
        node = pop()
        for field in known.get(type(node)) or fields(type(node)):
            value = getattr(node, field, None)
            if type(value) is not list:
                value = (value,)
            elif keep is not None and field in BLOCK_FIELDS:
                value = [s for s in value if keep(s)]
            for child in value:
                kind = type(child)
                if kind is name_class:
                    add((node, child))
                elif kind is not constant_class and isinstance(child, node_class):
                    append(child)
    return found


def dotted(node: ast.expr) -> str | None:
    """`np.linalg.norm` -> "np.linalg.norm"; None when not a chain of names."""
    parts: list[str] = []
    while isinstance(node, ast.Attribute):
        parts.append(node.attr)
        node = node.value
    if not isinstance(node, ast.Name):
        return None
    return ".".join([node.id, *reversed(parts)])


# the fields whose list holds statements (or `except` handlers); a `body` that is
# not a list is an expression's (`lambda`, `a if c else b`)
BLOCK_FIELDS = frozenset({"body", "orelse", "finalbody", "handlers"})
# every field of a statement that holds statements, handlers or cases, in the
# order the statement walks of the graph and parameter readings take them
STATEMENT_BLOCKS = ("body", "handlers", "orelse", "finalbody", "cases")


class Mentions:
    """Which statements of a tree may hold a name among `words`: those whose lines
    (decorators included) hold one of the words as text, or a character that is not
    ASCII (Python normalizes identifiers: a ligature or a fullwidth letter in the
    source is a plain letter in the name). A walk that keeps only these skips what
    cannot hold such a name.
    `lines` are the tree's source lines (`SourceFile.lines`); only lines `first` to
    `last` are read, and a statement not within them is kept."""

    def __init__(
        self,
        lines: list[str],
        words: Collection[str],
        first: int = 1,
        last: int | None = None,
    ) -> None:
        self.first = first
        self.last = len(lines) if last is None else min(last, len(lines))
        # hits[i]: how many of the first i lines read may hold one of the words
        hits = [0]
        count = 0
        read = lines[first - 1 : self.last]
        if len(words) == 1:
            (word,) = words
            for line in read:
                if word in line or not line.isascii():
                    count += 1
                hits.append(count)
        else:
            search = re.compile("|".join(map(re.escape, sorted(words)))).search
            for line in read:
                if not line.isascii() or search(line):
                    count += 1
                hits.append(count)
        self.hits = hits

    def __call__(self, node: ast.AST) -> bool:
        end: int | None = getattr(node, "end_lineno", None)
        if end is None or end > self.last:  # (a node made, not parsed: keep it)
            return True
        start: int = node.lineno  # type: ignore[attr-defined]
        for decorator in getattr(node, "decorator_list", ()):
            start = min(start, decorator.lineno)
        if start < self.first:
            return True
        return self.hits[end - self.first + 1] > self.hits[start - self.first]

    @staticmethod
    def of(lines: list[str], words: Collection[str], scope: ast.AST) -> Mentions:
        """Those of the statements of `scope` (a parsed function, class or module)."""
        if isinstance(scope, ast.Module):
            return Mentions(lines, words)
        first = scope.lineno  # type: ignore[attr-defined]
        for decorator in getattr(scope, "decorator_list", ()):
            first = min(first, decorator.lineno)
        return Mentions(lines, words, first, getattr(scope, "end_lineno", None))
