"""The branch decisions on a path, for RF301: which data each test looked at.

A name bound on some paths only is unbound on a path that a run surely takes only
if that path's decisions are independent of each other. Two tests that look at a
common name or attribute (`cp.shape[-1] == 3`, later `a.shape[-1] == 2`; `if not
auth:` then `if auth:` with `auth` rebound in between) may be tied by facts about
the data the analysis does not track (a list's length set from another's, a
credential found only for some URLs): on such a path the read stays silent.
Unless a name holds the same value the analysis tracks in both (`level > 0.5`, then
`level > 0.2`): the solver then knows how the tests are tied.
"""

from __future__ import annotations

import ast
from collections.abc import Callable, Hashable

from robotfix.astwalk import children

# One decision: the test's node id (the same test on a path counts once) and the
# names and attributes it mentions, each with the value the analysis tracks for it
# there (None: none, or an attribute).
Decision = tuple[int, frozenset[tuple[str, Hashable]]]
Decisions = tuple[Decision, ...]

# The receiver of every method: two tests of different attributes of `self` are
# not tied by `self` itself.
RECEIVERS = frozenset({"self", "cls"})


def decision(
    test: ast.expr,
    local_names: set[str],
    tracked: Callable[[str], Hashable],
    attributes: dict[int, int],
) -> Decision:
    """The data `test` looks at: the locals it reads (with `tracked(name)`) and the
    attributes it reads (with the symbol each gave, in `attributes`), not the
    functions or methods it calls, nor module names (`math`, a class)."""
    skipped: set[int] = set()  # callees and the objects of attributes
    found: set[tuple[str, Hashable]] = set()
    todo: list[ast.AST] = [test]  # (`walk`: parents before their children)
    push, extend, pop = todo.append, todo.extend, todo.pop
    # (node classes as local names: a module attribute costs a look-up a node)
    name_node, attribute_node, call_node = ast.Name, ast.Attribute, ast.Call
    while todo:
        node = pop()
        kind = type(node)
        if kind is name_node:  # (a name and a constant have no children)
            name: str = node.id  # type: ignore[attr-defined]
            local = name in local_names and name not in RECEIVERS
            if local and id(node) not in skipped:
                found.add((name, tracked(name)))
            continue
        if kind is attribute_node:
            value = node.value  # type: ignore[attr-defined]
            skipped.add(id(value))
            if id(node) not in skipped:  # `scan.range_min`: the field is the data
                found.add(("." + node.attr, attributes.get(id(node))))  # type: ignore[attr-defined]
            push(value)
            continue
        if kind is call_node:
            func = node.func  # type: ignore[attr-defined]
            skipped.add(id(func))
            push(func)
            extend(node.args)  # type: ignore[attr-defined]
            extend(node.keywords)  # type: ignore[attr-defined]
            continue
        if kind is ast.Compare:  # (the commonest tests push their own children)
            push(node.left)  # type: ignore[attr-defined]
            extend(node.comparators)  # type: ignore[attr-defined]
        elif kind is ast.UnaryOp:
            push(node.operand)  # type: ignore[attr-defined]
        elif kind is ast.BoolOp:
            extend(node.values)  # type: ignore[attr-defined]
        elif kind is not ast.Constant:
            extend(children(node))
    return id(test), frozenset(found)


def merged(*parts: Decisions) -> Decisions:
    """The decisions of several paths' records, each test once, in order."""
    seen: set[int] = set()
    out: list[Decision] = []
    for part in parts:
        for one in part:
            if one[0] not in seen:
                seen.add(one[0])
                out.append(one)
    return tuple(out)


def correlated(decisions: Decisions, early: frozenset[int] = frozenset()) -> bool:
    """Do two different tests mention a common name or attribute, other than a
    name holding one tracked value in both? Two `early` ones (taken before the
    paths split, on the path that bound the name too) do not count."""
    seen: dict[str, list[tuple[Hashable, bool]]] = {}
    for ident, names in decisions:
        late = ident not in early
        for name, value in names:
            for other, other_early in seen.get(name, ()):
                if (late or not other_early) and (value is None or other != value):
                    return True
        for name, value in names:
            seen.setdefault(name, []).append((value, not late))
    return False
