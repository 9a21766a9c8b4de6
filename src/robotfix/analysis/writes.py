"""Which objects named in a block of statements the block may change, read from its
syntax: a store into one (`p.header.frame_id = f`, `p.data[0] = v`), a method called
on one (`p.points.append(q)`), and the same through a name that aliases it there
(`m = p`, `h = p.header`, `for q in p.points`). Handing one to a call that is not
known to only read it, storing it elsewhere (`self.last = p`, `[p]`) or returning it
lets other code change it: it *escapes*. A read (`p.point.x` in an expression, a
number or string field anywhere, `do_transform_point(p, t)`, `pub.publish(p)`)
changes nothing. A loop's head forgets only what its body changes
(`paths.PathWalker.havoc`).
"""

from __future__ import annotations

import ast
import weakref
from collections.abc import Callable, Iterable

from robotfix.analysis import containers
from robotfix.astwalk import children

# (root name, field path under it) -> whether the value there is a number or a
# string (nothing can be changed through it)
Leaf = Callable[[str, tuple[str, ...]], bool]
# whether a call only reads the argument expression it is given
Reads = Callable[[ast.Call, ast.expr], bool]

READ, CHANGE, ESCAPE = "read", "change", "escape"
# what only reads a value (a list's reading parents but those that hand on its
# elements, or the value itself: a loop, `return`, `*xs`)
_READING = (
    containers.READING_PARENTS
    - {ast.For, ast.AsyncFor, ast.comprehension, ast.Starred, ast.Return}
) | {ast.JoinedStr}
_PASSING = (ast.BoolOp, ast.IfExp)  # `a or b`, `a if c else b`: the value goes on
_NESTED = (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)


def uses(
    nodes: Iterable[ast.AST], roots: set[str], leaf: Leaf, reads: Reads
) -> dict[str, set[str | tuple[str, ...]]]:
    """What `nodes` may do to the objects of `roots`, by name: CHANGE, ESCAPE, or
    the paths of the fields they store into (`("header", "stamp")`); a mention
    inside a function or class they define lets it escape (it may run at any
    time)."""
    nodes = list(nodes)
    top = nodes[0] if len(nodes) == 1 and type(nodes[0]) is not ast.Name else None
    under: dict[int, ast.AST] = {}
    if top is not None:  # a function or a module: asked again at every loop
        known = _SYNTAX.get(top)
        if known is None:
            known = _SYNTAX[top] = _syntax(nodes, kept=True)
        syntax = known
        # the memo leaves out the edges to `top` (a value holding its key would
        # keep it alive): they are made again here
        under = {id(child): top for child in children(top)}
    else:
        syntax = _syntax(nodes)
    parents = syntax[0]

    def parent_of(ident: int) -> ast.AST | None:
        return parents.get(ident) or under.get(ident)

    _, mentions, nested = syntax
    found: dict[str, set[str | tuple[str, ...]]] = {}
    for root in roots:
        kinds = found.setdefault(root, set())
        if root in nested:
            kinds.add(ESCAPE)
        aliases: list[tuple[str, tuple[str, ...]]] = [(root, ())]
        seen = {root}
        while aliases:
            name, prefix = aliases.pop()
            for mention in mentions.get(name, ()):
                use = _use(mention, prefix, root, parent_of, leaf, reads)
                if isinstance(use, str):
                    if use != READ:
                        kinds.add(use)
                    continue
                for alias, path in use:
                    if not alias:
                        kinds.add(path)
                    elif alias not in seen:
                        seen.add(alias)
                        aliases.append((alias, path))
    return found


# what `_syntax` found under one node, kept as long as the node's tree
Syntax = tuple[dict[int, ast.AST], dict[str, list[ast.Name]], set[str]]
_SYNTAX: weakref.WeakKeyDictionary[ast.AST, Syntax] = weakref.WeakKeyDictionary()


def _syntax(nodes: list[ast.AST], kept: bool = False) -> Syntax:
    """Each node's parent, the mentions of each name, and the names mentioned
    inside a function or class `nodes` define. `kept`: not the parent of a child
    of `nodes` (what `_SYNTAX` keeps must not hold its key)."""
    parents: dict[int, ast.AST] = {}
    mentions: dict[str, list[ast.Name]] = {}
    nested_names: set[str] = set()
    todo: list[tuple[ast.AST, bool]] = [(top, False) for top in nodes]
    while todo:
        node, nested = todo.pop()
        if isinstance(node, ast.Name):
            mentions.setdefault(node.id, []).append(node)
            if nested:
                nested_names.add(node.id)
            continue
        top = node in nodes
        inner = nested or (not top and isinstance(node, _NESTED))
        for child in children(node):
            if not (kept and top):
                parents[id(child)] = node
            todo.append((child, inner))
    return parents, mentions, nested_names


def _use(
    mention: ast.Name,
    prefix: tuple[str, ...],
    root: str,
    parent_of: Callable[[int], ast.AST | None],
    leaf: Leaf,
    reads: Reads,
) -> str | list[tuple[str, tuple[str, ...]]]:
    """What one mention does to the object: READ, CHANGE, ESCAPE, or the names it
    is bound to (with the path under the root they then hold; no name: the path of
    a field stored into)."""
    if not isinstance(mention.ctx, ast.Load):
        return READ  # (re)binding the name changes no object
    node: ast.expr = mention
    path = list(prefix)
    parent = parent_of(id(node))
    while isinstance(parent, (ast.Attribute, ast.Subscript)) and parent.value is node:
        path.append(parent.attr if isinstance(parent, ast.Attribute) else "[]")
        node, parent = parent, parent_of(id(parent))
    context = getattr(node, "ctx", None)
    if isinstance(context, ast.Store) and "[]" not in path:
        return [("", tuple(path))]  # a field stored into: only it changes
    if not isinstance(context, ast.Load):
        return CHANGE  # an element stored into, or deleted
    if leaf(root, tuple(path)):
        return READ  # a number or a string: nothing to change through it
    while isinstance(parent, _PASSING) and getattr(parent, "test", None) is not node:
        node, parent = parent, parent_of(id(parent))
    if isinstance(parent, ast.IfExp):
        return READ  # its test
    if isinstance(parent, ast.Call):
        if parent.func is node:  # a method, or the object called
            return CHANGE if node is not mention else ESCAPE
        return READ if reads(parent, node) else ESCAPE
    if isinstance(parent, (ast.keyword, ast.Starred)):
        call = parent_of(id(parent))
        return READ if isinstance(call, ast.Call) and reads(call, node) else ESCAPE
    if isinstance(parent, ast.Assign) and parent.value is node:
        targets = parent.targets
        if all(isinstance(t, ast.Name) for t in targets):
            return [(t.id, tuple(path)) for t in targets if isinstance(t, ast.Name)]
        return ESCAPE
    if isinstance(parent, (ast.AnnAssign, ast.NamedExpr)) and parent.value is node:
        target = parent.target
        return [(target.id, tuple(path))] if isinstance(target, ast.Name) else ESCAPE
    if isinstance(parent, (ast.For, ast.AsyncFor, ast.comprehension)):
        if parent.iter is node and isinstance(parent.target, ast.Name):
            return [(parent.target.id, (*path, "[]"))]
        return ESCAPE
    if parent.__class__ in _READING:
        return READ
    return ESCAPE
