"""Messages on the heap: construction, defaults, received messages, field units.

A field path is looked up from the outermost enclosing message inward, so a
refinement or unit declared on `Twist` for `linear.x` applies to `move.linear.x` but
not to a free-standing `Vector3`.
"""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction

from robotfix.analysis import containers
from robotfix.analysis.context import FileContext
from robotfix.analysis.state import State
from robotfix.analysis.values import (
    Items,
    Kept,
    MaybeDefault,
    MsgObj,
    ObjInvariant,
    Value,
)
from robotfix.annotations import ast as A
from robotfix.annotations.units import Unit, UnitError, label, resolve
from robotfix.messages import Declared
from robotfix.ros.catalog import (
    COMMENT,
    SUFFIX,
    FieldSpec,
    FieldUnit,
    Invariant,
    MsgSpec,
    constant_term,
)

DEFAULTS: dict[str, A.Expr] = {
    "int": A.Num(Fraction(0), True),
    "float": A.Num(Fraction(0), False),
    "bool": A.Bool(False),
    "str": A.Str(""),
}


def new_message(
    ctx: FileContext,
    state: State,
    msg_type: str,
    origin: str,
    owner: tuple[int, str] | None = None,
    label: str = "the message",
    stable: bool = False,
) -> Value:
    """A message; `label` names it in counterexamples (`request` in `request.a`).
    A received one satisfies its invariants: they are assumed when the code first
    reads or writes one of its fields (`settle`), and its sub-messages exist only
    once read, so a type with a fan-out of sub-messages costs what the code reads.
    A `stable` sub-message, one that was there all along, has the same id on every
    path."""
    ref = ctx.sub_id(*owner) if stable and owner else ctx.fresh_id()
    state.heap[ref] = MsgObj(
        msg_type, origin, owner=owner, pending=origin == "received", label=label
    )
    return Value("msg", ref=ref, name=msg_type)


def settle(ctx: FileContext, state: State, ref: int) -> None:
    """Assume the invariants of a received message's type, once, before the code
    touches its fields (the values they constrain are then still those received)."""
    obj = state.heap.get(ref)
    if obj is None or not obj.pending:
        return
    obj.pending = False
    spec = ctx.catalog.lookup(obj.type)
    if obj.origin != "received" or spec is None:
        return
    for inv in ctx.invariants(spec):
        predicate = lengths_resolved(ctx, state, ref, inv.predicate, obj.label)
        paths = {n.name for n in A.names(predicate)}
        terms = {p: resolve_path(ctx, state, ref, p, obj.label).term for p in paths}
        if all(t is not None for t in terms.values()):
            state.assume(A.substitute(predicate, terms))  # type: ignore[arg-type]


def chain(state: State, ref: int, name: str) -> list[tuple[int, str]]:
    """(message ref, path of field `name` relative to it) for `ref` and each message
    that holds it, outermost first."""
    out: list[tuple[int, str]] = []
    path = name
    current: int | None = ref
    while current is not None and current in state.heap and len(out) < 32:
        out.append((current, path))
        owner = state.heap[current].owner
        if owner is None:
            break
        current, path = owner[0], f"{owner[1]}.{path}"
    out.reverse()
    return out


def contexts(
    ctx: FileContext, state: State, ref: int, name: str
) -> list[tuple[MsgSpec, str]]:
    """(message spec, path relative to it) for field `name` of `ref`, outermost
    first."""
    out: list[tuple[MsgSpec, str]] = []
    path = name
    current: int | None = ref
    seen: set[int] = set()
    while current is not None and current in state.heap and current not in seen:
        seen.add(current)
        obj = state.heap[current]
        spec = ctx.catalog.lookup(obj.type)
        if spec is not None:
            out.append((spec, path))
        if obj.owner is None:
            break
        current, path = obj.owner[0], f"{obj.owner[1]}.{path}"
    out.reverse()
    return out


def owns(state: State, ref: int, inner: int) -> bool:
    """Whether message `inner` is `ref` or encloses it."""
    current: int | None = ref
    seen: set[int] = set()
    while current is not None and current in state.heap and current not in seen:
        if current == inner:
            return True
        seen.add(current)
        owner = state.heap[current].owner
        current = owner[0] if owner is not None else None
    return False


def extras_on(state: State, ref: int, name: str) -> list[tuple[ObjInvariant, str]]:
    """Refinements of variables that a message reached (`Annotated[Twist, ...]`)
    that mention only field `name` of `ref` (and what lies below it)."""
    found: list[tuple[ObjInvariant, str]] = []
    if not state.shared.extras:
        return found
    current: int | None = ref
    path = name
    for _ in range(32):
        obj = state.heap.get(current) if current is not None else None
        if obj is None:
            break
        for inv in obj.extra:
            if inv.unit is None and all(
                p == path or p.startswith(path + ".") for p in inv.paths
            ):
                found.append((inv, path))
        if obj.owner is None:
            break
        current, path = obj.owner[0], f"{obj.owner[1]}.{path}"
    return found


def below(ctx: FileContext, state: State, ref: int, name: str) -> set[str]:
    """Paths inside the message in field `name` of `ref` that have a unit or a
    refinement there: what a sub-message stored into that field must satisfy."""
    found: set[str] = set()
    for current, path in chain(state, ref, name):
        prefix = path + "."
        spec = ctx.catalog.lookup(state.heap[current].type)
        paths = [inv.paths for inv in state.heap[current].extra]
        if spec is not None:
            found.update(k[len(prefix) :] for k in spec.units if k.startswith(prefix))
            paths += [inv.paths for inv in spec.invariants]
        for group in paths:
            found.update(p[len(prefix) :] for p in group if p.startswith(prefix))
    return found


def field_spec(ctx: FileContext, state: State, ref: int, name: str) -> FieldSpec | None:
    spec = ctx.catalog.lookup(state.heap[ref].type)
    return None if spec is None else spec.fields.get(name)


def field_unit(
    ctx: FileContext, state: State, ref: int, name: str
) -> tuple[Unit | None, FieldUnit | None, MsgSpec | None]:
    for spec, path in contexts(ctx, state, ref, name):
        declared = spec.units.get(path)
        if declared is not None:
            return unit_of(declared.text), declared, spec
    extras = unit_extras(state, ref, name) if state.shared.extras else []
    return (unit_of(extras[0].unit or ""), None, None) if extras else (None, None, None)


def unit_extras(state: State, ref: int, name: str) -> list[ObjInvariant]:
    """`Unit(field) == "u"` of the refined values the message holding field `name`
    (or one enclosing it) reached."""
    return [
        inv
        for current, path in chain(state, ref, name)
        for inv in state.heap[current].extra
        if inv.unit is not None and inv.paths == {path}
    ]


def unit_declared_at(owner: MsgSpec, name: str, unit_decl: FieldUnit) -> Declared:
    """Where the unit of field `name` of an `owner` message was written: REP 103
    or a shipped definition's comment (`unit_decl.source` says which), or a line
    of the user's interface file, named as a comment's unit or a name's suffix
    when it is one (newuser2 §7: "name the `[us]` comment as the source")."""
    what = f"unit of {owner.name}"
    origin = unit_decl.origin
    if origin is None:
        return Declared(what, None, None, unit_decl.source, owner.name)
    field = name.rsplit(".", 1)[-1]
    written = {
        COMMENT: f"`{unit_decl.text}` in the comment of `{field}`",
        SUFFIX: f"`{unit_decl.text}` from the suffix of `{field}` (unit-suffixes)",
    }.get(unit_decl.source, "")
    return Declared(what, origin.path, origin.line, owner=owner.name, written=written)


def unit_of(text: str) -> Unit | None:
    kind, sep, rest = text.partition(":")
    if sep and kind in ("frame", "tag"):
        return label(kind, rest)
    try:
        return resolve(text)
    except UnitError:
        return None  # already reported where the unit was declared


def invariants_on(
    ctx: FileContext, state: State, ref: int, name: str
) -> list[tuple[MsgSpec, str, Invariant]]:
    """Invariants that mention only field `name` (and what lies below it)."""
    found = []
    for spec, path in contexts(ctx, state, ref, name):
        for inv in ctx.invariants(spec):
            if all(p == path or p.startswith(path + ".") for p in inv.paths):
                found.append((spec, path, inv))
    return found


def read_raw(
    ctx: FileContext, state: State, ref: int, name: str, description: str
) -> Value:
    """The value of a field, without any check; an unset field gives its default,
    marked with `default_of`."""
    obj = state.heap[ref]
    if name in obj.fields:
        return state.use(obj.fields[name])
    spec = field_spec(ctx, state, ref, name)
    if spec is None:
        return Value("unknown")
    if spec.array:
        return _array(ctx, state, ref, name, spec, description)
    if spec.kind == "msg" and not spec.array and spec.msg_type:
        sub = new_message(
            ctx,
            state,
            spec.msg_type,
            obj.origin,
            (ref, name),
            f"{obj.label}.{name}",
            stable=True,
        )
        obj.fields[name] = sub
        return sub
    unit = field_unit(ctx, state, ref, name)[0]
    if spec.kind not in DEFAULTS:
        value = Value("unknown", unit=unit)
        obj.fields[name] = value
        return value
    if obj.origin == "constructed" and name not in obj.reported:
        return Value(spec.kind, default_of(ctx, spec), unit, default_of=(ref, name))
    value = ctx.fresh(spec.kind, description, unit)
    if spec.values is not None and obj.origin == "received":
        ctx.ranged[value.term.ident] = spec.values  # type: ignore[union-attr]
    obj.fields[name] = value
    return value


def within(values: tuple[int, int], term: A.Expr) -> A.Expr:
    """`low <= term <= high` for an integer field's type range (`uint8`)."""
    low, high = (containers.number(v) for v in values)
    return A.Binary("and", A.Binary("<=", low, term), A.Binary("<=", term, high))


def _array(
    ctx: FileContext,
    state: State,
    ref: int,
    name: str,
    spec: FieldSpec,
    description: str,
) -> Value:
    """An array field: a sequence whose elements satisfy the field's refinements.
    Never set, it is its default: empty, or `size` zeros for a fixed-size array."""
    obj = state.heap[ref]
    kept = array_rule(ctx, state, ref, name, spec, description)
    if obj.origin == "constructed" and name not in obj.reported:
        return replace(default_array(spec, kept), default_of=(ref, name))
    if spec.size is not None:
        size: A.Expr = A.Binary("==", containers.SELF, containers.number(spec.size))
    else:
        length = ctx.fresh("int", f"`len({description})`").known_term
        size = A.conjoin(
            [
                A.Binary("==", containers.SELF, length),
                A.Binary(">=", containers.SELF, containers.number(0)),
            ]
        )
    size = A.conjoin([size, kept.size]) if kept.size != A.TRUE else size
    each = kept.each
    if spec.values is not None and obj.origin == "received":  # each element's range
        each = A.conjoin([within(spec.values, containers.SELF), *A.conjuncts(each)])
    message = (
        (spec.msg_type, obj.origin) if spec.kind == "msg" and spec.msg_type else None
    )
    items = Items(kept.item, each, size, kept, message=message)
    value = Value("list", unit=kept.unit, items=items)
    obj.fields[name] = value
    return value


def default_array(spec: FieldSpec, kept: Kept) -> Value:
    """What an array field never set holds: no element, or `size` zeros."""
    count = spec.size or 0
    zero = DEFAULTS.get(spec.kind)
    size = A.Binary("==", containers.SELF, containers.number(count))
    if zero is not None and count <= containers.MAX_SPELLED:
        element = Value(spec.kind, zero, kept.unit)
        return Value(
            "list",
            unit=kept.unit,
            elements=(element,) * count,
            items=Items(kept.item, kept.each, size, kept),
        )
    each = A.Binary("==", containers.SELF, zero) if zero is not None else A.TRUE
    return Value("list", unit=kept.unit, items=Items(kept.item, each, size, kept))


def array_rule(
    ctx: FileContext,
    state: State,
    ref: int,
    name: str,
    spec: FieldSpec,
    label: str,
) -> Kept:
    """What every value of array field `name` must satisfy: its elements' kind and
    unit, the `#RobotFix#` parts on its elements and on its length (`len(...)`),
    and its fixed size or bound."""
    each: list[A.Expr] = []
    size: list[A.Expr] = []
    declared: Declared | None = None
    for owner, path, inv in invariants_on(ctx, state, ref, name):
        on_each, on_size = array_parts(inv.predicate, path)
        each += [on_each] if on_each != A.TRUE else []
        size += [on_size] if on_size != A.TRUE else []
        if declared is None:
            declared = Declared(
                f"refinement of {owner.name}",
                inv.origin.path,
                inv.origin.line,
                owner=owner.name,
            )
    shape: list[A.Expr] = []
    if spec.size is not None:
        shape.append(A.Binary("==", containers.SELF, containers.number(spec.size)))
    if spec.bound is not None:
        shape.append(A.Binary("<=", containers.SELF, containers.number(spec.bound)))
    unit, unit_decl, unit_owner = field_unit(ctx, state, ref, name)
    unit_declared: Declared | None = None
    if unit_decl is not None and unit_owner is not None:
        unit_declared = unit_declared_at(unit_owner, name, unit_decl)
    msg_type = state.heap[ref].type
    declared = (
        declared
        or unit_declared
        or Declared(
            f"definition of {msg_type}", None, None, "its interface file", msg_type
        )
    )
    kind = spec.kind if spec.kind in DEFAULTS else "unknown"
    return Kept(
        kind,
        unit,
        A.conjoin(each),
        A.conjoin(size),
        label,
        declared,
        unit_declared,
        A.conjoin(shape),
    )


def array_parts(predicate: A.Expr, path: str) -> tuple[A.Expr, A.Expr]:
    """(on each element, on the length) of an invariant of array field `path`, both
    over `_`: `ranges >= 0` is on each element, `len(ranges) <= 10` on the length."""
    marker = A.Name("len(_)")
    lengths = containers.lengths_as(predicate, path, marker)
    if lengths is predicate:
        return A.substitute(predicate, {path: containers.SELF}), A.TRUE
    if any(n.name == path for n in A.names(lengths)):
        return A.TRUE, A.TRUE  # both at once: the catalog reported it
    return A.TRUE, A.substitute(lengths, {marker.name: containers.SELF})


def lengths_resolved(
    ctx: FileContext, state: State, ref: int, predicate: A.Expr, prefix: str
) -> A.Expr:
    """`predicate` with `len(path)` of each array field replaced by its length."""
    found: dict[str, A.Expr] = {}
    for node in A.walk(predicate):
        if isinstance(node, A.Func) and node.name == "len":
            arg = node.args[0]
            if isinstance(arg, A.Name) and arg.name not in found:
                value = resolve_path(ctx, state, ref, arg.name, prefix)
                length = containers.length_term(value)
                if length is not None:
                    found[arg.name] = length
    for path, length in found.items():
        predicate = containers.lengths_as(predicate, path, length)
    return predicate


def default_of(ctx: FileContext, spec: FieldSpec) -> A.Expr:
    """What a field never set holds: its interface file's default (`float64 w 1`;
    ROS 1 has none for standard messages), else 0, 0.0, False or ""."""
    if spec.default is not None and not (spec.std_default and ctx.ros1):
        term = constant_term("float64" if spec.kind == "float" else "", spec.default)
        if term is not None:
            return term
    return DEFAULTS[spec.kind]


def resolve_path(
    ctx: FileContext,
    state: State,
    ref: int,
    path: str,
    prefix: str,
    settled: bool = False,
) -> Value:
    """Follow a dotted field path from message `ref`, reading raw values; with
    `settled`, as the code would (each message's invariants assumed first)."""
    parts = path.split(".")
    value = Value("msg", ref=ref)
    for index, part in enumerate(parts):
        if value.ref is None or value.ref not in state.heap:
            return Value("unknown")
        if settled:
            settle(ctx, state, value.ref)
        value = read_raw(
            ctx, state, value.ref, part, f"{prefix}.{'.'.join(parts[: index + 1])}"
        )
    return value


def unset_at(
    ctx: FileContext, state: State, ref: int, path: str
) -> MaybeDefault | None:
    """When the field at `path` inside message `ref` still has its default, if it
    was set on some paths only."""
    inner, _, leaf = path.rpartition(".")
    holder: int | None = ref
    if inner:
        holder = resolve_path(ctx, state, ref, inner, "").ref
    obj = state.heap.get(holder) if holder is not None else None
    return obj.unset.get(leaf) if obj is not None and obj.unset else None


def havoc(state: State, ref: int, seen: set[int] | None = None) -> None:
    """Unknown code may have changed any field of this message and its sub-messages."""
    obj = state.heap.get(ref)
    seen = set() if seen is None else seen
    if obj is None or ref in seen:
        return
    seen.add(ref)
    for value in obj.fields.values():
        if value.ref is not None:
            havoc(state, value.ref, seen)
    obj.origin = "unknown"
    obj.pending = False
    obj.fields = {k: v for k, v in obj.fields.items() if v.ref is not None}
    obj.unset = None


def forget(ctx: FileContext, state: State, ref: int, path: tuple[str, ...]) -> None:
    """Code may have stored another value into the field at `path` of message `ref`
    (a loop's body): that field becomes unknown, a sub-message wholly so; the other
    fields keep what they hold."""
    holder = ref
    for part in path[:-1]:
        spec = field_spec(ctx, state, holder, part) if holder in state.heap else None
        inner = read_raw(ctx, state, holder, part, part).ref if spec else None
        if spec is None or spec.kind != "msg" or spec.array or inner is None:
            havoc(state, ref)
            return
        holder = inner
    obj = state.heap.get(holder)
    name = path[-1]
    spec = field_spec(ctx, state, holder, name) if obj is not None else None
    if obj is None or spec is None or spec.array:
        havoc(state, ref)
        return
    if obj.unset:
        obj.unset = {k: v for k, v in obj.unset.items() if k != name} or None
    label = f"{obj.label}.{name}"
    if spec.kind == "msg" and spec.msg_type:
        # another sub-message may be there now: one of its own, not the old one
        owner = (holder, name)
        obj.fields[name] = new_message(
            ctx, state, spec.msg_type, "unknown", owner, label
        )
    elif spec.kind in DEFAULTS:
        unit = field_unit(ctx, state, holder, name)[0]
        obj.fields[name] = ctx.fresh(spec.kind, label, unit)
    else:
        havoc(state, ref)
