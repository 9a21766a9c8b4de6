"""Where unannotated names flow, for `robotfix suggest`.

While a file is interpreted (only when suggestions are asked for), the interpreter
logs three kinds of events here: an expression reaching a place whose unit is known
(a message field, an annotated variable or attribute, a refined parameter or return
value, a unit parameter of a ROS API), a call of a user function (which argument
went to which parameter), and an assignment to an unannotated name or `self.attr`.

`suggestions` then follows the flows backwards, syntactically, through what keeps a
unit: `+`, `-`, a literal factor that is not a unit conversion (`speed * 0.5` but not
`speed / 3.6`), `min`, `max`, `abs`, `float`, `round`, a conditional expression; an
assignment (`v = speed`), a parameter of the enclosing function and the arguments
of its calls, `self.x` and its assignments in any method. A product or quotient of
two names carries nothing. A name gets a unit only when all its flows agree and it
can be annotated where it is first bound (a plain `x = ...`, an unannotated
parameter, `self.x = ...` in `__init__`); a name that reaches two different units
gets no suggestion (that is a bug for `robotfix check`, not an annotation).
"""

from __future__ import annotations

import ast
import math
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from robotfix.analysis.values import NUMERIC, Value
from robotfix.annotations.units import Unit

if TYPE_CHECKING:
    from robotfix.analysis.context import Scope
    from robotfix.analysis.program import Function, Program

# Literal factors that may be a unit conversion (`speed / 3.6` is km/h -> m/s,
# `deg * math.pi / 180` degrees -> radians): a flow through one says nothing sure.
_CONVERSIONS = (
    10.0,
    100.0,
    1000.0,
    1e4,
    1e5,
    1e6,
    1e9,
    3.6,
    60.0,
    3600.0,
    86400.0,
    math.pi,
    2 * math.pi,
    math.pi / 180,
    0.3048,
    0.0254,
    1.609344,
    0.44704,
    0.514444,
    1.852,
    9.80665,
    1024.0,
)
_KEEPING_CALLS = frozenset({"min", "max", "abs", "float", "round"})
_KEEPING_MATH = frozenset({"fabs"})  # math.copysign keeps its first argument's


@dataclass
class Where:
    """The code an event was seen in: a scope and, for a function, the function."""

    scope: Scope
    function: Function | None

    @property
    def self_name(self) -> str | None:
        """The name of `self` in a method, else None."""
        fn = self.function
        if fn is None or not fn.is_method or isinstance(fn.node, ast.Lambda):
            return None
        first = [*fn.node.args.posonlyargs, *fn.node.args.args][:1]
        return first[0].arg if first else None


@dataclass
class FlowLog:
    sinks: list[tuple[Where, ast.expr, Unit]] = field(default_factory=list)
    # function key -> (caller, parameter, argument)
    calls: dict[str, list[tuple[Where, str, ast.expr]]] = field(default_factory=dict)
    # ("local", id(scope node), name) / ("attr", class, attr) -> (where, value)
    binds: dict[tuple[object, ...], list[tuple[Where, ast.expr]]] = field(
        default_factory=dict
    )
    program: Program | None = None  # set when the file's program is collected
    _seen: set[tuple[object, ...]] = field(default_factory=set)

    def sink(
        self, where: Where, expr: ast.expr, unit: Unit | None, value: Value | None
    ) -> None:
        """`expr` (holding `value`) reached a place of `unit`."""
        if unit is None or not unit.text or unit.is_label:
            return
        if value is not None:
            if value.kind not in NUMERIC and value.kind != "unknown":
                return
            found = value.fit(unit)
            if found is not None and found.kind != "ok":
                return  # a bug `check` reports: nothing to learn from it
        if self._once("sink", id(expr), unit.text):
            self.sinks.append((where, expr, unit))

    def call(self, where: Where, key: str, param: str, expr: ast.expr) -> None:
        if self._once("call", id(expr), key, param):
            self.calls.setdefault(key, []).append((where, param, expr))

    def bind(self, where: Where, target: ast.expr, expr: ast.expr) -> None:
        """`target = expr` (or `target += expr`) for an unannotated target."""
        entity = _target_entity(where, target)
        if entity is not None and self._once("bind", id(expr), entity):
            self.binds.setdefault(entity, []).append((where, expr))

    def _once(self, *key: object) -> bool:
        if key in self._seen:
            return False
        self._seen.add(key)
        return True


@dataclass(frozen=True)
class Found:
    line: int
    col: int  # byte column of the name
    name: str
    unit: str


def _target_entity(where: Where, target: ast.expr) -> tuple[object, ...] | None:
    if isinstance(target, ast.Name):
        return ("local", id(where.scope.node), target.id)
    me = where.self_name
    fn = where.function
    if (
        me is not None
        and fn is not None
        and isinstance(target, ast.Attribute)
        and isinstance(target.value, ast.Name)
        and target.value.id == me
    ):
        return ("attr", fn.class_name, target.attr)
    return None


def suggestions(log: FlowLog, program: Program) -> list[Found]:
    """One unit for each name whose flows all agree and that can be annotated."""
    units: dict[tuple[object, ...], list[Unit]] = {}
    places: dict[tuple[object, ...], Where] = {}
    todo: list[tuple[tuple[object, ...], Where, Unit]] = []
    done: set[tuple[tuple[object, ...], str]] = set()
    for where, expr, unit in log.sinks:
        todo.extend((e, w, unit) for e, w in _carriers(expr, where))
    while todo:
        entity, where, unit = todo.pop()
        key = (entity, unit.text)
        if key in done:
            continue
        done.add(key)
        places.setdefault(entity, where)
        known = units.setdefault(entity, [])
        if not any(u.same_as(unit) for u in known):
            known.append(unit)
        for source_where, expr in _sources(log, entity):
            todo.extend((e, w, unit) for e, w in _carriers(expr, source_where))
    found = []
    shapes = _Shapes(program)
    for entity, known in units.items():
        if len(known) != 1:
            continue  # flows into different units: not for an annotation
        spot = shapes.spot(entity, places[entity])
        if spot is not None:
            found.append(Found(spot[0], spot[1], spot[2], known[0].text))
    return sorted(set(found), key=lambda f: (f.line, f.col))


def _sources(
    log: FlowLog, entity: tuple[object, ...]
) -> Iterator[tuple[Where, ast.expr]]:
    """The expressions whose value an entity takes: its assignments, and for a
    parameter the arguments of its calls."""
    yield from log.binds.get(entity, [])
    if entity[0] == "param":
        key, name = entity[2], entity[3]
        for where, param, expr in log.calls.get(str(key), []):
            if param == name:
                yield where, expr


def _carriers(
    expr: ast.expr, where: Where, factor: float = 1.0
) -> Iterator[tuple[tuple[object, ...], Where]]:
    """The names in `expr` whose unit the whole value has."""
    if _not_a_number(expr):  # `"/" + robot + "/reset"` reaching a timeout's place
        return
    if isinstance(expr, ast.Name):
        if not _conversion(factor):
            entity = _name_entity(expr.id, where)
            if entity is not None:
                yield entity, where
    elif isinstance(expr, ast.Attribute):
        entity = _target_entity(where, expr)
        if entity is not None and not _conversion(factor):
            yield entity, where
    elif isinstance(expr, ast.UnaryOp) and isinstance(expr.op, (ast.USub, ast.UAdd)):
        yield from _carriers(expr.operand, where, factor)
    elif isinstance(expr, ast.BinOp):
        if isinstance(expr.op, (ast.Add, ast.Sub)):
            yield from _carriers(expr.left, where, factor)
            yield from _carriers(expr.right, where, factor)
        elif isinstance(expr.op, ast.Mult):
            right, left = _literal(expr.right), _literal(expr.left)
            if right is not None:
                yield from _carriers(expr.left, where, factor * right)
            elif left is not None:
                yield from _carriers(expr.right, where, factor * left)
        elif isinstance(expr.op, ast.Div):
            right = _literal(expr.right)
            if right:
                yield from _carriers(expr.left, where, factor / right)
    elif isinstance(expr, ast.IfExp):
        yield from _carriers(expr.body, where, factor)
        yield from _carriers(expr.orelse, where, factor)
    elif isinstance(expr, ast.NamedExpr):
        yield from _carriers(expr.target, where, factor)
        yield from _carriers(expr.value, where, factor)
    elif isinstance(expr, ast.Call) and not expr.keywords:
        func = expr.func
        keeps = (
            isinstance(func, ast.Name)
            and func.id in _KEEPING_CALLS
            and func.id not in where.scope.module().local_names
        ) or (
            isinstance(func, ast.Attribute)
            and isinstance(func.value, ast.Name)
            and func.value.id == "math"
            and func.attr in _KEEPING_MATH
        )
        if keeps:
            args = expr.args[:1] if getattr(func, "id", "") == "round" else expr.args
            for arg in args:
                yield from _carriers(arg, where, factor)


def _name_entity(name: str, where: Where) -> tuple[object, ...] | None:
    fn = where.function
    scope = where.scope
    if fn is not None:
        if isinstance(fn.node, ast.Lambda):
            return None
        if name in _parameters(fn):
            return ("param", id(fn.node), fn.key, name)
        if name in scope.local_names:
            return ("local", id(scope.node), name)
    elif scope.kind == "module" and name in scope.local_names:
        return ("local", id(scope.node), name)
    module = scope.module()
    if scope.kind == "function" and name in module.local_names:
        return ("local", id(module.node), name)
    return None


def _default_of(args: ast.arguments, arg: ast.arg) -> ast.expr | None:
    positional = [*args.posonlyargs, *args.args]
    if arg in positional:
        index = positional.index(arg) - (len(positional) - len(args.defaults))
        return args.defaults[index] if index >= 0 else None
    if arg in args.kwonlyargs:
        return args.kw_defaults[args.kwonlyargs.index(arg)]
    return None


def _parameters(fn: Function) -> list[str]:
    """The parameters an annotation can be given (not `self`, `*args`)."""
    args = fn.node.args
    names = [a.arg for a in [*args.posonlyargs, *args.args, *args.kwonlyargs]]
    return names[1:] if fn.is_method else names


def _literal(expr: ast.expr) -> float | None:
    sign = 1.0
    if isinstance(expr, ast.UnaryOp) and isinstance(expr.op, (ast.USub, ast.UAdd)):
        sign = -1.0 if isinstance(expr.op, ast.USub) else 1.0
        expr = expr.operand
    if (
        isinstance(expr, ast.Constant)
        and isinstance(expr.value, (int, float))
        and not isinstance(expr.value, bool)
        and math.isfinite(expr.value)
        and expr.value != 0
    ):
        return sign * float(expr.value)
    return None


def _conversion(factor: float) -> bool:
    size = abs(factor)
    if size == 0 or not math.isfinite(size):
        return True
    for known in _CONVERSIONS:
        for candidate in (known, 1 / known):
            if math.isclose(size, candidate, rel_tol=2e-3):
                return True
    return False


class _Shapes:
    """Where an entity can be annotated, read from the syntax: the first plain
    `name = ...` of a scope, a bare parameter, `self.x = ...` in `__init__`."""

    def __init__(self, program: Program) -> None:
        self.program = program
        self._scans: dict[int, _Scan] = {}

    def spot(
        self, entity: tuple[object, ...], where: Where
    ) -> tuple[int, int, str] | None:
        kind = entity[0]
        if kind == "param":
            return self._parameter(entity, where)
        if kind == "local":
            name = str(entity[2])
            node = self._scope_node(entity, where)
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

    def _scope_node(self, entity: tuple[object, ...], where: Where) -> ast.AST | None:
        if id(where.scope.node) == entity[1]:
            return where.scope.node
        module = where.scope.module().node
        return module if id(module) == entity[1] else None

    def _parameter(
        self, entity: tuple[object, ...], where: Where
    ) -> tuple[int, int, str] | None:
        fn = self.program.functions.get(str(entity[2]))
        if fn is None or isinstance(fn.node, ast.Lambda):
            return None
        name = str(entity[3])
        args = fn.node.args
        for arg in [*args.posonlyargs, *args.args, *args.kwonlyargs]:
            if arg.arg == name:
                default = _default_of(fn.node.args, arg)
                if arg.annotation is not None or arg.type_comment:
                    return None
                if default is not None and _not_a_number(default):
                    return None  # `period=None`: not a float
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
        for fn in self.program.functions.values():
            if fn.class_name != class_name or isinstance(fn.node, ast.Lambda):
                continue
            scan = self._scan(fn.node)
            if attr in scan.bad_attrs:
                return None
            if fn.name == "__init__" and first is None:
                first = scan.attrs.get(attr)
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
                if _not_a_number(node.value):  # `x = None`, `x = "/" + name`
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


def _not_a_number(expr: ast.expr) -> bool:
    """Whether `expr` is surely not a plain number: `None`, a string or a
    concatenation with one, a container, a comprehension, a lambda (a call's
    arguments say nothing of what it returns)."""
    if isinstance(expr, ast.Constant):
        return not isinstance(expr.value, (int, float)) or isinstance(expr.value, bool)
    if isinstance(expr, ast.BinOp):
        return _not_a_number(expr.left) or _not_a_number(expr.right)
    if isinstance(expr, ast.UnaryOp):
        return _not_a_number(expr.operand)
    if isinstance(expr, ast.IfExp):
        return _not_a_number(expr.body) or _not_a_number(expr.orelse)
    if isinstance(expr, ast.Call):
        return isinstance(expr.func, ast.Name) and expr.func.id in {"str", "repr"}
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
