"""The checks of a value reaching a refined target: an assignment, an argument
bound to a refined parameter, a value leaving as a refined result
(`assign_refined`), and the value a refined name is assumed to hold (`assumed`).

`RefinedChecker` holds the scalar checks (`checks.Checker`) and the checks of
messages (`fieldchecks.FieldChecker`); a parameter read assigned to a refined
target goes to `paramchecks`.
"""

from __future__ import annotations

import ast

from robotfix.analysis import containers, frames, heap, paramchecks
from robotfix.analysis.checks import FAILED, WARNED, Checker
from robotfix.analysis.fieldchecks import FieldChecker
from robotfix.analysis.state import State
from robotfix.analysis.values import (
    MESSAGE_LIKE,
    Value,
    replace,
)
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Refinement
from robotfix.messages import Declared


class RefinedChecker:
    def __init__(self, core: Checker, fields: FieldChecker) -> None:
        self.core = core
        self.fields = fields
        self.ctx = core.ctx
        self.path = core.path

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
            read = paramchecks.read_of(self, value, site)
            if read is not None:  # a parameter read: its default is checked
                if read.default is not None and read.default_node is not None:
                    self.core.assign_sequence(
                        state, name, decl, read.default, read.default_node, lookup
                    )
                return self.assumed(state, name, decl, lookup)
            return self.core.assign_sequence(state, name, decl, value, site, lookup)
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
                rules = self.fields.message_rules(decl, name, lookup)
                self.fields.reach(state, value.ref, rules, site, name, leaving)
            return value
        read = paramchecks.read_of(self, value, site)
        if read is not None and paramchecks.attaches(read, decl, lookup):
            # a parameter read: the refinement becomes its own
            return paramchecks.attach(
                self, state, name, decl, value, site, lookup, read
            )
        if decl.elements is not None:
            return self._assign_elements(state, name, decl, value, site, lookup)
        if self.core.report_uninit(value, site, state):
            return self.assumed(state, name, decl, lookup)
        fits = self.core.base_fits(decl.base, value, site, f"`{name}`")
        agree = self.core.units_agree(
            decl.unit, value, site, f"`{name}`", declared, state
        )
        fits = agree and fits
        if not fits or value.term is None:
            return self.assumed(state, name, decl, lookup)
        for part in A.conjuncts(decl.predicate):
            goal = A.substitute(part, {**lookup, "_": value.term})
            shown = A.show(A.substitute(part, {"_": A.Name(name)}))
            outcome = self.core.goal_holds(
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
            found = containers.declared(decl.base, self.core.kept(name, decl, lookup))
            return self.core.with_length(found, name)
        if decl.base == "msg" and decl.msg_type is not None:
            message = heap.new_message(
                self.ctx, state, decl.msg_type, "received", label=name
            )
            assert message.ref is not None
            rules = self.fields.message_rules(decl, name, lookup)
            self.fields.assume_rules(state, message.ref, rules, name)
            frames.received_in(self.ctx, state, message.ref, decl.unit)
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
        self.fields.reach(
            state,
            stand_in.ref,
            self.fields.message_rules(decl, name, lookup),
            site,
            name,
            leaving,
        )
        del state.heap[stand_in.ref]
