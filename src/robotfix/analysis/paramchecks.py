"""The checks of a parameter read assigned to a refined target (`x: Annotated[float,
"0 < _ <= 1"] = self.declare_parameter('x', 0.5).value`): the refinement becomes
the parameter's, its default is checked against it, and the value is assumed to
satisfy it (parameter files are checked against it, `robotfix.paramcheck`).
The refinement checks (`analysis/refined.py`) call them; what they need of those
is `Checks`.
"""

from __future__ import annotations

import ast
from dataclasses import replace
from typing import Protocol

from robotfix import messages
from robotfix.analysis.context import FileContext
from robotfix.analysis.imported import RefinedChecks
from robotfix.analysis.parameters import ParamContext, ParamRead
from robotfix.analysis.state import State
from robotfix.analysis.values import Value
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Refinement
from robotfix.messages import Declared
from robotfix.vc import VC, Violated


class Scalar(Protocol):
    """What they need of the scalar checks (`checks.Checker`)."""

    def base_fits(
        self, expected: str, value: Value, site: ast.AST, target: str
    ) -> bool: ...

    def goal_holds(
        self,
        state: State,
        goal: A.Expr,
        probe: A.Expr | None,
        site: ast.AST,
        predicate: str,
        subject: str,
        declared: Declared,
    ) -> str: ...


class Checks(RefinedChecks, Protocol):
    """What the checks of a parameter read need of the refinement checks
    (`refined.RefinedChecker`), which call them: `assumed`, and the following."""

    @property
    def ctx(self) -> FileContext: ...

    @property
    def path(self) -> str: ...

    @property
    def core(self) -> Scalar: ...


def read_of(check: Checks, value: Value, site: ast.AST) -> ParamRead | None:
    """The parameter read `value` comes from, when it is assigned right where it
    was read (`x: Annotated[...] = self.declare_parameter(...).value`) and so the
    target's refinement becomes the parameter's."""
    params = check.ctx.parameters
    term = value.term
    if not isinstance(params, ParamContext) or not isinstance(term, A.Sym):
        return None
    read = params.reads.get(term.ident)
    if read is None or not read.attach:
        return None
    if getattr(site, "value", None) is not read.node:
        return None
    return read


def attaches(read: ParamRead, decl: Refinement, lookup: dict[str, A.Expr]) -> bool:
    """Whether a read's target refinement becomes the parameter's: always where it
    is declared; a later `get_parameter` read only when the refinement speaks of
    the value and constants alone (`_ == before` is no contract of a parameter)."""
    if not read.later:
        return True
    return not any(
        A.syms(lookup[n.name])
        for n in A.names(decl.predicate)
        if n.name != "_" and n.name in lookup
    )


def attach(
    check: Checks,
    state: State,
    name: str,
    decl: Refinement,
    value: Value,
    site: ast.AST,
    lookup: dict[str, A.Expr],
    read: ParamRead,
) -> Value:
    """A parameter read assigned to a refined target: the default is checked
    against the refinement (RF101 naming the default), and the value is assumed to
    satisfy it (parameter files are checked against it, `robotfix.paramcheck`)."""
    target = f"`{name}`"
    if not check.core.base_fits(decl.base, value, site, target):
        return check.assumed(state, name, decl, lookup)
    if value.kind == decl.base or (value.kind == "int" and decl.base == "float"):
        stored = value
    else:
        stored = check.ctx.fresh(decl.base, f"parameter `{read.name}`")
    if read.later and _never(check, state, decl, stored, site, name, lookup):
        return check.assumed(state, name, decl, lookup)
    default = read.default
    if (
        default is not None
        and default.term is not None
        and read.default_node is not None
        and check.core.base_fits(decl.base, default, read.default_node, target)
    ):
        _check_default(check, state, name, decl, default, read, lookup)
    if stored.term is not None:
        state.assume(A.substitute(decl.predicate, {**lookup, "_": stored.term}))
    return replace(stored, unit=decl.unit, literal=False) if decl.unit else stored


def _never(
    check: Checks,
    state: State,
    decl: Refinement,
    stored: Value,
    site: ast.AST,
    name: str,
    lookup: dict[str, A.Expr],
) -> bool:
    """A refinement no value of the declared range satisfies is RF101 at the read
    (`_ < 5` of a parameter in [5, 10]), as for any read, and is not assumed."""
    if stored.term is None:
        return False
    declared = Declared(f"annotation of `{name}`", decl.origin or check.path, decl.line)
    for part in A.conjuncts(decl.predicate):
        goal = A.substitute(part, {**lookup, "_": stored.term})
        verdict = check.ctx.discharge(VC(tuple(state.facts), goal, (stored.term,)))
        if isinstance(verdict, Violated):
            shown = A.show(A.substitute(part, {"_": A.Name(name)}))
            check.core.goal_holds(
                state, goal, stored.term, site, shown, f"`{name}`", declared
            )
            return True
    return False


def _check_default(
    check: Checks,
    state: State,
    name: str,
    decl: Refinement,
    default: Value,
    read: ParamRead,
    lookup: dict[str, A.Expr],
) -> None:
    assert default.term is not None and read.default_node is not None
    declared = Declared(f"annotation of `{name}`", check.path, decl.line)
    for part in A.conjuncts(decl.predicate):
        goal = A.substitute(part, {**lookup, "_": default.term})
        verdict = check.ctx.discharge(VC(tuple(state.facts), goal, (default.term,)))
        if isinstance(verdict, Violated):
            shown = A.show(A.substitute(part, {"_": A.Name(name)}))
            text = check.ctx.source.segment(read.default_node) or A.show(default.term)
            check.ctx.report(
                messages.parameter_value_violated(
                    check.path,
                    check.ctx.source.span(read.default_node),
                    f"the default `{text}` of parameter `{read.name}`",
                    f"`{shown}`",
                    declared,
                    "ROS uses the default when no parameter file or launch "
                    "argument sets the parameter",
                ),
                # a default read into several targets with one refinement: once
                once=("parameter-default", id(read.default_node), A.show(part)),
            )
            return
