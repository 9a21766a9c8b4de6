"""The checks: refinements (via VCs), units, base types, initialisation, publish.

Every check reports at most once and then lets the analysis go on as if the
refinement held, so one bug gives one diagnostic, not a cascade.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass, field, replace

from robotfix import messages
from robotfix.analysis import containers, frames, heap, parameters
from robotfix.analysis.context import FileContext
from robotfix.analysis.state import State
from robotfix.analysis.values import SEQUENCES, Items, Kept, Value
from robotfix.analysis.vc import VC, Proved, Undecided, Unproven, Violated
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Refinement
from robotfix.annotations.units import Unit
from robotfix.diagnostics import Span
from robotfix.messages import Declared
from robotfix.ros.catalog import FieldUnit, Invariant, MsgSpec

PROVED, WARNED, FAILED = "proved", "warned", "failed"
# Sub-messages one check may create before it checks only one of each type: the
# unset sub-messages of one type all hold the same defaults.
EXPANSION_LIMIT = 16
KIND_NAMES = {
    "int": "int",
    "float": "float",
    "bool": "bool",
    "str": "str",
    "msg": "message",
    "tuple": "tuple",
    "list": "list",
    "dict": "dict",
    "generator": "generator",
}
SCALAR_KINDS = frozenset({"int", "float", "bool", "str", "msg", "dict"})
MAX_CHECKED = 256  # elements of a display checked one by one


class Checker:
    def __init__(self, ctx: FileContext) -> None:
        self.ctx = ctx
        self.path = ctx.source.path

    # -- helpers -------------------------------------------------------------
    def where(self, node: ast.AST) -> tuple[Span, str]:
        return self.ctx.source.span(node), self.ctx.source.statement_text(node)

    def goal_holds(
        self,
        state: State,
        goal: A.Expr,
        probe: A.Expr | None,
        site: ast.AST,
        predicate: str,
        subject: str,
        declared: Declared,
    ) -> str:
        """Check `goal` under the path's facts; report RF101/RF102/RF901 if needed.
        Returns "proved", "warned" (RF102: the goal may hold) or "failed"."""
        if goal == A.TRUE:
            return PROVED
        probes = (probe,) if probe else ()
        verdict = self.ctx.discharge(VC(tuple(state.facts), goal, probes))
        span, stmt = self.where(site)
        if isinstance(verdict, Proved):
            return PROVED
        if isinstance(verdict, Violated):
            value = verdict.probe_values[0] if verdict.probe_values else None
            self.ctx.report(
                messages.refinement_violated(
                    self.path, span, stmt, predicate, subject, value, declared
                )
            )
            return FAILED
        if isinstance(verdict, Unproven):
            goal_syms = {s.ident for s in A.syms(goal)}
            unknowns = sorted({self._describe(i) for i in goal_syms})
            example = [
                f"{self._describe(i)} = {v}"
                for i, v in verdict.sym_values
                if i in goal_syms
            ]
            self.ctx.report(
                messages.refinement_unproven(
                    self.path,
                    span,
                    stmt,
                    predicate,
                    subject,
                    unknowns,
                    example[:3],
                    declared,
                )
            )
            return WARNED
        assert isinstance(verdict, Undecided)
        if verdict.out_of_budget:  # one report: every later question is undecided
            self.ctx.report(
                messages.solver_budget(self.path, span, stmt, predicate),
                once=("solver budget",),
            )
            return FAILED
        self.ctx.report(
            messages.solver_unknown(self.path, span, stmt, predicate, verdict.reason)
        )
        return FAILED

    def _describe(self, ident: int) -> str:
        return self.ctx.describe(ident)

    def report_uninit(self, value: Value, site: ast.AST) -> bool:
        if value.uninit is None:
            return False
        span, stmt = self.where(site)
        self.ctx.report(
            messages.used_before_assignment(
                self.path, span, stmt, value.uninit.name, value.uninit.declared
            ),
            once=("uninit", span.line, value.uninit.name),
        )
        return True

    def units_agree(
        self,
        expected: Unit | None,
        value: Value,
        site: ast.AST,
        target: str,
        declared: Declared,
    ) -> bool:
        found = None if expected is None else value.fit(expected)
        if expected is None or found is None or found.kind == "ok":
            return True
        span, stmt = self.where(site)
        if found.kind == "time":  # a P-controller's gain, a literal time step
            self.ctx.report(
                messages.implicit_unit_change(
                    self.path,
                    span,
                    stmt,
                    target,
                    expected,
                    found.got,
                    found.seconds,
                    declared,
                )
            )
            return True
        self.ctx.report(
            messages.unit_mismatch(
                self.path,
                span,
                stmt,
                target,
                expected,
                found.got,
                declared,
                found.aligned,
            )
        )
        return False

    def base_fits(
        self, expected: str, value: Value, site: ast.AST, target: str
    ) -> bool:
        got = value.kind
        numeric = {
            "int": {"int", "bool"},
            "float": {"int", "float", "bool"},
            "bool": {"bool"},
        }
        if expected not in KIND_NAMES or got not in KIND_NAMES or expected == "msg":
            return True
        if got == expected or got in numeric.get(expected, set()):
            return True
        span, stmt = self.where(site)
        self.ctx.report(
            messages.base_type_mismatch(
                self.path, span, stmt, target, KIND_NAMES[expected], KIND_NAMES[got]
            )
        )
        return False

    # -- variables -----------------------------------------------------------
    def assign_refined(
        self,
        state: State,
        name: str,
        decl: Refinement,
        value: Value,
        site: ast.AST,
        lookup: dict[str, A.Expr],
    ) -> Value:
        """Check `name = value` against its refinement; return what `name` holds."""
        if decl.item is not None:
            if decl.optional and value.kind == "none":
                return value
            read = parameters.read_of(self, value, site)
            if read is not None:  # a parameter read: its default is checked
                if read.default is not None and read.default_node is not None:
                    self.assign_sequence(
                        state, name, decl, read.default, read.default_node, lookup
                    )
                return self.assumed(state, name, decl, lookup)
            return self.assign_sequence(state, name, decl, value, site, lookup)
        declared = Declared(f"annotation of `{name}`", self.path, decl.line)
        if value.kind == "msg" or (decl.optional and value.kind == "none"):
            return value
        read = parameters.read_of(self, value, site)
        if read is not None:  # a parameter read: the refinement becomes its own
            return parameters.attach(self, state, name, decl, value, site, lookup, read)
        if decl.elements is not None:
            return self._assign_elements(state, name, decl, value, site, lookup)
        if self.report_uninit(value, site):
            return self.assumed(state, name, decl, lookup)
        fits = self.base_fits(decl.base, value, site, f"`{name}`")
        fits = self.units_agree(decl.unit, value, site, f"`{name}`", declared) and fits
        if not fits or value.term is None:
            return self.assumed(state, name, decl, lookup)
        for part in A.conjuncts(decl.predicate):
            goal = A.substitute(part, {**lookup, "_": value.term})
            shown = A.show(A.substitute(part, {"_": A.Name(name)}))
            outcome = self.goal_holds(
                state, goal, value.term, site, shown, f"`{name}`", declared
            )
            if outcome == FAILED:
                return self.assumed(state, name, decl, lookup)
            if outcome == WARNED:  # reported once: from here on, assume it all
                state.assume(A.substitute(decl.predicate, {**lookup, "_": value.term}))
                break
            state.assume(goal)
        return self._stored(value, decl)

    def assumed(
        self, state: State, name: str, decl: Refinement, lookup: dict[str, A.Expr]
    ) -> Value:
        """A fresh value of `name` that satisfies its refinement (an optional one's
        may be None: nothing is assumed; a tuple's elements each satisfy theirs; a
        container's elements and length satisfy its refinement)."""
        if decl.elements is not None:
            return Value(
                "tuple",
                elements=tuple(
                    self.assumed(state, f"{name}[{i}]", part, lookup)
                    if part is not None
                    else self.ctx.fresh("unknown", f"`{name}[{i}]`")
                    for i, part in enumerate(decl.elements)
                ),
            )
        if decl.item is not None:
            found = containers.declared(decl.base, self.kept(name, decl, lookup))
            return self.with_length(found, name)
        value = self.ctx.fresh(decl.base, f"`{name}`", decl.unit)
        if value.term is not None:
            state.assume(A.substitute(decl.assumable, {**lookup, "_": value.term}))
        return value

    def _assign_elements(
        self,
        state: State,
        name: str,
        decl: Refinement,
        value: Value,
        site: ast.AST,
        lookup: dict[str, A.Expr],
    ) -> Value:
        """`name = (a, b)` against `tuple[Annotated[...], ...]`: element-wise. A value
        whose elements are not known is not checked (and keeps what it is)."""
        assert decl.elements is not None
        parts = value.elements if value.kind == "tuple" else None
        if parts is None or len(parts) != len(decl.elements):
            return value
        return replace(
            value,
            elements=tuple(
                self.assign_refined(state, f"{name}[{i}]", part, got, site, lookup)
                if part is not None
                else got
                for i, (part, got) in enumerate(zip(decl.elements, parts, strict=True))
            ),
        )

    def _stored(self, value: Value, decl: Refinement) -> Value:
        if decl.unit is not None:
            return value.with_unit(decl.unit)
        return value

    # -- sequences -----------------------------------------------------------
    def kept(self, name: str, decl: Refinement, lookup: dict[str, A.Expr]) -> Kept:
        """What a refined list or tuple variable, parameter or attribute keeps."""
        return Kept(
            decl.item or "unknown",
            decl.unit,
            A.substitute(decl.predicate, lookup),
            A.substitute(decl.size, lookup),
            name,
            Declared(f"annotation of `{name}`", self.path, decl.line),
        )

    def with_length(self, value: Value, name: str) -> Value:
        """`value` with its length a symbol of its own, so that every `len()` and
        truth test of it in a path speak of the same number."""
        if value.items is None or containers.length_term(value) is not None:
            return value
        length = self.ctx.fresh("int", f"`len({name})`").known_term
        pinned = A.conjoin(
            [
                A.Binary("==", containers.SELF, length),
                A.Binary(">=", containers.SELF, containers.number(0)),
                *([value.items.size] if value.items.size != A.TRUE else []),
            ]
        )
        return replace(value, items=replace(value.items, size=pinned))

    def assign_sequence(
        self,
        state: State,
        name: str,
        decl: Refinement,
        value: Value,
        site: ast.AST,
        lookup: dict[str, A.Expr],
    ) -> Value:
        """`name = value` where `name` is a refined list or tuple: the refinement is
        on every element (its `len(_)` parts on the length)."""
        kept = self.kept(name, decl, lookup)
        if self.report_uninit(value, site):
            return containers.declared(decl.base, kept)
        if not self.sequence_fits(value, site, f"`{name}`", decl.base):
            return containers.declared(decl.base, kept)
        if not self.check_items(state, value, kept, site):
            return containers.declared(decl.base, kept)
        return self.stored(value, kept, decl.base)

    def sequence_fits(
        self, value: Value, site: ast.AST, target: str, expected: str
    ) -> bool:
        """A number, string or message where a list belongs is RF401."""
        if value.kind not in SCALAR_KINDS:
            return True
        span, stmt = self.where(site)
        self.ctx.report(
            messages.base_type_mismatch(
                self.path, span, stmt, target, expected, KIND_NAMES[value.kind]
            )
        )
        return False

    def check_items(
        self,
        state: State,
        value: Value,
        kept: Kept,
        site: ast.AST,
        labels: tuple[str, ...] | None = None,
    ) -> bool:
        """Do the elements of `value` (and its length) satisfy `kept`? Elements known
        one by one are checked one by one, where they are written; others through
        what holds of every element, which can only warn (the list may be empty).
        Returns False after an error (the caller then assumes the declaration)."""
        ok = True
        known = value.elements if value.kind in SEQUENCES else None
        if known is not None and len(known) > MAX_CHECKED:
            known = None  # a long table: through what holds of every element
        if known is not None:
            sites = (value.items.sites if value.items else None) or ()
            warned = False
            for index, element in enumerate(known):
                where = sites[index] if index < len(sites) else site
                assert isinstance(where, ast.AST)
                label = labels[index] if labels else f"{kept.label}[{index}]"
                outcome = self._check_item(
                    state,
                    element,
                    kept,
                    where,
                    label,
                    warned,
                )
                ok = ok and outcome != FAILED
                warned = warned or outcome == WARNED
        else:
            unit_declared = kept.unit_declared or kept.declared
            target = f"the elements of `{kept.label}`"
            ok = self.units_agree(kept.unit, value, site, target, unit_declared)
            if ok and kept.each != A.TRUE:
                self._check_every(state, value, kept, site)
        if ok and kept.size != A.TRUE:
            ok = self.check_size(state, value, kept, site)
        return ok and self.check_shape(state, value, kept, site)

    def check_shape(
        self, state: State, value: Value, kept: Kept, site: ast.AST
    ) -> bool:
        """A message array's fixed size or bound, when the length is known."""
        length = containers.length_term(value) if value.kind in SEQUENCES else None
        if kept.shape == A.TRUE or length is None or A.syms(length):
            return True
        return self.check_size(state, value, replace(kept, size=kept.shape), site)

    def _check_item(
        self,
        state: State,
        element: Value,
        kept: Kept,
        site: ast.AST,
        label: str,
        warned: bool,
    ) -> str:
        """One element against the declaration's base type, unit and predicate."""
        target = f"`{label}`"
        fits = kept.item not in KIND_NAMES or self.base_fits(
            kept.item, element, site, target
        )
        unit_declared = kept.unit_declared or kept.declared
        fits = (
            self.units_agree(kept.unit, element, site, target, unit_declared) and fits
        )
        if not fits:
            return FAILED
        if element.term is None:
            return PROVED  # not a number: nothing RobotFix can say of it
        outcome = PROVED
        for part in A.conjuncts(kept.each):
            goal = containers.at(part, element.known_term)
            if warned or outcome == WARNED:
                state.assume(goal)
                continue
            shown = A.show(A.substitute(part, {"_": A.Name(label)}))
            outcome = self.goal_holds(
                state, goal, element.term, site, shown, target, kept.declared
            )
            if outcome == FAILED:
                return FAILED
            state.assume(goal)
        return outcome

    def _check_every(
        self, state: State, value: Value, kept: Kept, site: ast.AST
    ) -> None:
        """Every element that `value` may have satisfies `kept.each` (a warning
        when not proved: an element that breaks it may not exist)."""
        kind = kept.item if kept.item in ("int", "float", "bool", "str") else "unknown"
        element = self.ctx.fresh(kind, f"an element of `{kept.label}`")
        have = self.instantiate(containers.each_of(value), element.known_term)
        label = f"{kept.label}[i]"
        for part in A.conjuncts(kept.each):
            goal = A.Binary(
                "or", A.Unary("not", have), containers.at(part, element.known_term)
            )
            shown = A.show(A.substitute(part, {"_": A.Name(label)}))
            outcome = self.goal_holds(
                state, goal, None, site, shown, f"`{label}`", kept.declared
            )
            if outcome != PROVED:
                return

    def instantiate(self, each: A.Expr, term: A.Expr) -> A.Expr:
        """What holds of every element, for the element `term` (with symbols of its
        own for the values each element has of its own)."""
        return containers.instantiate(each, term, self._bound_symbol)

    def _bound_symbol(self, name: str) -> A.Expr:
        """A fresh symbol for a bound name `#<id>`, described as the one it was."""
        described = self.ctx.sym_names.get(int(name[1:]), "an element")
        return self.ctx.fresh("unknown", described).known_term

    def check_size(self, state: State, value: Value, kept: Kept, site: ast.AST) -> bool:
        """The length of `value` keeps `kept.size` (a warning when not provable)."""
        length = containers.length_term(value) if value.kind in SEQUENCES else None
        if length is not None:
            goal = containers.at(kept.size, length)
        else:
            fresh = self.ctx.fresh("int", f"`len({kept.label})`").known_term
            have = containers.at(
                A.conjoin(
                    [
                        containers.size_of(value),
                        A.Binary(">=", containers.SELF, containers.number(0)),
                    ]
                ),
                fresh,
            )
            goal = A.Binary("or", A.Unary("not", have), containers.at(kept.size, fresh))
        shown = A.show(A.substitute(kept.size, {"_": A.Name(f"len({kept.label})")}))
        outcome = self.goal_holds(
            state, goal, length, site, shown, f"`len({kept.label})`", kept.declared
        )
        return outcome != FAILED

    def stored(self, value: Value, kept: Kept, base: str) -> Value:
        """What a refined sequence holds after a value passed its checks."""
        if value.kind not in SEQUENCES:
            return containers.declared(base, kept)
        elements = value.elements
        if elements is not None and kept.unit is not None:
            elements = tuple(
                e.with_unit(kept.unit) if e.term is not None else e for e in elements
            )
        each = kept.each
        if value.items is not None and value.items.each not in (A.TRUE, kept.each):
            each = A.conjoin([kept.each, value.items.each])
        size = containers.size_of(value)
        if kept.size != A.TRUE:
            size = A.conjoin([size, kept.size]) if size != A.TRUE else kept.size
        stored = Value(
            value.kind,
            unit=kept.unit or value.unit,
            elements=elements,
            items=Items(kept.item, each, size, kept),
        )
        return self.with_length(stored, kept.label)

    # -- message fields ------------------------------------------------------
    def write_field(
        self,
        state: State,
        ref: int,
        name: str,
        value: Value,
        site: ast.AST,
        target: str,
    ) -> None:
        heap.settle(self.ctx, state, ref)
        obj = state.heap[ref]
        spec = heap.field_spec(self.ctx, state, ref, name)
        if spec is None:
            obj.fields[name] = value
            return
        unit, unit_decl, owner = heap.field_unit(self.ctx, state, ref, name)
        invariants = heap.invariants_on(self.ctx, state, ref, name)
        refined = unit is not None or bool(invariants)
        if refined and self.report_uninit(value, site):
            obj.fields[name] = self.ctx.fresh(spec.kind, target, unit)
            obj.reported.discard(name)
            return
        if spec.array:
            self._write_array(state, ref, name, value, site, target)
            return
        if spec.kind == "msg":
            if value.ref is not None and value.ref in state.heap:
                frames.check_moved(self.ctx, state, ref, name, value.ref, site)
                if not heap.owns(state, ref, value.ref):  # `m.a = m`: no owner loop
                    state.heap[value.ref].owner = (ref, name)
                obj.fields[name] = value
                self.check_whole(state, value.ref, site, publishing=False, single=True)
            else:
                obj.fields[name] = heap.new_message(
                    self.ctx, state, spec.msg_type or "", "unknown", owner=(ref, name)
                )
            return
        ok = (
            spec.loose
            or spec.array  # the kind is the elements'
            or self.base_fits(spec.kind, value, site, f"`{target}`")
        )
        if unit_decl is not None and owner is not None:
            decl = self._field_declared(owner, name, unit_decl)
            framed, frame_decl = frames.expected_unit(self.ctx, state, ref, name, unit)
            if frame_decl is not None and frames.frame_of(value.unit) is not None:
                decl = frame_decl  # the frame is what can differ
            ok = self.units_agree(framed, value, site, f"`{target}`", decl) and ok
        stored = value.with_unit(unit) if unit is not None else value
        if stored.term is None:
            stored = self.ctx.fresh(spec.kind, f"`{target}`", unit)
        warned = False
        for owner_spec, path, inv in invariants:
            if not ok:
                break
            goal = A.substitute(inv.predicate, {path: stored.known_term})
            if warned:  # one report per statement; the rest is assumed
                state.assume(goal)
                continue
            declared = Declared(
                f"refinement of {owner_spec.name}",
                inv.origin.path,
                inv.origin.line,
                owner=owner_spec.name,
            )
            outcome = self.goal_holds(
                state, goal, stored.term, site, inv.text, f"`{target}`", declared
            )
            ok = outcome != FAILED
            warned = outcome == WARNED
            if ok:
                state.assume(goal)
        if not ok:
            stored = self.ctx.fresh(spec.kind, f"`{target}`", unit)
            for _, path, inv in invariants:
                state.assume(A.substitute(inv.predicate, {path: stored.known_term}))
        kept = frames.stored(state, ref, name, stored, value)
        obj.fields[name] = (
            kept if kept.default_of is None else replace(kept, default_of=None)
        )
        obj.reported.discard(name)

    def _write_array(
        self,
        state: State,
        ref: int,
        name: str,
        value: Value,
        site: ast.AST,
        target: str,
    ) -> None:
        """`msg.ranges = ...`: every element keeps the field's refinements; what the
        field then holds is what they say (a list stored in a message is shared)."""
        obj = state.heap[ref]
        spec = heap.field_spec(self.ctx, state, ref, name)
        assert spec is not None
        kept = heap.array_rule(self.ctx, state, ref, name, spec, target)
        if value.kind in ("int", "float", "bool") or (
            value.kind == "msg" and spec.kind != "msg"
        ):
            self.sequence_fits(value, site, f"`{target}`", "array")
        elif spec.kind != "msg" and not spec.loose:
            # rclpy's setters assert a fixed size or bound; ROS 1 only minds it when
            # the message is serialized, and code may fix the length before that
            shaped = replace(kept, shape=A.TRUE) if self.ctx.ros1 else kept
            self.check_items(state, value, shaped, site)
        # the field's declaration, which holds its fixed size too
        stored = containers.declared("list", kept)
        obj.fields[name] = stored
        obj.reported.discard(name)

    def _field_declared(
        self, owner: MsgSpec, name: str, unit_decl: FieldUnit
    ) -> Declared:
        what = f"unit of {owner.name}"
        if unit_decl.origin is None:
            return Declared(what, None, None, unit_decl.source, owner.name)
        return Declared(
            what, unit_decl.origin.path, unit_decl.origin.line, owner=owner.name
        )

    def read_field(
        self, state: State, ref: int, name: str, site: ast.AST, target: str
    ) -> Value:
        heap.settle(self.ctx, state, ref)
        value = heap.read_raw(self.ctx, state, ref, name, target)
        if value.default_of is None:
            return value
        if value.kind == "list":  # reading an empty array is fine (no RF302 yet)
            if self._array_default_breaks(state, ref, name, value, site, target, False):
                state.heap[ref].reported.add(name)
            return value
        for spec, path, inv in heap.invariants_on(self.ctx, state, ref, name):
            if inv.paths == {path} and value.term is not None:
                self._default_breaks(
                    state, spec, inv, path, value.term, site, target, False
                )
        state.heap[ref].reported.add(name)
        return value

    def _default_breaks(
        self,
        state: State,
        spec: MsgSpec,
        inv: Invariant,
        path: str,
        default: A.Expr,
        site: ast.AST,
        target: str,
        publishing: bool,
    ) -> bool:
        goal = A.substitute(inv.predicate, {path: default})
        verdict = self.ctx.discharge(VC((), goal))
        if not isinstance(verdict, Violated):
            return False
        span, stmt = self.where(site)
        declared = Declared(
            f"refinement of {spec.name}",
            inv.origin.path,
            inv.origin.line,
            owner=spec.name,
        )
        self.ctx.report(
            messages.unset_field(
                self.path,
                span,
                stmt,
                target,
                A.show(default),
                inv.text,
                declared,
                publishing,
            )
        )
        return True

    def _array_default_breaks(
        self,
        state: State,
        ref: int,
        name: str,
        value: Value,
        site: ast.AST,
        target: str,
        publishing: bool,
    ) -> bool:
        """RF302 for an array field never set whose default (empty, or zeros) breaks
        a refinement of its elements or its length."""
        count = containers.length_term(value)
        spec = heap.field_spec(self.ctx, state, ref, name)
        if count is None or spec is None:
            return False
        zero = heap.DEFAULTS.get(spec.kind)
        has_elements = count != containers.number(0)
        for owner, path, inv in heap.invariants_on(self.ctx, state, ref, name):
            each, size = heap.array_parts(inv.predicate, path)
            goals = [containers.at(size, count)] if size != A.TRUE else []
            if each != A.TRUE and zero is not None and has_elements:
                goals.append(containers.at(each, zero))
            if not goals:
                continue
            verdict = self.ctx.discharge(VC((), A.conjoin(goals)))
            if not isinstance(verdict, Violated):
                continue
            span, stmt = self.where(site)
            shown = (
                f"[{A.show(zero)}] * {A.show(count)}" if has_elements and zero else "[]"
            )
            declared = Declared(
                f"refinement of {owner.name}",
                inv.origin.path,
                inv.origin.line,
                owner=owner.name,
            )
            self.ctx.report(
                messages.unset_field(
                    self.path, span, stmt, target, shown, inv.text, declared, publishing
                )
            )
            return True
        return False

    def check_whole(
        self,
        state: State,
        ref: int,
        site: ast.AST,
        publishing: bool,
        single: bool = False,
        prefix: str = "",
    ) -> None:
        """A message leaves the node (or is stored into another): every field whose
        refinement its ROS default breaks must be set, and invariants over several
        fields must hold. Single-field invariants of set fields held when set."""
        label = prefix or self._name_of(site)
        self._check_tree(state, ref, site, publishing, single, label, _Walk(), ())

    def _check_tree(
        self,
        state: State,
        ref: int,
        site: ast.AST,
        publishing: bool,
        single: bool,
        label: str,
        walk: _Walk,
        enclosing: tuple[str, ...],
    ) -> None:
        obj = state.heap.get(ref)
        spec = self.ctx.catalog.lookup(obj.type) if obj else None
        # a received message the code never touched holds all its invariants
        if obj is None or spec is None or obj.pending or ref in walk.seen:
            return
        walk.seen.add(ref)
        for inv in self.ctx.invariants(spec):
            self._check_invariant(
                state, ref, spec, inv, site, label, publishing, single
            )
        enclosing = (*enclosing, spec.name)
        for fname, fs in spec.fields.items():
            if fs.array and fname not in obj.reported:
                value = heap.read_raw(self.ctx, state, ref, fname, f"{label}.{fname}")
                if value.default_of is not None and self._array_default_breaks(
                    state, ref, fname, value, site, f"{label}.{fname}", publishing
                ):
                    obj.reported.add(fname)
            if fs.kind != "msg" or fs.array or fs.msg_type is None:
                continue
            if fname not in obj.fields and not walk.expand(
                obj.origin, fs.msg_type, enclosing
            ):
                continue
            sub = heap.read_raw(self.ctx, state, ref, fname, f"{label}.{fname}")
            if sub.ref is not None:
                self._check_tree(
                    state,
                    sub.ref,
                    site,
                    publishing,
                    single,
                    f"{label}.{fname}",
                    walk,
                    enclosing,
                )

    def _check_invariant(
        self,
        state: State,
        ref: int,
        spec: MsgSpec,
        inv: Invariant,
        site: ast.AST,
        label: str,
        publishing: bool,
        single: bool,
    ) -> None:
        predicate = heap.lengths_resolved(self.ctx, state, ref, inv.predicate, label)
        values = {
            p: heap.resolve_path(self.ctx, state, ref, p, label, settled=True)
            for p in sorted({n.name for n in A.names(predicate)})
        }
        if any(v.term is None for v in values.values()):
            return
        unset = [p for p, v in values.items() if v.default_of is not None]
        terms = {p: v.term for p, v in values.items()}
        if unset:
            path = unset[0]
            default = terms[path]
            assert default is not None
            owner_ref, fname = values[path].default_of  # type: ignore[misc]
            if fname in state.heap[owner_ref].reported:
                return
            if self._default_breaks(
                state,
                spec,
                inv,
                path,
                default,
                site,
                f"{label}.{path}",
                publishing,
            ):
                state.heap[owner_ref].reported.add(fname)
            return
        if len(inv.paths) == 1 and not single:
            return
        goal = A.substitute(predicate, terms)  # type: ignore[arg-type]
        declared = Declared(
            f"refinement of {spec.name}",
            inv.origin.path,
            inv.origin.line,
            owner=spec.name,
        )
        self.goal_holds(state, goal, None, site, inv.text, label, declared)

    def _name_of(self, site: ast.AST) -> str:
        if (
            isinstance(site, ast.Expr)
            and isinstance(site.value, ast.Call)
            and site.value.args
        ):
            return self.ctx.source.segment(site.value.args[0]) or "the message"
        return "the message"


@dataclass
class _Walk:
    """What one `check_whole` visited, so that a message that holds itself or a
    fan-out of sub-messages costs a bounded amount."""

    seen: set[int] = field(default_factory=set)  # messages checked
    created: int = 0
    types: set[tuple[str, str]] = field(default_factory=set)

    def expand(self, origin: str, msg_type: str, enclosing: tuple[str, ...]) -> bool:
        """Whether to create, and check, a sub-message the code never read. A
        received one holds its invariants; one of a type that encloses it (a type
        that contains itself, invalid in ROS) would never end."""
        if origin == "received" or msg_type in enclosing:
            return False
        self.created += 1
        if self.created > EXPANSION_LIMIT and (msg_type, origin) in self.types:
            return False
        self.types.add((msg_type, origin))
        return True
