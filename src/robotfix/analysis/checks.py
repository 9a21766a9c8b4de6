"""The checks: refinements (via VCs), units, base types, initialisation, publish.

Every check reports at most once and then lets the analysis go on as if the
refinement held, so one bug gives one diagnostic, not a cascade.
"""

from __future__ import annotations

import ast
from dataclasses import replace

from robotfix import messages
from robotfix.analysis import heap
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
KIND_NAMES = {
    "int": "int",
    "float": "float",
    "bool": "bool",
    "str": "str",
    "msg": "message",
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
        if isinstance(verdict, Unproven):
            verdict = self._arm_violated(state, goal, probes) or verdict
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
        self.ctx.report(
            messages.solver_unknown(self.path, span, stmt, predicate, verdict.reason)
        )
        return FAILED

    def _arm_violated(
        self, state: State, goal: A.Expr, probes: tuple[A.Expr, ...]
    ) -> Violated | None:
        """`a if c else b` is two paths: the goal fails on every execution of one
        of them (a reachable one), which is an error."""
        arms = [e for e in A.walk(goal) if isinstance(e, A.Ite)][:2]
        for arm in arms:
            for cond in (arm.cond, A.Unary("not", arm.cond)):
                facts = (*state.facts, cond)
                verdict = self.ctx.discharge(VC(facts, goal, probes))
                if isinstance(verdict, Violated):
                    return verdict
        return None

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

    def possible(self, state: State, condition: A.Expr) -> bool:
        """Can `condition` hold on this path? (Undecided counts as no.)"""
        verdict = self.ctx.discharge(VC(tuple(state.facts), A.Unary("not", condition)))
        return isinstance(verdict, (Violated, Unproven))

    def unbound_here(
        self, state: State, when: A.Expr, name: str, site: ast.AST
    ) -> bool:
        """RF301 if `name` is unbound on some path to this read (`when` holds)."""
        span, stmt = self.where(site)
        once = ("uninit", span.line, name)
        if self.ctx.already(once) or not self.possible(state, when):
            return False
        self.ctx.report(
            messages.used_before_assignment(
                self.path, span, stmt, name, False, some_paths=when != A.TRUE
            ),
            once=once,
        )
        state.assume(A.Unary("not", when))  # that path raised here
        return True

    def units_agree(
        self,
        expected: Unit | None,
        value: Value,
        site: ast.AST,
        target: str,
        declared: Declared,
    ) -> bool:
        got = value.unit
        if (
            expected is None
            or got is None
            or value.literal
            or value.fits_unit(expected)
        ):
            return True
        span, stmt = self.where(site)
        self.ctx.report(
            messages.unit_mismatch(
                self.path, span, stmt, target, expected, got, declared
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
        declared = Declared(f"annotation of `{name}`", self.path, decl.line)
        if value.kind == "msg":
            return value
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
        """A fresh value of `name` that satisfies its refinement."""
        value = self.ctx.fresh(decl.base, f"`{name}`", decl.unit)
        if value.term is not None:
            state.assume(A.substitute(decl.predicate, {**lookup, "_": value.term}))
        return value

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
                state.heap[value.ref].owner = (ref, name)
                obj.fields[name] = value
                self.check_whole(state, value.ref, site, publishing=False, single=True)
            else:
                obj.fields[name] = heap.new_message(
                    self.ctx, state, spec.msg_type or "", "unknown", owner=(ref, name)
                )
            return
        ok = spec.loose or self.base_fits(spec.kind, value, site, f"`{target}`")
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
        obj.fields[name] = replace(stored, default_of=None, unset=None)
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

    def _unset_on_some_path(
        self,
        state: State,
        spec: MsgSpec,
        inv: Invariant,
        value: Value,
        site: ast.AST,
        label: str,
    ) -> None:
        """RF302 for a field left unset on some path to a publish, where its
        default breaks its refinement."""
        unset = value.unset
        assert unset is not None
        owner_ref, fname = unset.owner
        owner = state.heap.get(owner_ref)
        if owner is None or fname in owner.reported:
            return
        path = next(iter(inv.paths))
        goal = A.substitute(inv.predicate, {path: unset.default})
        if not isinstance(self.ctx.discharge(VC((), goal)), Violated):
            return
        if not self.possible(state, unset.when):
            return
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
                f"{label}.{path}",
                A.show(unset.default),
                inv.text,
                declared,
                True,
                some_paths=True,
            )
        )
        owner.reported.add(fname)

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
        obj = state.heap.get(ref)
        spec = self.ctx.catalog.lookup(obj.type) if obj else None
        if obj is None or spec is None:
            return
        label = prefix or self._name_of(site)
        for inv in spec.invariants:
            self._check_invariant(
                state, ref, spec, inv, site, label, publishing, single
            )
        for fname, fs in spec.fields.items():
            if fs.kind == "msg" and not fs.array:
                sub = heap.read_raw(self.ctx, state, ref, fname, f"{label}.{fname}")
                if sub.ref is not None:
                    self.check_whole(
                        state, sub.ref, site, publishing, single, f"{label}.{fname}"
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
            p: heap.resolve_path(self.ctx, state, ref, p, label)
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
        if len(inv.paths) == 1:
            value = next(iter(values.values()))
            if value.unset is not None and publishing:
                self._unset_on_some_path(state, spec, inv, value, site, label)
            if not single:
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
