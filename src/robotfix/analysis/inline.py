"""Which unannotated helpers a call may be evaluated through, read from the syntax.

A helper whose body (after an optional docstring) is one `return <expr>` is, at a
call, the expression with its parameters bound to the arguments: `clamp(omega, -M,
M)` has the unit, factors and term `max(-M, min(M, omega))` has. Only expressions
that read and call nothing with an effect qualify: names, constants, attribute and
item reads, operators, comparisons, conditional expressions, tuples, and calls of
pure builtins, of functions the stubs know under `math` and `numpy`, and of other
such helpers of the module (to `MAX_DEPTH`, never recursively). Anything else (a
statement, `*args`, a decorator, a lambda or comprehension, a call of unknown code)
keeps the call's result unknown, as before.

A helper that builds a message and returns it (`twist = Twist()`, stores into its
fields of such expressions, `return twist`: `built`) is, at a call, those
statements run with its parameters bound to the arguments: the message, with the
fields it sets, is the call's.
"""

from __future__ import annotations

import ast
from collections.abc import Callable

# builtins without effects whose result the analysis follows
PURE_BUILTINS = frozenset({"abs", "min", "max", "round", "float", "int", "bool", "pow"})
# libraries whose stubbed functions a helper may call (none changes its arguments
# unless told `out=`, refused below, or it is one of MUTATING)
PURE_LIBRARIES = frozenset({"math", "numpy"})
MUTATING = frozenset({"copyto", "put", "place", "putmask", "fill_diagonal"})
MAX_DEPTH = 4  # helpers evaluated inside one another at most
_NODES = (
    ast.Name,
    ast.Constant,
    ast.Attribute,
    ast.Subscript,
    ast.Slice,
    ast.BinOp,
    ast.UnaryOp,
    ast.BoolOp,
    ast.Compare,
    ast.IfExp,
    ast.Tuple,
    ast.Call,
    ast.keyword,
    ast.operator,
    ast.unaryop,
    ast.boolop,
    ast.cmpop,
    ast.expr_context,
)


def _body(node: ast.AST) -> list[ast.stmt] | None:
    """The statements of a plain `def f(a, b=1):` after its docstring, None for any
    other function (a decorator, `*args`, `**kwargs`)."""
    if not isinstance(node, ast.FunctionDef) or node.args.vararg or node.args.kwarg:
        return None
    if node.decorator_list:
        return None
    body = node.body
    if (
        len(body) >= 2
        and isinstance(body[0], ast.Expr)
        and isinstance(body[0].value, ast.Constant)
        and isinstance(body[0].value.value, str)
    ):
        body = body[1:]
    return body


def returned(node: ast.AST) -> ast.expr | None:
    """The expression of a plain `def f(a, b=1): return <expr>` (a docstring
    allowed), None for any other function."""
    body = _body(node)
    if body is None or len(body) != 1 or not isinstance(body[0], ast.Return):
        return None
    return body[0].value


def built(node: ast.AST) -> tuple[list[ast.Assign], str] | None:
    """A plain helper that builds a message and returns it: `v = Msg(...)`, then
    only stores into fields of `v` (`v.linear.x = speed`), then `return v`. Its
    assignments and `v`; None for any other function (what their expressions may
    be is the caller's to check, as `pure`)."""
    body = _body(node)
    if body is None or len(body) < 2:
        return None
    first, last = body[0], body[-1]
    if not (
        isinstance(first, ast.Assign)
        and len(first.targets) == 1
        and isinstance(first.targets[0], ast.Name)
        and isinstance(first.value, ast.Call)
        and isinstance(first.value.func, ast.Name)
    ):
        return None
    name = first.targets[0].id
    if not (
        isinstance(last, ast.Return)
        and isinstance(last.value, ast.Name)
        and last.value.id == name
    ):
        return None
    stores = body[1:-1]
    for store in stores:
        if not (
            isinstance(store, ast.Assign)
            and len(store.targets) == 1
            and isinstance(store.targets[0], ast.Attribute)
            and _root(store.targets[0]) == name
        ):
            return None
    return [first, *stores], name  # type: ignore[list-item]


def _root(node: ast.expr | None) -> str | None:
    """`v` of `v` or `v.a.b`, else None."""
    while isinstance(node, ast.Attribute):
        node = node.value
    return node.id if isinstance(node, ast.Name) else None


def pure(
    expr: ast.expr,
    callee_ok: Callable[[ast.Call], bool],
) -> bool:
    """Whether `expr` is built only of reads, operators and calls `callee_ok`
    accepts (no starred or `**` argument, no `out=`)."""
    for child in ast.walk(expr):
        if not isinstance(child, _NODES):
            return False
        if isinstance(child, ast.Call):
            if any(isinstance(a, ast.Starred) for a in child.args):
                return False
            if any(k.arg in (None, "out") for k in child.keywords):
                return False
            if not callee_ok(child):
                return False
    return True


def names(expr: ast.expr) -> set[str]:
    return {n.id for n in ast.walk(expr) if isinstance(n, ast.Name)}


def parameters(fn: ast.FunctionDef, bound: bool) -> list[tuple[str, ast.expr | None]]:
    """The parameters a call fills, with their defaults (`self` of a bound method
    left out)."""
    positional = [*fn.args.posonlyargs, *fn.args.args]
    defaults: list[ast.expr | None] = [None] * (
        len(positional) - len(fn.args.defaults)
    ) + list(fn.args.defaults)
    found = [(a.arg, d) for a, d in zip(positional, defaults, strict=True)]
    if bound:
        found = found[1:]
    found += [
        (a.arg, d) for a, d in zip(fn.args.kwonlyargs, fn.args.kw_defaults, strict=True)
    ]
    return found


def bind(
    fn: ast.FunctionDef,
    bound: bool,
    args: list[object],
    kwargs: dict[str | None, object],
) -> dict[str, object] | None:
    """Each parameter's argument, or its default expression (an `ast.expr`); None
    when the call does not fill them all as Python would."""
    params = parameters(fn, bound)
    positional = len(params) - len(fn.args.kwonlyargs)
    if len(args) > positional or None in kwargs:
        return None
    given: dict[str, object] = {n: a for (n, _), a in zip(params, args, strict=False)}
    for key, value in kwargs.items():
        if (
            key in given
            or key not in dict(params)
            or key in {a.arg for a in fn.args.posonlyargs}
        ):
            return None
        given[key] = value
    for name, default in params:
        if name not in given:
            if default is None:
                return None
            given[name] = default
    return given
