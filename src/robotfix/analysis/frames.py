"""Frames that follow `header.frame_id`, and tf2 transforms (data: `ros/frames_model`).

A stamped message whose `header.frame_id` holds a known string (a literal, a
constant, a parameter's default, an instance attribute bound once to one of these)
has its data in that frame: a number read from it carries the frame in its unit (so
`a.point.x - b.point.x` across frames is RF202, as for `Frame(...)` annotations), and
a value stored into it must not be in another frame (RF201). The frame is looked up
when the field is read or written, never stored with the field, so setting
`header.frame_id` after the data is the same as before. Frame names are compared
after removing one leading `/`, as tf2 does (see `ros/frames_model`). A frame not
known (a received message's, a parameter without a default, a formatted string)
compares with nothing.

tf2: `lookup_transform(target, source, ...)` is a received TransformStamped whose
`header.frame_id` is `target` and `child_frame_id` is `source`;
`do_transform_*(stamped, transform)` is the stamped value in the transform's target
frame (RF204 when the value's frame is not the transform's source);
`buffer.transform(stamped, target)` is in `target`. A literal frame with a leading `/`
given to a tf2 lookup is RF204 (tf2 throws).
"""

from __future__ import annotations

import ast
from collections import Counter
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from robotfix import messages
from robotfix.analysis import heap
from robotfix.analysis.state import State
from robotfix.analysis.values import NUMERIC, Value, replace
from robotfix.annotations import ast as A
from robotfix.annotations.units import Unit, is_frame, named
from robotfix.astwalk import walk
from robotfix.messages import Declared
from robotfix.ros.frames_model import (
    FRAMED_FIELDS,
    TF2_CALLS,
    TRANSFORM_TYPE,
    VALIDATED,
)

if TYPE_CHECKING:
    from robotfix.analysis.context import FileContext


@dataclass
class FrameFacts:
    """Per file: how often each attribute name is assigned anywhere (`x.name = ...`),
    and the frames and units of instance attributes bound once: (class, attribute)
    -> frame, -> the number stored (its unit, factors and radian), and those stored
    in more than one unit (a store met again in a loop). Entries are only added:
    the editor's memo sees a write by the sizes."""

    assigned: Counter[str]
    attributes: dict[tuple[str, str], str] = field(default_factory=dict)
    followed: set[int] = field(default_factory=set)  # ids of tf2 calls modelled
    units: dict[tuple[str, str], Value] = field(default_factory=dict)
    mixed: set[tuple[str, str]] = field(default_factory=set)
    # how often each attribute name is assigned `None` (`self.a = None`)
    nones: Counter[str] = field(default_factory=Counter)


def normalize(name: str) -> str:
    """The frame a name denotes: tf2 strips one leading `/` from stored frames."""
    return name[1:] if name.startswith("/") else name


def known_frame(value: Value | None) -> str | None:
    """The frame a string value names, when the analysis knows it."""
    if value is None:
        return None
    text = value.term.value if isinstance(value.term, A.Str) else value.frame
    if not text or not normalize(text):
        return None
    return normalize(text)


def with_frame(unit: Unit, frame: str) -> Unit:
    """`unit` in `frame` (replacing any frame it had)."""
    dims = [d for d in unit.dims if not is_frame(d[0])]
    dims.append((f"frame:{frame}", 1))
    framed = Unit(tuple(sorted(dims)), unit.factor, unit.offset)
    return Unit(framed.dims, framed.factor, framed.offset, f"{unit} in frame {frame}")


def unframed(unit: Unit | None) -> Unit | None:
    """`unit` without its frame: a norm (`math.hypot(dx, dy)`) is the same in every
    frame; a coordinate times a number (`dx * math.cos(yaw)`) may be in another."""
    if unit is None or not any(is_frame(d) for d, _ in unit.dims):
        return unit
    dims = tuple(d for d in unit.dims if not is_frame(d[0]))
    return named(Unit(dims, unit.factor, unit.offset))


def frame_of(unit: Unit | None) -> str | None:
    if unit is None:
        return None
    names = [d.split(":", 1)[1] for d, e in unit.dims if is_frame(d) and e == 1]
    return names[0] if len(names) == 1 else None


def peek(state: State, ref: int, path: str) -> Value | None:
    """The value at `path` below message `ref` if the code set or read it, without
    creating anything (a frame nobody set is not known)."""
    current: Value | None = Value("msg", ref=ref)
    for part in path.split("."):
        if current is None or current.ref is None or current.ref not in state.heap:
            return None
        current = state.heap[current.ref].fields.get(part)
    return current


def frame_at(state: State, ref: int, path: str) -> tuple[str, int, str] | None:
    """(frame, message, path of its frame string) for the data at `path` below
    message `ref`: the frame named by the innermost enclosing stamped message that
    frames it, when known."""
    current: int | None = ref
    seen: set[int] = set()
    while current is not None and current in state.heap and current not in seen:
        seen.add(current)
        obj = state.heap[current]
        for prefix, frame_path in FRAMED_FIELDS.get(obj.type, ()):
            if path.startswith(prefix + ".") or _within(prefix, path):
                frame = known_frame(peek(state, current, frame_path))
                return None if frame is None else (frame, current, frame_path)
        if obj.owner is None:
            return None
        current, path = obj.owner[0], f"{obj.owner[1]}.{path}"
    return None


def _within(prefix: str, path: str) -> bool:
    """`path` is the framed data itself or a message that contains it."""
    return prefix == path or prefix.startswith(path + ".")


def framed_read(state: State, ref: int, name: str, value: Value) -> Value:
    """A number read from a field of a message in a known frame carries it (or, in
    a message whose frame is not known, the frame of the data stored there)."""
    if not _numeric(value) or value.unit is None or value.literal:
        return value
    found = frame_at(state, ref, name)
    frame = found[0] if found is not None else value.frame
    if frame is None:
        return value
    return replace(value, unit=with_frame(value.unit, frame))


def _numeric(value: Value) -> bool:
    """A number, or a value of a kind not known stored in a numeric field."""
    return value.is_number or (value.kind == "unknown" and value.ref is None)


def stored(state: State, ref: int, name: str, value: Value, given: Value) -> Value:
    """The value field `name` keeps: a number remembers the frame of the data stored
    (its unit becomes the field's), so naming another frame before the message
    leaves is found; not a frame the message already contradicts (reported)."""
    if not _numeric(value):
        return value
    frame = frame_of(given.unit) or given.frame
    found = frame_at(state, ref, name)
    if found is not None and found[0] != frame:
        frame = None
    return replace(value, frame=frame)


def check_leaving(ctx: FileContext, state: State, ref: int, site: ast.AST) -> None:
    """A message leaves the node (`pub.publish(p)`) with data stored in one frame
    below a header that names another (`p.point.x = x_odom`, then
    `p.header.frame_id = 'map'`): RF201 there. Checked when it leaves, not when the
    frame is named, as a message reused for several frames is rewritten in between."""
    todo = [ref]
    seen: set[int] = set()
    while todo:
        current = todo.pop()
        if current in seen or current not in state.heap:
            continue
        seen.add(current)
        obj = state.heap[current]
        for prefix, frame_path in FRAMED_FIELDS.get(obj.type, ()):
            frame = known_frame(peek(state, current, frame_path))
            if frame is None:
                continue
            other = _other_frame(state, peek(state, current, prefix), frame)
            if other is not None:
                stmt = ctx.source.segment(site) or "publish"
                ctx.report(
                    messages.frame_mismatch(
                        ctx.source.path,
                        ctx.source.span(site),
                        stmt,
                        other,
                        frame,
                        leaving=True,
                    ),
                    once=("frames", id(site)),
                )
                return
        todo.extend(v.ref for _, v in sorted(obj.fields.items()) if v.ref is not None)


def check_message(
    ctx: FileContext,
    state: State,
    ref: int,
    unit: Unit | None,
    site: ast.AST,
    declared: Declared,
) -> None:
    """A stamped message given where a refinement names its frame (`msg:
    Annotated[PoseStamped, "Frame('map')"]`: the data its header frames is in
    `map`), whose header names another known frame: RF201 (a warning when that
    frame is a parameter's default, which a launch file may change). A frame
    not known compares with nothing."""
    expected = frame_of(unit)
    obj = state.heap.get(ref)
    if expected is None or obj is None:
        return
    frame_path, framing, part_of = _frame_path(ctx, obj.type), ref, None
    if frame_path is None:  # a Pose, Point, ...: framed by the message it is part of
        spec = ctx.catalog.lookup(obj.type)
        first = next(iter(spec.fields), None) if spec is not None else None
        found = frame_at(state, ref, first) if first is not None else None
        if found is None:
            return
        _, framing, frame_path = found
        part_of = state.heap[framing].type
    named = peek(state, framing, frame_path)
    frame = known_frame(named)
    if named is None or frame is None or frame == normalize(expected):
        return
    ctx.report(
        messages.message_frame_mismatch(
            ctx.source.path,
            ctx.source.span(site),
            ctx.source.segment(site) or obj.type,
            frame_path,
            frame,
            normalize(expected),
            declared,
            default=not isinstance(named.term, A.Str),
            part_of=part_of,
        ),
        once=("frames", id(site), declared.what),
    )


def _frame_path(ctx: FileContext, msg_type: str) -> str | None:
    """The string field that names the frame of a message's data, if it has one."""
    if FRAMED_FIELDS.get(msg_type):
        return FRAMED_FIELDS[msg_type][0][1]
    # any message with a header (sensor_msgs/LaserScan, Imu, Range, ...)
    spec = ctx.catalog.field_at(msg_type, "header.frame_id")
    if spec is None or spec.kind != "str" or spec.array:
        return None
    return "header.frame_id"


def received_in(ctx: FileContext, state: State, ref: int, unit: Unit | None) -> None:
    """A message that arrived whose refinement names its frame (`msg:
    Annotated[Odometry, "Frame('odom')"]`): its header names that frame, as the
    refinement says, so the data read from it is in it."""
    frame = frame_of(unit)
    obj = state.heap.get(ref)
    path = _frame_path(ctx, obj.type) if obj is not None else None
    if frame is None or path is None:
        return
    _set(ctx, state, ref, path, Value("str", A.Str(frame)))


def _other_frame(state: State, data: Value | None, frame: str) -> str | None:
    """A frame other than `frame` of the numbers stored below `data`."""
    todo = [data]
    seen: set[int] = set()
    while todo:
        value = todo.pop()
        if value is None:
            continue
        if _numeric(value) and value.frame is not None and value.frame != frame:
            return value.frame
        if value.ref is not None and value.ref in state.heap and value.ref not in seen:
            seen.add(value.ref)
            todo.extend(
                state.heap[value.ref].fields[k]
                for k in sorted(state.heap[value.ref].fields)
            )
    return None


def expected_unit(
    ctx: FileContext, state: State, ref: int, name: str, unit: Unit | None
) -> tuple[Unit | None, Declared | None]:
    """The unit a value stored into field `name` must have, in the frame of its
    message, and where that frame comes from (None: no frame known)."""
    if unit is None:
        return None, None
    found = frame_at(state, ref, name)
    if found is None:
        return unit, None
    frame, owner, frame_path = found
    declared = Declared(
        f"frame of the {state.heap[owner].type} that holds it",
        None,
        None,
        f"its `{frame_path}` is `{frame}`",
    )
    return with_frame(unit, frame), declared


def check_moved(
    ctx: FileContext, state: State, ref: int, name: str, moved: int, site: ast.AST
) -> None:
    """`p.pose = q.pose`: a sub-message taken from data in one frame stored where
    another frame is named (RF201)."""
    obj = state.heap.get(moved)
    if obj is None or obj.owner is None:
        return
    there = frame_at(state, ref, name)
    here = frame_at(state, obj.owner[0], obj.owner[1])
    if there is None or here is None or there[0] == here[0]:
        return
    stmt = ctx.source.segment(site) or name
    ctx.report(
        messages.frame_mismatch(
            ctx.source.path, ctx.source.span(site), stmt, here[0], there[0]
        ),
        once=("frames", id(site)),
    )


# -- tf2 --------------------------------------------------------------------------
def is_tf2(name: str) -> bool:
    return name in TF2_CALLS


def followed(ctx: FileContext, node: ast.Call) -> bool:
    """Whether `node` is a tf2 call this module modelled (it changes no message)."""
    found = ctx.frame_facts
    return isinstance(found, FrameFacts) and id(node) in found.followed


def tf2_call(
    ctx: FileContext,
    name: str,
    node: ast.Call,
    args: list[Value],
    kwargs: dict[str | None, Value],
    state: State,
) -> Value | None:
    """The value of a tf2 call, or None when it is not one this checker follows."""
    call = TF2_CALLS[name]

    def given(where: tuple[int, str] | None) -> Value | None:
        if where is None:
            return None
        position, keyword = where
        if keyword in kwargs:
            return kwargs[keyword]
        return args[position] if position < len(args) else None

    if name in VALIDATED:
        _check_slashes(ctx, name, node, [given(call.target), given(call.source)])
    if call.kind == "lookup":
        if len(args) + len(kwargs) < 3:  # target, source, time: else not tf2's
            return None
        result = heap.new_message(ctx, state, TRANSFORM_TYPE, "received")
        assert result.ref is not None
        _set(ctx, state, result.ref, "header.frame_id", given(call.target))
        _set(ctx, state, result.ref, "child_frame_id", given(call.source))
        facts(ctx).followed.add(id(node))
        return result
    data = given(call.data)
    if data is None or data.kind != "msg" or data.ref not in state.heap:
        return None
    assert data.ref is not None
    data_type = state.heap[data.ref].type
    if call.kind == "transform":
        # tf2 looks the transform up from the value's own frame: a `/` fails there
        _check_slashes(ctx, name, node, [peek(state, data.ref, "header.frame_id")])
        target = given(call.target)
        if target is None or target.kind not in ("str", "unknown"):
            return None
        facts(ctx).followed.add(id(node))
        return _moved(ctx, state, data_type, target)
    transform = given(call.transform)
    if transform is None or transform.ref not in state.heap:
        return None
    assert transform.ref is not None
    source = known_frame(peek(state, transform.ref, "child_frame_id"))
    frame = known_frame(peek(state, data.ref, "header.frame_id"))
    if source is not None and frame is not None and source != frame:
        into = known_frame(peek(state, transform.ref, "header.frame_id"))
        stmt = ctx.source.segment(node) or name
        ctx.report(
            messages.transform_frame_mismatch(
                ctx.source.path, ctx.source.span(node), stmt, frame, source, into
            ),
            once=("frames", id(node)),
        )
    facts(ctx).followed.add(id(node))
    return _moved(ctx, state, data_type, peek(state, transform.ref, "header.frame_id"))


def _moved(
    ctx: FileContext, state: State, data_type: str, target: Value | None
) -> Value:
    """A new message of `data_type` whose header names `target` (if it has one)."""
    result = heap.new_message(ctx, state, data_type, "received")
    assert result.ref is not None
    spec = ctx.catalog.lookup(data_type)
    if spec is not None and "header" in spec.fields:
        _set(ctx, state, result.ref, "header.frame_id", target)
    return result


def _set(
    ctx: FileContext, state: State, ref: int, path: str, value: Value | None
) -> None:
    """Set a string field of a new message to a known frame (nothing if unknown)."""
    if known_frame(value) is None:
        return
    assert value is not None
    *parents, last = path.split(".")
    current = ref
    for part in parents:
        sub = heap.read_raw(ctx, state, current, part, part)
        if sub.ref is None:
            return
        current = sub.ref
    state.heap[current].fields[last] = replace(value, kind="str", default_of=None)


def _check_slashes(
    ctx: FileContext, name: str, node: ast.Call, values: list[Value | None]
) -> None:
    """tf2 refuses a frame id with a leading `/` in a lookup (a literal one: a
    parameter's default may be overridden)."""
    for value in values:
        if value is None or not isinstance(value.term, A.Str):
            continue
        text = value.term.value
        if text.startswith("/"):
            stmt = ctx.source.segment(node) or name
            ctx.report(
                messages.frame_with_slash(
                    ctx.source.path, ctx.source.span(node), stmt, name, text
                ),
                once=("frames-slash", id(node), text),
            )


# -- instance attributes -----------------------------------------------------------
def facts(ctx: FileContext) -> FrameFacts:
    found = ctx.frame_facts
    if isinstance(found, FrameFacts):
        return found
    if ctx.index.scopes:  # `analyze_module`
        # the module's one walk counted them (assignments are statements: all of
        # them are indexed, once) and found the `setattr` calls
        found = FrameFacts(Counter(ctx.index.assigned))
        found.nones.update(ctx.index.assigned_none)
        if ctx.index.setattrs:
            found.assigned["*"] += 2 * len(ctx.index.setattrs)
    else:
        counts: Counter[str] = Counter()
        nones: Counter[str] = Counter()
        tree = ctx.source.tree
        for item in walk(tree) if tree is not None else ():  # once per file
            kind = type(item)  # (one test per node: this walks the whole file)
            targets: list[ast.expr]
            if kind is ast.Assign:
                targets = item.targets  # type: ignore[attr-defined]
            elif kind is ast.AugAssign or kind is ast.AnnAssign:
                targets = [item.target]  # type: ignore[attr-defined]
            else:
                if (
                    kind is ast.Call
                    and type(item.func) is ast.Name  # type: ignore[attr-defined]
                    and item.func.id == "setattr"  # type: ignore[attr-defined]
                ):
                    counts["*"] += 2  # any attribute may change: none is once-bound
                continue
            for target in targets:
                for part in walk(target):
                    if isinstance(part, ast.Attribute):
                        counts[part.attr] += 1
            value = getattr(item, "value", None)
            if kind is not ast.AugAssign and _is_none(value):
                nones.update(t.attr for t in targets if type(t) is ast.Attribute)
        found = FrameFacts(counts, nones=nones)
    ctx.frame_facts = found
    return found


def remember(ctx: FileContext, class_name: str, attr: str, value: Value) -> None:
    """`self.frame = 'map'` (or a parameter read with a default), bound nowhere else
    in the file: the attribute names that frame in every method. So does a number
    with a unit (`self.period = 1000.0 / self.rate_hz` is in ms in every method):
    its unit, not its value."""
    kind, frame = value.kind, None
    if kind in ("str", "unknown"):
        frame = known_frame(value)
        if frame is None:
            return
    elif kind not in NUMERIC or value.unit is None or value.literal:
        return
    found = facts(ctx)
    if found.assigned["*"]:
        return
    if found.assigned[attr] != 1 and (
        frame is not None or not _once_but_none(found, attr)
    ):
        return
    key = (class_name, attr)
    if frame is not None:
        found.attributes[key] = frame
    else:  # a number with a unit
        known = found.units.get(key)
        if known is None:
            found.units[key] = value
        elif _unit_of(known) != _unit_of(value):
            found.mixed.add(key)


def _is_none(node: ast.AST | None) -> bool:
    return type(node) is ast.Constant and node.value is None


def _once_but_none(found: FrameFacts, attr: str) -> bool:
    """Bound once to something other than `None` (a number's unit holds wherever it
    is not None: `if rate > 0: self.period = 1 / rate` / `else: self.period = None`)."""
    return found.assigned[attr] - found.nones[attr] == 1


def _unit_of(value: Value) -> tuple[object, ...]:
    return (value.unit, value.factors, value.rad_free)


def recall(ctx: FileContext, class_name: str, attr: str) -> Value | None:
    found = facts(ctx)
    key = (class_name, attr)
    frame = found.attributes.get(key)
    if frame is not None:
        return replace(ctx.fresh("str", f"`self.{attr}`"), frame=frame)
    stored = found.units.get(key)
    if stored is None or key in found.mixed:
        return None
    fresh = ctx.fresh(stored.kind, f"`self.{attr}`")
    return replace(
        fresh, unit=stored.unit, factors=stored.factors, rad_free=stored.rad_free
    )
