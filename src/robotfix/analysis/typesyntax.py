"""What a function body binds and what methods store on `self`, read from the
syntax alone, for the type model (`types.TypeModel`): a local's bindings (a
value, a declaration, an element of what a `for` iterates), the types that
assignment targets take, the stores to attributes, and small tests of
expressions (`None`, `...`). No context, no program: functions of the AST.
"""

from __future__ import annotations

import ast

from robotfix.analysis.typeterms import Tup, Type, plain
from robotfix.astwalk import TRIES, children


class BoundAnnotation:
    """A local's declared type (`x: list[Twist] = []`), in a local's bindings."""

    __slots__ = ("node",)

    def __init__(self, node: ast.expr) -> None:
        self.node = node


class BoundElement:
    """A `for` target's binding: an element of `node`."""

    __slots__ = ("node",)

    def __init__(self, node: ast.expr) -> None:
        self.node = node


Binding = ast.expr | BoundAnnotation | BoundElement | None


def local_bindings(node: ast.AST, walrus: bool = True) -> dict[str, list[Binding]]:
    """name -> what each binding of it in the function gives it: a value, an
    annotation, an element of an iterable, or None (a binding not followed).
    Without `walrus` (the file has no `:=`) expressions are not entered: `:=` is
    the one expression that binds a name of the function (comprehensions and
    lambdas have scopes of their own), so they hold nothing to find."""
    found: dict[str, list[Binding]] = {}
    declared: dict[str, ast.expr] = {}
    body = node.body if isinstance(node.body, list) else []  # type: ignore[attr-defined]
    todo: list[ast.AST] = list(body)
    while todo:
        child = todo.pop()
        kind = type(child)
        if kind in _READ:  # the others bind nothing: only walked under
            if kind in (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef):
                found.setdefault(child.name, []).append(None)  # type: ignore[attr-defined]
                continue
            if kind is ast.Lambda or kind in _COMPREHENSIONS:
                continue
            if kind is ast.Assign:
                for target in child.targets:  # type: ignore[attr-defined]
                    _record(found, target, child.value)  # type: ignore[attr-defined]
            elif kind is ast.AnnAssign:
                target = child.target  # type: ignore[attr-defined]
                if isinstance(target, ast.Name):
                    declared.setdefault(target.id, child.annotation)  # type: ignore[attr-defined]
                    if child.value is not None:  # type: ignore[attr-defined]
                        found.setdefault(target.id, []).append(child.value)  # type: ignore[attr-defined]
            elif kind in (ast.For, ast.AsyncFor):
                _record(found, child.target, BoundElement(child.iter))  # type: ignore[attr-defined]
            elif kind is ast.NamedExpr:
                _record(found, child.target, child.value)  # type: ignore[attr-defined]
            elif kind in (ast.AugAssign, ast.Delete, ast.Global, ast.Nonlocal):
                targets = getattr(child, "targets", None) or [
                    getattr(child, "target", None)
                ]
                names = getattr(child, "names", None) or []
                for target in targets:
                    for leaf in _names(target):
                        found.setdefault(leaf, []).append(None)
                for name in names:
                    found.setdefault(name, []).append(None)
            elif kind in (ast.Import, ast.ImportFrom):
                for alias in child.names:  # type: ignore[attr-defined]
                    local = alias.asname or alias.name.split(".")[0]
                    found.setdefault(local, []).append(None)
            elif kind in (ast.With, ast.AsyncWith):
                for item in child.items:  # type: ignore[attr-defined]
                    for leaf in _names(item.optional_vars):
                        found.setdefault(leaf, []).append(None)
            elif kind in (ast.ExceptHandler, ast.MatchAs, ast.MatchStar) and getattr(
                child, "name", None
            ):
                found.setdefault(child.name, []).append(None)  # type: ignore[attr-defined]
        if walrus:
            todo.extend(children(child))
        else:  # the fields that hold statements, handlers, cases and patterns
            inner = _INNER.get(kind)
            for name in inner if inner is not None else _inner(kind):
                value = getattr(child, name)
                if value.__class__ is list:
                    todo.extend(value)
                elif value is not None:
                    todo.append(value)
    for name, annotation in declared.items():
        found[name] = [BoundAnnotation(annotation)]  # a declaration is a fact
    return found


_COMPREHENSIONS = (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)
# what `local_bindings` reads of a node, or does not enter
_READ = frozenset(
    {ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda, *_COMPREHENSIONS}
    | {ast.Assign, ast.AnnAssign, ast.For, ast.AsyncFor, ast.NamedExpr, ast.AugAssign}
    | {ast.Delete, ast.Global, ast.Nonlocal, ast.Import, ast.ImportFrom, ast.With}
    | {ast.AsyncWith, ast.ExceptHandler, ast.MatchAs, ast.MatchStar}
)
# the fields of a statement, handler, case or pattern that hold no expression
# (`children` in field order, but for expressions, which bind nothing without `:=`)
_NOT_EXPRESSIONS = frozenset(
    {"body", "handlers", "orelse", "finalbody", "cases", "pattern", "patterns"}
    | {"kwd_patterns"}
)
_INNER: dict[type, tuple[str, ...]] = {}


def _inner(kind: type) -> tuple[str, ...]:
    every: tuple[str, ...] = kind._fields  # type: ignore[attr-defined]
    found = _INNER[kind] = tuple(f for f in every if f in _NOT_EXPRESSIONS)
    return found


def _record(found: dict[str, list[Binding]], target: ast.expr, value: Binding) -> None:
    if isinstance(target, ast.Name):
        found.setdefault(target.id, []).append(value)
    elif isinstance(target, (ast.Tuple, ast.List)):
        if isinstance(value, (ast.Tuple, ast.List)) and len(value.elts) == len(
            target.elts
        ):
            for part, given in zip(target.elts, value.elts, strict=True):
                _record(found, part, given)
            return
        for leaf in _names(target):
            found.setdefault(leaf, []).append(None)
    elif isinstance(target, ast.Starred):
        _record(found, target.value, None)


def _names(target: ast.AST | None) -> list[str]:
    if target is None:
        return []
    return [n.id for n in ast.walk(target) if isinstance(n, ast.Name)]


def bind_types(
    target: ast.expr, item: Type | None, env: dict[str, Type | None]
) -> None:
    if isinstance(target, ast.Name):
        env[target.id] = item
    elif isinstance(target, (ast.Tuple, ast.List)):
        parts = plain(item)
        for index, part in enumerate(target.elts):
            found = (
                parts.items[index]
                if isinstance(parts, Tup) and len(parts.items) == len(target.elts)
                else None
            )
            bind_types(part, found, env)


def self_stores(
    node: ast.FunctionDef | ast.AsyncFunctionDef, self_name: str
) -> list[tuple[str, ast.expr]]:
    """(attribute, value) for each store to `self.<attribute>` in a method, found
    through its statements only (an expression cannot store to an attribute;
    nested functions and classes aside: their `self` may be another); a store whose
    value is not told is given `ast.expr()`, which no inference types."""
    found: list[tuple[str, ast.expr]] = []
    todo: list[ast.stmt] = list(node.body)
    while todo:
        child = todo.pop()
        kind = type(child)
        if kind is ast.Assign:
            for target in child.targets:  # type: ignore[attr-defined]
                _attribute_stores(found, target, child.value, self_name)  # type: ignore[attr-defined]
        elif kind is ast.AnnAssign:
            if child.value is not None:  # type: ignore[attr-defined]
                _attribute_stores(found, child.target, child.value, self_name)  # type: ignore[attr-defined]
        elif kind is ast.AugAssign:
            _attribute_stores(found, child.target, ast.expr(), self_name)  # type: ignore[attr-defined]
        elif kind is ast.Delete:
            for target in child.targets:  # type: ignore[attr-defined]
                _attribute_stores(found, target, ast.expr(), self_name)
        elif kind in _BLOCKS:
            if kind is ast.For or kind is ast.AsyncFor:
                _attribute_stores(found, child.target, ast.expr(), self_name)  # type: ignore[attr-defined]
            elif kind is ast.With or kind is ast.AsyncWith:
                for item in child.items:  # type: ignore[attr-defined]
                    if item.optional_vars is not None:
                        _attribute_stores(
                            found, item.optional_vars, ast.expr(), self_name
                        )
            todo.extend(getattr(child, "body", ()))
            todo.extend(getattr(child, "orelse", ()))
            todo.extend(getattr(child, "finalbody", ()))
            for handler in getattr(child, "handlers", ()):
                todo.extend(handler.body)
            for case in getattr(child, "cases", ()):
                todo.extend(case.body)
    found.reverse()
    return found


_BLOCKS = frozenset(
    {ast.If, ast.For, ast.AsyncFor, ast.While, ast.With, ast.AsyncWith, *TRIES}
    | {ast.Match}
)


def _attribute_stores(
    found: list[tuple[str, ast.expr]], target: ast.AST, value: ast.expr, self_name: str
) -> None:
    if (
        isinstance(target, ast.Attribute)
        and isinstance(target.value, ast.Name)
        and target.value.id == self_name
    ):
        found.append((target.attr, value))
    elif isinstance(target, (ast.Tuple, ast.List)):
        given = (
            value.elts
            if isinstance(value, (ast.Tuple, ast.List))
            and len(value.elts) == len(target.elts)
            else [ast.expr()] * len(target.elts)
        )
        for part, part_value in zip(target.elts, given, strict=True):
            _attribute_stores(found, part, part_value, self_name)
    elif isinstance(target, ast.Starred):
        _attribute_stores(found, target.value, ast.expr(), self_name)


def last_name(node: ast.expr) -> str:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        return node.attr
    return ""


def is_none(node: ast.expr | None) -> bool:
    return isinstance(node, ast.Constant) and node.value is None


def is_ellipsis(node: ast.expr) -> bool:
    return isinstance(node, ast.Constant) and node.value is Ellipsis
