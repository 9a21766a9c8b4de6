"""Calls into libraries RobotFix cannot see into, as their stubs describe them
(`robotfix/stubs/`): arguments are checked against the parameters' units and
refinements, results get the return's unit and refinement, or become objects of a
stub class whose properties and methods are known in turn (`self.get_clock().now()
.nanoseconds` is in ns). A subclass of a stub class (`class Ticker(Node)`) inherits
its methods. A method called on a value of unknown type is looked up by its name
among the stubs' methods, and used only as far as they all agree.

`Libraries` is a collaborator of the evaluator (`calls.CallEvaluator.libraries`),
made with the file's context, program and the checks it reports through; what it
needs of the walker at a call, the statement being run and where a value
reaching a unit is logged for `robotfix suggest`, it is handed as `at`
(`imported.Site`), and it never calls the walker otherwise.
"""

from __future__ import annotations

import ast
import math
from dataclasses import replace
from fractions import Fraction
from typing import TYPE_CHECKING

from robotfix import messages
from robotfix.analysis import fixes, frames, heap, imported
from robotfix.analysis.imported import Site, resolve_library
from robotfix.analysis.state import State
from robotfix.analysis.types import OPERATOR_METHODS
from robotfix.analysis.values import Conversion, Value
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Refinement
from robotfix.annotations.numbers import NUMBERS, named_number
from robotfix.annotations.units import Unit, named
from robotfix.messages import Declared
from robotfix.stubs import byname
from robotfix.stubs import load as stubs

if TYPE_CHECKING:
    from robotfix.analysis.checks import Checker
    from robotfix.analysis.context import FileContext
    from robotfix.analysis.lookups import Lookups
    from robotfix.analysis.program import Program
    from robotfix.analysis.refined import RefinedChecker

ZERO = A.Num(Fraction(0), True)


class Libraries:
    def __init__(
        self,
        ctx: FileContext,
        program: Program,
        check: Checker,
        refined: RefinedChecker,
        lookups: Lookups,
    ) -> None:
        self.ctx = ctx
        self.program = program
        self.check = check
        self.refined = refined
        self.lookups = lookups
        self._stub_set: stubs.StubSet | None = None  # (`_stubs`, on first use)

    # -- names ---------------------------------------------------------------
    def object_member(self, cls_name: str, attr: str, state: State) -> Value | None:
        """`t.nanoseconds`, `d.to_sec` of an object of a stub class."""
        cls = resolve_library(self.ctx, cls_name)
        if not isinstance(cls, stubs.Class):
            return None
        set_ = self._stubs()
        function = set_.member(cls, attr)
        if function is not None:
            if function.kind == "property":
                return self.library_result(function, {}, f"`.{attr}`", state)
            return Value("libmethod", name=function.qualname)
        found = set_.attribute(cls, attr)
        if found is None:
            return None
        if found.decl is not None:
            lookup = self._lookup(found.decl, {})
            return self.refined.assumed(state, f".{attr}", found.decl, lookup)
        return self._object(found.type, state, f"`.{attr}`")

    def object_operation(
        self, at: Site, node: ast.BinOp, left: Value, right: Value, state: State
    ) -> Value | None:
        """`now - self.prev` (rclpy Times: a Duration), `d * 2` (a rospy Duration):
        the left operand's `__sub__`, or the right one's `__rsub__`, as its stub
        says; an overload for the other operand's class (or builtin kind) first."""
        name = OPERATOR_METHODS.get(type(node.op))
        if name is None:
            return None
        for obj, other, method in (
            (left, right, name),
            (right, left, f"__r{name[2:]}"),
        ):
            if obj.kind != "object":
                continue
            cls = resolve_library(self.ctx, obj.name)
            if not isinstance(cls, stubs.Class):
                continue
            operand = other.name if other.kind == "object" else _builtin(other)
            keys = [f"{method}:{operand}", method]
            if operand == "int":  # an int goes where a float is taken
                keys.insert(1, f"{method}:float")
            set_ = self._stubs()
            function = next(
                (f for f in (set_.member(cls, k) for k in keys) if f is not None), None
            )
            if function is None:
                continue
            param = function.params[0] if function.params else None
            if param is not None and other.kind != "object":
                self._check_argument(at, function, param, other, state)
            return self.library_result(function, {}, node, state)
        return None

    def inherited_method(self, class_name: str, attr: str) -> Value | None:
        """`self.create_timer` in a class derived from a stub class (`Node`), when
        neither the class nor its code defines `attr`."""
        if (
            f"{class_name}.{attr}" in self.program.functions
            or attr in self.program.attributes.get(class_name, {})
            or self.lookups.class_constant(class_name, attr) is not None
        ):
            return None
        for cls in self.program.types.library_bases(class_name):
            function = self._stubs().member(cls, attr)
            if function is not None and function.kind == "method":
                return Value("libmethod", name=function.qualname)
        return None

    # -- calls ---------------------------------------------------------------
    def library_call(
        self,
        at: Site,
        callee: Value,
        node: ast.Call,
        args: list[Value],
        kwargs: dict[str | None, Value],
        state: State,
        method: str | None,
    ) -> Value | None:
        """The value of a call of a stubbed function, method or class; None when
        no stub speaks of it. `method`: the callee's attribute (`x.m(...)`), if it
        is one."""
        kind = callee.kind
        if kind == "unknown":  # a method of a value of unknown type: by its name
            if method is None:
                return None
            stub_set = self._stub_set or self._stubs()  # (no call: most calls)
            if stubs.unchecked_call(stub_set, method, len(args), kwargs):
                return None  # (`super().__init__(...)`: no stub parsed to know)
            candidates = stubs.methods_named(stub_set, method)
            if not candidates:
                return None  # (most calls: no stub has a method of that name)
        elif kind not in ("libmethod", "module"):
            return None
        if imported.starred(node, kwargs):
            args = []  # positions unknown: only keywords are checked
        if kind == "libmethod":
            found = resolve_library(self.ctx, callee.name)
            if isinstance(found, stubs.Function):
                return self.call_function(at, found, args, kwargs, node, state, 0)
            return None
        if kind == "module":
            found = resolve_library(self.ctx, callee.name)
            if isinstance(found, stubs.Class):
                init = self._stubs().member(found, "__init__")
                if init is not None:
                    self.call_function(at, init, args, kwargs, node, state, 0)
                return Value("object", name=found.qualname)
            if isinstance(found, stubs.Function):
                # `Duration.to_sec(d)`: a method through its class takes self first
                shift = 1 if found.kind == "method" else 0
                return self.call_function(at, found, args, kwargs, node, state, shift)
            return None
        return self._by_method_name(at, candidates, node, args, kwargs, state)

    def _by_method_name(
        self,
        at: Site,
        candidates: tuple[stubs.Function, ...],
        node: ast.Call,
        args: list[Value],
        kwargs: dict[str | None, Value],
        state: State,
    ) -> Value | None:
        """A call of a method of a value of unknown type, which one of the stubs'
        `candidates` of its name (at least one) may be."""
        if byname.agree(candidates):
            return self.call_function(at, candidates[0], args, kwargs, node, state, 0)
        # they differ: check only the arguments every candidate gives one unit
        first = candidates[0]
        for index, value in enumerate(args):
            if byname.position_checked(candidates, index):
                param = byname.param_at(first, index, None)
                self._check_argument(at, first, param, value, state)  # type: ignore[arg-type]
        for key, value in kwargs.items():
            if key is not None and byname.keyword_checked(candidates, key):
                given = (byname.param_at(f, None, key) for f in candidates)
                param = next(p for p in given if p is not None)
                self._check_argument(at, first, param, value, state)
        return None

    def call_function(
        self,
        at: Site,
        function: stubs.Function,
        args: list[Value],
        kwargs: dict[str | None, Value],
        node: ast.Call,
        state: State,
        shift: int,
    ) -> Value:
        given: dict[str, list[Value]] = {}
        for param in function.params:
            if param.keyword and param.name in kwargs:
                given[param.name] = [kwargs[param.name]]
            elif param.positional is not None:
                start = param.positional + shift
                given[param.name] = (
                    args[start:] if param.variadic else args[start : start + 1]
                )
        for param in function.params:
            for value in given.get(param.name, []):
                if function.rule != "scale":  # see `_scaled`
                    self._check_argument(at, function, param, value, state)
        self._argument_flows(at, function, node, args, kwargs, shift)
        # a condition (`where(cond, x, y)`) has no part in a unit rule
        quantities = [p for p in function.params if not p.flag]
        first = [v for p in quantities for v in given.get(p.name, [])[:1]]
        values = [v for p in quantities for v in given.get(p.name, [])]
        if function.rule is not None and values:
            found = self._unit_rule(at, function, first[0], values, node, state)
            if found is not None:
                return found
        terms = {
            name: found[0].term
            for name, found in given.items()
            if found and found[0].term is not None
        }
        result = self.library_result(function, terms, node, state)
        if values and all(v.literal for v in values) and _pure_number(result):
            # `math.sin(math.radians(45))`: a number, taking the unit of its context
            return replace(result, unit=None, literal=True)
        return result

    def _argument_flows(
        self,
        at: Site,
        function: stubs.Function,
        node: ast.Call,
        args: list[Value],
        kwargs: dict[str | None, Value],
        shift: int,
    ) -> None:
        """For `robotfix suggest`: an argument reached a parameter with a unit."""
        if self.ctx.unit_flows is None:
            return
        keywords = {k.arg: k.value for k in node.keywords if k.arg is not None}
        for param in function.params:
            unit = param.decl.unit if param.decl is not None else None
            if unit is None or param.decl is None:
                continue
            integer = param.decl.base == "int"
            if param.keyword and param.name in kwargs and param.name in keywords:
                at.note_sink(keywords[param.name], unit, kwargs[param.name], integer)
            elif param.positional is not None and not param.variadic and args:
                index = param.positional + shift
                if index < len(node.args) and index < len(args):
                    at.note_sink(node.args[index], unit, args[index], integer)

    def _check_argument(
        self,
        at: Site,
        function: stubs.Function,
        param: stubs.Param,
        value: Value,
        state: State,
    ) -> None:
        decl = param.decl
        if decl is None:
            return
        target = f"the `{param.name}` argument of {function.short}()"
        unit = f" is in {decl.unit.text}" if decl.unit is not None else ""
        declared = (
            Declared(f"annotation of {target}", function.path, function.line)
            if function.path is not None
            else Declared(
                f"{target}{unit}",
                None,
                None,
                f"by the stub {function.origin} shipped with RobotFix",
            )
        )
        if not self.check.units_agree(
            decl.unit, value, at.site, target, declared, state
        ):
            return
        if value.term is None or decl.predicate == A.TRUE or value.kind == "object":
            return
        lookup = self._lookup(decl, {})
        for part in A.conjuncts(decl.predicate):
            goal = A.substitute(part, {**lookup, "_": value.term})
            shown = A.show(A.substitute(part, {"_": A.Name(param.name)}))
            outcome = self.check.goal_holds(
                state, goal, value.term, at.site, shown, target, declared
            )
            if outcome != "proved":
                break

    def library_result(
        self,
        function: stubs.Function,
        terms: dict[str, A.Expr],
        node: ast.AST | str,
        state: State,
    ) -> Value:
        if function.returns is not None:
            lookup = self._lookup(function.returns, terms)
            return self.refined.assumed(
                state, f"{function.short}()", function.returns, lookup
            )
        if function.returns_type is not None:
            return self._object(function.returns_type, state, node)
        return self.ctx.fresh(function.returns_kind or "unknown", node)

    def _object(
        self, qualified: str | None, state: State, node: ast.AST | str
    ) -> Value:
        if qualified is None:
            return self.ctx.fresh("unknown", node)
        msg_type = self.ctx.msg_type_named(qualified)
        if msg_type is not None:
            label = node if isinstance(node, str) else self.ctx.source.segment(node)
            return heap.new_message(
                self.ctx, state, msg_type, "received", label=label or "result"
            )
        if isinstance(resolve_library(self.ctx, qualified), stubs.Class):
            return Value("object", name=qualified)
        return self.ctx.fresh("unknown", node)

    def _lookup(self, decl: Refinement, terms: dict[str, A.Expr]) -> dict[str, A.Expr]:
        """Terms for the names a stub's refinement mentions: the call's arguments,
        `math.pi` and its kin (the doubles), else fresh unknowns."""
        found: dict[str, A.Expr] = {}
        for ref in [n for p in decl.predicates() for n in A.names(p)]:
            name = ref.name
            if name == "_" or name in found:
                continue
            number = named_number(name) if name.rsplit(".", 1)[-1] in NUMBERS else None
            if name in terms:
                found[name] = terms[name]
            elif number is not None:
                found[name] = A.Num(number, False)
            else:
                found[name] = self.ctx.fresh("unknown", f"`{name}`").known_term
        return found

    # -- results whose unit follows the arguments' ---------------------------
    def _unit_rule(
        self,
        at: Site,
        function: stubs.Function,
        first: Value,
        values: list[Value],
        node: ast.Call,
        state: State,
    ) -> Value | None:
        rule, short = function.rule, function.qualname.rsplit(".", 1)[-1]
        if rule == "agree":
            for other in values[1:]:
                self.check.unit_of_sum(values[0], other, node, short)
            return None  # the result is as annotated
        if rule == "scale":
            return self._scaled(at, function, first, node)
        if rule == "root":
            root = (
                _root(first.unit)
                if first.unit is not None and not first.literal
                else None
            )
            value = self.ctx.fresh("float", node, root)
            state.assume(A.Binary(">=", value.known_term, ZERO))
            return replace(value, literal=first.literal)
        # same: the arguments' common unit
        units = [
            self.check.unit_of_sum(first, other, node, short)[0] for other in values[1:]
        ]
        unit: Unit | None = first.unit if not first.literal else None
        if unit is None:
            unit = next((u for u in units if u is not None), None)
        if unit is not None and (
            any(
                found is None and other.unit is not None and not other.literal
                for found, other in zip(units, values[1:], strict=True)
            )
            or any(self.ctx.already(("operands", id(arg))) for arg in node.args)
        ):
            # its arguments' units, or an argument's own operands', were reported
            # not to agree (RF202): no unit, as for `+`, so no cascade
            unit = None
        if short == "hypot":
            unit = frames.unframed(unit)  # a length is the same in every frame
        if function.returns_kind == "int":
            return self.ctx.fresh("int", node, unit)
        value = self.library_result(function, {}, node, state)
        if short in ("fabs", "abs", "absolute") and first.term is not None:
            return replace(first, kind="float", term=A.Func("abs", (first.known_term,)))
        return value.with_unit(unit) if value.term is not None else value

    def _scaled(
        self, at: Site, function: stubs.Function, first: Value, node: ast.Call
    ) -> Value | None:
        """`radians(x)`: x times the ratio of the parameter's unit to the result's.
        The argument may carry more than the angle (`radians(deg_s)` is in rad/s);
        one already in the result's unit (`radians(yaw)`, yaw in rad) is a bug. The
        result records the call and its argument's unit (`Conversion`), so a unit
        message says which call to remove or swap."""
        param = function.params[0].decl if function.params else None
        result = function.returns
        if param is None or param.unit is None or result is None:
            return None
        if result.unit is None or first.term is None:
            return None
        factor = param.unit.factor / result.unit.factor
        term = A.Binary("*", first.term, A.Num(Fraction(factor), False))
        call = self.ctx.source.segment(node.func) or function.short
        if first.literal:  # in the parameter's unit: `radians(90.0)` is in rad
            done = Conversion(call, param.unit)
            return Value("float", term, result.unit, True, conversion=done)
        if first.unit is None:
            return Value("float", term, result.unit)
        angle = {d for d, _ in result.unit.dims}
        converted = (
            angle <= {d for d, _ in first.unit.dims}
            and math.isclose(first.unit.factor, result.unit.factor)
            and not math.isclose(param.unit.factor, result.unit.factor)
        )
        if converted:
            span, stmt = self.check.where(at.site)
            name = function.params[0].name
            declared = Declared(
                f"the `{name}` argument of {function.short}() is in {param.unit.text}",
                function.path,
                function.line if function.path else None,
                f"by the stub {function.origin} shipped with RobotFix",
            )
            key = ("converted-twice", id(node))
            self.ctx.defer(
                messages.converted_twice(
                    self.ctx.source.path,
                    span,
                    stmt,
                    call,
                    first.unit,
                    declared,
                    fixes.undo_call(self.ctx.source, node, call),
                ),
                key,
            )
            done = Conversion(call, first.unit, key)
            return Value("float", term, result.unit, conversion=done)
        unit = named(Unit(first.unit.dims, first.unit.factor / factor, text=""))
        return Value("float", term, unit, conversion=Conversion(call, first.unit))

    def _stubs(self) -> stubs.StubSet:
        """The stubs the file's context reads (`imported.stub_set_of`)."""
        found = self._stub_set
        if found is None:
            found = self._stub_set = imported.stub_set_of(self.ctx)
        return found


def _builtin(value: Value) -> str:
    """The builtin type an operand's overload is written with (`float` for a
    number of unknown kind)."""
    return value.kind if value.kind in ("int", "bool") else "float"


def _pure_number(value: Value) -> bool:
    return value.is_number and (value.unit is None or not value.unit.dims)


def _root(unit: Unit) -> Unit | None:
    return unit.raised(Fraction(1, 2))
