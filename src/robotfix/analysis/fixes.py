"""Where a unit message's quick fix edits, found in the syntax of the reported
statement: the value it stores (`Written`), the factor or conversion call the
message says to remove (an `Edit` putting back what it was applied to), and the
module the file calls `radians()` of. The message builders (`messages.py`) make
the fixes; an editor checks each one again before it offers it (`lsp/server.py`).
Nothing here decides whether a fix is right: a fix it cannot place is not made.
"""

from __future__ import annotations

import ast
import math
from collections.abc import Sequence

from robotfix.diagnostics import Edit
from robotfix.messages import Written
from robotfix.source import SourceFile

# expressions that need no parentheses as an operand of `*` or `/`
_ATOMS = (ast.Name, ast.Attribute, ast.Call, ast.Subscript, ast.Constant)
_ANGLE_MODULES = ("math", "numpy")  # whose radians() and degrees() a fix may call


def stored(source: SourceFile, site: ast.AST) -> ast.expr | None:
    """The value a statement stores into its one target, or the expression the
    check was made at; None when it is not one expression for one target."""
    if isinstance(site, ast.expr):
        return site
    if isinstance(site, ast.Assign):
        simple = all(
            isinstance(t, (ast.Name, ast.Attribute, ast.Subscript))
            for t in site.targets
        )
        value = site.value if simple else None
    elif isinstance(site, (ast.AnnAssign, ast.AugAssign, ast.Return)):
        value = site.value
    else:
        return None
    if value is None or isinstance(value, (ast.Tuple, ast.List, ast.Starred)):
        return None
    return value


def written(source: SourceFile, node: ast.expr | None) -> Written | None:
    text = None if node is None else source.segment(node)
    if node is None or not text:
        return None
    return Written(source.span(node), text, isinstance(node, _ATOMS))


def undo_factor(source: SourceFile, within: ast.AST, factor: float) -> Edit | None:
    """The one `x * factor` (or `factor * x`, `x / (1 / factor)`) in `within`,
    replaced by `x`."""
    found = []
    for node in ast.walk(within):
        if not isinstance(node, ast.BinOp):
            continue
        if isinstance(node.op, ast.Mult):
            for number, other in ((node.right, node.left), (node.left, node.right)):
                if _is_number(number, factor):
                    found.append((node, other))
        elif isinstance(node.op, ast.Div) and _is_number(node.right, 1 / factor):
            found.append((node, node.left))
    return _replaced(source, found)


def undo_call(source: SourceFile, within: ast.AST, call: str) -> Edit | None:
    """The one call of `call` (as written, `math.degrees`) with one argument in
    `within`, replaced by its argument."""
    found = [
        (node, node.args[0])
        for node in ast.walk(within)
        if isinstance(node, ast.Call)
        and len(node.args) == 1
        and not node.keywords
        and not isinstance(node.args[0], ast.Starred)
        and source.segment(node.func) == call
    ]
    return _replaced(source, found)


def angles(source: SourceFile) -> str:
    """The name a top-level `import math` (else `import numpy`) binds, or ""."""
    tree = source.tree
    bound: dict[str, str] = {}
    for node in tree.body if tree is not None else ():
        if isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name in _ANGLE_MODULES:
                    bound.setdefault(alias.name, alias.asname or alias.name)
    return next((bound[m] for m in _ANGLE_MODULES if m in bound), "")


def _replaced(
    source: SourceFile, found: Sequence[tuple[ast.expr, ast.expr]]
) -> Edit | None:
    if len(found) != 1:
        return None
    node, kept = found[0]
    text = source.segment(kept)
    if not text:
        return None
    atom = isinstance(kept, _ATOMS)
    return Edit(source.span(node), text if atom else f"({text})")


def _is_number(node: ast.expr, value: float) -> bool:
    return (
        isinstance(node, ast.Constant)
        and isinstance(node.value, (int, float))
        and not isinstance(node.value, bool)
        and math.isclose(node.value, value, rel_tol=1e-9)
    )
