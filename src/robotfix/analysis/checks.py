"""The checks: refinements (via VCs), units, base types, initialisation, publish.

Every check reports at most once and then lets the analysis go on as if the
refinement held, so one bug gives one diagnostic, not a cascade.
"""

from __future__ import annotations

import ast
from fractions import Fraction

from robotfix import messages
from robotfix.analysis import containers, fixes, heap
from robotfix.analysis.context import SOLVER_BUDGET, FileContext
from robotfix.analysis.state import State
from robotfix.analysis.values import (
    SEQUENCES,
    Items,
    Kept,
    Value,
    replace,
)
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Refinement
from robotfix.annotations.units import Unit, converted
from robotfix.diagnostics import Span
from robotfix.messages import Declared
from robotfix.vc import VC, Proved, Undecided, Unproven, Violated

PROVED, WARNED, FAILED = "proved", "warned", "failed"
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

    def unit_of_sum(
        self, left: Value, right: Value, node: ast.AST, op: str
    ) -> tuple[Unit | None, bool]:
        if left.literal and right.literal:
            return None, True
        if left.literal or right.literal:
            return (right.unit if left.literal else left.unit), False
        if left.unit is None or right.unit is None:
            # one side's unit unknown (a loop's havoc, a parameter, a lost
            # product): a sum that means anything is in the other's unit, and
            # one that does not is the bug itself
            return (right.unit if left.unit is None else left.unit), False
        if left.unit.same_as(right.unit) and not left.factors and not right.factors:
            return left.unit, False
        # each side against the unit the other has after its converting factors
        # (`x_kmh / 3.6 + v`; `age > stale_s * 1000` compares s with ms)
        there = right.fit(converted(left.unit, left.factors))
        back = left.fit(converted(right.unit, right.factors))
        if (there is not None and there.kind == "ok") or (
            back is not None and back.kind == "ok"
        ):
            # the unit of a side its literal factors did not convert
            plain = [v for v in (left, right) if v.scale == 1.0 and not v.rad_free]
            return (plain[0] if plain else left).unit, False
        text = self.ctx.source.segment(node) or op
        if (
            there is not None
            and there.kind == "time"
            and (left.scale != 1.0 or right.scale != 1.0)
        ):  # `x + vx * 0.1`: a literal time step (RF203)
            stepped = right if right.scale != 1.0 else left
            kept = left if stepped is right else right
            found = stepped.fit(kept.unit)  # type: ignore[arg-type]
            assert found is not None
            self.ctx.report(
                messages.implicit_operand_change(
                    self.ctx.source.path,
                    self.ctx.source.span(node),
                    text,
                    found.got,
                    kept.unit,  # type: ignore[arg-type]
                    found.seconds,
                ),
                once=("operands", id(node)),
            )
            return kept.unit, False
        folded = [
            (found, other, unit)
            for found, other, unit in (
                (there, left, left.unit),
                (back, right, right.unit),
            )
            if found is not None and found.kind == "folded"
        ]
        if folded:  # `d < d_cm * 0.02`: maybe `/ 100 * 2` in one number (RF203)
            found, other, unit = folded[0]
            self.ctx.report(
                messages.folded_conversion(
                    self.ctx.source.path,
                    self.ctx.source.span(node),
                    text,
                    f"combines {unit} with",
                    converted(unit, other.factors),
                    found.got,
                    found.scale,
                ),
                once=("operands", id(node)),
            )
            return unit, False
        self.ctx.report(
            messages.operand_units(
                self.ctx.source.path,
                self.ctx.source.span(node),
                text,
                op,
                converted(left.unit, left.factors),  # `t * 1000` is in ms
                converted(right.unit, right.factors),
            ),
            once=("operands", id(node)),
        )
        return None, False

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
        length = self.ctx.derived_term(key, "int", description)
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
