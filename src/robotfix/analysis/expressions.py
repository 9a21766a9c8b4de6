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
from fractions import Fraction
from functools import partial
from typing import TypeVar

from robotfix.analysis import (
    arith,
    containers,
    frames,
    heap,
    hover,
    imported,
    typeterms,
)
from robotfix.analysis.checks import Checker
from robotfix.analysis.constants import is_constant
from robotfix.analysis.context import TERM_LIMIT, FileContext
from robotfix.analysis.fieldchecks import FieldChecker
from robotfix.analysis.flows import FlowLog, Where
from robotfix.analysis.program import Program
from robotfix.analysis.refined import RefinedChecker
from robotfix.analysis.state import State
from robotfix.analysis.values import NONE, SEQUENCES, Items, Value, replace
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Refinement
from robotfix.annotations.numbers import NUMBERS, named_code, named_number
from robotfix.annotations.units import Factors, Unit
from robotfix.diagnostics import Span
from robotfix.ros.catalog import constant_term

T = TypeVar("T")
ARITH = {
    ast.Add: "+",
    ast.Sub: "-",
    ast.Mult: "*",
    ast.Div: "/",
    ast.FloorDiv: "//",  # floored, as `A.arith` and the encoder compute it
    ast.Mod: "%",
}
COMPARE = {
    ast.Eq: "==",
    ast.NotEq: "!=",
    ast.Lt: "<",
    ast.LtE: "<=",
    ast.Gt: ">",
    ast.GtE: ">=",
}
_DECIMAL = re.compile(r"[0-9_]*\.?[0-9_]*([eE][+-]?[0-9_]+)?")
# A literal this large (or this finely divided) is an unknown number of its kind:
# folded with others it would overflow floats, z3's input and the texts shown.
MAX_NUMBER: int = 10**100
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


# (evaluator class, node class) -> its `eval_<node class>` function, or None: the
# dispatch of `ExpressionEvaluator.eval` without building a name and a bound method
_EVAL: dict[tuple[type, type], Callable[..., Value] | None] = {}
_MISSING: Callable[..., Value] = lambda *_: NONE  # noqa: E731 - a marker only
MAX_ROOT = 4  # `x ** 0.25` has a unit; `x ** 0.3` (3/10) is left without one
# terms with no subterms: never larger than TERM_LIMIT
_LEAF_TERMS = (A.Sym, A.Num, A.Bool, A.Str, A.Name)


class ExpressionEvaluator:
    def __init__(self, ctx: FileContext, program: Program) -> None:
        self.ctx = ctx
        self.program = program
        # the checks that report diagnostics, as collaborators: the scalar checks,
        # those of messages, and those of values that reach a refined target
        self.check = Checker(ctx)
        self.fields = FieldChecker(self.check)
        self.refined = RefinedChecker(self.check, self.fields)
        self.site: ast.AST = ast.Pass()  # the statement being interpreted
        self.lists_seen = False  # whether a list was stored in a name or attribute
        # the symbol each attribute read last gave (`decisions.py`: two tests of
        # `scan.range_min` read one tracked value)
        self.attribute_terms: dict[int, int] = {}

    # -- to be provided by the statement interpreter --------------------------
    def lookup_name(self, name: str, state: State, node: ast.AST) -> Value:
        raise NotImplementedError

    def bind(self, target: ast.expr, value: Value, state: State) -> None:
        raise NotImplementedError

    def static_value(self, name: str) -> Value | None:
        """What a module-level name surely holds here (a module, class, constant)."""
        return None

    def refinement_term(self, name: str, state: State) -> A.Expr | None:
        """The term for a name a refinement mentions, if it is known here."""
        bound = state.env.get(name)
        return state.use(bound).term if isinstance(bound, Value) else None

    def global_term(self, name: str, state: State) -> A.Expr | None:
        """The term of a module name that no function rebinds, as read here."""
        return None

    def is_read_only_table(self, node: ast.expr) -> bool:
        """Whether `node` names a module dict or list that no code changes."""
        return False

    def flow_where(self) -> Where | None:
        """Where the code being interpreted is, for the flows `robotfix suggest`
        follows (provided by the statement interpreter)."""
        return None

    def flow_log(self) -> FlowLog | None:
        """The file's log of where units flow (`robotfix suggest`), if one is kept."""
        log = self.ctx.unit_flows
        return log if isinstance(log, FlowLog) else None

    def note_sink(
        self,
        expr: ast.expr,
        unit: Unit | None,
        value: Value | None,
        integer: bool = False,
    ) -> None:
        """For `robotfix suggest`: `expr`, holding `value`, reached `unit`'s place
        (an `int` one if `integer`)."""
        log, where = self.flow_log(), self.flow_where()
        if log is not None and where is not None:
            log.sink(where, expr, unit, value, integer=integer)

    # -- dispatch ------------------------------------------------------------
    def eval(self, node: ast.expr, state: State) -> Value:
        self.ctx.step(node)
        kind = type(node)
        key = (type(self), kind)
        method = _EVAL.get(key, _MISSING)
        if method is _MISSING:  # the evaluator's class's method for this node class
            method = _EVAL[key] = getattr(type(self), f"eval_{kind.__name__}", None)
        if method is None:
            self.eval_children(node, state)
            return self.unknown(node)
        result: Value = method(self, node, state)
        term = result.term
        if kind is ast.Attribute and type(term) is A.Sym:
            self.attribute_terms[id(node)] = term.ident
        if (
            term is not None
            and type(term) not in _LEAF_TERMS
            and A.larger_than(term, TERM_LIMIT)
        ):
            # e.g. `x = x + x` in a row: the term's tree doubles each time
            return replace(
                self.unknown(node, result.kind, result.unit), factors=result.factors
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
        if isinstance(value, int) or (
            isinstance(value, float) and math.isfinite(value)
        ):
            kind = "int" if isinstance(value, int) else "float"
            exact = Fraction(value) if kind == "int" else self._exact(node, value)
            if _too_large(exact):
                return replace(self.unknown(node, kind), literal=True)
            return Value(kind, A.Num(exact, kind == "int"), literal=True)
        if isinstance(value, str):
            return Value("str", A.Str(value))
        if value is None:
            return NONE
        return self.unknown(node)

    def _exact(self, node: ast.Constant, value: float) -> Fraction:
        """Reals are exact: `3.141592653589793238` is read from the source text."""
        text = self.ctx.source.segment(node) or ""
        match = _DECIMAL.fullmatch(text) if text else None
        # the exponent bounded: Fraction("1e-999999999") computes 10**999999999
        if match and len(match.group(1) or "") < 6:
            try:
                return Fraction(text.replace("_", ""))
            except (ValueError, ZeroDivisionError):
                pass
        return Fraction(value)

    def eval_Name(self, node: ast.Name, state: State) -> Value:
        value = self.lookup_name(node.id, state, node)
        self.note_hover(node, lambda: self.describe_name(node.id, value, state))
        return value

    def note_hover(self, node: ast.AST | Span, describe: Callable[[], str]) -> None:
        """Remember what the editor shows over `node` (only when it asks)."""
        if self.ctx.hovers is not None:
            span = node if isinstance(node, Span) else self.ctx.source.span(node)
            self.ctx.hovers.append((span, describe()))

    def describe_name(self, name: str, value: Value, state: State) -> str:
        """Hover text for a variable: its type, unit and refinement."""
        return hover.variable(self.ctx, state, name, value, self.decl_of(name))

    def decl_of(self, name: str) -> Refinement | None:
        return None

    def parameter_attribute(
        self, base: Value, node: ast.Attribute, state: State
    ) -> Value:
        """`.value` of a parameter handle (see `analysis/param_eval.py`)."""
        return self.unknown(node)

    def eval_Attribute(
        self, node: ast.Attribute, state: State, base: Value | None = None
    ) -> Value:
        """`base.attr`; `base`, the value of `node.value`, when already known."""
        if base is None:
            base = self.eval(node.value, state)
        if base.kind in ("parameter", "parameter_value"):
            return self.parameter_attribute(base, node, state)
        if base.kind == "msg" and base.ref in state.heap:
            constant = self.member(base, node.attr, state)
            if constant is not None:  # `msg.ULTRASOUND`
                return constant
            text = self.ctx.source.segment(node) or node.attr
            ref = base.ref
            self.note_hover(node, lambda: hover.field(self.ctx, state, ref, node.attr))
            value = self.fields.read_field(state, base.ref, node.attr, self.site, text)
            return frames.framed_read(state, base.ref, node.attr, value)
        if base.kind in ("instance", "goal_handle") and isinstance(
            node.value, ast.Name
        ):
            var = node.value.id
            value = self.instance_attribute(base, var, node, state)
            self.note_hover(
                node,
                lambda: self.describe_attribute(base, var, node.attr, value, state),
            )
            return value
        found = self.member(base, node.attr, state)
        if found is not None:
            return found
        if base.kind == "instance":  # `self.chassis.left`: the attribute's type
            typed = self.program.types.attribute(base.name, node.attr)
            if typed is not None:
                return self.typed(typed, node, state)
        if base.kind == "unknown" and isinstance(base.term, A.Sym):
            # `args.verbose` twice is one value, until something may change args
            version = state.version(base.term)
            key = ("attribute", base.term.ident, node.attr, version)
            return self.ctx.derived(key, "unknown", node)
        return self.unknown(node)

    def member(self, base: Value, attr: str, state: State) -> Value | None:
        """`base.attr` when `base` is a module, an interface or message class, a
        message (its constants), or a class or instance (its class constants)."""
        if base.kind == "module":
            return self._module_attribute(base.name, attr)
        if base.kind == "msgclass":
            return self._constant(base.name, attr)
        if base.kind == "msg" and base.ref in state.heap:
            return self._constant(state.heap[base.ref].type, attr)
        if base.kind == "interface":
            found = self.ctx.msg_type_named(f"{base.name.replace('/', '.msg.')}_{attr}")
            return Value("msgclass", name=found) if found else None
        if base.kind in ("class", "instance"):
            return self.class_constant(base.name, attr) or self._method(base, attr)
        return None

    def _method(self, base: Value, attr: str) -> Value | None:
        """A method, read from an instance (`self.turn`, `Path().turn`, also of
        another module's class) or from a class of this file (`Path.turn`: a
        staticmethod helper, called with every argument, or a classmethod, its
        `cls` given)."""
        key = f"{base.name}.{attr}"
        function = self.program.functions.get(key)
        if function is None:
            if base.kind == "instance" and "." in base.name:  # another module's class
                found = imported.resolve(self.ctx.resolver, key)
                if isinstance(found, imported.FunctionSummary):
                    return Value("method", name=key)
            return None
        if base.kind == "instance" or "classmethod" in function.decorators:
            return Value("method", name=key)  # the first parameter is given
        return Value("function", name=key)

    def class_constant(self, class_name: str, attr: str) -> Value | None:
        """A constant class attribute (`MAX_SPEED = 0.22` in the class body), also
        one inherited from a class of this file."""
        if attr not in self.ctx.constants.class_attrs:
            return None
        seen: set[str] = set()
        todo = [class_name]
        while todo:
            name = todo.pop(0)
            if name in seen:
                continue
            seen.add(name)
            found = self.ctx.constants.class_constant(name, attr)
            if found is not None:
                return found
            scope = self.program.classes.get(name)
            if scope is not None and isinstance(scope.node, ast.ClassDef):
                todo += [b.id for b in scope.node.bases if isinstance(b, ast.Name)]
        return None

    def describe_attribute(
        self, base: Value, var: str, attr: str, value: Value, state: State
    ) -> str:
        """Hover text for `self.x`: its value and the class's refinement of `x`."""
        decl = (
            self.program.attributes.get(base.name, {}).get(attr)
            if base.kind == "instance"
            else None
        )
        return hover.variable(self.ctx, state, f"{var}.{attr}", value, decl)

    def _module_attribute(self, module: str, attr: str) -> Value:
        qualified = f"{module}.{attr}"
        number = named_number(qualified) if attr in NUMBERS else None
        if number is not None:
            return Value("float", A.Num(number, False), literal=True)
        code = named_code(qualified)
        if code is not None:
            return Value("int", A.Num(Fraction(code), True), literal=True)
        msg_type = self.ctx.msg_type_named(qualified)
        if msg_type is not None:
            return Value("msgclass", name=msg_type)
        interface = self.ctx.interface_named(qualified)
        if interface is not None:
            return Value("interface", name=interface)
        constant = imported.constant(self.ctx.resolver, qualified)
        return constant or Value("module", name=qualified)

    def instance_attribute(
        self, base: Value, var: str, node: ast.Attribute, state: State
    ) -> Value:
        """`self.x`: the value last stored in this path, else what its refinement says
        (or, for a goal handle, the goal that arrived)."""
        key = f"{var}.{node.attr}"
        bound = state.env.get(key)
        if isinstance(bound, Value):
            return state.use(bound)
        method = self._method(base, node.attr) if base.kind == "instance" else None
        if method is not None:
            return method
        if base.kind == "instance" and "." in base.name:  # another module's constant
            found = imported.resolve(self.ctx.resolver, f"{base.name}.{node.attr}")
            if isinstance(found, Value):
                return found
        constant = self.class_constant(base.name, node.attr)
        if base.kind == "instance" and constant is not None:
            return constant
        if base.kind == "goal_handle" and node.attr == "request":
            value = heap.new_message(
                self.ctx, state, f"{base.name}_Goal", "received", label=key
            )
        else:
            decl = self.program.attributes.get(base.name, {}).get(node.attr)
            typed = (
                self.program.types.attribute(base.name, node.attr)
                if base.kind == "instance" and decl is None
                else None
            )
            if decl is not None:
                lookup = self.refinement_lookup(decl, state)
                value = self.refined.assumed(state, key, decl, lookup)
            elif typed is not None:
                # a message or object kept on self: a message's fields are unknown
                # but refined, as any attribute is in a method that did not set it
                value = self.typed(typed, node, state, key)
            else:
                remembered = frames.recall(self.ctx, base.name, node.attr)
                value = remembered or self.unknown(node)
                if remembered is None and isinstance(value.term, A.Sym):
                    self.ctx.first_read(("attribute", key), value.term)
            self.lists_seen = self.lists_seen or value.kind == "list"
        state.env[key] = value
        return value

    def typed(
        self,
        found: typeterms.Type | None,
        node: ast.AST,
        state: State,
        label: str | None = None,
    ) -> Value:
        """A value of the type the type model gives (`analysis/types.py`): a message
        with unknown but refined fields, an instance, a container of typed
        elements; an unknown value when no type is known."""
        if found is None:
            return self.unknown(node)
        if label is None:
            label = self.ctx.source.segment(node) or "the value"
        found = typeterms.plain(found)
        if isinstance(found, typeterms.Msg):
            if self.ctx.catalog.lookup(found.name) is None:
                return self.unknown(node)
            return heap.new_message(
                self.ctx, state, found.name, "received", label=label
            )
        if isinstance(found, typeterms.Obj):
            if "." in found.name:  # another module's class: its refined attributes
                known = imported.resolve(self.ctx.resolver, found.name)
                if isinstance(known, imported.ClassSummary):
                    self.program.attributes.setdefault(
                        found.name, dict(known.attributes)
                    )
            # an id of its own: whether it is None is not known (even a declared
            # `client: Client` may be given None), the same for each test of it
            return Value("instance", name=found.name, ref=self.ctx.fresh_id())
        if isinstance(found, typeterms.Lib):  # `self.last: Time`, a stub's result
            return Value("object", name=found.name)
        if isinstance(found, typeterms.Tup):
            parts = tuple(self.typed(t, node, state, label) for t in found.items)
            return Value("tuple", elements=parts)
        if isinstance(found, typeterms.Seq) and isinstance(found.item, typeterms.Msg):
            return Value("list", items=Items(message=(found.item.name, "received")))
        if isinstance(found, typeterms.Seq):
            return Value("list", items=Items(of=found.item))
        if isinstance(found, typeterms.Map):
            return Value("dict", items=Items(of=found.value))
        return self.unknown(node)

    def refinement_lookup(self, decl: Refinement, state: State) -> dict[str, A.Expr]:
        """Terms for the other names a refinement mentions (`y == x`, `MAX_SPEED`,
        `math.pi`); a name not known here is a fresh unknown."""
        found: dict[str, A.Expr] = {}
        mentioned = [n for p in decl.predicates() for n in A.names(p)]
        for ref_name in mentioned:
            name = ref_name.name
            if name == "_" or name in found:
                continue
            term = self.refinement_term(name, state)
            if term is None:
                term = self.ctx.fresh("unknown", f"`{name}`").known_term
            found[name] = term
        return found

    def constant_named(self, dotted: str, state: State) -> Value | None:
        """The value of `MAX_SPEED`, `math.pi`, `Range.ULTRASOUND`, `Node.LIMIT` where
        the name is a constant (not shadowed by a local: the caller checks)."""
        head, *rest = dotted.split(".")
        value = self.static_value(head)
        for attr in rest:
            if value is None:
                return None
            value = self.member(value, attr, state)
        return value if value is not None and is_constant(value) else None

    def scoped_constant(
        self, name: str, state: State, class_name: str | None
    ) -> Value | None:
        """`constant_named`, and a bare name of a constant of `class_name` (as a
        class-level annotation names one); None if the two disagree."""
        found = self.constant_named(name, state)
        in_class = (
            self.class_constant(class_name, name)
            if class_name and "." not in name
            else None
        )
        if in_class is None:
            return found
        return in_class if found is None or found.term == in_class.term else None

    def _constant(self, msg_type: str, attr: str) -> Value | None:
        spec = self.ctx.catalog.lookup(msg_type)
        if spec is None or attr not in spec.constants or attr in spec.fields:
            return None
        type_, value = spec.constants[attr]
        term = constant_term(type_, value)
        if isinstance(term, A.Num):
            return Value("int" if term.is_int else "float", term, literal=True)
        if isinstance(term, A.Bool):
            return Value("bool", term)
        return None if term is None else Value("str", term)

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
        if left.kind in SEQUENCES or right.kind in SEQUENCES:
            return self._sequence_binop(node, left, right)
        if left.kind == "object" or right.kind == "object":
            found = self.object_operation(node, left, right, state)
            if found is not None:
                return found
        uninit = left.uninit or right.uninit
        op = ARITH.get(type(node.op))
        if op is None:
            return replace(self._other_binop(node, left, right), uninit=uninit)
        factors: Factors = ()
        rad_free = left.rad_free or right.rad_free
        if op in "+-":
            unit, literal = self.check.unit_of_sum(left, right, node, op)
            factors = (
                left.factors
                if unit is not None and unit == left.unit
                else right.factors
            )
        elif op == "%":  # `a % b` is in a's unit: a - b * (a // b)
            unit, literal = left.unit, left.literal and right.literal
            factors, rad_free = left.factors, left.rad_free
        else:
            unit, literal = arith.unit_of_product(left, right, op)
            factors = arith.factors_of_product(left, right, op)
            rad_free = rad_free or any(
                v.unit is not None and not v.literal and _has_length(v.unit)
                for v in (left, right)
            )
        # `-math.degrees(x) / 2.`: a literal factor keeps the call that gave the unit
        scaled = right if left.literal else left
        done = (
            scaled.conversion
            if op in "*/" and left.literal != right.literal and unit == scaled.unit
            else None
        )
        kind = arith.numeric_kind(left, right, op)
        if kind is None or left.term is None or right.term is None:
            return replace(
                self.unknown(node, unit=unit),
                uninit=uninit,
                factors=factors,
                rad_free=rad_free,
                conversion=done,
            )
        term = A.Binary(op, left.term, right.term)
        return Value(
            kind,
            term,
            unit,
            literal,
            uninit=uninit,
            factors=factors,
            rad_free=rad_free,
            conversion=done,
        )

    def object_operation(
        self, node: ast.BinOp, left: Value, right: Value, state: State
    ) -> Value | None:
        """`a - b` of objects of library classes (`Time - Time` is a Duration): what
        the classes' stubs say (`library.py`); None when nothing is known."""
        return None

    def _sequence_binop(self, node: ast.BinOp, left: Value, right: Value) -> Value:
        """`xs + ys` and `[0.0] * n` of lists and tuples."""
        found: Value | None = None
        both = left.kind in SEQUENCES and right.kind in SEQUENCES
        if (
            isinstance(node.op, ast.Add)
            and both
            and "generator"
            not in (
                left.kind,
                right.kind,
            )
        ):
            found = containers.concatenated(left, right)
        elif isinstance(node.op, ast.Mult) and not both:
            sequence, times = (left, right) if left.kind in SEQUENCES else (right, left)
            if sequence.kind != "generator":
                found = containers.repeated(sequence, times)
        return found if found is not None else self.unknown(node)

    def _other_binop(self, node: ast.BinOp, left: Value, right: Value) -> Value:
        exponent = _literal(right.term) if right.literal else None
        if (
            isinstance(node.op, ast.Pow)
            and isinstance(exponent, Fraction)
            and exponent.denominator <= MAX_ROOT
            and left.unit is not None
            and not left.literal
        ):  # `d ** 2`, `d ** 0.5` (a square root: the unit's root)
            return self.unknown(node, unit=left.unit.raised(exponent))
        return self.unknown(node)

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
                self.check.unit_of_sum(left, right, node, name or "==")
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
        if left.kind == "instance" and left.ref is not None:  # a typed object
            return self.ctx.derived(("is None", left.ref), "bool", "`is None`").term
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
        term = A.Ite(cond, then.term, orelse.term)
        # the arms must agree as the sides of a sum do (`a_m if c else b_ft`: RF202);
        # a choice between frames (`p_map if use_map else p_odom`) is in neither
        if (
            then.unit is not None
            and orelse.unit is not None
            and frames.frame_of(then.unit) != frames.frame_of(orelse.unit)
        ):
            then = replace(then, unit=frames.unframed(then.unit))
            orelse = replace(orelse, unit=frames.unframed(orelse.unit))
        unit, literal = self.check.unit_of_sum(then, orelse, node, "if")
        factors = then.factors if unit is not None and unit == then.unit else ()
        if unit is not None and unit != then.unit:
            factors = orelse.factors
        return Value(kind, term, unit, literal, factors=factors)

    def sized(
        self,
        node: ast.List | ast.Set | ast.Dict,
        state: State,
        value: Value | None = None,
    ) -> Value:
        """A list, set or dict display (`value`, if its elements are modelled): its
        length and truth are known until something may change it."""
        sym = self.unknown(node)
        items = node.keys if isinstance(node, ast.Dict) else node.elts
        term = sym.term
        if not isinstance(term, A.Sym) or any(
            i is None or isinstance(i, ast.Starred) for i in items
        ):
            return value if value is not None else sym
        self.ctx.sizes[term.ident] = len(items)
        state.shared.watched.add(term.ident)  # `xs = []; xs.append(1)` changes it
        return sym if value is None else replace(value, term=term)

    def eval_Set(self, node: ast.Set, state: State) -> Value:
        self.eval_children(node, state)
        return self.sized(node, state)

    def eval_Subscript(self, node: ast.Subscript, state: State) -> Value:
        base = self.eval(node.value, state)
        key = self.eval(node.slice, state)
        if base.elements is not None and (
            base.kind in ("tuple", "list") or self.is_read_only_table(node.value)
        ):  # a list keeps its elements only while nothing else can change it
            found = self._look_up(base, key, node, state)
            if found is not None:  # a list inside a table is shared with it
                return containers.stripped(found)
        if base.kind == "dict" and base.items is not None and base.items.of:
            return self.typed(base.items.of, node, state)  # `dict[str, Driver]`
        if base.kind in SEQUENCES and key.kind in ("int", "bool", "unknown"):
            if isinstance(node.slice, ast.Slice):
                return containers.sliced(base, containers.slice_length(node.slice))
            return self.element(base, node, state)
        return self.unknown(node, unit=base.unit if not base.literal else None)

    def message_element(
        self, message: tuple[str, str], node: ast.AST, state: State
    ) -> Value:
        """An element of a message array field (`path.poses[i]`, `for p in
        msg.poses`): a message of the element type, received (its type's
        invariants hold) when the array arrived, else unknown-but-typed."""
        msg_type, origin = message
        label = self.ctx.source.segment(node) or "an element"
        return heap.new_message(
            self.ctx,
            state,
            msg_type,
            "received" if origin == "received" else "unknown",
            label=label,
        )

    def element(self, sequence: Value, node: ast.AST, state: State) -> Value:
        """One element of `sequence`: what holds of every element holds of it."""
        if sequence.keys is not None and sequence.name in ("zip", "enumerate"):
            parts = tuple(self.element(k, node, state) for k in sequence.keys)
            return Value("tuple", elements=parts)
        if sequence.elements and len(sequence.elements) <= containers.MAX_SPELLED:
            found = self._one_of(list(sequence.elements), node, state)
            if found is None:
                found = self._any_message(sequence.elements, node, state)
            if found is not None:
                return containers.stripped(found)
        if sequence.items is not None and sequence.items.message is not None:
            return self.message_element(sequence.items.message, node, state)
        if sequence.items is not None and sequence.items.of is not None:
            return self.typed(sequence.items.of, node, state)
        kind = containers.item_kind(sequence)
        if kind not in ("int", "float", "bool", "str"):
            kind = "unknown"
        value = replace(
            self.unknown(node, kind, sequence.unit), factors=sequence.factors
        )
        each = containers.each_of(sequence)
        if each != A.TRUE:
            state.assume(self.check.instantiate(each, value.known_term))
        return value

    def _any_message(
        self, options: tuple[Value, ...], node: ast.AST, state: State
    ) -> Value | None:
        """One of several messages of one type (`for cmd in [left, right]`): a
        message of that type with unknown fields. The code may change any of them
        through it, so what they held is forgotten."""
        names = {
            o.name if o.kind == "msg" and o.ref is not None else "" for o in options
        }
        if len(names) != 1 or "" in names:
            return None
        for option in options:
            heap.havoc(state, option.ref)  # type: ignore[arg-type]
        label = self.ctx.source.segment(node) or "an element"
        return heap.new_message(self.ctx, state, names.pop(), "unknown", label=label)

    def eval_Tuple(self, node: ast.Tuple | ast.List, state: State) -> Value:
        values = []
        modelled = True
        for element in node.elts:
            value = self.eval(element, state)
            values.append(value)
            if element.__class__ is ast.Starred or (
                value.term is None and value.elements is None and value.kind != "msg"
            ):  # a message is kept by its reference (`cmds = [Twist(), Twist()]`)
                modelled = False
        if not modelled:
            if node.__class__ is ast.List:  # still a list, of elements not followed
                return Value("list", items=Items())
            return self.unknown(node)
        kind = "tuple" if node.__class__ is ast.Tuple else "list"
        elements = tuple(values)
        unit = containers.common_unit(elements)
        scales = {v.factors for v in elements if not v.literal and v.unit == unit}
        return Value(
            kind,
            unit=unit,
            elements=elements,
            items=Items(sites=tuple(node.elts)),
            factors=scales.pop() if unit is not None and len(scales) == 1 else (),
        )

    eval_List = eval_Tuple

    def eval_Dict(self, node: ast.Dict, state: State) -> Value:
        keys = [self.eval(k, state) if k is not None else NONE for k in node.keys]
        values = [self.eval(v, state) for v in node.values]
        if any(k is None for k in node.keys) or any(
            v.term is None and v.elements is None for v in keys + values
        ):
            return self.sized(node, state)
        table = Value("dict", elements=tuple(values), keys=tuple(keys))
        return self.sized(node, state, table)

    def _look_up(
        self, table: Value, key: Value, node: ast.Subscript, state: State
    ) -> Value | None:
        """`table[key]`: the entry when the key is known, else one of the entries
        (a value bounded by them); None when it is not modelled (a slice)."""
        assert table.elements is not None
        wanted = _literal(key.term)
        if table.kind == "dict":
            keys = [_literal(k.term) for k in table.keys or ()]
            if None in keys:
                return None
            entries = dict(zip(keys, table.elements, strict=True))
            if wanted is not None:
                return entries.get(wanted)
            return self._one_of(list(entries.values()), node, state)
        if isinstance(node.slice, ast.Slice) or key.kind not in (
            "int",
            "bool",
            "unknown",
        ):
            return None
        if wanted is not None:
            index = int(wanted)
            inside = -len(table.elements) <= index < len(table.elements)
            return table.elements[index] if inside else None
        return self._one_of(list(table.elements), node, state)

    def _one_of(
        self, options: list[Value], node: ast.AST, state: State
    ) -> Value | None:
        """A value that is one of `options` (tuples element by element)."""
        if not options:
            return None
        if all(o == options[0] for o in options):
            return options[0]
        sizes = {len(o.elements) for o in options if o.elements is not None}
        if all(o.kind == "tuple" for o in options) and len(sizes) == 1:
            parts = [
                self._one_of([o.elements[i] for o in options], node, state)  # type: ignore[index]
                for i in range(sizes.pop())
            ]
            if any(p is None for p in parts):
                return None
            return Value("tuple", elements=tuple(parts))  # type: ignore[arg-type]
        kinds = {o.kind for o in options}
        if any(o.term is None for o in options) or not (
            kinds <= {"int", "float", "bool"} or kinds == {"str"}
        ):
            return None
        kind = max(kinds, key=KIND_ORDER.index) if kinds != {"str"} else "str"
        units = {o.unit for o in options if not o.literal}
        value = self.ctx.fresh(kind, node, units.pop() if len(units) == 1 else None)
        terms = list(dict.fromkeys(o.known_term for o in options))
        state.assume(A.disjoin([A.Binary("==", value.known_term, t) for t in terms]))
        return replace(value, literal=all(o.literal for o in options))

    def eval_NamedExpr(self, node: ast.NamedExpr, state: State) -> Value:
        value = self.eval(node.value, state)
        self.bind(node.target, value, state)
        return value

    def eval_Lambda(self, node: ast.Lambda, state: State) -> Value:
        # its body is analysed later as a function of its own, in this scope (names
        # of the enclosing function by their declarations, as for a nested `def`)
        pending = getattr(self, "pending", None)
        if pending is not None:
            pending.append((node, self.scope))  # type: ignore[attr-defined]
        return self.unknown(node)

    def eval_SetComp(self, node: ast.expr, state: State) -> Value:
        return self.unknown(node)

    eval_DictComp = eval_SetComp

    def eval_ListComp(self, node: ast.ListComp, state: State) -> Value:
        return self.comprehension(node, "list", state)

    def eval_GeneratorExp(self, node: ast.GeneratorExp, state: State) -> Value:
        return self.comprehension(node, "generator", state)

    def comprehension(
        self, node: ast.ListComp | ast.GeneratorExp, kind: str, state: State
    ) -> Value:
        """A list or generator of the values of a comprehension."""
        return Value(kind, items=Items())

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
        length = containers.length_term(value) if value.kind in SEQUENCES else None
        if (
            length is not None and value.kind != "generator"
        ):  # a list is true if not empty
            return A.Binary(">", length, A.Num(Fraction(0), True))
        if value.kind == "tuple" and value.elements is not None:
            return A.Bool(len(value.elements) > 0)
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


def _has_length(unit: Unit) -> bool:
    return dict(unit.dims).get("meter", 0) != 0


def _literal(term: A.Expr | None) -> Fraction | str | None:
    """A dict key or index as Python compares it (`1 == 1.0 == True`)."""
    if isinstance(term, A.Num):
        return term.value
    if isinstance(term, A.Bool):
        return Fraction(int(term.value))
    if isinstance(term, A.Str):
        return term.value
    if isinstance(term, A.Unary) and term.op == "-" and isinstance(term.operand, A.Num):
        return -term.operand.value
    return None


def _too_large(value: Fraction) -> bool:
    return abs(value.numerator) >= MAX_NUMBER or value.denominator >= MAX_NUMBER


def _sorts_differ(left: Value, right: Value) -> bool:
    """An unknown (a real in the solver) against a str or a bool, both leaves."""
    kinds = {left.kind, right.kind}
    return (
        "unknown" in kinds
        and bool(kinds & {"str", "bool"})
        and isinstance(left.term, LEAVES)
        and isinstance(right.term, LEAVES)
    )
