"""Where unannotated names flow, for `robotfix suggest`.

While a file is interpreted (only when suggestions are asked for), the interpreter
logs three kinds of events here: an expression reaching a place whose unit is known
(a message field, an annotated variable or attribute, a refined parameter or return
value, a unit parameter of a ROS API), a call of a user function (which argument
went to which parameter), and an assignment to an unannotated name or `self.attr`.

`suggestions` then follows the flows backwards, syntactically, through what keeps a
unit: `+`, `-`, a literal factor that is not a unit conversion (`speed * 0.5` but not
`speed / 3.6`) nor a placeholder gain (`error * 1.0`), `min`, `max`, `abs`, `float`,
`round`, a conditional expression; an assignment (`v = speed`), a parameter of the
enclosing function and the arguments of its calls, `self.x` and its assignments in
any method. A product or quotient of two names carries nothing. Units that values
are known to have (`math.atan2` gives rad) go forwards through the same flows. A
name gets a unit only when all the units it meets agree and it can be annotated
where it is first bound (a plain `x = ...`, an unannotated parameter, `self.x = ...`
in `__init__`, a class constant); a name that meets two different units gets no
suggestion (that is a bug for `robotfix check`, or a controller's implicit gain,
not an annotation). A name that holds a sequence (bound to a list or tuple, or
reaching a message's array field) gets no `Annotated[float, ...]`: its applied file
would fail the check (RF401). One bound only to lists of numbers whose flows reach
array fields of one unit gets `Annotated[list[float], "Unit(...)"]`. A message
constructor's arguments, positional or keyword, reach the fields they set, and a
nested constructor's the fields below (`Twist(Vector3(tv, 0.0, 0.0))`), with the
units of the place the message is built or stored in.
"""

from __future__ import annotations

import ast
import math
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, TypeVar

from robotfix.analysis import heap
from robotfix.analysis.flowshapes import Shapes, default_of, not_a_number
from robotfix.analysis.values import NUMERIC, Value
from robotfix.annotations.units import Unit

if TYPE_CHECKING:
    from robotfix.analysis.context import FileContext, Scope
    from robotfix.analysis.program import Function, Program
    from robotfix.analysis.state import State
    from robotfix.ros.catalog import FieldSpec, MsgCatalog, MsgSpec

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
# what a name is: ("local", id(scope node), name), ("param", id(function node),
# function key, name), ("attr", class name, attribute)
Entity = tuple[object, ...]
_T = TypeVar("_T")
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
    """What `robotfix suggest` logs of a check: where values flow (sinks, calls,
    bindings, sequences)."""

    # (where, expression, the place's unit, whether the place holds an int)
    sinks: list[tuple[Where, ast.expr, Unit, bool]] = field(default_factory=list)
    # function key -> (caller, parameter, argument)
    calls: dict[str, list[tuple[Where, str, ast.expr]]] = field(default_factory=dict)
    # ("local", id(scope node), name) / ("attr", class, attr) -> (where, value)
    binds: dict[tuple[object, ...], list[tuple[Where, ast.expr]]] = field(
        default_factory=dict
    )
    # (entity, a unit a value assigned to it has)
    held: list[tuple[tuple[object, ...], Unit]] = field(default_factory=list)
    # entities bound to a sequence, those bound to something other than a list of
    # numbers, and the expressions that reach an array field (with the unit and
    # kind of its elements)
    sequences: set[tuple[object, ...]] = field(default_factory=set)
    floats: set[tuple[object, ...]] = field(default_factory=set)  # bound to a float
    not_number_lists: set[tuple[object, ...]] = field(default_factory=set)
    array_sinks: list[tuple[Where, ast.expr, Unit | None, str]] = field(
        default_factory=list
    )
    program: Program | None = None  # set when the file's program is collected
    # `self.cmd.linear.x = speed` where the analysis does not know `self.cmd` (set
    # in another method): (where, attribute entity, field path, value expression)
    attribute_fields: list[tuple[Where, tuple[object, ...], str, ast.expr, Value]] = (
        field(default_factory=list)
    )
    # a message constructor call -> (field, argument, its value) for each argument
    constructed: dict[int, list[tuple[str, ast.expr, Value]]] = field(
        default_factory=dict
    )
    _seen: set[tuple[object, ...]] = field(default_factory=set)

    def sink(
        self,
        where: Where,
        expr: ast.expr,
        unit: Unit | None,
        value: Value | None,
        array: str = "",
        integer: bool = False,
    ) -> None:
        """`expr` (holding `value`) reached a place of `unit` (a dimensionless one
        only tells a name apart from one with a unit: it is never suggested); an
        `array` place (a message's array field of `array` numbers, `unit` theirs)
        says its names hold sequences; an `integer` place (`Duration.sec`) that
        they hold an int."""
        if array:
            if self._once("array", id(expr)):
                self.array_sinks.append((where, expr, unit, array))
            return
        if unit is None or unit.is_label:
            return
        if value is not None:
            if value.kind not in NUMERIC and value.kind != "unknown":
                return
            found = value.fit(unit)
            if found is not None and found.kind != "ok":
                return  # a bug `check` reports: nothing to learn from it
        if self._once("sink", id(expr), str(unit), integer):
            self.sinks.append((where, expr, unit, integer))

    def constructor(
        self,
        ctx: FileContext,
        state: State,
        where: Where,
        ref: int,
        node: ast.Call,
        given: list[tuple[str, ast.expr, Value]],
    ) -> None:
        """`Twist(Vector3(speed, 0.0, 0.0))` built the message `ref`: each argument
        reached the field it set (see `message_sinks`)."""
        self.constructed[id(node)] = given
        self.message_sinks(ctx, state, where, ref, node)

    def message_sinks(
        self, ctx: FileContext, state: State, where: Where, ref: int, node: ast.Call
    ) -> None:
        """The arguments of constructor `node`, whose message is now `ref` (built
        there, or stored into a field: `odom.twist.twist = Twist(...)`), reached
        the fields they set, with those fields' units as `ref`'s place gives them;
        a nested constructor's arguments (`Twist(Vector3(speed, ...))`) reached
        the fields below."""
        obj = state.heap.get(ref)
        for name, expr, value in self.constructed.get(id(node), []) if obj else []:
            assert obj is not None
            held = obj.fields.get(name)
            inner = held.ref if isinstance(held, Value) else None
            if isinstance(expr, ast.Call) and inner in state.heap:
                assert inner is not None
                self.message_sinks(ctx, state, where, inner, expr)
                continue
            spec = heap.field_spec(ctx, state, ref, name)
            unit = heap.field_unit(ctx, state, ref, name)[0]
            integer = spec is not None and spec.kind == "int"
            self.sink(where, expr, unit, value, array_kind(spec), integer)

    def call(self, where: Where, key: str, param: str, expr: ast.expr) -> None:
        if self._once("call", id(expr), key, param):
            self.calls.setdefault(key, []).append((where, param, expr))

    def bind(
        self, where: Where, target: ast.expr, expr: ast.expr, value: Value
    ) -> None:
        """`target = expr` (or `target += expr`) for an unannotated target; a unit
        the value is known to have (`math.atan2(...)` is rad) is kept to find names
        that hold two units (never a suggestion by itself)."""
        entity = _target_entity(where, target)
        if entity is None:
            return
        if self._once("bind", id(expr), entity):
            self.binds.setdefault(entity, []).append((where, expr))
        if _is_sequence(value):
            self.sequences.add(entity)
        if not _is_number_list(expr, value, where):
            self.not_number_lists.add(entity)
        if value.kind == "float":
            self.floats.add(entity)
        unit = value.unit
        kept = unit is not None and not value.literal and value.scale == 1.0
        if kept and unit is not None and not unit.is_label:
            self.held.append((entity, unit))

    def attribute_field(
        self, where: Where, target: ast.Attribute, expr: ast.expr, value: Value
    ) -> None:
        """`self.cmd.linear.x = expr`, `self.cmd` unknown here: its type is looked
        for in the class's assignments at the end (`settle_attribute_fields`)."""
        if value.kind not in NUMERIC and value.kind != "unknown":
            return
        path: list[str] = []
        node: ast.expr = target
        while isinstance(node, ast.Attribute):
            entity = _target_entity(where, node)
            if entity is not None:
                if path and self._once("field", id(expr)):
                    self.attribute_fields.append(
                        (where, entity, ".".join(reversed(path)), expr, value)
                    )
                return
            path.append(node.attr)
            node = node.value

    def settle_attribute_fields(
        self,
        msg_type_of: Callable[[ast.expr], str | None],
        unit_of: Callable[[str, str], Unit | None],
    ) -> None:
        """The writes into fields of messages held in attributes become sinks when
        every assignment of the attribute constructs the same message type."""
        for where, entity, path, expr, value in self.attribute_fields:
            types = {
                msg_type_of(value.func) if isinstance(value, ast.Call) else None
                for _, value in self.binds.get(entity, [])
            }
            if len(types) != 1 or None in types:
                continue
            msg_type = types.pop()
            assert msg_type is not None
            self.sink(where, expr, unit_of(msg_type, path), value)

    def _once(self, *key: object) -> bool:
        if key in self._seen:
            return False
        self._seen.add(key)
        return True


@dataclass(frozen=True)
class Found:
    """A name `robotfix suggest` can annotate, and the unit it would write."""

    line: int
    col: int  # byte column of the name
    name: str
    unit: str
    kind: str = "float"  # `list[float]`: a list of numbers in `unit`


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


def path_unit(catalog: MsgCatalog, msg_type: str, path: str) -> Unit | None:
    """The unit of the number at `path` (`linear.x`) of a `msg_type` message, by
    the same rule as the analysis's (`heap.field_unit`): the outermost message
    that declares one."""
    parts = path.split(".")
    chain: list[tuple[MsgSpec, str]] = []
    current = msg_type
    for index, part in enumerate(parts):
        spec = catalog.lookup(current)
        found = spec.fields.get(part) if spec is not None else None
        if spec is None or found is None or found.array:
            return None
        chain.append((spec, ".".join(parts[index:])))
        if index == len(parts) - 1:
            if found.kind not in ("int", "float"):
                return None
        elif found.kind != "msg" or not found.msg_type:
            return None
        else:
            current = found.msg_type
    for spec, rest in chain:
        declared = spec.units.get(rest)
        if declared is not None:
            return heap.unit_of(declared.text)
    return None


def suggestions(log: FlowLog, program: Program) -> list[Found]:
    """One unit for each name whose flows all agree and that can be annotated.

    The unit of a place goes backwards, to the names whose values reach it
    (`cmd.linear.x = v`, `v = speed * 0.5`: both m/s); a unit a value is known to
    have (`math.atan2(...)` is rad) goes forwards, to the names that take it
    (`error = heading - yaw`), so that a name holding rad that reaches rad/s (a
    controller's implicit gain) gets no suggestion. A name gets one when all the
    units it meets agree."""
    sources: dict[tuple[object, ...], list[tuple[Where, ast.expr]]] = {}
    for entity, assigned in log.binds.items():
        sources.setdefault(entity, []).extend(assigned)
    for key, calls in log.calls.items():
        function = program.functions.get(key)
        for where, param, expr in calls if function is not None else []:
            assert function is not None
            entity = ("param", id(function.node), key, param)
            sources.setdefault(entity, []).append((where, expr))
    carried: dict[tuple[object, ...], list[tuple[tuple[object, ...], Where]]] = {}
    places: dict[tuple[object, ...], Where] = {}

    def carriers(
        expr: ast.expr, where: Where
    ) -> list[tuple[tuple[object, ...], Where]]:
        found = carried.get((id(expr),))
        if found is None:
            found = carried[(id(expr),)] = list(_carriers(expr, where))
            for entity, at in found:
                places.setdefault(entity, at)
        return found

    def back(entity: tuple[object, ...]) -> Iterator[tuple[object, ...]]:
        for where, expr in sources.get(entity, []):
            yield from (e for e, _ in carriers(expr, where))

    def back_gains(entity: tuple[object, ...]) -> Iterator[tuple[object, ...]]:
        for where, expr in sources.get(entity, []):
            yield from (e for e, _ in _carriers(expr, where, gains=True))

    sinks = [
        (entity, unit, integer)
        for where, expr, unit, integer in log.sinks
        for entity, _ in carriers(expr, where)
    ]
    # backwards, from the places: the units names reach, those that reach an int,
    # the units of array fields their elements reach
    reached = _spread([(e, unit) for e, unit, _ in sinks], back)
    ints = _spread([(e, None) for e, _, integer in sinks if integer], back)
    elements = _spread(
        [
            (e, (unit, kind))
            for w, x, unit, kind in log.array_sinks
            for e, _ in carriers(x, w)
        ],
        back,
    )
    sequences = set(log.sequences) | set(elements)
    # the units names meet through a placeholder gain too (`turn = error * 1.0`
    # into rad/s): never a suggestion by itself, but one that differs is a conflict
    gained = _spread(
        [(e, u) for w, x, u, _ in log.sinks for e, _ in _carriers(x, w, gains=True)],
        back_gains,
    )
    takers: dict[tuple[object, ...], list[tuple[object, ...]]] = {}
    for entity in sources:
        for carrier in back_gains(entity):  # `turn` holds what `error` holds
            takers.setdefault(carrier, []).append(entity)
    held = _spread(list(log.held), lambda e: iter(takers.get(e, [])))  # forwards
    found = []
    shapes = Shapes(program, log.calls)
    for entity, met_elements in elements.items():
        if entity in reached or entity in log.not_number_lists:
            continue  # also a number, or not always a list of numbers
        if entity not in log.binds:
            continue  # a parameter: what its callers pass is not known to be a list
        kinds = {kind for _, kind in met_elements}
        element = met_elements[0][0]
        if kinds not in ({"float"}, {"int"}) or element is None:
            continue
        if any(e is None or not e.same_as(element) for e, _ in met_elements):
            continue
        if not element.dims or element.is_label or not element.text:
            continue
        spot = shapes.spot(entity, places.get(entity))
        if spot is not None:
            found.append(Found(*spot, element.text, f"list[{kinds.pop()}]"))
    for entity, units in reached.items():
        met: list[Unit] = []
        for unit in [*units, *held.get(entity, []), *gained.get(entity, [])]:
            _add(met, unit)
        if len(met) != 1 or not met[0].dims or not met[0].text:
            continue  # several units: a bug for `check`, not an annotation
        if entity in sequences:
            continue  # not a float; its elements' type is not known
        kind = "float"
        if entity in ints:  # an int place: `Duration(sec=timeout)`
            if entity in log.floats or _float_given(entity, log, program):
                continue  # a float in an int place: RF401 for `check`
            kind = "int"
        spot = shapes.spot(entity, places.get(entity))
        if spot is not None:
            found.append(Found(*spot, met[0].text, kind))
    return sorted(set(found), key=lambda f: (f.line, f.col))


def _spread(
    todo: list[tuple[tuple[object, ...], _T]],
    after: Callable[[tuple[object, ...]], Iterator[tuple[object, ...]]],
) -> dict[tuple[object, ...], list[_T]]:
    """Each (name, fact) goes on to the names `after` the name (those its
    assigned values carry, backwards; those it is assigned to, forwards): the
    facts each name meets."""
    met: dict[tuple[object, ...], list[_T]] = {}
    done: set[tuple[tuple[object, ...], str]] = set()
    while todo:
        entity, fact = todo.pop()
        if (entity, str(fact)) in done:
            continue
        done.add((entity, str(fact)))
        met.setdefault(entity, []).append(fact)
        todo.extend((e, fact) for e in after(entity))
    return met


def _is_sequence(value: Value) -> bool:
    return value.kind in ("list", "tuple") or value.items is not None


def _is_number_list(expr: ast.expr, value: Value, where: Where) -> bool:
    """A list whose known elements are numbers (`[]`, `[0.0] * n`), or a copy
    the builtin `list()` makes of what the analysis does not know (`list(xs)`)."""
    if value.kind == "unknown" and isinstance(expr, ast.Call):
        func = expr.func
        return (
            isinstance(func, ast.Name)
            and func.id == "list"
            and func.id not in where.scope.module().local_names
        )
    return value.kind == "list" and all(
        e.kind in NUMERIC or e.kind == "unknown" for e in value.elements or ()
    )


def array_kind(spec: FieldSpec | None) -> str:
    """`float` or `int` for a message's array field of numbers, else ""."""
    if spec is None or not spec.array:
        return ""
    return spec.kind if spec.kind in ("int", "float") else "unknown"


def _add(units: list[Unit], unit: Unit) -> None:
    if not any(u.same_as(unit) for u in units):
        units.append(unit)


def _float_given(entity: tuple[object, ...], log: FlowLog, program: Program) -> bool:
    """A parameter whose default or an argument of a call is a float literal."""
    if entity[0] != "param":
        return False
    key, name = str(entity[2]), str(entity[3])
    given = [expr for _, param, expr in log.calls.get(key, []) if param == name]
    function = program.functions.get(key)
    if function is not None and not isinstance(function.node, ast.Lambda):
        args = function.node.args
        for arg in [*args.posonlyargs, *args.args, *args.kwonlyargs]:
            default = default_of(args, arg) if arg.arg == name else None
            given += [default] if default is not None else []
    return any(
        isinstance(e, ast.Constant) and isinstance(e.value, float)
        for expr in given
        for e in ast.walk(expr)
    )


def _carriers(
    expr: ast.expr, where: Where, factor: float = 1.0, gains: bool = False
) -> Iterator[tuple[tuple[object, ...], Where]]:
    """The names in `expr` whose unit the whole value has; with `gains`, also
    through a placeholder gain (`error * 1.0`)."""
    if not_a_number(expr):  # `"/" + robot + "/reset"` reaching a timeout's place
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
        yield from _carriers(expr.operand, where, factor, gains)
    elif isinstance(expr, ast.BinOp):
        if isinstance(expr.op, (ast.Add, ast.Sub)):
            yield from _carriers(expr.left, where, factor, gains)
            yield from _carriers(expr.right, where, factor, gains)
        elif isinstance(expr.op, ast.Mult):
            # `error * 1.0`: a factor of one is written as a gain's placeholder
            right, left = _literal(expr.right), _literal(expr.left)
            if right is not None and (right != 1 or gains):
                yield from _carriers(expr.left, where, factor * right, gains)
            elif left is not None and (left != 1 or gains):
                yield from _carriers(expr.right, where, factor * left, gains)
        elif isinstance(expr.op, ast.Div):
            right = _literal(expr.right)
            if right and (right != 1 or gains):
                yield from _carriers(expr.left, where, factor / right, gains)
    elif isinstance(expr, ast.IfExp):
        yield from _carriers(expr.body, where, factor, gains)
        yield from _carriers(expr.orelse, where, factor, gains)
    elif isinstance(expr, ast.NamedExpr):
        yield from _carriers(expr.target, where, factor, gains)
        yield from _carriers(expr.value, where, factor, gains)
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
                yield from _carriers(arg, where, factor, gains)


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
