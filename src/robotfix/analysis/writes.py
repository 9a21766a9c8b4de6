"""Which objects named in a block of statements the block may change, read from its
syntax: a store into one (`p.header.frame_id = f`, `p.data[0] = v`), a method called
on one (`p.points.append(q)`), and the same through a name that aliases it there
(`m = p`, `h = p.header`, `for q in p.points`). Handing one to a call that is not
known to only read it, storing it elsewhere (`self.last = p`, `[p]`) or returning it
lets other code change it: it *escapes*. A read (`p.point.x` in an expression, a
number or string field anywhere, `do_transform_point(p, t)`, `pub.publish(p)`)
changes nothing. A loop's head forgets only what its body changes (interpreter.py).
"""

from __future__ import annotations

import ast
from collections.abc import Callable, Iterable

# (root name, field path under it) -> whether the value there is a number or a
# string (nothing can be changed through it)
Leaf = Callable[[str, tuple[str, ...]], bool]
# whether a call only reads the argument expression it is given
Reads = Callable[[ast.Call, ast.expr], bool]

READ, CHANGE, ESCAPE = "read", "change", "escape"
_READING = frozenset(
    {
        ast.Compare,
        ast.UnaryOp,
        ast.BinOp,
        ast.If,
        ast.While,
        ast.Assert,
        ast.FormattedValue,
        ast.JoinedStr,
        ast.Expr,
    }
)
_PASSING = (ast.BoolOp, ast.IfExp)  # `a or b`, `a if c else b`: the value goes on
_NESTED = (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)


def uses(
    nodes: Iterable[ast.AST], roots: set[str], leaf: Leaf, reads: Reads
) -> dict[str, set[str | tuple[str, ...]]]:
    """What `nodes` may do to the objects of `roots`, by name: CHANGE, ESCAPE, or
    the paths of the fields they store into (`("header", "stamp")`); a mention
    inside a function or class they define lets it escape (it may run at any
    time)."""
    parents: dict[int, ast.AST] = {}
    mentions: dict[str, list[ast.Name]] = {}
    found: dict[str, set[str | tuple[str, ...]]] = {}
    for top in nodes:
        for node in ast.walk(top):
            if node is not top and node.__class__ in _NESTED:
                for inner in ast.walk(node):
                    if inner.__class__ is ast.Name and inner.id in roots:  # type: ignore[attr-defined]
                        found.setdefault(inner.id, set()).add(ESCAPE)  # type: ignore[attr-defined]
            for child in ast.iter_child_nodes(node):
                parents[id(child)] = node
            if node.__class__ is ast.Name:
                mentions.setdefault(node.id, []).append(node)  # type: ignore[attr-defined]
    for root in roots:
        kinds = found.setdefault(root, set())
        todo, seen = [(root, ())], {root}
        while todo:
            name, prefix = todo.pop()
            for mention in mentions.get(name, ()):
                use = _use(mention, prefix, root, parents, leaf, reads)
                if isinstance(use, str):
                    if use != READ:
                        kinds.add(use)
                    continue
                for alias, path in use:
                    if not alias:
                        kinds.add(path)
                    elif alias not in seen:
                        seen.add(alias)
                        todo.append((alias, path))
    return found


def _use(
    mention: ast.Name,
    prefix: tuple[str, ...],
    root: str,
    parents: dict[int, ast.AST],
    leaf: Leaf,
    reads: Reads,
) -> str | list[tuple[str, tuple[str, ...]]]:
    """What one mention does to the object: READ, CHANGE, ESCAPE, or the names it
    is bound to (with the path under the root they then hold; no name: the path of
    a field stored into)."""
    if mention.ctx.__class__ is not ast.Load:
        return READ  # (re)binding the name changes no object
    node: ast.AST = mention
    path = list(prefix)
    parent = parents.get(id(node))
    while parent.__class__ in (ast.Attribute, ast.Subscript) and parent.value is node:  # type: ignore[union-attr]
        path.append(parent.attr if parent.__class__ is ast.Attribute else "[]")  # type: ignore[union-attr]
        node, parent = parent, parents.get(id(parent))  # type: ignore[assignment]
    if node.ctx.__class__ is ast.Store and "[]" not in path:  # type: ignore[attr-defined]
        return [("", tuple(path))]  # a field stored into: only it changes
    if node.ctx.__class__ is not ast.Load:  # type: ignore[attr-defined]
        return CHANGE  # an element stored into, or deleted
    if leaf(root, tuple(path)):
        return READ  # a number or a string: nothing to change through it
    while isinstance(parent, _PASSING) and getattr(parent, "test", None) is not node:
        node, parent = parent, parents.get(id(parent))  # type: ignore[assignment]
    kind = parent.__class__
    if kind is ast.IfExp:
        return READ  # its test
    if kind is ast.Call:
        if parent.func is node:  # type: ignore[union-attr]
            return CHANGE if node is not mention else ESCAPE  # a method, or a callable
        return READ if reads(parent, node) else ESCAPE  # type: ignore[arg-type]
    if kind is ast.keyword or kind is ast.Starred:
        call = parents.get(id(parent))
        if call.__class__ is ast.Call and reads(call, node):  # type: ignore[arg-type]
            return READ
        return ESCAPE
    if kind is ast.Assign and parent.value is node:  # type: ignore[union-attr]
        targets = parent.targets  # type: ignore[union-attr]
        if all(t.__class__ is ast.Name for t in targets):
            return [(t.id, tuple(path)) for t in targets]
        return ESCAPE
    if kind in (ast.AnnAssign, ast.NamedExpr) and parent.value is node:  # type: ignore[union-attr]
        target = parent.target  # type: ignore[union-attr]
        return [(target.id, tuple(path))] if target.__class__ is ast.Name else ESCAPE
    if kind in (ast.For, ast.AsyncFor, ast.comprehension) and parent.iter is node:  # type: ignore[union-attr]
        target = parent.target  # type: ignore[union-attr]
        if target.__class__ is ast.Name:
            return [(target.id, (*path, "[]"))]
        return ESCAPE
    if kind in _READING:
        return READ
    return ESCAPE
