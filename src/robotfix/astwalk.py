"""Fast traversal of the stdlib AST (about twice as fast as `ast.walk`).

`ast.walk` goes through generator-based `iter_child_nodes`; on real ROS trees the
analysis walks every node several times, so the plain loop here matters.
"""

from __future__ import annotations

import ast
from collections.abc import Iterable, Iterator


def children(node: ast.AST) -> list[ast.AST]:
    found: list[ast.AST] = []
    for name in node._fields:
        value = getattr(node, name, None)
        if value.__class__ is list:
            found.extend(v for v in value if isinstance(v, ast.AST))
        elif isinstance(value, ast.AST):
            found.append(value)
    return found


def walk(roots: ast.AST | Iterable[ast.AST]) -> Iterator[ast.AST]:
    """Every node under `roots` (roots included), in no particular order."""
    todo = [roots] if isinstance(roots, ast.AST) else list(roots)
    while todo:
        node = todo.pop()
        yield node
        todo.extend(children(node))
