"""The checks: refinements (via VCs), units, base types, initialisation, publish.

Every check reports at most once and then lets the analysis go on as if the
refinement held, so one bug gives one diagnostic, not a cascade.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass, field, replace

from robotfix import messages
from robotfix.analysis import heap, parameters
from robotfix.analysis.context import FileContext
from robotfix.analysis.state import State
from robotfix.analysis.values import Value
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
}


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
        declared = Declared(
            f"annotation of `{name}`", decl.origin or self.path, decl.line
        )
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
        may be None: nothing is assumed; a tuple's elements each satisfy theirs)."""
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
        if spec.kind == "msg":
            if value.ref is not None and value.ref in state.heap:
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
            ok = self.units_agree(unit, value, site, f"`{target}`", decl) and ok
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
        obj.fields[name] = replace(stored, default_of=None)
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
        values = {
            p: heap.resolve_path(self.ctx, state, ref, p, label, settled=True)
            for p in sorted(inv.paths)
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
        goal = A.substitute(inv.predicate, terms)  # type: ignore[arg-type]
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
