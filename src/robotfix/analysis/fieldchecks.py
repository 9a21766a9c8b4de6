"""The checks of messages: a field written (its unit, type, range and the
message's invariants), a field read before it is set (a default that breaks an
invariant), a whole message at `publish` or as it leaves, and refinements of
message values (`Annotated[Twist, "abs(linear.x) <= limit"]`).

`FieldChecker` asks the solver through the scalar checks (`checks.Checker`),
which it holds; the statement walker and the refinement checks hold it.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass, field
from typing import NamedTuple

from robotfix import messages
from robotfix.analysis import containers, frames, heap
from robotfix.analysis.checks import FAILED, WARNED, Checker
from robotfix.analysis.state import State
from robotfix.analysis.values import (
    MaybeDefault,
    ObjInvariant,
    Value,
    replace,
)
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Refinement
from robotfix.annotations.witness import closed_value
from robotfix.messages import Declared
from robotfix.ros.catalog import FieldSpec, FieldUnit, Invariant, MsgSpec
from robotfix.vc import VC, Violated

# Sub-messages one check may create before it checks only one of each type: the
# unset sub-messages of one type all hold the same defaults.
EXPANSION_LIMIT = 16


class FieldChecker:
    def __init__(self, core: Checker) -> None:
        self.core = core
        self.ctx = core.ctx
        self.path = core.path

    # -- message fields ------------------------------------------------------
    def rules_on(
        self, state: State, ref: int, name: str
    ) -> list[tuple[FieldRule, str]]:
        """Refinements that mention only field `name` of `ref` (and what lies below
        it), with the path of the field relative to where each was declared."""
        found = [
            (_catalog_rule(spec, inv), path)
            for spec, path, inv in heap.invariants_on(self.ctx, state, ref, name)
        ]
        found += [
            (_object_rule(inv), path) for inv, path in heap.extras_on(state, ref, name)
        ]
        return found

    def rules_of(
        self, state: State, ref: int, spec: MsgSpec | None = None
    ) -> list[FieldRule]:
        """Every refinement declared on message `ref` itself: its type's and those
        of the variables it reached."""
        obj = state.heap[ref]
        spec = spec or self.ctx.catalog.lookup(obj.type)
        found = (
            [_catalog_rule(spec, inv) for inv in self.ctx.invariants(spec)]
            if spec
            else []
        )
        return found + [_object_rule(i) for i in obj.extra if i.unit is None]

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
        rules = self.rules_on(state, ref, name)
        refined = unit is not None or bool(rules)
        if refined and self.core.report_uninit(value, site, state):
            obj.fields[name] = self.ctx.fresh(spec.kind, target, unit)
            obj.reported.discard(name)
            return
        if spec.array:
            self._write_array(state, ref, name, value, site, target)
            return
        if spec.kind == "msg":
            sub = state.heap.get(value.ref) if value.ref is not None else None
            if (
                sub is not None
                and value.ref is not None
                and not spec.array
                and sub.type == spec.msg_type
                and not heap.owns(state, ref, value.ref)  # `m.a = m`: no owner loop
            ):
                frames.check_moved(self.ctx, state, ref, name, value.ref, site)
                self.adopt(state, ref, name, value, site, target)
            else:
                obj.fields[name] = heap.new_message(
                    self.ctx, state, spec.msg_type or "", "unknown", owner=(ref, name)
                )
                if sub is not None and value.ref is not None:
                    self._alike(state, ref, name, value.ref, site, target)
            return
        ok = (
            spec.loose
            or spec.array  # the kind is the elements'
            or self.core.base_fits(spec.kind, value, site, f"`{target}`")
        )
        ok = ok and self._in_type_range(state, ref, name, spec, value, site, target)
        if unit_decl is not None and owner is not None:
            decl = self._field_declared(owner, name, unit_decl)
            framed, frame_decl = frames.expected_unit(self.ctx, state, ref, name, unit)
            if frame_decl is not None and frames.frame_of(value.unit) is not None:
                decl = frame_decl  # the frame is what can differ
            ok = (
                self.core.units_agree(framed, value, site, f"`{target}`", decl, state)
                and ok
            )
        elif unit is not None:  # a refined value's `Unit(field) == "u"`
            for inv in heap.unit_extras(state, ref, name)[:1]:
                ok = self._unit_holds_of(value, inv, site, f"`{target}`") and ok
        stored = value.with_unit(unit) if unit is not None else value
        if stored.term is None:
            stored = self.ctx.fresh(spec.kind, f"`{target}`", unit)
        warned = False
        for rule, path in rules:
            if not ok:
                break
            goal = A.substitute(rule.predicate, {path: stored.known_term})
            if warned:  # one report per statement; the rest is assumed
                state.assume(goal)
                continue
            outcome = self.core.goal_holds(
                state,
                goal,
                stored.term,
                site,
                rule.text,
                f"`{target}`",
                rule.declared,
            )
            ok = outcome != FAILED
            warned = outcome == WARNED
            if ok:
                state.assume(goal)
        if not ok:
            stored = self.ctx.fresh(spec.kind, f"`{target}`", unit)
            for rule, path in rules:
                state.assume(A.substitute(rule.predicate, {path: stored.known_term}))
        kept = frames.stored(state, ref, name, stored, value)
        obj.fields[name] = replace(kept, default_of=None)
        obj.set_on_all_paths(name)
        obj.reported.discard(name)

    def _in_type_range(
        self,
        state: State,
        ref: int,
        name: str,
        spec: FieldSpec,
        value: Value,
        site: ast.AST,
        target: str,
    ) -> bool:
        """A number written into an integer field lies in its type's range: RF101
        only when certain (a value worked out exactly: `data = 300` into uint8, or
        one every value of the received fields it is made of breaks); anything
        else is left alone, as rosidl's own check would be at run time."""
        if spec.values is None or value.term is None:
            return True
        low, high = spec.values
        exact = closed_value(value.term)
        if isinstance(exact, bool):
            return True
        if exact is None:  # certain only from other fields' ranges (`u8 + 256`)
            goal = heap.within(spec.values, value.term)
            ranges = self.core.ranges(goal)
            if not ranges:
                return True
            verdict = self.ctx.discharge(VC((*state.facts, *ranges), goal))
            if not isinstance(verdict, Violated):
                return True
        elif low <= exact <= high:
            return True
        msg_type = state.heap[ref].type
        origin = next(
            (
                s.declared_at.get(p)
                for s, p in heap.contexts(self.ctx, state, ref, name)
            ),
            None,
        )
        what = f"integer type of {msg_type}.{name}"
        declared = (
            Declared(what, origin.path, origin.line, owner=msg_type)
            if origin is not None
            else Declared(what, None, None, f"it holds {low} to {high}", msg_type)
        )
        span, stmt = self.core.where(site)
        predicate = f"{low} <= {name} <= {high}"
        self.ctx.report(
            messages.refinement_violated(
                self.path, span, stmt, predicate, f"`{target}`", None, declared
            )
        )
        return False

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
            self.core.sequence_fits(value, site, f"`{target}`", "array")
        elif spec.kind != "msg" and not spec.loose:
            # rclpy's setters assert a fixed size or bound; ROS 1 only minds it when
            # the message is serialized, and code may fix the length before that
            shaped = replace(kept, shape=A.TRUE) if self.ctx.ros1 else kept
            self.core.check_items(state, value, shaped, site)
        # the field's declaration, which holds its fixed size too
        stored = containers.declared("list", kept)
        obj.fields[name] = stored
        obj.reported.discard(name)

    def adopt(
        self,
        state: State,
        ref: int,
        name: str,
        value: Value,
        site: ast.AST,
        target: str,
    ) -> None:
        """A message stored into field `name` of `ref` (`cmd.linear = Vector3(...)`,
        `odom.header = msg.header`, a nested constructor): what it holds must fit
        the units and refinements of its new place, exactly as if it had been
        written there field by field. (A field it leaves at its default is
        checked when the message is sent, as any unset field.)"""
        sub_ref = value.ref
        assert sub_ref is not None
        held: dict[str, Value] = {}
        for path in sorted(heap.below(self.ctx, state, ref, name)):
            found = heap.resolve_path(
                self.ctx, state, sub_ref, path, f"{target}.{path}", settled=True
            )
            if (
                found.default_of is None
                and found.ref is None
                and heap.unset_at(self.ctx, state, sub_ref, path) is None
            ):
                held[path] = found
        state.heap[sub_ref].owner = (ref, name)
        state.heap[ref].fields[name] = value
        reported = len(self.ctx.diagnostics)
        for path, found in held.items():
            inner, _, leaf = path.rpartition(".")
            holder = (
                heap.resolve_path(self.ctx, state, sub_ref, inner, target)
                if inner
                else value
            )
            if holder.ref is None or holder.ref not in state.heap:
                continue
            # one statement, one diagnostic: `cmd.linear = odom...angular` is one
            # unit mix-up, not one per axis
            muted = len(self.ctx.diagnostics) > reported
            self.ctx.muted += muted
            self.write_field(state, holder.ref, leaf, found, site, f"{target}.{path}")
            self.ctx.muted -= muted
        for owner_ref, path in heap.chain(state, ref, name):
            label = target[: -len(path) - 1] if target.endswith("." + path) else ""
            for rule in self.rules_of(state, owner_ref):
                if len(rule.paths) > 1 and all(
                    p.startswith(path + ".") for p in rule.paths
                ):
                    self._check_invariant(
                        state, owner_ref, rule, site, label or target, False, True
                    )
        self.check_whole(state, sub_ref, site, publishing=False, single=True)

    def _alike(
        self, state: State, ref: int, name: str, source: int, site: ast.AST, target: str
    ) -> None:
        """A message of another type stored into field `name` of `ref` (`pose.position
        = odom.twist.twist.linear`, a Vector3 in m/s into a Point in m): what its
        fields of the same names hold must fit their new place (units and
        refinements), once per statement. The field itself is unknown after."""
        stored = state.heap[ref].fields[name]
        if stored.ref is None:
            return
        source_spec = self.ctx.catalog.lookup(state.heap[source].type)
        target_spec = self.ctx.catalog.lookup(state.heap[stored.ref].type)
        if source_spec is None or target_spec is None:
            return
        reported = len(self.ctx.diagnostics)
        for path, spec in target_spec.fields.items():
            other = source_spec.fields.get(path)
            if (
                other is None
                or "msg" in (spec.kind, other.kind)
                or other.array
                or spec.array
            ):
                continue  # only the scalar fields both types have
            found = heap.resolve_path(
                self.ctx, state, source, path, f"{target}.{path}", settled=True
            )
            if found.default_of is not None or found.term is None:
                continue
            muted = len(self.ctx.diagnostics) > reported
            self.ctx.muted += muted
            self.write_field(state, stored.ref, path, found, site, f"{target}.{path}")
            self.ctx.muted -= muted
        heap.havoc(state, stored.ref)

    def _field_declared(
        self, owner: MsgSpec, name: str, unit_decl: FieldUnit
    ) -> Declared:
        return heap.unit_declared_at(owner, name, unit_decl)

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
        for rule, path in self.rules_on(state, ref, name):
            if rule.paths == {path} and value.term is not None:
                self._default_breaks(state, rule, path, value.term, site, target, False)
        state.heap[ref].reported.add(name)
        return value

    def _default_breaks(
        self,
        state: State,
        rule: FieldRule,
        path: str,
        default: A.Expr,
        site: ast.AST,
        target: str,
        publishing: bool,
        some_paths: bool = False,
    ) -> bool:
        """RF302 if the default breaks the refinement, on a path that can run."""
        goal = A.substitute(rule.predicate, {path: default})
        verdict = self.ctx.discharge(VC((), goal))
        if not isinstance(verdict, Violated):
            return False
        if state.facts and not some_paths and not self.core.possible(state, A.TRUE):
            return False  # a path no execution takes (`if c: ... if not c: send`)
        span, stmt = self.core.where(site)
        self.ctx.report(
            messages.unset_field(
                self.path,
                span,
                stmt,
                target,
                A.show(default),
                rule.text,
                rule.declared,
                publishing,
                some_paths=some_paths,
            )
        )
        return True

    def _unset_on_some_path(
        self,
        state: State,
        rule: FieldRule,
        unset: MaybeDefault,
        site: ast.AST,
        label: str,
    ) -> None:
        """RF302 for a field left unset on some path to a publish, where its
        default breaks its refinement."""
        owner_ref, fname = unset.owner
        owner = state.heap.get(owner_ref)
        if owner is None or fname in owner.reported:
            return
        path = next(iter(rule.paths))
        goal = A.substitute(rule.predicate, {path: unset.default})
        if not isinstance(self.ctx.discharge(VC((), goal)), Violated):
            return
        if not self.core.surely_possible(state, unset.when):
            return
        self._default_breaks(
            state,
            rule,
            path,
            unset.default,
            site,
            f"{label}.{path}",
            True,
            some_paths=True,
        )
        owner.reported.add(fname)

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
            span, stmt = self.core.where(site)
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
        for rule in self.rules_of(state, ref, spec):
            self._check_invariant(state, ref, rule, site, label, publishing, single)
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
        rule: FieldRule,
        site: ast.AST,
        label: str,
        publishing: bool,
        single: bool,
        defaults: bool = True,
    ) -> None:
        predicate = heap.lengths_resolved(self.ctx, state, ref, rule.predicate, label)
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
            if not defaults or fname in state.heap[owner_ref].reported:
                return
            if self._default_breaks(
                state, rule, path, default, site, f"{label}.{path}", publishing
            ):
                state.heap[owner_ref].reported.add(fname)
            return
        if len(rule.paths) == 1:
            if publishing:
                path = next(iter(rule.paths))
                maybe = heap.unset_at(self.ctx, state, ref, path)
                if maybe is not None:
                    self._unset_on_some_path(state, rule, maybe, site, label)
            if not single:
                return
        goal = A.substitute(predicate, terms)  # type: ignore[arg-type]
        self.core.goal_holds(state, goal, None, site, rule.text, label, rule.declared)

    # -- refinements on message values ----------------------------------------
    def message_rules(
        self, decl: Refinement, name: str, lookup: dict[str, A.Expr]
    ) -> tuple[ObjInvariant, ...]:
        """`Annotated[Twist, "abs(linear.x) <= limit"]` as invariants of the value:
        field paths stay names, other names become their current terms."""
        if decl.msg_type is None:
            return ()
        found = []
        for part in A.conjuncts(decl.predicate):
            paths = {
                n.name
                for n in A.names(part)
                if self.ctx.catalog.field_at(decl.msg_type, n.name) is not None
            }
            if not paths:
                continue
            others = {k: v for k, v in lookup.items() if k not in paths}
            found.append(
                ObjInvariant(
                    A.substitute(part, others),
                    frozenset(paths),
                    A.show(part),
                    f"annotation of `{name}`",
                    decl.origin or self.path,
                    decl.line,
                )
            )
        found += [
            ObjInvariant(
                A.TRUE,
                frozenset({u.target or ""}),
                f'Unit({u.target}) == "{u.text}"',
                f"annotation of `{name}`",
                decl.origin or self.path,
                decl.line,
                u.text,
            )
            for u in decl.field_units
            # a unit the interface gives the field comes first (a different one
            # is RF507 where the annotation is read)
            if self.ctx.catalog.unit_at(decl.msg_type, u.target or "") is None
        ]
        return tuple(found)

    def reach(
        self,
        state: State,
        ref: int,
        rules: tuple[ObjInvariant, ...],
        site: ast.AST,
        label: str,
        leaving: bool,
    ) -> None:
        """A message reaches a variable, parameter or attribute refined with
        `Annotated[Msg, "..."]`: what it holds must satisfy the refinement now
        (and, when it leaves as an argument, its unset fields too); from here on
        it keeps that refinement, checked at every field write and when sent."""
        obj = state.heap.get(ref)
        if obj is None or not rules:
            return
        for inv in rules:
            if inv.unit is not None:
                self._unit_holds(state, ref, inv, site, label)
                continue
            self._check_invariant(
                state, ref, _object_rule(inv), site, label, leaving, True, leaving
            )
        obj.extra += tuple(inv for inv in rules if inv not in obj.extra)
        state.shared.extras = True

    def _unit_holds(
        self, state: State, ref: int, inv: ObjInvariant, site: ast.AST, label: str
    ) -> None:
        """A message reaching a value whose refinement gives field `path` a unit:
        what that field holds now must be in it (a plain number fits, RF201's
        rule for literals)."""
        path = next(iter(inv.paths))
        value = heap.resolve_path(self.ctx, state, ref, path, label)
        shown = f"`{label}.{path}`" if label.isidentifier() else f"`{path}` of {label}"
        self._unit_holds_of(value, inv, site, shown)

    def _unit_holds_of(
        self, value: Value, inv: ObjInvariant, site: ast.AST, target: str
    ) -> bool:
        declared = Declared(inv.what, inv.path, inv.line, written=f"`{inv.text}`")
        return self.core.units_agree(
            heap.unit_of(inv.unit or ""), value, site, target, declared
        )

    def assume_rules(
        self, state: State, ref: int, rules: tuple[ObjInvariant, ...], label: str
    ) -> None:
        """A refined message that is read (a parameter, an attribute): its
        refinement holds, and keeps holding."""
        obj = state.heap.get(ref)
        if obj is None:
            return
        obj.extra += tuple(
            i for i in rules if i.unit is not None and i not in obj.extra
        )
        state.shared.extras = state.shared.extras or obj.extra != ()
        for inv in rules:
            if inv.unit is not None:
                continue  # above: a field read from here on is in its unit
            values = {
                p: heap.resolve_path(self.ctx, state, ref, p, label) for p in inv.paths
            }
            if all(v.term is not None for v in values.values()):
                terms = {p: v.known_term for p, v in values.items()}
                state.assume(A.substitute(inv.predicate, terms))
        obj.extra += tuple(inv for inv in rules if inv not in obj.extra)
        state.shared.extras = state.shared.extras or bool(rules)

    def _name_of(self, site: ast.AST) -> str:
        if (
            isinstance(site, ast.Expr)
            and isinstance(site.value, ast.Call)
            and site.value.args
        ):
            return self.ctx.source.segment(site.value.args[0]) or "the message"
        if isinstance(site, ast.Return) and site.value is not None:  # a response
            return self.ctx.source.segment(site.value) or "the message"
        return "the message"


class FieldRule(NamedTuple):
    """A refinement over message fields, wherever it was declared."""

    predicate: A.Expr  # names are field paths relative to where it was declared
    paths: frozenset[str]
    text: str
    declared: Declared


def _catalog_rule(spec: MsgSpec, inv: Invariant) -> FieldRule:
    declared = Declared(
        f"refinement of {spec.name}",
        inv.origin.path,
        inv.origin.line,
        owner=spec.name,
    )
    return FieldRule(inv.predicate, inv.paths, inv.text, declared)


def _object_rule(inv: ObjInvariant) -> FieldRule:
    return FieldRule(
        inv.predicate, inv.paths, inv.text, Declared(inv.what, inv.path, inv.line)
    )


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
