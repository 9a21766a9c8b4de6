"""The syntax nodes `cpp._File` reads of a C++ file's tree, found from the
words of its bytes: each node around a place where one of the words stands (on
the way down from the root to it), and nothing else of the tree.

A node the reading takes something from holds such a word: a call that makes
something its callee's last name, a whole name (`cpp_scan.makers_in`, and
`init` of `ros::init`), or the class `std::make_unique` builds; an
`alias_declaration` or a `using_declaration` its `using`; a `declaration` that
holds `NodeHandle` or `make_shared` (a `field_declaration` `NodeHandle`), as
the reading matches them; a class whose base is a node class, and an
initializer that names a node (`Node("talker")`), their `Node` (`_NODE`). The
nodes on the way that are none of these are passed by (a call of another
name). What is looked for by a name, when the reading first asks (`named`): a
function definition for a roscpp callback, an initializer giving a NodeHandle
a namespace (`pnh_("~")`).

A tree-sitter query found them before: compiling one cost 63 M instructions in
every run that parses C++ (tree-sitter reads the grammar's whole parse table,
whatever the patterns), and its cursor visited every node of every tree (80 M
on issue 25's default subset); the way down visits 5% of the nodes. (A node
tree-sitter inserts to recover from an error, MISSING, has no bytes: a
`using` or a name of no bytes is no word; the query found them.)
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from typing import Any

from robotfix.ros.graph.cpp_scan import WORD_BYTES

# what the reading matches declarations by (the query's `#match?` did before)
_DECLARATION = re.compile(rb"NodeHandle|make_shared")
# a base class's `Node`, its blanks apart (`_File._bases` drops what `\s` of a
# `str` takes: a non-ASCII byte may be one), not going on into a longer name
_GAP = rb"[\s\x1c-\x1f\x80-\xff]*"
_NODE = re.compile(rb"N" + _GAP + rb"o" + _GAP + rb"d" + _GAP + rb"e(?![A-Za-z0-9_$])")
# the nodes found, by what the reading calls them
KINDS = {
    "call_expression": "call",
    "alias_declaration": "alias",
    "using_declaration": "using",
    "field_initializer": "init",
    "declaration": "decl",
    "field_declaration": "decl",
    "class_specifier": "cls",
    "struct_specifier": "cls",
}


def nodes(
    root: Any, data: bytes, makers: list[tuple[int, int, bytes]]
) -> dict[str, list[Any]]:
    """The nodes of `KINDS` the reading may take something from, each kind in
    source order: every one around a place in `_places`, declarations only
    those that hold `NodeHandle` or `make_shared` (a field's: `NodeHandle`)."""
    found: dict[str, list[Any]] = {}
    for node in _around(root, _places(data, makers)):
        kind = KINDS.get(node.type)
        if kind is None:
            continue
        if kind == "decl":
            text = data[node.start_byte : node.end_byte]
            if node.type == "declaration":
                if _DECLARATION.search(text) is None:
                    continue
            elif b"NodeHandle" not in text:
                continue
        found.setdefault(kind, []).append(node)
    for kinds in found.values():
        kinds.sort(key=_place)
    return found


def named(root: Any, data: bytes, name: str, kind: str) -> list[Any]:
    """The nodes of type `kind` (a function definition, an initializer), in
    source order, whose name may be `name`: those around a place where `name`
    is written (all of them when it is empty or holds a character decoding
    replaced, which is in no byte)."""
    if not name or "\ufffd" in name:
        out = [n for n in _all(root) if n.type == kind]
    else:
        places = _occurrences(data, name.encode())
        out = [n for n in _around(root, places) if n.type == kind]
    return sorted(out, key=_place)


def _place(node: Any) -> tuple[int, int]:
    return node.start_byte, node.end_byte


def _occurrences(data: bytes, word: bytes) -> Iterable[tuple[int, int]]:
    at = data.find(word)
    while at >= 0:
        yield at, at + len(word)
        at = data.find(word, at + 1)


def _places(data: bytes, makers: list[tuple[int, int, bytes]]) -> set[tuple[int, int]]:
    """Where a node the reading looks at holds something of its own (the
    module's docstring): the spans of its words. `makers`: where a name that
    makes an endpoint stands as a whole name (`cpp_scan.makers_in`): a call's
    name, or a class of `CLASSES` `std::make_unique` builds."""
    places = {(start, end) for start, end, _ in makers}
    for start, end in _occurrences(data, b"init"):  # (`ros::init`)
        if (start == 0 or data[start - 1] not in WORD_BYTES) and (
            end == len(data) or data[end] not in WORD_BYTES
        ):
            places.add((start, end))
    places.update(m.span() for m in _NODE.finditer(data))
    for word in (b"using", b"NodeHandle", b"make_shared"):
        places.update(_occurrences(data, word))
    return places


def _around(root: Any, places: Iterable[tuple[int, int]]) -> list[Any]:
    """Each node around any of `places` (from the root down to the smallest
    node around the place), once."""
    seen: set[int] = set()
    out: list[Any] = []
    path: list[tuple[Any, int, int]] = []
    for start, end in sorted(places):
        while path and not (path[-1][1] <= start and end <= path[-1][2]):
            path.pop()
        if not path:
            if not (root.start_byte <= start and end <= root.end_byte):
                continue  # (around no node)
            path.append((root, root.start_byte, root.end_byte))
            if root.id not in seen:
                seen.add(root.id)
                out.append(root)
        node = path[-1][0]
        target = node.descendant_for_byte_range(start, end)
        while node != target:
            node = node.child_with_descendant(target)
            if node is None:
                break
            path.append((node, node.start_byte, node.end_byte))
            if node.id not in seen:
                seen.add(node.id)
                out.append(node)
    return out


def _all(root: Any) -> list[Any]:
    """Every node of the tree (a walk: only when no word can say where)."""
    out = []
    cursor = root.walk()
    while True:
        out.append(cursor.node)
        if cursor.goto_first_child() or cursor.goto_next_sibling():
            continue
        while cursor.goto_parent():
            if cursor.goto_next_sibling():
                break
        else:
            return out
