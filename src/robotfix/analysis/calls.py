"""Calls -> abstract values: user functions (refined parameters are checked at the call,
refined returns assumed), message constructors, messages that leave the node, ROS API
parameters with units, math, and builtins. Unknown callees give unknown values and
forget what they may change in the messages and instances they are handed.
"""

from __future__ import annotations

import ast
import math
from dataclasses import replace
from fractions import Fraction

from robotfix.analysis import heap, imported
from robotfix.analysis.param_eval import ParameterEvaluator
from robotfix.analysis.program import Function
from robotfix.analysis.state import State
from robotfix.analysis.values import NONE, Value
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Refinement
from robotfix.annotations.numbers import INFINITY, NUMBERS
from robotfix.annotations.units import Unit, named, resolve
from robotfix.messages import Declared
from robotfix.ros.api_model import MATH_UNITS, PARAMETER_CALLS, UNIT_PARAMETERS

# Methods whose first argument leaves the node: it must satisfy its refinements.
LEAVING = frozenset(
    {
        "publish",
        "publish_feedback",
        "set_succeeded",
        "set_aborted",
        "set_preempted",
        "call",
        "call_async",
        "send_goal",
        "send_goal_async",
    }
)
# atan2, asin, acos... return at most math.pi (the double, below the real pi)
PI_BOUND = A.Num(NUMBERS["pi"], False)
ONE = A.Num(Fraction(1), True)
ZERO = A.Num(Fraction(0), True)


class CallEvaluator(ParameterEvaluator):
    def eval_Call(self, node: ast.Call, state: State) -> Value:
        func = node.func
        method = func.attr if isinstance(func, ast.Attribute) else None
        if method in LEAVING and node.args:
            self.eval(node.func.value, state)  # type: ignore[attr-defined]
            values = [self.eval(a, state) for a in node.args]
            for value in values[:1]:
                if value.kind == "msg" and value.ref is not None:
                    self.check.check_whole(state, value.ref, self.site, publishing=True)
            return self.unknown(node)
        callee = self.eval(func, state)
        args = [self.eval(a, state) for a in node.args]
        kwargs = {k.arg: self.eval(k.value, state) for k in node.keywords}
        result = self._dispatch(callee, node, args, kwargs, state)
        self._forget_after_call(node, args, kwargs, state, callee)
        return result

    def _dispatch(
        self,
        callee: Value,
        node: ast.Call,
        args: list[Value],
        kwargs: dict[str | None, Value],
        state: State,
    ) -> Value:
        if callee.kind == "msgclass":
            return self.construct(callee.name, args, kwargs, state)
        if callee.kind == "parameter_method":  # p.get_parameter_value()
            return Value("parameter_value", name=callee.name)
        if (
            callee.kind in ("function", "method")
            and callee.name in self.program.functions
        ):
            starred = (
                any(isinstance(a, ast.Starred) for a in node.args) or None in kwargs
            )
            if not starred:
                return self.call_known(
                    self.program.functions[callee.name],
                    args,
                    kwargs,
                    node,
                    state,
                    bound=callee.kind == "method",
                )
        if callee.kind == "class" and callee.name in self.program.classes:
            init = self.program.functions.get(f"{callee.name}.__init__")
            if init is not None and not any(
                isinstance(a, ast.Starred) for a in node.args
            ):
                self.call_known(init, args, kwargs, node, state, bound=True)
            return Value("instance", name=callee.name)
        if callee.kind == "builtin":
            found = self.builtin(callee.name, args, node, state)
            if found is not None:
                return found
        if callee.kind == "module" and callee.name.startswith("math."):
            found = self.math_call(callee.name[5:], args, node, state)
            if found is not None:
                return found
        found = self.imported_call(callee, node, args, kwargs, state)
        if found is not None:
            return found
        name = (
            callee.name.rsplit(".", 1)[-1]
            if callee.kind == "module"
            else node.func.attr
            if isinstance(node.func, ast.Attribute)
            else ""
        )
        if name in PARAMETER_CALLS:
            found = self.parameter_call(name, callee, node, args, kwargs, state)
            if found is not None:
                return found
        if name in UNIT_PARAMETERS:
            self._check_api_units(name, node, args, kwargs)
        return self.unknown(node)

    def imported_call(
        self,
        callee: Value,
        node: ast.Call,
        args: list[Value],
        kwargs: dict[str | None, Value],
        state: State,
    ) -> Value | None:
        """A function, class or method of another module of the tree."""
        if callee.kind not in ("module", "method") or self.ctx.resolver is None:
            return None
        found = imported.resolve(self.ctx.resolver, callee.name)
        if imported.starred(node, kwargs):
            found = None if isinstance(found, imported.FunctionSummary) else found
        if isinstance(found, imported.FunctionSummary):
            bound = callee.kind == "method"
            return imported.call(self, found, args, kwargs, node, state, bound)
        if isinstance(found, imported.ClassSummary):
            methods = dict(found.methods)
            init = methods.get("__init__")
            if init is not None and not imported.starred(node, kwargs):
                imported.call(self, init, args, kwargs, node, state, True)
            self.program.attributes.setdefault(callee.name, dict(found.attributes))
            return Value("instance", name=callee.name)
        return None

    def _forget_after_call(
        self,
        node: ast.Call,
        args: list[Value],
        kwargs: dict[str | None, Value],
        state: State,
        callee: Value,
    ) -> None:
        """Unknown code may change the messages and instances it is handed."""
        if callee.kind in ("msgclass", "builtin", "parameter_method") or (
            callee.kind == "module" and callee.name.startswith("math.")
        ):
            return
        if isinstance(node.func, ast.Attribute) and node.func.attr in PARAMETER_CALLS:
            return  # rclpy and rospy change no attribute of the node's class
        for value in [*args, *kwargs.values()]:
            if value.kind == "msg" and value.ref is not None:
                heap.havoc(state, value.ref)
        names = [a for a in node.args if isinstance(a, ast.Name)]
        if isinstance(node.func, ast.Attribute) and isinstance(
            node.func.value, ast.Name
        ):
            names.append(node.func.value)
        for name in names:
            bound = state.env.get(name.id)
            if isinstance(bound, Value) and bound.kind == "instance":
                prefix = name.id + "."
                for key in [k for k in state.env if k.startswith(prefix)]:
                    del state.env[key]

    # -- user functions ------------------------------------------------------
    def call_known(
        self,
        function: Function,
        args: list[Value],
        kwargs: dict[str | None, Value],
        node: ast.Call,
        state: State,
        bound: bool,
    ) -> Value:
        scope = self.program.signature(self.ctx, function)
        fn = function.node
        params = [a.arg for a in [*fn.args.posonlyargs, *fn.args.args]]
        if bound and function.is_method and params:
            params = params[1:]
        given: dict[str, Value] = dict(zip(params, args, strict=False))
        given.update({k: v for k, v in kwargs.items() if k is not None})
        terms = {k: v.term for k, v in given.items() if v.term is not None}
        for name, value in given.items():
            decl = scope.decls.get(name)
            if decl is not None:
                lookup = {**self._callee_names(decl, function, state), **terms}
                self.check.assign_refined(state, name, decl, value, self.site, lookup)
        if function.returns is None:
            return self.unknown(node)
        lookup = {**self._callee_names(function.returns, function, state), **terms}
        return self.check.assumed(state, f"{function.name}()", function.returns, lookup)

    def _callee_names(
        self, decl: object, function: Function, state: State
    ) -> dict[str, A.Expr]:
        """Terms for the names a callee's refinement mentions: constants and module
        names (which hold one value during the call), else fresh unknowns (the
        callee's own parameters are filled in by the caller)."""
        predicates = decl.predicates() if isinstance(decl, Refinement) else []
        own = function.scope.local_names if function.scope is not None else set()
        found: dict[str, A.Expr] = {}
        for ref in [n for p in predicates for n in A.names(p)]:
            name = ref.name
            if name == "_" or name in found:
                continue
            term: A.Expr | None = None
            if name.split(".")[0] not in own:
                constant = self.scoped_constant(name, state, function.class_name)
                term = constant.term if constant is not None else None
                if term is None and "." not in name:
                    term = self.global_term(name, state)
            if term is None:
                term = self.ctx.fresh("unknown", f"`{name}`").known_term
            found[name] = term
        return found

    # -- messages ------------------------------------------------------------
    def construct(
        self,
        msg_type: str,
        args: list[Value],
        kwargs: dict[str | None, Value],
        state: State,
    ) -> Value:
        message = heap.new_message(self.ctx, state, msg_type, "constructed")
        spec = self.ctx.catalog.lookup(msg_type)
        assert message.ref is not None and spec is not None
        short = msg_type.split("/")[-1]
        given = list(zip(spec.fields, args, strict=False))
        given += [(k, v) for k, v in kwargs.items() if k]
        for name, value in given:
            self.check.write_field(
                state, message.ref, name, value, self.site, f"{short}.{name}"
            )
        return message

    # -- ROS API and math ----------------------------------------------------
    def _check_api_units(
        self,
        name: str,
        node: ast.Call,
        args: list[Value],
        kwargs: dict[str | None, Value],
    ) -> None:
        for position, keyword, unit_text in UNIT_PARAMETERS[name]:
            value = kwargs.get(keyword) or (
                args[position] if position < len(args) else None
            )
            if value is None:
                continue
            declared = Declared(
                f"ROS API: the `{keyword}` argument of {name}() is in {unit_text}",
                None,
                None,
                "by the API's definition",
            )
            self.check.units_agree(
                resolve(unit_text),
                value,
                self.site,
                f"the `{keyword}` argument of {name}()",
                declared,
            )

    def math_call(
        self, name: str, args: list[Value], node: ast.Call, state: State
    ) -> Value | None:
        if not args:
            return None
        first = args[0]
        if name in ("radians", "degrees"):
            factor = math.pi / 180 if name == "radians" else 180 / math.pi
            source = resolve("degree" if name == "radians" else "rad")
            if first.unit is not None and not first.literal:
                source = first.unit
            result_unit = Unit(source.dims, source.factor / factor, text="")
            if first.term is None:
                return None
            term = A.Binary("*", first.term, A.Num(Fraction(factor), False))
            return Value("float", term, named(result_unit), first.literal)
        if name in MATH_UNITS:
            argument, result = MATH_UNITS[name]
            if argument is not None:
                self.check.units_agree(
                    resolve(argument),
                    first,
                    self.site,
                    f"the argument of math.{name}()",
                    Declared(
                        f"math.{name}() takes {argument}",
                        None,
                        None,
                        "by its definition",
                    ),
                )
            value = self.unknown(node, "float", resolve(result) if result else None)
            bound = (
                ONE if name in ("sin", "cos") else PI_BOUND if name != "tan" else None
            )
            if bound is not None and value.term is not None:
                state.assume(A.Binary("<=", A.Unary("-", bound), value.known_term))
                state.assume(A.Binary("<=", value.known_term, bound))
            return value
        if name == "atan2" and len(args) == 2:
            self.unit_of_sum(args[0], args[1], node, "atan2")
            value = self.unknown(node, "float", resolve("rad"))
            state.assume(A.Binary("<=", A.Unary("-", PI_BOUND), value.known_term))
            state.assume(A.Binary("<=", value.known_term, PI_BOUND))
            return value
        if name in ("sqrt", "hypot"):
            unit: Unit | None = first.unit
            if name == "sqrt":
                unit = (
                    _root(first.unit)
                    if first.unit is not None and not first.literal
                    else None
                )
            else:
                for other in args[1:]:
                    self.unit_of_sum(first, other, node, "hypot")
            value = self.unknown(node, "float", unit)
            state.assume(A.Binary(">=", value.known_term, ZERO))
            return replace(value, literal=first.literal and name == "sqrt")
        if name == "fabs" and first.term is not None:
            return replace(first, kind="float", term=A.Func("abs", (first.known_term,)))
        if name in ("floor", "ceil", "trunc"):
            return self.unknown(node, "int", first.unit)
        return None

    def builtin(
        self, name: str, args: list[Value], node: ast.Call, state: State
    ) -> Value | None:
        if name == "len" and len(args) == 1:
            value = self.unknown(node, "int")
            state.assume(A.Binary(">=", value.known_term, ZERO))
            return value
        if not args:
            return None
        first = args[0]
        if name in ("min", "max") and len(args) == 1:  # of an iterable: its unit
            return self.unknown(node, "unknown", first.unit)
        if any(a.term is None for a in args):
            return None
        if name == "abs" and len(args) == 1:
            return replace(first, term=A.Func("abs", (first.known_term,)))
        if name in ("min", "max"):
            result = first
            for other in args[1:]:
                unit, literal = self.unit_of_sum(result, other, node, name)
                kind = self.numeric_kind(result, other, "+")
                if kind is None:
                    return None
                term = A.Func(name, (result.known_term, other.known_term))
                # the literal factors of the side that gave the unit (as for +)
                scale = result.scale if unit == result.unit else other.scale
                free = result.rad_free or other.rad_free
                result = Value(kind, term, unit, literal, scale=scale, rad_free=free)
            return result
        if (
            name == "float"
            and len(args) == 1
            and first.kind in ("int", "float", "bool")
        ):
            return replace(first, kind="float")
        if name == "float" and len(args) == 1 and isinstance(first.term, A.Str):
            return _float_of(first.term.value)
        if name in ("int", "round") and first.kind != "str":
            # `int(t * 1e9)` keeps its conversion: ns
            value = self.unknown(node, "int" if len(args) == 1 else "float", first.unit)
            return replace(value, scale=first.scale, rad_free=first.rad_free)
        if name == "bool" and len(args) == 1:
            return Value("bool", self.truthy(first, node))
        return None if name != "print" else NONE


def _float_of(text: str) -> Value | None:
    """`float('inf')`, `float('0.5')`: the number, exactly."""
    cleaned = text.strip().lower()
    sign = -1 if cleaned.startswith("-") else 1
    if cleaned.lstrip("+-") in ("inf", "infinity"):
        return Value("float", A.Num(sign * INFINITY, False), literal=True)
    try:
        return Value("float", A.Num(Fraction(cleaned), False), literal=True)
    except (ValueError, ZeroDivisionError):
        return None


def _root(unit: Unit) -> Unit | None:
    if any(exp % 2 for _, exp in unit.dims) or unit.offset:
        return None
    dims = tuple((d, e // 2) for d, e in unit.dims)
    return named(Unit(dims, math.sqrt(unit.factor)))
