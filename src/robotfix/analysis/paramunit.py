"""The nodes one unit of a file's parameter walk reads (`paramwalk.Walker.unit`):
its calls and assignments, in the order of their positions. A function's come
from the calls the check's index found (`Placed`) and a walk of its statements,
not from a walk of every node of it; the module's statements' from that walk.
"""

from __future__ import annotations

import ast
import operator
from bisect import bisect_left

from robotfix.astwalk import STATEMENT_BLOCKS, select

UNIT_KINDS = frozenset({ast.Call, ast.Assign, ast.AnnAssign})  # what a unit reads
_DEFINITIONS = frozenset(
    {ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda}
)
PLACE = operator.attrgetter("lineno", "col_offset")  # the order a unit reads in
_CALLS = frozenset({ast.Call})


class Placed:
    """Every call of a module (`FileIndex.calls`) by position: a stable sort of
    the index's order, in which a call comes before those within it (the order
    `select` meets two calls that start at one place)."""

    def __init__(self, calls: list[tuple[str | None, ast.Call]]) -> None:
        self.calls = sorted((call for _, call in calls), key=PLACE)
        self.starts = [(c.lineno, c.col_offset) for c in self.calls]


def unit_nodes(
    body: list[ast.stmt], function: bool, placed: Placed | None
) -> list[ast.AST]:
    """The calls and assignments of `body` by position, as a sorted `select` of
    them finds them: all of a function's (`function`), the module's statements'
    but for what its functions, classes and lambdas hold."""
    if not function or placed is None or not body:
        skip = frozenset() if function else _DEFINITIONS
        return sorted(select(body, UNIT_KINDS, skip), key=PLACE)
    last = body[-1]
    end = (last.end_lineno, last.end_col_offset)
    if end[0] is None or end[1] is None:  # (a tree made, not parsed)
        return sorted(select(body, UNIT_KINDS), key=PLACE)
    first = body[0]
    start = min([PLACE(first), *map(PLACE, getattr(first, "decorator_list", ()))])
    found: list[ast.AST] = []
    todo: list[ast.AST] = list(body)
    while todo:  # statements only: an assignment holds none
        node = todo.pop()
        kind = node.__class__
        if kind is ast.Assign or kind is ast.AnnAssign:
            found.append(node)
            continue
        if kind is ast.FunctionDef or kind is ast.AsyncFunctionDef:
            found += _annotation_calls(node)  # type: ignore[arg-type]
        for name in STATEMENT_BLOCKS:
            block = getattr(node, name, None)
            if block.__class__ is list:
                todo += block
    starts = placed.starts
    # every node of a statement lies within its lines, its decorators' too
    found += placed.calls[bisect_left(starts, start) : bisect_left(starts, end)]
    return sorted(found, key=PLACE)  # at one place: an assignment first


def _annotation_calls(node: ast.FunctionDef | ast.AsyncFunctionDef) -> list[ast.AST]:
    """The calls in the annotations of a function's parameters and return, which
    the index's walk does not enter."""
    args = node.args
    every = [*args.posonlyargs, *args.args, *args.kwonlyargs, args.vararg, args.kwarg]
    annotations = [a.annotation for a in every if a is not None and a.annotation]
    if node.returns is not None:
        annotations.append(node.returns)
    return select(annotations, _CALLS) if annotations else []
