"""Builtins and sequences, a layer of the evaluator below the calls (`calls.py`):
`len`, `min`/`max`, `abs`, `float`/`int`/`round`/`bool`, `isinstance`; builtins of
lists and tuples (`len`, `sum`, `min`/`max`, `zip`, `range`, `sorted`, ...), a
method's receiver, and the methods that change or read a list (`append`,
`extend`, `insert`, `pop`, `index`, ...), checked against the list's declaration.
A changed list goes back where it lives through `store` (the walker's `Binder`).
"""

from __future__ import annotations

import ast
from dataclasses import replace
from fractions import Fraction

from robotfix.analysis import arith, containers, heap
from robotfix.analysis.expressions import ExpressionEvaluator
from robotfix.analysis.state import State
from robotfix.analysis.values import (
    NONE,
    SEQUENCES,
    Items,
    Kept,
    Value,
)
from robotfix.annotations import ast as A
from robotfix.annotations.numbers import INFINITY

# Methods whose first argument leaves the node: it must satisfy its refinements.
ZERO = A.Num(Fraction(0), True)


class BuiltinEvaluator(ExpressionEvaluator):
    # -- builtins ------------------------------------------------------------
    def builtin(
        self,
        name: str,
        args: list[Value],
        node: ast.Call,
        state: State,
        kwargs: dict[str | None, Value] | None = None,
    ) -> Value | None:
        for given in node.args:  # (a loop: no generator's frame per call)
            if type(given) is ast.Starred:
                return None
        kwargs = kwargs or {}
        if (args and args[0].kind in SEQUENCES) or name in ("zip", "range"):
            found = self.sequence_builtin(name, args, kwargs, node, state)
            if found is not None:
                return found
        if name == "len" and len(args) == 1:
            # the same length for the same object until something may change it
            # (`if len(sys.argv) > 1:` twice agrees)
            of = args[0]
            if of.kind == "tuple" and of.elements is not None:
                return Value("int", A.Num(Fraction(len(of.elements)), True))
            if isinstance(of.term, A.Sym):
                version = state.version(of.term)
                size = self.ctx.sizes.get(of.term.ident) if not version else None
                if size is not None:  # a display: `len([])` is 0
                    return Value("int", A.Num(Fraction(size), True))
            shared = self.check.length_of(state, of, node)
            if shared is not None:
                return Value("int", shared)
            if of.kind != "module":
                value = self.unknown(node, "int")
            else:
                value = self.ctx.derived(("len", of.name), "int", node)
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
                unit, literal = self.check.unit_of_sum(result, other, node, name)
                kind = arith.numeric_kind(result, other, "+")
                if kind is None:
                    return None
                term = A.Func(name, (result.known_term, other.known_term))
                # the literal factors of the side that gave the unit (as for +)
                held = result.factors if unit == result.unit else other.factors
                free = result.rad_free or other.rad_free
                result = Value(kind, term, unit, literal, factors=held, rad_free=free)
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
            return replace(value, factors=first.factors, rad_free=first.rad_free)
        if name == "bool" and len(args) == 1:
            return Value("bool", self.truthy(first, node, state))
        return None if name != "print" else NONE

    # -- sequences -----------------------------------------------------------
    def receiver(self, node: ast.expr, state: State) -> Value:
        """The object a method is called on; a message's array field is read without
        the check of its default (`msg.ranges.append(x)` sets it)."""
        if isinstance(node, ast.Attribute):
            base = self.eval(node.value, state)
            if base.kind == "msg" and base.ref in state.heap:
                spec = heap.field_spec(self.ctx, state, base.ref, node.attr)
                if spec is not None and spec.array:
                    text = self.ctx.source.segment(node) or node.attr
                    return heap.read_raw(self.ctx, state, base.ref, node.attr, text)
            return self.eval_Attribute(node, state, base)
        return self.eval(node, state)

    def sequence_builtin(
        self,
        name: str,
        args: list[Value],
        kwargs: dict[str | None, Value],
        node: ast.Call,
        state: State,
    ) -> Value | None:
        """len, min, max, sum, sorted, list, tuple, reversed, enumerate, zip and range
        of lists, tuples and array fields."""
        if name == "range":
            return self._range(args, node, state)
        if name == "zip" and args and all(a.kind in SEQUENCES for a in args):
            return Value("generator", name="zip", keys=tuple(args))
        if not args or (len(args) > 1 and name != "sum"):
            return None
        sequence = args[0]
        if name == "len" and not kwargs:
            return self.length(sequence, node, state)
        if name in ("min", "max") and set(kwargs) <= {"key", "default"}:
            return self._extreme(name, sequence, kwargs, node, state)
        if name == "sum" and not kwargs:
            return self._sum(sequence, args[1] if len(args) > 1 else None, node, state)
        copies = name in ("list", "tuple", "reversed") and not kwargs
        if copies or (name == "sorted" and set(kwargs) <= {"key", "reverse"}):
            copy = containers.copied(sequence)
            kind = {"tuple": "tuple", "reversed": "generator"}.get(name, "list")
            elements = sequence.elements if name in ("list", "tuple") else None
            return replace(copy, kind=kind, elements=elements)
        if name == "enumerate" and not kwargs:
            index = Value(
                "generator",
                items=Items("int", A.Binary(">=", containers.SELF, ZERO)),
            )
            return Value("generator", name="enumerate", keys=(index, sequence))
        return None

    def length(self, sequence: Value, node: ast.AST, state: State) -> Value:
        """`len(xs)`: its length when known, else a number its size allows."""
        term = containers.length_term(sequence)
        if term is not None:
            if A.syms(term):  # what else its size says of it
                state.assume(containers.at(containers.size_of(sequence), term))
            return Value("int", term)
        shared = self.check.length_of(state, sequence, node)
        value = self.unknown(node, "int") if shared is None else Value("int", shared)
        size = containers.size_of(sequence)
        state.assume(A.Binary(">=", value.known_term, ZERO))
        if size != A.TRUE:
            state.assume(containers.at(size, value.known_term))
        return value

    def _extreme(
        self,
        name: str,
        sequence: Value,
        kwargs: dict[str | None, Value],
        node: ast.Call,
        state: State,
    ) -> Value | None:
        """min() and max() of a sequence: one of its elements (it was not empty, or
        they raised), or the `default`."""
        known = sequence.elements
        if (
            known
            and "key" not in kwargs
            and len(known) <= containers.MAX_SPELLED
            and all(e.term is not None for e in known)
        ):
            if len(known) == 1:
                return known[0]
            return self.builtin(name, list(known), node, state)
        element = self.lookups.element(sequence, node, state)
        default = kwargs.get("default")
        if default is None:
            return element
        if element.term is None or default.term is None:
            return None
        result = self.unknown(node, element.kind, element.unit)
        state.assume(
            A.Binary(
                "or",
                A.Binary("==", result.known_term, element.term),
                A.Binary("==", result.known_term, default.term),
            )
        )
        return result

    def _sum(
        self, sequence: Value, start: Value | None, node: ast.Call, state: State
    ) -> Value | None:
        """sum() of a sequence: exact when its elements are known; else each of a
        known number of elements (up to MAX_SUMMED) satisfies what every element
        does; else within the length times the elements' bounds."""
        first = start.term if start is not None else ZERO
        if first is None:
            return None
        kind = containers.item_kind(sequence)
        kind = (
            "float"
            if kind == "float"
            else "int"
            if kind in ("int", "bool")
            else "unknown"
        )
        if start is not None and start.kind == "float" and kind == "int":
            kind = "float"
        unit = sequence.unit
        known = sequence.elements
        if known is not None and len(known) <= 4 * containers.MAX_SPELLED:
            terms = [e.term for e in known]
            if all(t is not None for t in terms) and all(
                e.kind in ("int", "float", "bool") for e in known
            ):
                total = first
                for term in terms:
                    total = A.Binary("+", total, term)  # type: ignore[arg-type]
                literal = all(e.literal for e in known)
                return Value(kind, total, unit, literal)
        length = containers.length_term(sequence)
        count = containers.fold(length) if length is not None else None
        each = containers.each_of(sequence)
        if count is not None and 0 <= count <= containers.MAX_SUMMED:
            total = first
            for _ in range(int(count)):
                element = self.lookups.element(sequence, node, state)
                if element.term is None:
                    return None
                total = A.Binary("+", total, element.term)
            return Value(kind, total, unit)
        result = self.unknown(node, kind, unit)
        low, high = containers.bounds(each)
        if low is None and high is None:
            return result
        if length is None:
            length = self.length(sequence, node, state).known_term
        for bound, op in ((low, ">="), (high, "<=")):
            if bound is not None:
                limit = A.Binary("+", first, A.Binary("*", length, bound))
                state.assume(A.Binary(op, result.known_term, limit))
        return result

    def _range(self, args: list[Value], node: ast.Call, state: State) -> Value | None:
        """range(stop) and range(start, stop): the numbers from start up to stop."""
        if not 1 <= len(args) <= 2 or any(
            a.term is None or a.kind not in ("int", "bool") for a in args
        ):
            return None
        low = args[0].known_term if len(args) == 2 else ZERO
        high = args[-1].known_term
        each = A.Binary(
            "and",
            A.Binary("<=", low, containers.SELF),
            A.Binary("<", containers.SELF, high),
        )
        count = A.Ite(A.Binary(">", high, low), A.Binary("-", high, low), ZERO)
        size = A.Binary("==", containers.SELF, count)
        return Value("generator", name="range", items=Items("int", each, size))

    def sequence_method(
        self,
        func: ast.Attribute,
        receiver: Value,
        args: list[Value],
        node: ast.Call,
        state: State,
    ) -> Value:
        """`xs.append(v)`, `extend`, `insert`, `pop`, `clear`, `sort`...: a new
        element is checked against the list's declaration, and what the list
        holds afterwards is stored back where it came from."""
        method = func.attr
        kept = receiver.items.kept if receiver.items is not None else None
        updated: Value | None = None
        result: Value = NONE
        new: Value | None = None
        if method in ("append", "insert") and len(args) == (
            1 if method == "append" else 2
        ):
            new = args[-1]
            if receiver.kind == "list":
                index = _index(args[0]) if method == "insert" else None
                updated = containers.with_element(receiver, new, grows=True)
                if method == "insert" and (index is None or updated.elements is None):
                    updated = replace(updated, elements=None)
                elif method == "insert" and updated.elements is not None:
                    moved = list(receiver.elements or ())
                    moved.insert(index, new)  # type: ignore[arg-type]
                    updated = replace(updated, elements=tuple(moved))
        elif method == "extend" and len(args) == 1 and receiver.kind == "list":
            new = args[0]
            if new.kind in SEQUENCES and new.kind != "generator":
                updated = containers.concatenated(receiver, new)
            else:
                updated = containers.forgetting(receiver, grows=True)
            if kept is not None:
                updated = replace(
                    updated,
                    unit=kept.unit,
                    items=replace(updated.items or Items(), kept=kept),
                )
        elif method == "pop" and len(args) <= 1 and receiver.kind == "list":
            result = self.lookups.element(receiver, node, state)
            updated = containers.forgetting(receiver, grows=False)
        elif method == "clear" and not args and receiver.kind == "list":
            updated = Value(
                "list",
                unit=receiver.unit,
                elements=(),
                items=Items(containers.item_kind(receiver), A.TRUE, A.TRUE, kept),
            )
        elif method == "remove" and receiver.kind == "list":
            updated = containers.forgetting(receiver, grows=False)
        elif method in ("sort", "reverse") and receiver.kind == "list":
            reordered = containers.copied(receiver)  # the same elements
            items = reordered.items or Items()
            updated = replace(reordered, items=replace(items, kept=kept))
        elif method == "copy" and not args:
            return containers.copied(receiver)
        elif method in ("index", "count"):
            result = self.unknown(node, "int")
            state.assume(A.Binary(">=", result.known_term, ZERO))
            return result
        else:
            return self.unknown(node)
        ok, reports = True, len(self.ctx.diagnostics)
        if kept is not None and new is not None:
            ok = self._check_new(state, new, kept, method, self.site)
        quiet = len(self.ctx.diagnostics) == reports  # one report per statement
        if ok and quiet and kept is not None and kept.size != A.TRUE and updated:
            ok = self.check.check_size(state, updated, kept, self.site)
        if not ok and kept is not None:  # reported: from here on, its declaration
            updated = containers.declared(receiver.kind, kept)
        elif updated is not None:
            updated = containers.holding(updated)
        if updated is not None:
            self.store(func.value, updated, state)
        return result

    def _check_new(
        self, state: State, new: Value, kept: Kept, method: str, site: ast.AST
    ) -> bool:
        """The elements `append`, `insert` or `extend` add keep the declaration."""
        one = containers.each_only(kept)
        if method == "extend":  # its elements end the list: name them from the end
            count = len(new.elements) if new.elements is not None else 0
            labels = tuple(f"{kept.label}[{i - count}]" for i in range(count))
            return self.check.check_items(state, new, one, site, labels or None)
        label = f"{kept.label}[-1]" if method == "append" else f"{kept.label}[i]"
        element = Value("list", elements=(new,), items=Items(sites=(site,)))
        return self.check.check_items(state, element, one, site, labels=(label,))

    def store(self, target: ast.expr, value: Value, state: State) -> None:
        """Put a list that changed back where it lives (nothing to do elsewhere)."""
        raise NotImplementedError


def _index(value: Value) -> int | None:
    if isinstance(value.term, A.Num) and value.term.is_int:
        return int(value.term.value)
    return None


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
