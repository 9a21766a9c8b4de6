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

from robotfix.analysis import heap
from robotfix.analysis.expressions import ExpressionEvaluator
from robotfix.analysis.program import Function, attribute_key
from robotfix.analysis.state import State
from robotfix.analysis.values import NONE, Value
from robotfix.annotations import ast as A
from robotfix.annotations.units import Unit, named, resolve
from robotfix.messages import Declared
from robotfix.ros.api_model import MATH_UNITS, UNIT_PARAMETERS

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
# Methods after which a container holds an element.
FILLING = frozenset({"append", "appendleft", "insert", "add"})
PI_BOUND = A.Num(Fraction(355, 113), False)  # > pi: a sound bound for angles
ONE = A.Num(Fraction(1), True)
ZERO = A.Num(Fraction(0), True)


class CallEvaluator(ExpressionEvaluator):
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
        name = (
            callee.name.rsplit(".", 1)[-1]
            if callee.kind == "module"
            else node.func.attr
            if isinstance(node.func, ast.Attribute)
            else ""
        )
        if name in UNIT_PARAMETERS:
            self._check_api_units(name, node, args, kwargs)
        return self.unknown(node)

    def _forget_after_call(
        self,
        node: ast.Call,
        args: list[Value],
        kwargs: dict[str | None, Value],
        state: State,
        callee: Value,
    ) -> None:
        """Unknown code may change the messages and instances it is handed."""
        if callee.kind in ("msgclass", "builtin") or (
            callee.kind == "module" and callee.name.startswith("math.")
        ):
            return
        for value in [*args, *kwargs.values()]:
            if value.kind == "msg" and value.ref is not None:
                heap.havoc(state, value.ref)
            elif value.kind == "unknown" and type(value.term) is A.Sym:
                state.changed(value)
        names = [a for a in node.args if isinstance(a, ast.Name)]
        if isinstance(node.func, ast.Attribute):
            owner = node.func.value
            if isinstance(owner, ast.Name):
                # a method of this file's class may change `self.x`; rclpy's and
                # rospy's own (`self.get_clock()`) do not touch its attributes
                receiver = state.env.get(owner.id)
                if (
                    callee.kind == "method"
                    or not isinstance(receiver, Value)
                    or receiver.kind != "instance"
                ):
                    names.append(owner)
            elif isinstance(owner, ast.Attribute):  # self.x.reset()
                state.env.pop(attribute_key(owner) or "", None)
        for name in names:
            bound = state.env.get(name.id)
            if isinstance(bound, Value) and bound.kind == "unknown":
                state.changed(bound)
                if (
                    isinstance(bound.term, A.Sym)
                    and getattr(node.func, "attr", "") in FILLING
                ):  # `xs.append(v)`: xs is not empty now
                    state.assume(self.truthy(bound, node, state))
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
                lookup = {**self._fresh_names(decl), **terms}
                self.check.assign_refined(
                    state, name, decl, value, self.site, lookup, leaving=True
                )
        if function.returns is None:
            return self.unknown(node)
        lookup = {**self._fresh_names(function.returns), **terms}
        return self.check.assumed(state, f"{function.name}()", function.returns, lookup)

    def _fresh_names(self, decl: object) -> dict[str, A.Expr]:
        predicate = getattr(decl, "predicate", A.TRUE)
        found: dict[str, A.Expr] = {}
        for name in A.names(predicate):
            if name.name != "_" and name.name not in found:
                value = self.ctx.fresh("unknown", f"`{name.name}`")
                found[name.name] = value.known_term
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
            # the same length for the same object until something may change it
            # (`if len(sys.argv) > 1:` twice agrees)
            of = args[0]
            key: tuple[object, ...] | None = None
            if isinstance(of.term, A.Sym):
                version = state.version(of.term)
                size = self.ctx.sizes.get(of.term.ident) if not version else None
                if size is not None:  # a display: `len([])` is 0
                    return Value("int", A.Num(Fraction(size), True))
                key = ("len", of.term.ident, version)
            elif of.kind == "module":
                key = ("len", of.name)
            value = (
                self.unknown(node, "int")
                if key is None
                else self.ctx.derived(key, "int", node)
            )
            state.assume(A.Binary(">=", value.known_term, ZERO))
            return value
        if not args:
            return None
        first = args[0]
        if name in ("isinstance", "hasattr") and len(node.args) == 2:
            # one answer for one object and one class (or attribute name)
            if not isinstance(first.term, A.Sym):
                return None
            version = state.version(first.term)
            second = self.ctx.source.segment(node.args[1])
            key = (name, first.term.ident, second, version)
            return self.ctx.derived(key, "bool", node)
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
                result = Value(kind, term, unit, literal)
            return result
        if (
            name == "float"
            and len(args) == 1
            and first.kind in ("int", "float", "bool")
        ):
            return replace(first, kind="float")
        if name in ("int", "round") and len(args) == 1 and first.kind != "str":
            return self.unknown(node, "int", first.unit)
        if name == "bool" and len(args) == 1:
            return Value("bool", self.truthy(first, node, state))
        return None if name != "print" else NONE


def _root(unit: Unit) -> Unit | None:
    if any(exp % 2 for _, exp in unit.dims) or unit.offset:
        return None
    dims = tuple((d, e // 2) for d, e in unit.dims)
    return named(Unit(dims, math.sqrt(unit.factor)))
