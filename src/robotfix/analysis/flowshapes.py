"""Where `robotfix suggest` can write an annotation, read from the syntax
(`flows.suggestions` asks `Shapes.spot`): the first plain `name = ...` of a
scope, a bare parameter whose default and callers' arguments may be numbers,
`self.x = ...` in `__init__`; and which expressions are surely not a number.
"""

from __future__ import annotations

import ast
from collections.abc import Iterator, Mapping, Sequence
from typing import TYPE_CHECKING, Protocol

from robotfix.ros.api_model import TIME_OBJECTS

if TYPE_CHECKING:
    from robotfix.analysis.context import Scope
    from robotfix.analysis.program import Program


class Place(Protocol):
    """Where an entity was seen (`flows.Where`): its scope."""

    scope: Scope


def default_of(args: ast.arguments, arg: ast.arg) -> ast.expr | None:
    positional = [*args.posonlyargs, *args.args]
    if arg in positional:
        index = positional.index(arg) - (len(positional) - len(args.defaults))
        return args.defaults[index] if index >= 0 else None
    if arg in args.kwonlyargs:
        return args.kw_defaults[args.kwonlyargs.index(arg)]
    return None


class Shapes:
    """Where an entity can be annotated, read from the syntax: the first plain
    `name = ...` of a scope, a bare parameter, `self.x = ...` in `__init__`."""

    def __init__(
        self,
        program: Program,
        calls: Mapping[str, Sequence[tuple[object, str, ast.expr]]],
    ) -> None:
        self.program = program
        self.calls = calls  # `FlowLog.calls`: a function's key -> its calls
        self._scans: dict[int, _Scan] = {}

    def spot(
        self, entity: tuple[object, ...], where: Place | None
    ) -> tuple[int, int, str] | None:
        kind = entity[0]
        if kind == "param":
            return self._parameter(entity)
        if kind == "local":
            name = str(entity[2])
            node = self._scope_node(entity, where) if where is not None else None
            if node is None:
                return None
            scan = self._scan(node)
            if name in scan.bad or name not in scan.plain:
                return None
            if (
                isinstance(node, ast.Module)
                and name in self._scan(node).declared_global
            ):
                return None
            target = scan.plain[name]
            return target.lineno, target.col_offset, name
        if kind == "attr":
            return self._attribute(str(entity[1]), str(entity[2]))
        return None

    def _scope_node(self, entity: tuple[object, ...], where: Place) -> ast.AST | None:
        if id(where.scope.node) == entity[1]:
            return where.scope.node
        module = where.scope.module().node
        return module if id(module) == entity[1] else None

    def _parameter(self, entity: tuple[object, ...]) -> tuple[int, int, str] | None:
        fn = self.program.functions.get(str(entity[2]))
        if fn is None or isinstance(fn.node, ast.Lambda):
            return None
        name = str(entity[3])
        args = fn.node.args
        for arg in [*args.posonlyargs, *args.args, *args.kwonlyargs]:
            if arg.arg == name:
                default = default_of(fn.node.args, arg)
                if arg.annotation is not None or arg.type_comment:
                    return None
                if default is not None and not_a_number(default):
                    return None  # `period=None`: not a float
                if any(
                    param == name and not_a_number(expr)
                    for _, param, expr in self.calls.get(fn.key, [])
                ):
                    return None  # `self.hold(None)`
                scan = self._scan(fn.node)
                if name in scan.bad:
                    return None
                return arg.lineno, arg.col_offset, name
        return None

    def _attribute(self, class_name: str, attr: str) -> tuple[int, int, str] | None:
        if attr in self.program.attributes.get(class_name, {}):
            return None
        cls = self.program.classes.get(class_name)
        if cls is None or not isinstance(cls.node, ast.ClassDef):
            return None
        for statement in cls.node.body:  # `speed: float` in the class body
            if (
                isinstance(statement, ast.AnnAssign)
                and isinstance(statement.target, ast.Name)
                and statement.target.id == attr
            ):
                return None
        first: ast.Attribute | None = None
        assigned = False
        for fn in self.program.functions.values():
            if fn.class_name != class_name or isinstance(fn.node, ast.Lambda):
                continue
            scan = self._scan(fn.node)
            if attr in scan.bad_attrs:
                return None
            assigned = assigned or attr in scan.attrs
            if fn.name == "__init__" and first is None:
                first = scan.attrs.get(attr)
        if not assigned:  # a class constant: `MAX_SPEED = 0.22` in the class body
            body = self._scan(cls.node)
            if attr in body.bad or attr not in body.plain:
                return None
            target = body.plain[attr]
            return target.lineno, target.col_offset, attr
        if first is None or first.end_lineno != first.lineno:
            return None
        col = (first.end_col_offset or 0) - len(attr.encode("utf-8"))
        return first.lineno, col, attr

    def _scan(self, node: ast.AST) -> _Scan:
        found = self._scans.get(id(node))
        if found is None:
            found = self._scans[id(node)] = _Scan(node)
        return found


class _Scan:
    """How a scope binds its names (not looking into nested functions and classes):
    the first plain `name = ...` target of each, and the names bound any other way
    (annotated, unpacked, a loop or `with` target, `global`, deleted...)."""

    def __init__(self, scope: ast.AST) -> None:
        self.plain: dict[str, ast.Name] = {}
        self.bad: set[str] = set()
        self.attrs: dict[str, ast.Attribute] = {}  # `self.x = ...`, first of each
        self.bad_attrs: set[str] = set()
        self.declared_global: set[str] = set()
        self.me: str | None = None
        if isinstance(scope, (ast.FunctionDef, ast.AsyncFunctionDef)):
            first = [*scope.args.posonlyargs, *scope.args.args][:1]
            self.me = first[0].arg if first else None
            body: list[ast.stmt] = scope.body
        elif isinstance(scope, ast.ClassDef):
            body = scope.body
        elif isinstance(scope, ast.Module):
            body = scope.body
            for node in ast.walk(scope):
                if isinstance(node, ast.Global):
                    self.declared_global.update(node.names)
        else:
            body = []
        plain: set[int] = set()
        for node in _walk_scope(body):
            if isinstance(node, ast.Assign) and len(node.targets) == 1:
                target = node.targets[0]
                if not_a_number(node.value):  # `x = None`, `x = "/" + name`
                    continue
                plain.add(id(target))
                if isinstance(target, ast.Name):
                    self.plain.setdefault(target.id, target)
                elif self._is_self(target):
                    assert isinstance(target, ast.Attribute)
                    self.attrs.setdefault(target.attr, target)
            elif isinstance(node, ast.AugAssign):
                plain.add(id(node.target))
            elif isinstance(node, (ast.Global, ast.Nonlocal)):
                self.bad.update(node.names)
        for node in _walk_scope(body):
            if isinstance(node, ast.Name) and not isinstance(node.ctx, ast.Load):
                if id(node) not in plain:
                    self.bad.add(node.id)
            elif (
                isinstance(node, ast.Attribute)
                and not isinstance(node.ctx, ast.Load)
                and self._is_self(node)
                and id(node) not in plain
            ):
                self.bad_attrs.add(node.attr)
            elif isinstance(node, ast.ExceptHandler) and node.name:
                self.bad.add(node.name)
            elif isinstance(node, (ast.Import, ast.ImportFrom)):
                self.bad.update((a.asname or a.name).split(".")[0] for a in node.names)

    def _is_self(self, node: ast.expr) -> bool:
        return (
            self.me is not None
            and isinstance(node, ast.Attribute)
            and isinstance(node.value, ast.Name)
            and node.value.id == self.me
        )


_NOT_NUMBERS = (
    ast.JoinedStr,
    ast.List,
    ast.Tuple,
    ast.Dict,
    ast.Set,
    ast.ListComp,
    ast.DictComp,
    ast.SetComp,
    ast.GeneratorExp,
    ast.Lambda,
)


def not_a_number(expr: ast.expr) -> bool:
    """Whether `expr` is surely not a plain number: `None`, a string or a
    concatenation with one, a container, a comprehension, a lambda (a call's
    arguments say nothing of what it returns)."""
    if isinstance(expr, ast.Constant):
        return not isinstance(expr.value, (int, float)) or isinstance(expr.value, bool)
    if isinstance(expr, ast.BinOp):
        return not_a_number(expr.left) or not_a_number(expr.right)
    if isinstance(expr, ast.UnaryOp):
        return not_a_number(expr.operand)
    if isinstance(expr, ast.IfExp):
        return not_a_number(expr.body) or not_a_number(expr.orelse)
    if isinstance(expr, ast.Call):
        func = expr.func
        name = (
            func.id
            if isinstance(func, ast.Name)
            else func.attr
            if isinstance(func, ast.Attribute)
            else ""
        )
        return name in TIME_OBJECTS or (
            isinstance(func, ast.Name) and name in {"str", "repr"}
        )
    return isinstance(expr, _NOT_NUMBERS)


def _walk_scope(body: list[ast.stmt]) -> Iterator[ast.AST]:
    """Every node of a scope's body, not entering nested functions, lambdas and
    classes (their names are theirs; a definition binds its own name)."""
    todo: list[ast.AST] = list(reversed(body))
    while todo:
        node = todo.pop()
        yield node
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            yield ast.Name(node.name, ast.Store())  # binds the name: not plain
            continue
        if isinstance(node, ast.Lambda):
            continue
        todo.extend(reversed(list(ast.iter_child_nodes(node))))
