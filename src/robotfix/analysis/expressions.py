"""Expressions -> abstract values (cf. mypy's checkexpr.py; statements are elsewhere).

Every expression yields a `Value`. What is not modelled yields an unknown value with a
fresh symbol named after its source text, so a refinement that depends on it is a
warning that names it, never an error.
"""

from __future__ import annotations

import ast
import math
import re
from collections.abc import Callable
from dataclasses import replace
from fractions import Fraction
from functools import partial
from typing import TypeVar

from robotfix import messages
from robotfix.analysis import heap
from robotfix.analysis.checks import Checker
from robotfix.analysis.context import TERM_LIMIT, FileContext
from robotfix.analysis.program import Program
from robotfix.analysis.state import State
from robotfix.analysis.values import NONE, Value
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Refinement
from robotfix.annotations.units import DIMENSIONLESS, Unit

T = TypeVar("T")
ARITH = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/"}
COMPARE = {
    ast.Eq: "==",
    ast.NotEq: "!=",
    ast.Lt: "<",
    ast.LtE: "<=",
    ast.Gt: ">",
    ast.GtE: ">=",
}
_DECIMAL = re.compile(r"[0-9_]*\.?[0-9_]*([eE][+-]?[0-9_]+)?")
MATH_CONSTANTS = {"pi": math.pi, "e": math.e, "tau": math.tau}
KIND_ORDER = ("bool", "int", "float")
LEAVES = (A.Sym, A.Str, A.Bool, A.Num)
# Values that are never None.
STATIC_VALUES = frozenset(
    {
        "module",
        "msgclass",
        "interface",
        "function",
        "class",
        "method",
        "builtin",
        "instance",
        "goal_handle",
    }
)


class ExpressionEvaluator:
    def __init__(self, ctx: FileContext, program: Program) -> None:
        self.ctx = ctx
        self.program = program
        self.check = Checker(ctx)
        self.site: ast.AST = ast.Pass()  # the statement being interpreted

    # -- to be provided by the statement interpreter --------------------------
    def lookup_name(self, name: str, state: State, node: ast.AST) -> Value:
        raise NotImplementedError

    def bind(self, target: ast.expr, value: Value, state: State) -> None:
        raise NotImplementedError

    # -- dispatch ------------------------------------------------------------
    def eval(self, node: ast.expr, state: State) -> Value:
        self.ctx.step(node)
        method = getattr(self, f"eval_{type(node).__name__}", None)
        if method is None:
            self.eval_children(node, state)
            return self.unknown(node)
        result: Value = method(node, state)
        if result.term is not None and A.larger_than(result.term, TERM_LIMIT):
            # e.g. `x = x + x` in a row: the term's tree doubles each time
            return replace(
                self.unknown(node, result.kind, result.unit), scale=result.scale
            )
        return result

    def eval_children(self, node: ast.AST, state: State) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.expr):
                self.eval(child, state)

    def unknown(
        self, node: ast.AST, kind: str = "unknown", unit: Unit | None = None
    ) -> Value:
        return self.ctx.fresh(kind, node, unit)

    # -- leaves --------------------------------------------------------------
    def eval_Constant(self, node: ast.Constant, state: State) -> Value:
        value = node.value
        if isinstance(value, bool):
            return Value("bool", A.Bool(value))
        if isinstance(value, int):
            return Value("int", A.Num(Fraction(value), True), literal=True)
        if isinstance(value, float) and math.isfinite(value):
            return Value("float", A.Num(self._exact(node, value), False), literal=True)
        if isinstance(value, str):
            return Value("str", A.Str(value))
        if value is None:
            return NONE
        return self.unknown(node)

    def _exact(self, node: ast.Constant, value: float) -> Fraction:
        """Reals are exact: `3.141592653589793238` is read from the source text."""
        text = self.ctx.source.segment(node) or ""
        if text and _DECIMAL.fullmatch(text):
            try:
                return Fraction(text.replace("_", ""))
            except (ValueError, ZeroDivisionError):
                pass
        return Fraction(value)

    def eval_Name(self, node: ast.Name, state: State) -> Value:
        value = self.lookup_name(node.id, state, node)
        if self.ctx.hovers is not None:
            self.ctx.hovers.append(
                (self.ctx.source.span(node), self.describe_name(node.id, value))
            )
        return value

    def describe_name(self, name: str, value: Value) -> str:
        """Hover text for a variable: its type, unit and refinement."""
        decl = self.decl_of(name)
        kind = value.name if value.kind == "msg" else value.kind
        if decl is not None and decl.base != "other":
            kind = (decl.msg_type or "message") if decl.base == "msg" else decl.base
        parts = [f"**{name}**: `{kind}`"]
        unit = decl.unit if decl is not None and decl.unit is not None else value.unit
        if unit is not None:
            parts.append(f"in `{unit}`")
        if decl is not None and decl.predicate != A.TRUE:
            parts.append(f"— refinement `{A.show(decl.predicate)}` (line {decl.line})")
        return " ".join(parts)

    def decl_of(self, name: str) -> Refinement | None:
        return None

    def eval_Attribute(self, node: ast.Attribute, state: State) -> Value:
        base = self.eval(node.value, state)
        if base.kind == "msg" and base.ref in state.heap:
            text = self.ctx.source.segment(node) or node.attr
            if self.ctx.hovers is not None:
                self.ctx.hovers.append(
                    (
                        self.ctx.source.span(node),
                        self.describe_field(state, base.ref, node.attr),
                    )
                )
            return self.check.read_field(state, base.ref, node.attr, self.site, text)
        if base.kind == "module":
            return self._module_attribute(base.name, node)
        if base.kind == "msgclass":
            return self._constant(base.name, node)
        if base.kind == "interface":
            found = self.ctx.msg_type_named(
                f"{base.name.replace('/', '.msg.')}_{node.attr}"
            )
            return Value("msgclass", name=found) if found else self.unknown(node)
        if base.kind in ("instance", "goal_handle") and isinstance(
            node.value, ast.Name
        ):
            return self.instance_attribute(base, node.value.id, node, state)
        if base.kind == "unknown" and isinstance(base.term, A.Sym):
            # `args.verbose` twice is one value, until something may change args
            version = state.version(base.term)
            key = ("attribute", base.term.ident, node.attr, version)
            return self.ctx.derived(key, "unknown", node)
        return self.unknown(node)

    def describe_field(self, state: State, ref: int, name: str) -> str:
        """Hover text for a message field: type, unit and refinements."""
        msg_type = state.heap[ref].type
        spec = heap.field_spec(self.ctx, state, ref, name)
        if spec is None:
            return f"`{name}`: not a field of `{msg_type}`"
        outer = heap.contexts(self.ctx, state, ref, name)
        owner, path = (outer[0][0].name, outer[0][1]) if outer else (msg_type, name)
        kind = spec.msg_type if spec.kind == "msg" else spec.kind
        parts = [f"**{path}** of `{owner}`: `{kind}{'[]' if spec.array else ''}`"]
        unit = heap.field_unit(self.ctx, state, ref, name)[0]
        if unit is not None:
            parts.append(f"in `{unit}`")
        rules = [
            inv.text for _, _, inv in heap.invariants_on(self.ctx, state, ref, name)
        ]
        if rules:
            parts.append("— refinements: " + ", ".join(f"`{r}`" for r in rules))
        return " ".join(parts)

    def _module_attribute(self, module: str, node: ast.Attribute) -> Value:
        qualified = f"{module}.{node.attr}"
        if module == "math" and node.attr in MATH_CONSTANTS:
            exact = Fraction(MATH_CONSTANTS[node.attr])
            return Value("float", A.Num(exact, False), literal=True)
        msg_type = self.ctx.msg_type_named(qualified)
        if msg_type is not None:
            return Value("msgclass", name=msg_type)
        interface = self.ctx.interface_named(qualified)
        if interface is not None:
            return Value("interface", name=interface)
        return Value("module", name=qualified)

    def instance_attribute(
        self, base: Value, var: str, node: ast.Attribute, state: State
    ) -> Value:
        """`self.x`: the value last stored in this path, else what its refinement says
        (or, for a goal handle, the goal that arrived)."""
        key = f"{var}.{node.attr}"
        bound = state.env.get(key)
        if isinstance(bound, Value):
            return state.use(bound)
        method = f"{base.name}.{node.attr}"
        if base.kind == "instance" and method in self.program.functions:
            return Value("method", name=method)
        if base.kind == "goal_handle" and node.attr == "request":
            value = heap.new_message(
                self.ctx, state, f"{base.name}_Goal", "received", label=key
            )
        else:
            decl = self.program.attributes.get(base.name, {}).get(node.attr)
            msg_type = (
                self.program.message_attribute(base.name, node.attr)
                if base.kind == "instance" and decl is None
                else None
            )
            if decl is not None:
                lookup = self.refinement_lookup(decl, state)
                value = self.check.assumed(state, key, decl, lookup)
            elif msg_type is not None:
                # a message kept on self: its fields are unknown but refined, as
                # any attribute is in a method that did not set it
                value = heap.new_message(
                    self.ctx, state, msg_type, "received", label=key
                )
            else:
                value = self.unknown(node)
        state.env[key] = value
        return value

    def refinement_lookup(self, decl: Refinement, state: State) -> dict[str, A.Expr]:
        """Terms for the other variables a refinement names (`y == x`)."""
        found: dict[str, A.Expr] = {}
        for ref_name in A.names(decl.predicate):
            name = ref_name.name
            if name == "_" or name in found:
                continue
            bound = state.env.get(name)
            if isinstance(bound, Value) and bound.term is not None:
                found[name] = state.use(bound).known_term
            else:
                found[name] = self.ctx.fresh("unknown", f"`{name}`").term  # type: ignore[assignment]
        return found

    def _constant(self, msg_type: str, node: ast.Attribute) -> Value:
        spec = self.ctx.catalog.lookup(msg_type)
        if spec is None or node.attr not in spec.constants:
            return self.unknown(node)
        type_, value = spec.constants[node.attr]
        if isinstance(value, bool):
            return Value("bool", A.Bool(value))
        if isinstance(value, (int, float)):
            kind = "float" if type_ in ("float32", "float64") else "int"
            return Value(kind, A.Num(Fraction(value), kind == "int"), literal=True)
        if isinstance(value, str):
            return Value("str", A.Str(value))
        return self.unknown(node)

    # -- arithmetic ----------------------------------------------------------
    def eval_UnaryOp(self, node: ast.UnaryOp, state: State) -> Value:
        operand = self.eval(node.operand, state)
        if isinstance(node.op, ast.Not):
            truth = self.truthy(operand, node.operand, state)
            return Value("bool", A.Unary("not", truth))
        if (
            isinstance(node.op, (ast.USub, ast.UAdd))
            and operand.term is not None
            and operand.kind in ("int", "float", "bool", "unknown")
        ):
            if isinstance(node.op, ast.UAdd):
                return operand
            term = operand.term
            negated = (
                A.Num(-term.value, term.is_int)
                if isinstance(term, A.Num)
                else A.Unary("-", term)
            )
            kind = "int" if operand.kind == "bool" else operand.kind
            return replace(operand, kind=kind, term=negated)
        return self.unknown(node)

    def eval_BinOp(self, node: ast.BinOp, state: State) -> Value:
        left, right = self.eval(node.left, state), self.eval(node.right, state)
        uninit = left.uninit or right.uninit
        op = ARITH.get(type(node.op))
        if op is None:
            return replace(self._other_binop(node, left, right), uninit=uninit)
        scale = 1.0
        if op in "+-":
            unit, literal = self.unit_of_sum(left, right, node, op)
            scale = (
                left.scale if unit is not None and unit == left.unit else right.scale
            )
        else:
            unit, literal = self.unit_of_product(left, right, op)
            scale = self.scale_of_product(left, right, op)
        kind = self.numeric_kind(left, right, op)
        if kind is None or left.term is None or right.term is None:
            return replace(self.unknown(node, unit=unit), uninit=uninit, scale=scale)
        term = A.Binary(op, left.term, right.term)
        return Value(kind, term, unit, literal, uninit=uninit, scale=scale)

    def _other_binop(self, node: ast.BinOp, left: Value, right: Value) -> Value:
        if isinstance(node.op, ast.Mod):
            return self.unknown(node, unit=left.unit)
        if isinstance(node.op, ast.FloorDiv):
            return self.unknown(node, "int", self.unit_of_product(left, right, "/")[0])
        if (
            isinstance(node.op, ast.Pow)
            and isinstance(right.term, A.Num)
            and right.term.is_int
            and left.unit is not None
            and not left.literal
        ):
            return self.unknown(node, unit=left.unit.power(int(right.term.value)))
        return self.unknown(node)

    def scale_of_product(self, left: Value, right: Value, op: str) -> float:
        """Literal factors carried along (see `Value.scale`)."""
        if left.literal == right.literal:
            return (
                left.scale * (right.scale if op == "*" else 1 / right.scale)
                if not left.literal
                else 1.0
            )
        number = constant_value(right.term if right.literal else left.term)
        if number is None or number == 0:
            return 1.0
        if right.literal:
            return left.scale * (number if op == "*" else 1 / number)
        return right.scale * number if op == "*" else 1.0

    def numeric_kind(self, left: Value, right: Value, op: str) -> str | None:
        kinds = {left.kind, right.kind}
        if not kinds <= {"int", "float", "bool", "unknown"}:
            return None
        if "unknown" in kinds:
            return "unknown"
        if op == "/" or "float" in kinds:
            return "float"
        return "int"

    def unit_of_sum(
        self, left: Value, right: Value, node: ast.AST, op: str
    ) -> tuple[Unit | None, bool]:
        if left.literal and right.literal:
            return None, True
        if left.literal or right.literal:
            return (right.unit if left.literal else left.unit), False
        if left.unit is None or right.unit is None:
            return None, False
        if left.unit.same_as(right.unit):
            return left.unit, False
        if right.fits_unit(left.unit) or left.fits_unit(right.unit):
            same = left.unit.same_dimension(right.unit)
            return (
                left.unit if left.scale == 1.0 else right.unit
            ) if same else None, False
        text = self.ctx.source.segment(node) or op
        self.ctx.report(
            messages.operand_units(
                self.ctx.source.path,
                self.ctx.source.span(node),
                text,
                op,
                left.unit,
                right.unit,
            ),
            once=("operands", id(node)),
        )
        return None, False

    def unit_of_product(
        self, left: Value, right: Value, op: str
    ) -> tuple[Unit | None, bool]:
        if left.literal and right.literal:
            return None, True
        lu = DIMENSIONLESS if left.literal else left.unit
        ru = DIMENSIONLESS if right.literal else right.unit
        if lu is None or ru is None:
            return None, False
        if ru == DIMENSIONLESS:
            return lu, False
        if lu == DIMENSIONLESS and op == "*":
            return ru, False
        return (lu * ru if op == "*" else lu / ru), False

    def eval_Compare(self, node: ast.Compare, state: State) -> Value:
        operands = [self.eval(node.left, state)] + [
            self.eval(c, state) for c in node.comparators
        ]
        parts: list[A.Expr] = []
        for op, left, right in zip(node.ops, operands, operands[1:], strict=False):
            if isinstance(op, (ast.Is, ast.IsNot)):
                fact = self._is_none(left, right, state)
                if fact is None:
                    return self.unknown(node, "bool")
                parts.append(fact if isinstance(op, ast.Is) else A.Unary("not", fact))
                continue
            name = COMPARE.get(type(op))
            if (name is not None and name not in ("==", "!=")) or (
                left.is_number and right.is_number
            ):
                self.unit_of_sum(left, right, node, name or "==")
            if name is None or left.term is None or right.term is None:
                return self.unknown(node, "bool")
            if name in ("==", "!=") and _sorts_differ(left, right):
                # `command == "slow"` of an unknown: the solver cannot compare
                # them, but the same test of the same values is the same
                key = ("==", left.term, right.term)
                same = self.ctx.derived(key, "bool", node).known_term
                parts.append(same if name == "==" else A.Unary("not", same))
                continue
            parts.append(A.Binary(name, left.term, right.term))
        return Value("bool", A.conjoin(parts))

    def _is_none(self, left: Value, right: Value, state: State) -> A.Expr | None:
        """`x is None`: known for None and built messages, else the same unknown
        for the same value of x (so that two tests of it agree)."""
        if right.kind != "none":
            left, right = right, left
        if right.kind != "none":
            return None
        if left.kind == "none":
            return A.TRUE
        if left.kind == "msg" and left.ref is not None:
            obj = state.heap.get(left.ref)
            if obj is not None and obj.origin == "constructed":
                return A.Bool(False)
            return self.ctx.derived(("is None", left.ref), "bool", "`is None`").term
        if isinstance(left.term, A.Sym):
            key = ("is None", left.term.ident)
            return self.ctx.derived(key, "bool", "`is None`").term
        if left.kind in STATIC_VALUES:
            return A.Bool(False)
        return None

    def eval_BoolOp(self, node: ast.BoolOp, state: State) -> Value:
        values = [self.eval(node.values[0], state)]
        so_far: A.Expr = self.truthy(values[0], node.values[0], state)
        for operand in node.values[1:]:  # evaluated only where the others let it
            fact = self._goes_on(node, so_far)
            value = self.under(state, fact, partial(self.eval, operand, state))
            values.append(value)
            so_far = A.Binary(
                "and" if isinstance(node.op, ast.And) else "or",
                so_far,
                self.truthy(value, operand, state),
            )
        if any(v.kind != "bool" or v.term is None for v in values):
            return self.unknown(node)
        op = "and" if isinstance(node.op, ast.And) else "or"
        term = values[0].term
        for value in values[1:]:
            term = A.Binary(op, term, value.term)  # type: ignore[arg-type]
        return Value("bool", term)

    def eval_IfExp(self, node: ast.IfExp, state: State) -> Value:
        cond = self.condition(node.test, state)
        then = self.under(state, cond, partial(self.eval, node.body, state))
        orelse = self.under(
            state, A.Unary("not", cond), partial(self.eval, node.orelse, state)
        )
        kinds = {then.kind, orelse.kind}
        if (
            then.term is None
            or orelse.term is None
            or (len(kinds) > 1 and not kinds <= {"int", "float", "bool"})
        ):
            return self.unknown(node)
        kind = max(kinds, key=lambda k: KIND_ORDER.index(k) if k in KIND_ORDER else -1)
        unit: Unit | None = None
        if then.unit is not None and (orelse.literal or orelse.unit == then.unit):
            unit = then.unit
        elif orelse.unit is not None and then.literal:
            unit = orelse.unit
        return Value(
            kind,
            A.Ite(cond, then.term, orelse.term),
            unit,
            then.literal and orelse.literal,
        )

    def eval_List(self, node: ast.List | ast.Set | ast.Dict, state: State) -> Value:
        """A container display: unknown, but its length and truth are known."""
        self.eval_children(node, state)
        value = self.unknown(node)
        items = node.keys if isinstance(node, ast.Dict) else node.elts
        term = value.term
        if isinstance(term, A.Sym) and not any(
            i is None or isinstance(i, ast.Starred) for i in items
        ):
            self.ctx.sizes[term.ident] = len(items)
            state.shared.watched.add(term.ident)  # `xs = []; xs.append(1)` changes it
        return value

    eval_Set = eval_Dict = eval_List

    def eval_Subscript(self, node: ast.Subscript, state: State) -> Value:
        base = self.eval(node.value, state)
        self.eval(node.slice, state)
        return self.unknown(node, unit=base.unit if not base.literal else None)

    def eval_NamedExpr(self, node: ast.NamedExpr, state: State) -> Value:
        value = self.eval(node.value, state)
        self.bind(node.target, value, state)
        return value

    def eval_Lambda(self, node: ast.Lambda, state: State) -> Value:
        return self.unknown(node)

    eval_ListComp = eval_SetComp = eval_DictComp = eval_GeneratorExp = eval_Lambda

    # -- conditions ----------------------------------------------------------
    def condition(self, node: ast.expr, state: State) -> A.Expr:
        """The fact that holds when `node` is truthy (unknown parts: fresh booleans)."""
        if isinstance(node, ast.BoolOp):
            op = "and" if isinstance(node.op, ast.And) else "or"
            result = self.condition(node.values[0], state)
            for operand in node.values[1:]:  # `x and x.y`: y read only if x holds
                fact = self._goes_on(node, result)
                part = self.under(state, fact, partial(self.condition, operand, state))
                result = A.Binary(op, result, part)
            return result
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.Not):
            return A.Unary("not", self.condition(node.operand, state))
        return self.truthy(self.eval(node, state), node, state)

    @staticmethod
    def _goes_on(node: ast.BoolOp, so_far: A.Expr) -> A.Expr:
        """When `a and b` (`a or b`) evaluates b: a is true (false)."""
        return so_far if isinstance(node.op, ast.And) else A.Unary("not", so_far)

    def under(self, state: State, fact: A.Expr, evaluate: Callable[[], T]) -> T:
        """Evaluate on the path where `fact` holds (the right side of `and`, an arm
        of `a if c else b`); the fact is dropped afterwards."""
        if fact == A.TRUE:
            return evaluate()
        at = len(state.facts)
        state.facts.append(fact)
        try:
            return evaluate()
        finally:
            if len(state.facts) > at and state.facts[at] is fact:
                del state.facts[at]

    def truthy(self, value: Value, node: ast.AST, state: State | None = None) -> A.Expr:
        """The fact that `value` is true. An unknown object's truth is the same
        until something may change it (an empty list filled)."""
        if value.term is not None and value.kind == "bool":
            return value.term
        if value.term is not None and value.kind in ("int", "float"):
            return A.Binary("!=", value.term, A.Num(Fraction(0), value.kind == "int"))
        if value.term is not None and value.kind == "str":
            return A.Binary("!=", value.term, A.Str(""))
        if value.kind == "none":
            return A.Bool(False)
        term = value.term
        if type(term) is A.Sym:
            version = state.version(term) if state else 0
            size = self.ctx.sizes.get(term.ident) if not version else None
            if size is not None:  # a display: `[]` is false
                return A.Bool(size > 0)
            key = ("truthy", term.ident, version)
            return self.ctx.derived(key, "bool", node).known_term
        if value.kind == "module":  # `if TYPE_CHECKING:`, `if sys.flags.debug:`
            if value.name.endswith("TYPE_CHECKING"):
                return A.Bool(False)
            return self.ctx.derived(("truthy", value.name), "bool", node).known_term
        return self.unknown(node, "bool").term  # type: ignore[return-value]


def _sorts_differ(left: Value, right: Value) -> bool:
    """An unknown (a real in the solver) against a str or a bool, both leaves."""
    kinds = {left.kind, right.kind}
    return (
        "unknown" in kinds
        and bool(kinds & {"str", "bool"})
        and isinstance(left.term, LEAVES)
        and isinstance(right.term, LEAVES)
    )


def constant_value(term: A.Expr | None) -> float | None:
    """The value of a term built from number literals only."""
    if isinstance(term, A.Num):
        return float(term.value)
    if isinstance(term, A.Unary) and term.op == "-":
        inner = constant_value(term.operand)
        return None if inner is None else -inner
    if isinstance(term, A.Binary) and term.op in "+-*/":
        left, right = constant_value(term.left), constant_value(term.right)
        if left is None or right is None or (term.op == "/" and right == 0):
            return None
        return {"+": left + right, "-": left - right, "*": left * right}.get(
            term.op, left / right if right else 0.0
        )
    return None
