"""The checks: refinements (via VCs), units, base types, initialisation, publish.

Every check reports at most once and then lets the analysis go on as if the
refinement held, so one bug gives one diagnostic, not a cascade.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass, field
from fractions import Fraction
from typing import NamedTuple

from robotfix import messages
from robotfix.analysis import containers, fixes, frames, heap, parameters
from robotfix.analysis.context import SOLVER_BUDGET, FileContext
from robotfix.analysis.state import State
from robotfix.analysis.values import (
    MESSAGE_LIKE,
    SEQUENCES,
    Items,
    Kept,
    MaybeDefault,
    ObjInvariant,
    Value,
    replace,
)
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Refinement
from robotfix.annotations.units import Unit
from robotfix.annotations.witness import closed_value
from robotfix.diagnostics import Span
from robotfix.messages import Declared
from robotfix.ros.catalog import FieldSpec, FieldUnit, Invariant, MsgSpec
from robotfix.vc import VC, Proved, Undecided, Unproven, Violated

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
_SIZED = SEQUENCES | {"unknown"}  # values `len()` of one object is one term for


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
        facts = (*state.facts, *self.ranges(goal))
        verdict = self.ctx.discharge(VC(facts, goal, probes))
        if isinstance(verdict, Proved):
            return PROVED
        span, stmt = self.where(site)
        if isinstance(verdict, Unproven):
            arm = self._arm_violated(state, goal, probes)
            if arm is not None:
                verdict, facts = arm
        if isinstance(verdict, Violated):
            value = verdict.probe_values[0] if verdict.probe_values else None
            if value is not None and probe is not None:
                value = self._only_value(facts, probe, value)
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
        if verdict.out_of_budget:  # the analysis stops at its next step
            self.ctx.report(
                messages.solver_budget(self.path, span, stmt, predicate),
                once=SOLVER_BUDGET,
            )
            return FAILED
        self.ctx.report(
            messages.solver_unknown(self.path, span, stmt, predicate, verdict.reason)
        )
        return FAILED

    def ranges(self, goal: A.Expr) -> list[A.Expr]:
        """The type ranges of the received integer fields `goal` names (`uint8`
        data: `0 <= data <= 255`): asked only where a question involves one."""
        if not self.ctx.ranged:
            return []
        found = ((s, self.ctx.ranged.get(s.ident)) for s in A.syms(goal))
        return [heap.within(values, sym) for sym, values in found if values]

    def _only_value(
        self, facts: tuple[A.Expr, ...], probe: A.Expr, value: str
    ) -> str | None:
        """The value that breaks the refinement, if it is the only one possible
        there; when paths that joined give several (`5` or `7`), naming one would
        be arbitrary."""
        shown = _term_of(value)
        if shown is None or isinstance(probe, A.Num):
            return value
        goal = A.Binary("==", probe, shown)
        unique = self.ctx.discharge(VC(facts, goal))
        return value if isinstance(unique, Proved) else None

    def _arm_violated(
        self, state: State, goal: A.Expr, probes: tuple[A.Expr, ...]
    ) -> tuple[Violated, tuple[A.Expr, ...]] | None:
        """`a if c else b` is two paths: the goal fails on every execution of one
        of them (a reachable one), which is an error. The verdict and that path."""
        arms = [e for e in A.walk(goal) if isinstance(e, A.Ite)][:2]
        for arm in arms:
            for cond in (arm.cond, A.Unary("not", arm.cond)):
                facts = (*state.facts, cond)
                verdict = self.ctx.discharge(VC(facts, goal, probes))
                if isinstance(verdict, Violated):
                    return verdict, facts
        return None

    def _describe(self, ident: int) -> str:
        return self.ctx.describe(ident)

    def report_uninit(self, value: Value, site: ast.AST, state: State) -> bool:
        """Is `value` a read of a name that holds nothing? RF301 if that path can
        run."""
        if value.uninit is None:
            return False
        once = ("uninit", getattr(site, "lineno", 1), value.uninit.name)
        if self.ctx.already(once) or (state.facts and not self.possible(state, A.TRUE)):
            return True
        span, stmt = self._read_where(site, value.uninit.name)
        self.ctx.report(
            messages.used_before_assignment(
                self.path, span, stmt, value.uninit.name, value.uninit.declared
            ),
            once=once,
        )
        return True

    def _read_where(
        self, site: ast.AST, name: str, read: ast.AST | None = None
    ) -> tuple[Span, str]:
        """The span of the read of `name` (`read`, else its first read in the
        statement `site`): the caret goes under the name, at its line; and the
        statement's text."""
        if read is None:
            reads = [
                n
                for n in ast.walk(site)
                if isinstance(n, ast.Name)
                and n.id == name
                and isinstance(n.ctx, ast.Load)
            ]
            read = min(reads, key=lambda n: (n.lineno, n.col_offset), default=site)
        return self.ctx.source.span(read), self.ctx.source.statement_text(site)

    def possible(self, state: State, condition: A.Expr) -> bool:
        """Can `condition` hold on this path? (Undecided counts as no.)"""
        goal = A.Unary("not", condition)
        verdict = self.ctx.discharge(VC(tuple(state.facts), goal, question=True))
        return isinstance(verdict, (Violated, Unproven))

    def surely_possible(self, state: State, condition: A.Expr) -> bool:
        """`possible`, also if no call changed the objects they were handed: two
        tests of `self.flag` with a call between agree, for all the analysis
        can tell, so a path on which they differ is not surely one a run takes."""
        if not self.possible(state, condition):
            return False
        firm = state.shared.firm
        unchanged = {
            ident: first
            for ident, (first, read) in self.ctx.unchanged.items()
            if read not in firm
        }
        if not unchanged:
            return True
        memo: dict[int, A.Expr] = {}
        facts = [_first_reads(f, unchanged, memo) for f in state.facts]
        goal = A.Unary("not", _first_reads(condition, unchanged, memo))
        verdict = self.ctx.discharge(VC(tuple(facts), goal, question=True))
        return isinstance(verdict, (Violated, Unproven))

    def unbound_here(
        self,
        state: State,
        when: A.Expr,
        name: str,
        site: ast.AST,
        read: ast.AST | None = None,
        scope: ast.AST | None = None,
    ) -> bool:
        """RF301 if `name` is unbound on some path to this read (`when` holds);
        `read`: the Name read, `scope`: the function whose local it is (the
        message names where else it is assigned)."""
        once = ("uninit", getattr(site, "lineno", 1), name)
        cause = ("unbound", name, when)  # one bug, one diagnostic, however many reads
        if when != A.TRUE and self.ctx.already(cause):
            return False
        if self.ctx.already(once) or not self.surely_possible(state, when):
            return False
        if when != A.TRUE:
            self.ctx.report_once(cause)
        span, stmt = self._read_where(site, name, read)
        assigned = None
        if when == A.TRUE and scope is not None:
            assigned = _first_assignment(scope, name)
        self.ctx.report(
            messages.used_before_assignment(
                self.path,
                span,
                stmt,
                name,
                False,
                some_paths=when != A.TRUE,
                assigned=assigned,
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
        state: State | None = None,
        some_paths: bool = False,
    ) -> bool:
        """Whether `value` fits the unit `expected` of `target`; a report if not.
        With `state`: a number merged at a join from ones in different units does
        not fit if one that does not is feasible on its path (RF201, "on some
        path": the error is a real bug on that path)."""
        found = None if expected is None else value.fit(expected)
        if expected is not None and found is None and state is not None:
            bad = self._bad_choice(expected, value, state)
            if bad is not None:  # reported as that path's value, "on some path"
                return self.units_agree(
                    expected, bad, site, target, declared, some_paths=True
                )
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
        done = value.conversion
        called = None if done is None else (done.call, done.argument)
        if found.kind == "folded":  # `d_cm * 0.02` into m: maybe / 100 * 2
            self.ctx.report(
                messages.folded_conversion(
                    self.path,
                    span,
                    stmt,
                    f"gives {target}",
                    expected,
                    found.got,
                    found.scale,
                    declared,
                )
            )
            return True
        source = self.ctx.source
        stored = fixes.stored(source, site)
        within = site if stored is None else stored
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
                found.twice,
                called,
                some_paths=some_paths,
                value=fixes.written(source, stored),
                undo=(
                    fixes.undo_factor(source, within, found.twice)
                    if found.twice is not None
                    else fixes.undo_call(source, within, done.call)
                    if done is not None
                    else None
                ),
                angles=fixes.angles(source),
            ),
            once=None if done is None else done.twice,  # replaces the deferred one
        )
        return False

    def _bad_choice(self, expected: Unit, value: Value, state: State) -> Value | None:
        """What a number merged at a join is on a feasible path where its unit does
        not fit `expected` (a warning's doubt is no path's error), if any."""
        for option in value.options():
            found = option.value.fit(expected)
            if found is None or found.kind != "mismatch":
                continue
            when = A.conjoin([*state.pending(option.defs), option.when])
            if self.surely_possible(state, when):
                return option.value
        return None

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
        leaving: bool = False,
    ) -> Value:
        """Check `name = value` against its refinement; return what `name` holds.
        (`leaving`: an argument, whose unset message fields count too.)"""
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
        declared = Declared(
            f"annotation of `{name}`", decl.origin or self.path, decl.line
        )
        if decl.optional and value.kind == "none":
            return value
        if decl.base == "msg" and value.kind in MESSAGE_LIKE and value.ref is None:
            # a message the analysis does not follow (two joined at an `if`, one
            # a loop changed): any message of the type, so nothing is proved
            self._reach_any(state, name, decl, site, lookup, leaving)
            return value
        if value.kind == "msg":
            if decl.base == "msg" and value.ref is not None:
                frames.check_message(
                    self.ctx, state, value.ref, decl.unit, site, declared
                )
                rules = self.message_rules(decl, name, lookup)
                self.reach(state, value.ref, rules, site, name, leaving)
            return value
        read = parameters.read_of(self, value, site)
        if read is not None and parameters.attaches(read, decl, lookup):
            # a parameter read: the refinement becomes its own
            return parameters.attach(self, state, name, decl, value, site, lookup, read)
        if decl.elements is not None:
            return self._assign_elements(state, name, decl, value, site, lookup)
        if self.report_uninit(value, site, state):
            return self.assumed(state, name, decl, lookup)
        fits = self.base_fits(decl.base, value, site, f"`{name}`")
        agree = self.units_agree(decl.unit, value, site, f"`{name}`", declared, state)
        fits = agree and fits
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
        if decl.base == "msg" and decl.msg_type is not None:
            message = heap.new_message(
                self.ctx, state, decl.msg_type, "received", label=name
            )
            assert message.ref is not None
            rules = self.message_rules(decl, name, lookup)
            self.assume_rules(state, message.ref, rules, name)
            return message
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
            Declared(f"annotation of `{name}`", decl.origin or self.path, decl.line),
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
        if self.report_uninit(value, site, state):
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

    def length_of(
        self, state: State, value: Value, description: str | ast.AST
    ) -> A.Expr | None:
        """The length of a list or tuple no size pins, as one term for one object
        until something may change it: `len(xs)` in code and `len(_)` in the
        refinement it is checked against are the same number."""
        if not isinstance(value.term, A.Sym) or value.kind not in _SIZED:
            return None
        key = ("len", value.term.ident, state.version(value.term))
        length = self.ctx.derived(key, "int", description).known_term
        state.assume(A.Binary(">=", length, containers.number(0)))
        return length

    def check_size(self, state: State, value: Value, kept: Kept, site: ast.AST) -> bool:
        """The length of `value` keeps `kept.size` (a warning when not provable)."""
        length = containers.length_term(value) if value.kind in SEQUENCES else None
        if length is None:
            length = self.length_of(state, value, f"`len({kept.label})`")
        if length is not None and A.syms(length):  # what else its size says of it
            state.assume(containers.at(containers.size_of(value), length))
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
        return found + [_object_rule(inv) for inv in obj.extra]

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
        if refined and self.report_uninit(value, site, state):
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
            or self.base_fits(spec.kind, value, site, f"`{target}`")
        )
        ok = ok and self._in_type_range(state, ref, name, spec, value, site, target)
        if unit_decl is not None and owner is not None:
            decl = self._field_declared(owner, name, unit_decl)
            framed, frame_decl = frames.expected_unit(self.ctx, state, ref, name, unit)
            if frame_decl is not None and frames.frame_of(value.unit) is not None:
                decl = frame_decl  # the frame is what can differ
            ok = (
                self.units_agree(framed, value, site, f"`{target}`", decl, state) and ok
            )
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
            outcome = self.goal_holds(
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
            ranges = self.ranges(goal)
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
        span, stmt = self.where(site)
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
        if state.facts and not some_paths and not self.possible(state, A.TRUE):
            return False  # a path no execution takes (`if c: ... if not c: send`)
        span, stmt = self.where(site)
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
        if not self.surely_possible(state, unset.when):
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
        self.goal_holds(state, goal, None, site, rule.text, label, rule.declared)

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
            self._check_invariant(
                state, ref, _object_rule(inv), site, label, leaving, True, leaving
            )
        obj.extra += tuple(inv for inv in rules if inv not in obj.extra)
        state.shared.extras = True

    def _reach_any(
        self,
        state: State,
        name: str,
        decl: Refinement,
        site: ast.AST,
        lookup: dict[str, A.Expr],
        leaving: bool,
    ) -> None:
        """A value the analysis does not follow reaches a refined message: checked
        as a received message of the type, whose fields may hold anything."""
        if decl.msg_type is None or self.ctx.catalog.lookup(decl.msg_type) is None:
            return
        stand_in = heap.new_message(
            self.ctx, state, decl.msg_type, "received", label=name
        )
        assert stand_in.ref is not None
        self.reach(
            state,
            stand_in.ref,
            self.message_rules(decl, name, lookup),
            site,
            name,
            leaving,
        )
        del state.heap[stand_in.ref]

    def assume_rules(
        self, state: State, ref: int, rules: tuple[ObjInvariant, ...], label: str
    ) -> None:
        """A refined message that is read (a parameter, an attribute): its
        refinement holds, and keeps holding."""
        obj = state.heap.get(ref)
        if obj is None:
            return
        for inv in rules:
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


def _first_assignment(scope: ast.AST, name: str) -> int | None:
    """The line of the first `name = ...` (or loop or `with` target) in a
    function's own body, not in the functions and classes it defines."""
    found: list[int] = []
    todo = list(ast.iter_child_nodes(scope))
    while todo:
        node = todo.pop()
        if isinstance(node, ast.Name) and node.id == name:
            if isinstance(node.ctx, ast.Store):
                found.append(node.lineno)
        elif not isinstance(
            node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda)
        ):
            todo.extend(ast.iter_child_nodes(node))
    return min(found, default=None)


def _first_reads(
    expr: A.Expr, unchanged: dict[int, A.Sym], memo: dict[int, A.Expr]
) -> A.Expr:
    """`expr` with each read of a changed object replaced by its first read."""
    found = memo.get(id(expr))
    if found is not None:
        return found
    if type(expr) is A.Sym:
        result: A.Expr = unchanged.get(expr.ident, expr)
    else:
        kids = A.children(expr)
        result = (
            A.rebuild(expr, tuple(_first_reads(k, unchanged, memo) for k in kids))
            if kids
            else expr
        )
    memo[id(expr)] = result
    return result


def _term_of(shown: str) -> A.Expr | None:
    """A solver value as printed (`5`, `2.5`, `1/3`, `True`, `'a'`) as a term."""
    if shown in ("True", "False"):
        return A.Bool(shown == "True")
    if len(shown) >= 2 and shown[0] == shown[-1] == "'":
        return A.Str(shown[1:-1])
    try:
        number = Fraction(shown)
    except (ValueError, ZeroDivisionError):
        return None
    return A.Num(number, number.denominator == 1 and "." not in shown)


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
