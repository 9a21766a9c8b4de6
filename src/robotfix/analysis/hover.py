"""Editor hover text: what a variable, attribute, parameter or message field is (its
type, unit and refinement), in Markdown. Built only when an editor asks (see
`FileContext.hovers`); nothing here changes what the analysis finds.

A message, or a sub-message such as `linear` of a Twist, also lists the units of the
fields below it, as its enclosing messages declare them (REP 103, interface files).
"""

from __future__ import annotations

from robotfix.analysis import heap
from robotfix.analysis.context import FileContext
from robotfix.analysis.state import State
from robotfix.analysis.values import Value
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Refinement
from robotfix.ros.catalog import MsgSpec

MAX_LISTED = 16  # field paths listed under a message; the rest are counted
MAX_DEPTH = 4  # sub-message levels followed


def variable(
    ctx: FileContext, state: State, name: str, value: Value, decl: Refinement | None
) -> str:
    """A variable, parameter or attribute: its type, unit and refinement."""
    if value.kind == "msgclass" and value.name:
        return f"**{name}**: message class `{value.name}`" + _fields(
            ctx, [], value.name
        )
    kind = (
        value.name if value.kind in ("msg", "instance") and value.name else value.kind
    )
    if decl is not None and decl.base != "other":
        kind = (decl.msg_type or "message") if decl.base == "msg" else decl.base
        if decl.item is not None:
            kind = f"{decl.base}[{decl.item if decl.item != 'other' else 'Any'}]"
    parts = [f"**{name}**: `{kind}`"]
    unit = decl.unit if decl is not None and decl.unit is not None else value.unit
    if unit is not None:
        parts.append(
            f"in `{unit}`" if decl is None or decl.item is None else f"of `{unit}`"
        )
    if decl is not None and decl.predicate != A.TRUE:
        shown = A.show(decl.predicate)
        what = "each element" if decl.item is not None else "refinement"
        parts.append(f"— {what} `{shown}` (line {decl.line})")
    if decl is not None and decl.item is not None and decl.size != A.TRUE:
        parts.append(f"— length `{A.show(decl.size)}`")
    text = " ".join(parts)
    if value.kind == "msg" and value.ref in state.heap:
        assert value.ref is not None
        text += _fields(ctx, _outer(ctx, state, value.ref), state.heap[value.ref].type)
    elif decl is not None and decl.base == "msg" and decl.msg_type:
        text += _fields(ctx, [], decl.msg_type)
    return text


def field(ctx: FileContext, state: State, ref: int, name: str) -> str:
    """A message field: its type, unit and refinements."""
    msg_type = state.heap[ref].type
    spec = heap.field_spec(ctx, state, ref, name)
    if spec is None:
        return f"`{name}`: not a field of `{msg_type}`"
    outer = heap.contexts(ctx, state, ref, name)
    owner, path = (outer[0][0].name, outer[0][1]) if outer else (msg_type, name)
    kind = spec.msg_type if spec.kind == "msg" else spec.kind
    parts = [f"**{path}** of `{owner}`: `{kind}{'[]' if spec.array else ''}`"]
    unit = heap.field_unit(ctx, state, ref, name)[0]
    if unit is not None:
        parts.append(f"in `{unit}`")
    rules = [inv.text for _, _, inv in heap.invariants_on(ctx, state, ref, name)]
    if rules:
        parts.append("— refinements: " + ", ".join(f"`{r}`" for r in rules))
    text = " ".join(parts)
    if spec.kind == "msg" and spec.msg_type and not spec.array:
        text += _fields(ctx, outer, spec.msg_type)
    return text


def _outer(ctx: FileContext, state: State, ref: int) -> list[tuple[MsgSpec, str]]:
    """The messages around message `ref` (outermost first), with its path in each."""
    owner = state.heap[ref].owner
    return [] if owner is None else heap.contexts(ctx, state, *owner)


def _fields(ctx: FileContext, outer: list[tuple[MsgSpec, str]], msg_type: str) -> str:
    """The fields of `msg_type` that have a unit, as "fields: `x`, `y` in `m/s`";
    `outer` are the enclosing messages and this message's path in each."""
    found: list[tuple[str, str]] = []
    _collect(ctx, outer, msg_type, "", found, 0)
    if not found:
        return ""
    by_unit: dict[str, list[str]] = {}
    for path, unit in found[:MAX_LISTED]:
        by_unit.setdefault(unit, []).append(f"`{path}`")
    listed = "; ".join(f"{', '.join(paths)} in `{u}`" for u, paths in by_unit.items())
    more = len(found) - MAX_LISTED
    return f"\n\nfields: {listed}" + (f"; {more} more" if more > 0 else "")


def _collect(
    ctx: FileContext,
    outer: list[tuple[MsgSpec, str]],
    msg_type: str,
    prefix: str,
    found: list[tuple[str, str]],
    depth: int,
) -> None:
    spec = ctx.catalog.lookup(msg_type)
    if spec is None or depth > MAX_DEPTH:
        return
    chain = [*outer, (spec, "")]
    for name, info in spec.fields.items():
        here = [(s, f"{p}.{name}" if p else name) for s, p in chain]
        path = f"{prefix}{name}"
        if info.kind == "msg":
            if info.msg_type and not info.array:
                _collect(ctx, here, info.msg_type, f"{path}.", found, depth + 1)
            continue
        for owner, relative in here:  # the outermost declaration wins, as in checks
            declared = owner.units.get(relative)
            unit = heap.unit_of(declared.text) if declared is not None else None
            if unit is not None:
                found.append((path, str(unit)))
                break
