"""What a value the evaluator reads, rather than computes, stands for: a value of
a type the type model gives (`typed`), a method, a class constant, a module's
attribute, a message constant, an element of a sequence or an entry of a table.
`Lookups` reads the file's context and program, never the state of the walk; the
expression evaluator holds one.
"""

from __future__ import annotations

import ast
from fractions import Fraction

from robotfix.analysis import (
    arith,
    containers,
    heap,
    hover,
    imported,
    typeterms,
)
from robotfix.analysis.checks import Checker
from robotfix.analysis.context import FileContext
from robotfix.analysis.program import Program
from robotfix.analysis.state import State
from robotfix.analysis.values import Items, Value, replace
from robotfix.annotations import ast as A
from robotfix.annotations.numbers import NUMBERS, named_code, named_number
from robotfix.annotations.units import Unit
from robotfix.ros.catalog import constant_term


class Lookups:
    def __init__(self, ctx: FileContext, program: Program, check: Checker) -> None:
        self.ctx = ctx
        self.program = program
        self.check = check

    def _unknown(
        self, node: ast.AST, kind: str = "unknown", unit: Unit | None = None
    ) -> Value:
        return self.ctx.fresh(kind, node, unit)

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
            return self._unknown(node)
        if label is None:
            label = self.ctx.source.segment(node) or "the value"
        found = typeterms.plain(found)
        if isinstance(found, typeterms.Msg):
            if self.ctx.catalog.lookup(found.name) is None:
                return self._unknown(node)
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
        if isinstance(found, typeterms.Tup):  # (a loop: a generator makes cells)
            parts = []
            for item in found.items:
                parts.append(self.typed(item, node, state, label))
            return Value("tuple", elements=tuple(parts))
        if isinstance(found, typeterms.Seq) and isinstance(found.item, typeterms.Msg):
            return Value("list", items=Items(message=(found.item.name, "received")))
        if isinstance(found, typeterms.Seq):
            return Value("list", items=Items(of=found.item))
        if isinstance(found, typeterms.Map):
            return Value("dict", items=Items(of=found.value))
        return self._unknown(node)

    def method(self, base: Value, attr: str) -> Value | None:
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

    def module_attribute(self, module: str, attr: str) -> Value:
        """`math.pi`, `std_msgs.msg.String`, an imported constant, else a module
        (a module's function): once per name and file (`Program.module_attributes`;
        nothing here depends on the path walked)."""
        qualified = f"{module}.{attr}"
        known = self.program.module_attributes
        found = known.get(qualified)
        if found is None:
            found = known[qualified] = self._module_attribute(qualified, attr)
        return found

    def _module_attribute(self, qualified: str, attr: str) -> Value:
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

    def message_constant(self, msg_type: str, attr: str) -> Value | None:
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
            found = self.one_of(list(sequence.elements), node, state)
            if found is None:
                found = self.any_message(sequence.elements, node, state)
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
            self._unknown(node, kind, sequence.unit), factors=sequence.factors
        )
        each = containers.each_of(sequence)
        if each != A.TRUE:
            state.assume(self.check.instantiate(each, value.known_term))
        return value

    def any_message(
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

    def look_up(
        self, table: Value, key: Value, node: ast.Subscript, state: State
    ) -> Value | None:
        """`table[key]`: the entry when the key is known, else one of the entries
        (a value bounded by them); None when it is not modelled (a slice)."""
        assert table.elements is not None
        wanted = arith.literal(key.term)
        if table.kind == "dict":
            keys = [arith.literal(k.term) for k in table.keys or ()]
            if None in keys:
                return None
            entries = dict(zip(keys, table.elements, strict=True))
            if wanted is not None:
                return entries.get(wanted)
            return self.one_of(list(entries.values()), node, state)
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
        return self.one_of(list(table.elements), node, state)

    def one_of(self, options: list[Value], node: ast.AST, state: State) -> Value | None:
        """A value that is one of `options` (tuples element by element)."""
        if not options:
            return None
        if all(o == options[0] for o in options):
            return options[0]
        sizes = {len(o.elements) for o in options if o.elements is not None}
        if all(o.kind == "tuple" for o in options) and len(sizes) == 1:
            parts = [
                self.one_of([o.elements[i] for o in options], node, state)  # type: ignore[index]
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
        kind = max(kinds, key=arith.KIND_ORDER.index) if kinds != {"str"} else "str"
        units = {o.unit for o in options if not o.literal}
        value = self.ctx.fresh(kind, node, units.pop() if len(units) == 1 else None)
        terms = list(dict.fromkeys(o.known_term for o in options))
        state.assume(A.disjoin([A.Binary("==", value.known_term, t) for t in terms]))
        return replace(value, literal=all(o.literal for o in options))
