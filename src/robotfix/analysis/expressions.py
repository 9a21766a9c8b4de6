"""Expressions -> abstract values (cf. mypy's checkexpr.py; statements are elsewhere).

Every expression yields a `Value`. What is not modelled yields an unknown value with a
fresh symbol named after its source text, so a refinement that depends on it is a
warning that names it, never an error.
"""

from __future__ import annotations

import ast
import math
from collections.abc import Callable
from fractions import Fraction
from functools import partial
from typing import TYPE_CHECKING, TypeVar, cast

from robotfix.analysis import (
    arith,
    containers,
    frames,
    heap,
    hover,
    imported,
)
from robotfix.analysis.collaborators import Collaborators
from robotfix.analysis.constants import is_constant
from robotfix.analysis.context import TERM_LIMIT, BudgetExceededError, FileContext
from robotfix.analysis.literals import float_term, int_value, str_value
from robotfix.analysis.program import Program
from robotfix.analysis.state import State
from robotfix.analysis.values import NONE, SEQUENCES, Items, Value, replace
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Refinement
from robotfix.annotations.units import Factors, Unit
from robotfix.diagnostics import Span

if TYPE_CHECKING:  # only `robotfix suggest` keeps flows: a check never loads them
    from robotfix.analysis.flows import FlowLog, Where

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


# evaluator class -> node class -> its `eval_<node class>` function, or None: the
# dispatch of `ExpressionEvaluator.eval` without building a name and a bound method
_EVAL: dict[type, dict[type, Callable[..., Value] | None]] = {}
MAX_ROOT = 4  # `x ** 0.25` has a unit; `x ** 0.3` (3/10) is left without one
# terms with no subterms: never larger than TERM_LIMIT
_LEAF_TERMS = (A.Sym, A.Num, A.Bool, A.Str, A.Name)
# what a number's or a string's truth compares it with (terms are immutable)
_ZEROS = {False: A.Num(Fraction(0), False), True: A.Num(Fraction(0), True)}
_EMPTY = A.Str("")
_UNREAD = object()  # `self.x` not read nor stored on this path yet
_BOOLS = {False: Value("bool", A.Bool(False)), True: Value("bool", A.Bool(True))}
_NO_SITE = ast.Pass()  # the site before the first statement (never changed)
_ATTRIBUTE = ast.Attribute  # (`eval` tests every node: no module attribute read)


class ExpressionEvaluator:
    def __init__(
        self, ctx: FileContext, program: Program, parts: Collaborators | None = None
    ) -> None:
        self.ctx = ctx
        self.program = program
        if parts is None:
            parts = Collaborators(ctx, program)
        self.parts = parts
        self.check = parts.check
        self.fields = parts.fields
        self.refined = parts.refined
        self.lookups = parts.lookups
        self.params = parts.params
        self.site: ast.AST = _NO_SITE  # the statement being interpreted
        self.lists_seen = False  # whether a list was stored in a name or attribute
        # the symbol each attribute read last gave (`decisions.py`: two tests of
        # `scan.range_min` read one tracked value)
        self.attribute_terms: dict[int, int] = {}
        self._eval_table = _EVAL.setdefault(type(self), {})  # `eval`'s dispatch

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
        return cast("FlowLog | None", self.ctx.unit_flows)  # set by api.py alone

    def note_sink(
        self,
        expr: ast.expr,
        unit: Unit | None,
        value: Value | None,
        integer: bool = False,
    ) -> None:
        """For `robotfix suggest`: `expr`, holding `value`, reached `unit`'s place
        (an `int` one if `integer`)."""
        log = self.ctx.unit_flows  # (no call: it is hot)
        if log is not None:
            where = self.flow_where()
            if where is not None:
                cast("FlowLog", log).sink(where, expr, unit, value, integer=integer)

    # -- dispatch ------------------------------------------------------------
    def eval(self, node: ast.expr, state: State) -> Value:
        budget = self.ctx.budget  # `FileContext.step`, inline: a call per node
        used = budget.used + 1  # (its slot read once)
        budget.used = used
        if used > budget.limit:
            raise BudgetExceededError(getattr(node, "lineno", 1))
        kind = type(node)
        try:  # (a subscript: cheaper than a `get` call; found all but once a class)
            method = self._eval_table[kind]
        except KeyError:  # the evaluator's class's method for this node class
            method = self._eval_table[kind] = getattr(
                type(self), f"eval_{kind.__name__}", None
            )
        if method is None:
            self.eval_children(node, state)
            return self.unknown(node)
        result: Value = method(self, node, state)
        term = result.term
        if kind is _ATTRIBUTE and type(term) is A.Sym:
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
        kind = type(value)  # (a literal's value is never of a subclass)
        if kind is str:
            return str_value(value)
        if kind is int:
            found = int_value(value)
            if found is None:
                return replace(self.unknown(node, "int"), literal=True)
            return found
        if value is None:
            return NONE
        if isinstance(value, bool):
            return _BOOLS[value]
        if isinstance(value, float) and math.isfinite(value):
            term = float_term(self.ctx.source.segment(node) or "", value)
            if term is None:
                return replace(self.unknown(node, "float"), literal=True)
            return Value("float", term, literal=True)
        return self.unknown(node)

    def eval_Name(self, node: ast.Name, state: State) -> Value:
        value = self.lookup_name(node.id, state, node)
        if self.ctx.hovers is not None:  # the editor asks: one closure per name read
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

    def eval_Attribute(
        self, node: ast.Attribute, state: State, base: Value | None = None
    ) -> Value:
        """`base.attr`; `base`, the value of `node.value`, when already known. The
        most frequent bases first, as `member` answers them, without its calls.
        (Its fields read once: see `CallEvaluator.eval_Call`.)"""
        owner, attr = node.value, node.attr
        if base is None:
            base = self.eval(owner, state)
        kind = base.kind
        if kind == "unknown":  # (it has no member)
            if type(base.term) is A.Sym:
                # `args.verbose` twice is one value, until something may change args
                version = state.version(base.term)
                key = ("attribute", base.term.ident, attr, version)
                return self.ctx.derived(key, "unknown", node)
            return self.unknown(node)
        if kind == "module":  # `math.pi`, `rospy.loginfo` (always a value)
            return self.lookups.module_attribute(base.name, attr)
        if kind in ("parameter", "parameter_value"):
            return self.params.parameter_attribute(base, node, state)
        if kind == "msg" and base.ref in state.heap:
            constant = self.member(base, attr, state)
            if constant is not None:  # `msg.ULTRASOUND`
                return constant
            text = self.ctx.source.segment(node) or attr
            ref = base.ref
            if self.ctx.hovers is not None:  # the editor asks: else no closure
                self.note_hover(node, partial(hover.field, self.ctx, state, ref, attr))
            value = self.fields.read_field(state, ref, attr, self.site, text)
            return frames.framed_read(state, ref, attr, value)
        if kind in ("instance", "goal_handle") and type(owner) is ast.Name:
            var = owner.id
            value = self.instance_attribute(base, var, attr, node, state)
            if self.ctx.hovers is not None:
                describe = self.lookups.describe_attribute  # (no closure: no cells)
                self.note_hover(node, partial(describe, base, var, attr, value, state))
            return value
        found = self.member(base, attr, state)
        if found is not None:
            return found
        if kind == "instance":  # `self.chassis.left`: the attribute's type
            typed = self.program.types.attribute(base.name, attr)
            if typed is not None:
                return self.lookups.typed(typed, node, state)
        return self.unknown(node)

    def member(self, base: Value, attr: str, state: State) -> Value | None:
        """`base.attr` when `base` is a module, an interface or message class, a
        message (its constants), or a class or instance (its class constants)."""
        if base.kind == "module":
            return self.lookups.module_attribute(base.name, attr)
        if base.kind == "msgclass":
            return self.lookups.message_constant(base.name, attr)
        if base.kind == "msg" and base.ref in state.heap:
            return self.lookups.message_constant(state.heap[base.ref].type, attr)
        if base.kind == "interface":
            found = self.ctx.msg_type_named(f"{base.name.replace('/', '.msg.')}_{attr}")
            return Value("msgclass", name=found) if found else None
        if base.kind in ("class", "instance"):
            return self.lookups.class_constant(base.name, attr) or self.lookups.method(
                base, attr
            )
        return None

    def instance_attribute(
        self, base: Value, var: str, attr: str, node: ast.Attribute, state: State
    ) -> Value:
        """`self.x` (`var`, `attr`: the fields of `node`, handed on as read, see
        `eval_Attribute`): the value last stored in this path, else what its
        refinement says (or, for a goal handle, the goal that arrived)."""
        key = f"{var}.{attr}"
        bound = state.env.get(key, _UNREAD)
        if isinstance(bound, Value):
            return state.use(bound) if state.shared.defs else bound
        instance = base.kind == "instance"
        if bound is _UNREAD and instance:
            inherited = self.inherited_method(base.name, attr)
            if inherited is not None:
                return inherited
        method = self.lookups.method(base, attr) if instance else None
        if method is not None:
            return method
        if instance and "." in base.name:  # another module's constant
            found = imported.resolve(self.ctx.resolver, f"{base.name}.{attr}")
            if isinstance(found, Value):
                return found
        constant = self.lookups.class_constant(base.name, attr)
        if instance and constant is not None:
            return constant
        if base.kind == "goal_handle" and attr == "request":
            value = heap.new_message(
                self.ctx, state, f"{base.name}_Goal", "received", label=key
            )
        else:
            decl = self.program.attributes.get(base.name, {}).get(attr)
            typed = (
                self.program.types.attribute(base.name, attr)
                if instance and decl is None
                else None
            )
            if decl is not None:
                lookup = self.refinement_lookup(decl, state)
                value = self.refined.assumed(state, key, decl, lookup)
            elif typed is not None:
                # a message or object kept on self: a message's fields are unknown
                # but refined, as any attribute is in a method that did not set it
                value = self.lookups.typed(typed, node, state, key)
            else:
                remembered = frames.recall(self.ctx, base.name, attr)
                value = remembered or self.unknown(node)
                if remembered is None and isinstance(value.term, A.Sym):
                    self.ctx.first_read(("attribute", key), value.term)
            self.lists_seen = self.lists_seen or value.kind == "list"
        state.env[key] = value
        return value

    def inherited_method(self, class_name: str, attr: str) -> Value | None:
        """`self.create_timer` where the class derives it from a library's class
        (the call evaluator knows the stubs)."""
        return None

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
            self.lookups.class_constant(class_name, name)
            if class_name and "." not in name
            else None
        )
        if in_class is None:
            return found
        return in_class if found is None or found.term == in_class.term else None

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
                v.unit is not None and not v.literal and arith.has_length(v.unit)
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
            and "generator" not in (left.kind, right.kind)
        ):
            found = containers.concatenated(left, right)
        elif isinstance(node.op, ast.Mult) and not both:
            sequence, times = (left, right) if left.kind in SEQUENCES else (right, left)
            if sequence.kind != "generator":
                found = containers.repeated(sequence, times)
        return found if found is not None else self.unknown(node)

    def _other_binop(self, node: ast.BinOp, left: Value, right: Value) -> Value:
        exponent = arith.literal(right.term) if right.literal else None
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
        operands = [self.eval(node.left, state)]
        for comparator in node.comparators:  # (a loop: no comprehension's frame)
            operands.append(self.eval(comparator, state))
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
            if name in ("==", "!=") and arith.sorts_differ(left, right):
                # `command == "slow"` of an unknown: the solver cannot compare
                # them, but the same test of the same values is the same
                key = ("==", left.term, right.term)
                same = self.ctx.derived_term(key, "bool", node)
                parts.append(same if name == "==" else A.Unary("not", same))
                continue
            parts.append(A.Binary(name, left.term, right.term))
        # (one comparison, most often: it is its own conjunction)
        return Value("bool", parts[0] if len(parts) == 1 else A.conjoin(parts))

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
            return self.ctx.derived_term(("is None", left.ref), "bool", "`is None`")
        if isinstance(left.term, A.Sym):
            key = ("is None", left.term.ident)
            return self.ctx.derived_term(key, "bool", "`is None`")
        if left.kind == "instance" and left.ref is not None:  # a typed object
            return self.ctx.derived_term(("is None", left.ref), "bool", "`is None`")
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
        kind = max(
            kinds,
            key=lambda k: arith.KIND_ORDER.index(k) if k in arith.KIND_ORDER else -1,
        )
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
            found = self.lookups.look_up(base, key, node, state)
            if found is not None:  # a list inside a table is shared with it
                return containers.stripped(found)
        if base.kind == "dict" and base.items is not None and base.items.of:
            return self.lookups.typed(base.items.of, node, state)  # `dict[str, Driver]`
        if base.kind in SEQUENCES and key.kind in ("int", "bool", "unknown"):
            if isinstance(node.slice, ast.Slice):
                return containers.sliced(base, containers.slice_length(node.slice))
            return self.lookups.element(base, node, state)
        return self.unknown(node, unit=base.unit if not base.literal else None)

    def eval_Tuple(self, node: ast.Tuple | ast.List, state: State) -> Value:
        values, modelled, elts = [], True, node.elts
        for element in elts:
            value = self.eval(element, state)
            values.append(value)
            if type(element) is ast.Starred or (
                value.term is None and value.elements is None and value.kind != "msg"
            ):  # a message is kept by its reference (`cmds = [Twist(), Twist()]`)
                modelled = False
        if not modelled:
            if type(node) is ast.List:  # still a list, of elements not followed
                return Value("list", items=Items())
            return self.unknown(node)
        kind = "tuple" if type(node) is ast.Tuple else "list"
        elements = tuple(values)
        unit = containers.common_unit(elements)
        scales = {v.factors for v in elements if not v.literal and v.unit == unit}
        return Value(
            kind,
            unit=unit,
            elements=elements,
            items=Items(sites=tuple(elts)),
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
        if type(fact) is A.Bool and fact == A.TRUE:  # (as `State.assume` asks)
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
            return A.Binary("!=", value.term, _ZEROS[value.kind == "int"])
        if value.term is not None and value.kind == "str":
            return A.Binary("!=", value.term, _EMPTY)
        if value.kind == "none":
            return A.Bool(False)
        length = containers.length_term(value) if value.kind in SEQUENCES else None
        if (
            length is not None and value.kind != "generator"
        ):  # a list is true if not empty
            return A.Binary(">", length, _ZEROS[True])
        if value.kind == "tuple" and value.elements is not None:
            return A.Bool(len(value.elements) > 0)
        term = value.term
        if type(term) is A.Sym:
            version = state.version(term) if state else 0
            size = self.ctx.sizes.get(term.ident) if not version else None
            if size is not None:  # a display: `[]` is false
                return A.Bool(size > 0)
            key = ("truthy", term.ident, version)
            return self.ctx.derived_term(key, "bool", node)
        if value.kind == "module":  # `if TYPE_CHECKING:`, `if sys.flags.debug:`
            if value.name.endswith("TYPE_CHECKING"):
                return A.Bool(False)
            return self.ctx.derived_term(("truthy", value.name), "bool", node)
        return self.unknown(node, "bool").term  # type: ignore[return-value]
