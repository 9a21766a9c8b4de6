"""Every diagnostic's wording: one builder per kind. Checkers never format strings.

Builders take source-level facts (statement text, names, units, values) and return a
`Diagnostic`; nothing here knows about the solver or the analysis state.
"""

from __future__ import annotations

import math
import re
import sys
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from robotfix import rules
from robotfix.diagnostics import Diagnostic, Edit, Fix, Note, Rule, Severity, Span

if TYPE_CHECKING:  # a cached run, reporting only what it kept, needs no units
    from robotfix.annotations.units import Unit
    from robotfix.ros.launch.model import Place as Placed


@dataclass(frozen=True)
class Declared:
    """Where a refinement or unit was written down."""

    what: str  # "refinement of `timeout`", "unit of geometry_msgs/Twist.linear.x"
    path: str | None
    line: int | None
    source: str = ""  # e.g. "REP 103: ..."
    owner: str = ""  # the message type whose refinement this is, if any
    written: str = ""  # how it is written at path:line, "`us` in the comment of `t`"

    def note(self) -> Note:
        if self.path is not None and self.written:
            return Note(f"{self.what}: {self.written}", self.path, self.line)
        if self.path is not None:
            return Note(f"{self.what} declared here", self.path, self.line)
        return Note(f"{self.what}: {self.source}")


@dataclass(frozen=True)
class Written:
    """An expression as the code writes it, for a fix that rewrites it: where it is,
    its text, and whether it needs no parentheses as an operand (`atom`)."""

    span: Span
    text: str
    atom: bool


def unreadable(path: str, detail: str) -> Diagnostic:
    return Diagnostic(rules.UNREADABLE_FILE, path, Span.point(1), detail)


def outside_link(path: str, target: str) -> Diagnostic:
    """RF004: a symlink under the checked paths whose target is outside them; it is
    named with its target, and never read."""
    return Diagnostic(
        rules.PATH_NOT_CHECKED,
        path,
        Span.point(1),
        f"not checked: a symlink to `{target}`, outside the checked paths",
        (Note("name the target on the command line (or in msg-paths) to check it"),),
    )


def folder_not_read(path: str, reason: str) -> Diagnostic:
    """RF004: a folder under the checked paths that could not be listed."""
    return Diagnostic(
        rules.PATH_NOT_CHECKED,
        path,
        Span.point(1),
        f"folder not checked: cannot read it ({reason})",
    )


def analysis_budget(path: str, line: int, why: str) -> Diagnostic:
    return Diagnostic(
        rules.ANALYSIS_BUDGET,
        path,
        Span.point(line),
        f"analysis of this file stopped early ({why}); what was found before is "
        "reported, the rest of the file is not checked",
        (Note("split very large or deeply nested code, or exclude generated files"),),
    )


def unused_suppression(
    path: str, line: int, col: int, unknown: list[str], unused: list[str]
) -> Diagnostic:
    if unknown:
        detail = (
            f"{', '.join(f'`{c}`' for c in unknown)} is not a RobotFix code or name"
        )
        detail += " (`robotfix rules` lists them)"
    elif unused:
        detail = f"nothing on this line is {', '.join(unused)}: remove the suppression"
    else:
        detail = "nothing on this line is reported: remove the suppression"
    return Diagnostic(rules.UNUSED_SUPPRESSION, path, Span.point(line, col), detail)


def syntax_error(path: str, span: Span, detail: str, rule: Rule) -> Diagnostic:
    if rule == rules.PYTHON2_SOURCE:
        message = f"this looks like Python 2 ({detail}); RobotFix checks Python 3 only"
        notes = (Note("port it to Python 3, or exclude it from the check"),)
        return Diagnostic(rule, path, span, message, notes)
    if rule == rules.NEWER_PYTHON_SOURCE:
        running = f"{sys.version_info.major}.{sys.version_info.minor}"
        message = (
            f"this uses Python {detail} syntax, and RobotFix runs on Python {running}:"
            " the file was not checked"
        )
        notes = (Note(f"run RobotFix with Python {detail} or newer to check it"),)
        return Diagnostic(rule, path, span, message, notes)
    return Diagnostic(rule, path, span, f"not valid Python 3: {detail}")


def annotation_problem(
    path: str,
    line: int,
    col: int,
    rule: Rule,
    detail: str,
    notes: tuple[Note, ...] = (),
) -> Diagnostic:
    return Diagnostic(rule, path, Span.point(line, col), detail, notes)


def malformed_stub(path: str, line: int, col: int, detail: str) -> Diagnostic:
    """RF512: a user stub (`stub-paths`) that does not read; what it spoils is
    treated as unannotated."""
    return Diagnostic(
        rules.MALFORMED_STUB,
        path,
        Span.point(line, col),
        f"{detail}; this part of the stub is not used",
    )


def unused_metadata(
    path: str,
    line: int,
    col: int,
    shown: str,
    why: str | None = None,
    hint: str | None = None,
) -> Diagnostic:
    """RF511: `why` it is not read (default: it is no string), and how to write it."""
    return Diagnostic(
        rules.UNUSED_METADATA,
        path,
        Span.point(line, col),
        f"`{shown}` in `Annotated` is not checked: "
        + (why or "RobotFix reads only string refinements"),
        (
            Note(
                hint
                or "write the refinement as a string "
                "(`\"Unit('m') and 0 <= _ <= 1\"`), "
                "or bind a module name to one and use that name"
            ),
        ),
    )


def duplicate_interface(path: str, type_name: str, first: str) -> Diagnostic:
    return Diagnostic(
        rules.DUPLICATE_INTERFACE,
        path,
        Span.point(1),
        f"`{type_name}` is already defined by {first}: this definition is ignored",
        (
            Note(f"`{type_name}` first defined here", first, 1),
            Note(
                "the first definition wins (the checked packages' files, then "
                "msg-paths in order): remove or rename the other; a file that only "
                "adds `#RobotFix#` lines to a type leaves its fields out "
                "(`[pkg/Type]:`)"
            ),
        ),
    )


def conflicting_label(
    path: str,
    span: Span,
    field: str,
    kind: str,
    first: tuple[str, int],
    second: str,
) -> Diagnostic:
    """A second, different Unit/Frame/Tag for one message field."""
    text, line = first
    return Diagnostic(
        rules.MISPLACED_UNIT,
        path,
        span,
        f"`{field}` already has the {kind} `{text}` (line {line}), so `{second}` is "
        f"not used: a field has one {kind}",
    )


def unprocessable_interface(
    path: str, line: int, col: int, what: str, error: BaseException
) -> Diagnostic:
    """A failure of RobotFix itself on one interface file or annotation line."""
    rule = (
        rules.ANNOTATION_SYNTAX if what == "annotation" else rules.MALFORMED_INTERFACE
    )
    return Diagnostic(
        rule,
        path,
        Span.point(line, col),
        f"RobotFix could not process this {what} ({type(error).__name__}); it is "
        "skipped",
        (Note("this is a RobotFix bug: please report it with the file"),),
    )


def interface_problem(
    found: Diagnostic, used: bool, absent_package: str | None = None
) -> Diagnostic:
    """A problem of one of the user's interface files. When a checked file uses a
    type of that file: the rule's severity, but a warning when a field names a
    package of which no type is known (the field is not checked, not wrong). When
    none does: a note, which never changes the exit status."""
    notes = list(found.notes)
    level = found.level
    if absent_package is not None:
        level = Severity.WARNING
        notes.append(
            Note(
                f"no interface files of {absent_package} were found: pass them with "
                "--msg-path, or source an install space that has them"
            )
        )
    if not used:
        level = Severity.NOTE
        notes.append(
            Note(
                "no checked Python file uses a type of this file, so this does not "
                "fail the run"
            )
        )
    return replace(found, notes=tuple(notes), level=level)


def contradictory_refinement(
    path: str, line: int, col: int, predicate: str, subject: str
) -> Diagnostic:
    return Diagnostic(
        rules.CONTRADICTORY_REFINEMENT,
        path,
        Span.point(line, col),
        f"no value satisfies `{predicate}`: the refinement of {subject} contradicts "
        "itself, and is ignored",
        (Note("fix the bounds (a typo such as `>` for `<`?)"),),
    )


def contradictory_invariant(
    path: str,
    line: int,
    msg_type: str,
    predicate: str,
    earlier: tuple[str, int] | None,
) -> Diagnostic:
    if earlier is None:
        detail = f"no {msg_type} satisfies `{predicate}`: it contradicts itself"
        notes: tuple[Note, ...] = ()
    else:
        detail = (
            f"no {msg_type} satisfies `{predicate}` together with the refinements "
            "declared before it"
        )
        notes = (Note(f"refinement of {msg_type} declared here", *earlier),)
    return Diagnostic(
        rules.CONTRADICTORY_REFINEMENT,
        path,
        Span.point(line),
        f"{detail}; it is ignored",
        (*notes, Note("fix the bounds (a typo such as `>` for `<`?)")),
    )


def unknown_message_class(path: str, span: Span, qualified: str) -> Diagnostic:
    package = qualified.split(".")[0]
    return Diagnostic(
        rules.UNKNOWN_MESSAGE_CLASS,
        path,
        span,
        f"`{qualified}` is not a known message type: its fields are not checked",
        (
            Note(
                f"pass the folder with {package}'s .msg files with --msg-path, add "
                "it to msg-paths in [tool.robotfix], or source the install space "
                "that has it"
            ),
        ),
    )


def refinement_violated(
    path: str,
    span: Span,
    stmt: str,
    predicate: str,
    subject: str,
    value: str | None,
    declared: Declared,
) -> Diagnostic:
    """RF101; `value`: the one value `subject` has there, shown in the message
    itself (a call's argument, `time_allowance=LOOK_TIME`, hides it), unless the
    statement already shows it (`timeout = 200`)."""
    written = value is not None and re.search(
        rf"(?<![\w.'\"]){re.escape(value)}(?![\w.'\"])", stmt
    )
    shown = f": here {subject} = {value}" if value is not None and not written else ""
    return Diagnostic(
        rules.REFINEMENT_VIOLATED,
        path,
        span,
        f"`{stmt}` violates `{predicate}`{_owner(declared)}{shown}",
        (declared.note(),),
    )


def refinement_unproven(
    path: str,
    span: Span,
    stmt: str,
    predicate: str,
    subject: str,
    unknowns: list[str],
    example: list[str],
    declared: Declared,
) -> Diagnostic:
    why = (
        f"it does not hold for every possible value of {_join(unknowns)}"
        if unknowns
        else "it depends on values RobotFix cannot follow"
    )
    notes = [declared.note()]
    if example:
        notes.append(Note(f"for example {', '.join(example)} breaks it"))
    notes.append(
        Note(
            f"add a refinement to the inputs, or a check such as `assert` before "
            f"{subject} is set"
        )
    )
    return Diagnostic(
        rules.REFINEMENT_UNPROVEN,
        path,
        span,
        f"cannot prove that `{stmt}` keeps `{predicate}`{_owner(declared)}: {why}",
        tuple(notes),
    )


def solver_unknown(
    path: str, span: Span, stmt: str, predicate: str, reason: str
) -> Diagnostic:
    return Diagnostic(
        rules.SOLVER_UNKNOWN,
        path,
        span,
        f"could not decide whether `{stmt}` keeps `{predicate}` (solver: {reason})",
    )


def solver_budget(path: str, span: Span, stmt: str, predicate: str) -> Diagnostic:
    return Diagnostic(
        rules.SOLVER_UNKNOWN,
        path,
        span,
        f"could not decide whether `{stmt}` keeps `{predicate}`: the work budget "
        "of this file is used up, so the analysis stops here; what was found before "
        "is reported, the rest of the file is not checked",
        (Note("split the file, or simplify nonlinear refinements and expressions"),),
    )


def unit_mismatch(
    path: str,
    span: Span,
    stmt: str,
    target: str,
    expected: Unit,
    got: Unit,
    declared: Declared,
    aligned: Unit | None = None,
    twice: float | None = None,
    called: tuple[str, Unit] | None = None,
    some_paths: bool = False,
    value: Written | None = None,
    undo: Edit | None = None,
    angles: str = "",
) -> Diagnostic:
    """`aligned`: the value's unit over the expected dimensions, when only the
    scale differs once the radian cancels (`omega_deg * r`); `twice`: the literal
    factor that converted a value already in `expected` (`p_s * 1000` into s);
    `called`: the conversion call that last changed the value's unit and its
    argument's unit (`math.degrees`, rad): the advice is about that call;
    `some_paths`: the value is in `got` on some of the paths that set it.
    For the quick fix (`Diagnostic.fixes`): `value`, the value as written; `undo`,
    the edit that removes the factor or the call the advice names; `angles`, the
    module the file calls `radians()` and `degrees()` of (`math`, `np`)."""
    where = " on some path" if some_paths else ""
    message = (
        f"`{stmt}` gives {target} a value in {got}{where}, but {target} "
        f"{_is(target)} in {expected}"
    )
    fix = conversion(got if aligned is None else aligned, expected)
    if aligned is not None and fix:
        ratio = aligned.factor / expected.factor
        if dict(got.dims).get("radian") and math.isclose(ratio, math.pi / 180):
            fix = f"use math.radians() on the angle to convert {got} to {expected}"
        fix = fix.replace(f"convert {aligned} to", f"convert {got} to")
    advice = "" if called is None else _called_fix(called, expected)
    fix = advice or fix
    if twice is not None:
        how = (
            f"multiplying by {twice:.6g}"
            if twice > 1
            else f"dividing by {1 / twice:.6g}"
        )
        fix = (
            f"the value was in {expected} already, and {how} converts it a second "
            "time: remove the factor"
        )
    notes = [declared.note()]
    if fix:
        message += f": {fix}"
    fixes: tuple[Fix, ...] = ()
    call = None if called is None or not called[1].same_as(expected) else called[0]
    if some_paths:
        pass  # the other paths' values are right: no one edit fixes them all
    elif twice is not None or call is not None:
        what = "the factor" if twice is not None else f"`{call}()`"
        fixes = (Fix(f"Remove {what}", (undo,)),) if undo is not None else ()
    elif value is not None and not advice:
        fixes = _scale_fix(value, aligned or got, expected, angles)
    return Diagnostic(
        rules.UNIT_MISMATCH, path, span, message, tuple(notes), fixes=fixes
    )


def _scale_fix(
    value: Written, got: Unit, expected: Unit, angles: str
) -> tuple[Fix, ...]:
    """The value times the factor that takes `got` to `expected`, when it is exact as
    written (`/ 3.6`, `* 1000`) or a degree-radian conversion of `angles`."""
    if expected.is_label or not got.same_dimension(expected):
        return ()
    if not math.isclose(got.offset, expected.offset):
        return ()
    ratio = got.factor / expected.factor
    operand = value.text if value.atom else f"({value.text})"
    angle = dict(got.dims).get("radian")
    for call, factor in (("radians", math.pi / 180), ("degrees", 180 / math.pi)):
        if angle and angles and math.isclose(ratio, factor):
            return _rewrite(f"{angles}.{call}", value, f"{angles}.{call}({value.text})")
    op, number = ("/", 1 / ratio) if ratio < 1 else ("*", ratio)
    shown = f"{number:.6g}"
    if math.isclose(number, 1.0) or not math.isclose(
        float(shown), number, rel_tol=1e-12
    ):
        return ()
    return _rewrite(f"{op} {shown}", value, f"{operand} {op} {shown}")


def _rewrite(what: str, value: Written, text: str) -> tuple[Fix, ...]:
    return (Fix(f"Convert with `{what}`", (Edit(value.span, text),)),)


def _called_fix(called: tuple[str, Unit], expected: Unit) -> str:
    """Advice on the conversion call that gave a value its wrong unit: remove it
    when its argument is in the expected unit, swap it for the call that converts
    the argument when `conversion` names one (`math.degrees(deg)` into rad)."""
    call, argument = called
    if argument.same_as(expected):
        return f"remove `{call}()`: the value is in {expected} without it"
    fix = conversion(argument, expected)
    for name in ("radians", "degrees"):
        if fix.startswith(f"use math.{name}()"):
            module = call.rpartition(".")[0]
            other = f"{module}.{name}" if module else name
            return (
                f"use `{other}()` in place of `{call}()` (its argument is in "
                f"{argument})"
            )
    return ""


def _is(target: str) -> str:
    """The verb for a target: "the elements of `ranges`" are in m."""
    return "are" if target.startswith("the elements of") else "is"


def converted_twice(
    path: str,
    span: Span,
    stmt: str,
    function: str,
    got: Unit,
    declared: Declared,
    undo: Edit | None = None,
) -> Diagnostic:
    """RF201: a conversion (`math.radians`) of a value already in its result's unit;
    the fix is to drop it, not to convert back (`undo`: the call replaced by its
    argument)."""
    message = (
        f"`{stmt}` applies `{function}()` to a value already in {got}: drop the call, "
        "it would convert a second time"
    )
    fixes = (Fix(f"Remove `{function}()`", (undo,)),) if undo is not None else ()
    return Diagnostic(
        rules.UNIT_MISMATCH, path, span, message, (declared.note(),), fixes=fixes
    )


def implicit_unit_change(
    path: str,
    span: Span,
    stmt: str,
    target: str,
    expected: Unit,
    got: Unit,
    seconds: int,
    declared: Declared | None,
) -> Diagnostic:
    """RF203: the value is `seconds` powers of s away from its target's unit."""
    if seconds > 0:
        kind, unit, example = "a gain", "1/s", "K_P: Annotated[float, \"Unit('1/s')\"]"
    else:
        kind, unit, example = "a time step", "s", "DT: Annotated[float, \"Unit('s')\"]"
    message = (
        f"`{stmt}` gives {target} a value in {got}, but {target} {_is(target)} in "
        f"{expected}: an implicit {kind[2:]} in {unit}; multiply by {kind} declared "
        f"with its unit (`{example} = ...`)"
    )
    notes = (declared.note(),) if declared is not None else ()
    return Diagnostic(rules.IMPLICIT_UNIT_CHANGE, path, span, message, notes)


def implicit_operand_change(
    path: str, span: Span, expr: str, stepped: Unit, kept: Unit, seconds: int
) -> Diagnostic:
    """RF203 in `+`, `-` or a comparison: `x + vx * 0.1` (a literal time step)."""
    what, unit = ("gain", "1/s") if seconds > 0 else ("time step", "s")
    message = (
        f"`{expr}` combines {kept} with a value in {stepped}: the literal factor is "
        f"an implicit {what} in {unit}; name it and declare its unit "
        f"(`Annotated[float, \"Unit('{unit}')\"]`)"
    )
    return Diagnostic(rules.IMPLICIT_UNIT_CHANGE, path, span, message)


def folded_conversion(
    path: str,
    span: Span,
    stmt: str,
    what: str,
    expected: Unit,
    got: Unit,
    scale: float,
    declared: Declared | None = None,
) -> Diagnostic:
    """RF203: literal factors that do not hold the conversion a value needs, one of
    which (`scale`) may be that conversion folded with a gain into one number
    (`d_cm * 0.02` into m).
    `what`: "gives `x`" ... or "compares" ..., the sentence's verb and object."""
    gain = scale * expected.factor / got.factor
    fix = conversion(got, expected)
    message = (
        f"`{stmt}` {what} a value in {got}, where {expected} is expected: if the "
        f"literal {scale:.6g} is the conversion ({fix}) and a gain of {gain:.6g} "
        "folded into one number, write them apart so each can be checked"
    )
    notes = (declared.note(),) if declared is not None else ()
    return Diagnostic(rules.IMPLICIT_UNIT_CHANGE, path, span, message, notes)


def operand_units(
    path: str, span: Span, expr: str, op: str, left: Unit, right: Unit
) -> Diagnostic:
    verb = {"+": "add", "-": "subtract", "if": "choose between"}.get(op, "compare")
    message = f"`{expr}`: cannot {verb} {left} and {right}"
    fix = conversion(right, left)
    if fix:
        message += f" ({fix.replace('convert', 'convert the right side from', 1)})"
    return Diagnostic(rules.OPERAND_UNIT_MISMATCH, path, span, message)


def _axes(a: str, b: str) -> str:
    """Why two frames that differ only by a REP 103 suffix are not the same."""
    for suffix, axes in (
        ("_optical", "an `_optical` frame has z forward, x right, y down"),
        ("_ned", "an `_ned` frame has x north (forward), y east (right), z down"),
        ("_enu", "an `_enu` frame has x east, y north, z up"),
    ):
        if a + suffix == b or b + suffix == a:
            return f" (REP 103: {axes})"
    return ""


def frame_mismatch(
    path: str, span: Span, stmt: str, got: str, expected: str, leaving: bool = False
) -> Diagnostic:
    """RF201: data of one frame stored into a message whose header names another
    (`leaving`: found when the message leaves the node)."""
    verb = "sends" if leaving else "stores"
    into = "in a message whose header names" if leaving else "into a message in"
    message = (
        f"`{stmt}` {verb} data in frame `{got}` {into} frame `{expected}`"
        f"{_axes(got, expected)}: transform it with tf2 first"
    )
    return Diagnostic(rules.UNIT_MISMATCH, path, span, message)


def message_frame_mismatch(
    path: str,
    span: Span,
    stmt: str,
    frame_path: str,
    got: str,
    expected: str,
    declared: Declared,
    default: bool = False,
    part_of: str | None = None,
) -> Diagnostic:
    """RF201: a stamped message whose header names one frame given where a
    refinement says another (`Annotated[PoseStamped, "Frame('map')"]`), or a part
    of one (`msg.pose.pose`, `part_of` its type); a warning when the frame is a
    parameter's default (`default`), which a launch or parameter file may change."""
    whose = "its" if part_of is None else f"the {part_of} it is part of, its"
    message = (
        f"`{stmt}` gives a message in frame `{got}` ({whose} `{frame_path}`) where "
        f"`{expected}` is assumed{_axes(got, expected)}: transform it with tf2 first"
    )
    notes = [declared.note()]
    if default:
        notes.append(
            Note(
                f"`{got}` is a parameter's default, which a launch or parameter "
                "file may change"
            )
        )
    level = Severity.WARNING if default else None
    return Diagnostic(
        rules.UNIT_MISMATCH, path, span, message, tuple(notes), level=level
    )


def transform_frame_mismatch(
    path: str, span: Span, stmt: str, frame: str, source: str, target: str | None
) -> Diagnostic:
    """RF204: do_transform_*(stamped, transform) with stamped not in the source."""
    into = f" to `{target}`" if target is not None else ""
    message = (
        f"`{stmt}` applies the transform from `{source}`{into} to data in frame "
        f"`{frame}`{_axes(frame, source)}: look up the transform with source frame "
        f"`{frame}` (`lookup_transform(target, '{frame}', time)`), or use "
        "`buffer.transform(stamped, target)`"
    )
    return Diagnostic(rules.TRANSFORM_FRAME_MISMATCH, path, span, message)


def frame_with_slash(
    path: str, span: Span, stmt: str, call: str, frame: str
) -> Diagnostic:
    """RF204: a tf2 lookup given a frame id with a leading `/` (tf2 throws)."""
    message = (
        f"`{stmt}` gives {call}() the frame `{frame}`: tf2 frame ids cannot start "
        f"with a '/' (it raises InvalidArgumentException); write `{frame[1:]}`"
    )
    return Diagnostic(rules.TRANSFORM_FRAME_MISMATCH, path, span, message)


def conversion(got: Unit, expected: Unit) -> str:
    """How to turn a value in `got` into `expected`, when only the scale differs."""
    if expected.is_label:
        return ""
    if not got.same_dimension(expected):
        return _revolutions(got, expected)
    ratio = got.factor / expected.factor
    if math.isclose(ratio, 1.0) and math.isclose(got.offset, expected.offset):
        return ""
    if not math.isclose(got.offset, expected.offset):
        shift = (got.offset - expected.offset) / expected.factor
        return (
            f"convert {got} to {expected} by multiplying by {ratio:.6g} "
            f"and adding {shift:.6g}"
        )
    angle = dict(got.dims).get("radian")
    if angle and math.isclose(ratio, math.pi / 180):
        return f"use math.radians() to convert {got} to {expected}"
    if angle and math.isclose(ratio, 180 / math.pi):
        return f"use math.degrees() to convert {got} to {expected}"
    if ratio < 1:
        return f"divide by {1 / ratio:.6g} to convert {got} to {expected}"
    return f"multiply by {ratio:.6g} to convert {got} to {expected}"


def _revolutions(got: Unit, expected: Unit) -> str:
    """Hz (cycles per second) against rad/s: the missing factor is 2*pi."""
    ours, theirs = dict(got.dims), dict(expected.dims)
    angle = ours.get("radian", 0) - theirs.get("radian", 0)
    rest = {d: e for d, e in ours.items() if d != "radian"}
    if (
        abs(angle) != 1
        or rest != {d: e for d, e in theirs.items() if d != "radian"}
        or rest != {"second": -1}
    ):
        return ""
    factor = got.factor * (2 * math.pi if angle < 0 else 1 / (2 * math.pi))
    ratio = factor / expected.factor
    how = "multiply by" if ratio > 1 else "divide by"
    shown = "2*math.pi" if math.isclose(ratio, 2 * math.pi) else None
    if shown is None and math.isclose(ratio, 1 / (2 * math.pi)):
        shown = "2*math.pi"
    number = shown or f"{ratio if ratio > 1 else 1 / ratio:.6g}"
    return f"{how} {number} to convert {got} (a revolution is 2*pi rad) to {expected}"


def used_before_assignment(
    path: str,
    span: Span,
    stmt: str,
    name: str,
    declared: bool,
    some_paths: bool = False,
    assigned: int | None = None,
) -> Diagnostic:
    """RF301; `assigned`: the line where the function assigns `name`, on paths
    that do not lead to this read."""
    if some_paths:
        detail = (
            f"`{name}`, which is not assigned on every path to this line: "
            "on the others it raises UnboundLocalError or NameError"
        )
    elif assigned is not None:
        where = (
            f"only after this line (line {assigned})"
            if assigned > span.line
            else f"only on other paths (line {assigned})"
        )
        detail = (
            f"`{name}`, which is assigned {where}: here it raises UnboundLocalError"
        )
    elif declared:
        detail = f"`{name}`, which is declared but not assigned on this path"
    else:
        detail = f"`{name}`, which is not defined here"
    advice = "on every path to" if some_paths else "before"
    return Diagnostic(
        rules.USED_BEFORE_ASSIGNMENT,
        path,
        span,
        f"`{stmt}` reads {detail}",
        (Note(f"assign `{name}` {advice} this line"),),
    )


def unset_field(
    path: str,
    span: Span,
    stmt: str,
    field: str,
    default: str,
    predicate: str,
    declared: Declared,
    publishing: bool,
    some_paths: bool = False,
) -> Diagnostic:
    verb = "sends" if publishing else "reads"
    where = "not set on every path to this line" if some_paths else "never set"
    advice = "on every path before" if some_paths else "before"
    return Diagnostic(
        rules.UNSET_FIELD_DEFAULT,
        path,
        span,
        f"`{stmt}` {verb} `{field}`, which is {where}: its ROS default {default} "
        f"violates `{predicate}`{_owner(declared)}",
        (declared.note(), Note(f"set `{field}` {advice} this line")),
    )


def base_type_mismatch(
    path: str, span: Span, stmt: str, target: str, expected: str, got: str
) -> Diagnostic:
    return Diagnostic(
        rules.BASE_TYPE_MISMATCH,
        path,
        span,
        f"`{stmt}` gives {target} {_article(got)} {got}, but {target} is declared "
        f"{expected}",
        (Note(f"convert explicitly, e.g. {expected}(...), if that is what you mean"),),
    )


def parameter_file_unreadable(
    path: str, line: int, col: int, detail: str
) -> Diagnostic:
    """RF003 for a parameter file named on the command line (or a
    generate_parameter_library definitions file) that cannot be read or parsed."""
    return Diagnostic(rules.UNREADABLE_FILE, path, Span.point(line, col), detail)


def parameter_file_not_checked(
    path: str, line: int, col: int, detail: str
) -> Diagnostic:
    """RF004 for a parameter file found in a package's config folder that cannot
    be read or parsed: a warning, since it may be a template or another tool's."""
    return _parameter_warning(
        path,
        line,
        col,
        f"parameter file not checked: {detail}",
        "ROS cannot load it either, unless it is not a parameter file",
    )


def parameter_file_reference(path: str, line: int, col: int, alias: bool) -> Diagnostic:
    """RF004 for a ROS 2 parameter file with an alias or a merge key, which rcl
    does not read; its values are checked as PyYAML expands the file."""
    if alias:
        message = (
            'rcl refuses aliases ("Will not support aliasing"): a node given this '
            "file with --params-file does not start"
        )
    else:
        message = (
            "rcl does not apply the merge key `<<`: it reads the keys under it as "
            "parameters named `<<.name`"
        )
    return _parameter_warning(
        path,
        line,
        col,
        message,
        "its values are checked as PyYAML expands the file, as a launch file that "
        "rewrites it first does (nav2_common's RewrittenYaml)",
    )


def parameter_merge_refused(path: str, line: int, col: int, detail: str) -> Diagnostic:
    """RF004 for a merge key PyYAML refuses: what it would bring in is not checked."""
    return _parameter_warning(
        path,
        line,
        col,
        f"merge not checked: {detail}",
        "PyYAML refuses the file, and so do rosparam and tools built on it",
    )


def _parameter_warning(
    path: str, line: int, col: int, message: str, note: str
) -> Diagnostic:
    return Diagnostic(
        rules.PATH_NOT_CHECKED, path, Span.point(line, col), message, (Note(note),)
    )


def parameter_value_not_checked(
    path: str, span: Span, subject: str, why: str
) -> Diagnostic:
    """RF004 for a value in a parameter file that its loader cannot read."""
    return Diagnostic(
        rules.PATH_NOT_CHECKED, path, span, f"{subject} is not checked: {why}"
    )


def launch_file_not_read(path: str, line: int, col: int, detail: str) -> Diagnostic:
    """RF004 for a launch file that cannot be read or parsed (its nodes are not
    checked; `ros2 launch` or `roslaunch` refuses it too)."""
    return Diagnostic(
        rules.PATH_NOT_CHECKED,
        path,
        Span.point(line, col),
        f"launch file not checked: {detail}",
    )


def launch_parameter_undeclared(
    path: str, line: int, col: int, name: str, node: str, where: Note
) -> Diagnostic:
    """RF601: a launch file (or a parameter file it names, in the section for its
    node) sets a parameter the node's code never declares."""
    return Diagnostic(
        rules.LAUNCH_PARAMETER_UNDECLARED,
        path,
        Span.point(line, col),
        f"parameter `{name}` is set for node {node}, which declares no such "
        "parameter (a typo?)",
        (
            where,
            Note(
                "rclpy ignores a parameter override nobody declares: the node "
                "keeps its default"
            ),
        ),
    )


def parameter_section_unmatched(
    path: str, line: int, col: int, keys: list[str]
) -> Diagnostic:
    """RF602, once per file, at the first of its ROS 2 sections whose node no
    node of the run RobotFix read is named (its code, C++ too, or a launch file)."""
    shown = [f"`{k}`" for k in keys[:5]] + (
        [f"{len(keys) - 5} more"] if len(keys) > 5 else []
    )
    what = "section " if len(keys) == 1 else "sections "
    verb = "names" if len(keys) == 1 else "name"
    return Diagnostic(
        rules.PARAMETER_SECTION_UNMATCHED,
        path,
        Span.point(line, col),
        f"{what}{_join(shown)} {verb} no node that RobotFix read in the checked "
        "workspace or its launch files: not checked against any node's declarations",
        (
            Note(
                "a node of another workspace, or one whose name the code computes, "
                "may be named so; a launch file that renames a node (`name=`) makes "
                "its section apply"
            ),
        ),
    )


def section_applies_to_none(
    path: str, line: int, col: int, name: str, keys: list[str], section: Note
) -> Diagnostic:
    """RF602 as a warning: a launch entry passes its node a parameter file none
    of whose sections applies to it or to any other node of the run."""
    shown = _join(
        [f"`{k}`" for k in keys[:3]]
        + ([f"{len(keys) - 3} more"] if len(keys) > 3 else [])
    )
    return Diagnostic(
        rules.PARAMETER_SECTION_UNMATCHED,
        path,
        Span.point(line, col),
        f"this entry passes node `{name}` a parameter file none of whose sections "
        f"({shown}) applies to it: the node gets none of the file's parameters and "
        "runs with its defaults",
        (
            section,
            Note(
                f"key a section `{name}` (or `/**`), or give the node the name its "
                "section has (a launch file's `name=` renames it)"
            ),
        ),
        level=Severity.WARNING,
    )


def remapped_here(place: Placed, node: str, written: str | None, resolved: str) -> Note:
    """Where a launch file's remapping renamed an endpoint of a graph finding."""
    return Note(
        f"this remapping makes `{written or '?'}` of node `{node}` `{resolved}`",
        place.path,
        place.line,
    )


def graph_type_mismatch(
    path: str,
    line: int,
    col: int,
    what: str,
    name: str,
    mine: str,
    others: list[str],
    other: Note,
    together: bool,
) -> Diagnostic:
    """RF603, at one side of a channel whose nodes use two certain types: an
    error when the two nodes run together (one package's launch files or code), a
    warning for programs of different packages no launch file starts together."""
    apart = (
        ()
        if together
        else (
            Note(
                "no launch file of the workspace starts these two nodes (of one "
                "package) together: an error if they ever run in one system"
            ),
        )
    )
    return Diagnostic(
        rules.TOPIC_TYPE_MISMATCH,
        path,
        Span.point(line, col),
        f"{what} `{name}` is used here with type `{mine}` and elsewhere with "
        f"{_join([f'`{t}`' for t in others])}: ROS never connects endpoints whose "
        "types differ",
        (
            other,
            *apart,
            Note("a remapping in a launch file, or one type on both sides, fixes it"),
        ),
        level=None if together else Severity.WARNING,
    )


def graph_qos_incompatible(
    path: str,
    line: int,
    col: int,
    name: str,
    why: list[str],
    publisher: Note,
    certain: bool,
    apart: bool = False,
) -> Diagnostic:
    """RF604 (both profiles constants) or RF605: a subscription that never hears
    a publisher of its topic."""
    rule = rules.QOS_INCOMPATIBLE if certain else rules.QOS_MAYBE_INCOMPATIBLE
    notes = [publisher]
    if apart:
        notes.append(
            Note(
                "no launch file of the workspace starts these two nodes (of one "
                "package) together"
            )
        )
    elif not certain:
        notes.append(
            Note(
                "a profile here can change at run time (a parameter's QoS "
                "override, or one of several profiles)"
            )
        )
    notes.append(
        Note(
            "ROS 2 connects a publisher and a subscription only when the offered "
            "QoS is at least what is requested"
        )
    )
    return Diagnostic(
        rule,
        path,
        Span.point(line, col),
        f"this subscription to `{name}` "
        + (
            "never receives"
            if certain
            else "does not receive, with the profiles written,"
        )
        + " from the publisher noted: "
        + "; ".join(why),
        tuple(notes),
    )


def contract_note(
    family: str = "topic", route: str = "", launch: tuple[str, int] | None = None
) -> Note:
    """On a publisher's RF101/RF102 against a subscriber's contract, a client's
    against its server's, a server's response against its client's (issue 23
    §3); `route`: the way the message goes through the graph; `launch`: the
    launch entry that starts the sender."""
    sides, what = {
        "service": (
            "this client and that service on one name",
            "the server's callback assumes this of every request it receives",
        ),
        "response": (
            "this service and that client on one name",
            "the client assumes this of every response it receives",
        ),
        "action": (
            "this action client and that action server on one name",
            "the server's goal callback assumes this of every goal it receives",
        ),
    }.get(
        family,
        (
            "this publisher and that subscriber on one topic",
            "the subscriber's callback assumes this of every message it receives",
        ),
    )
    way = f" ({route})" if route else ""
    path, line = launch if launch is not None else (None, None)
    return Note(f"a launch file starts {sides}{way}: {what}", path, line)


def graph_unmatched(
    path: str, line: int, col: int, name: str, published: bool, where: list[Note]
) -> Diagnostic:
    """RF606 / RF607: a topic with subscriptions and no publisher in the
    checked tree, or the reverse."""
    if published:
        rule = rules.TOPIC_NOT_SUBSCRIBED
        done, missing = "published", "subscribed"
    else:
        rule = rules.TOPIC_NOT_PUBLISHED
        done, missing = "subscribed", "published"
    text = (
        f"topic `{name}` is {done} here but {missing} nowhere in the checked workspace"
    )
    return Diagnostic(
        rule,
        path,
        Span.point(line, col),
        text,
        (
            *where,
            Note(
                "a driver, a simulator, a tool (`ros2 topic pub`, rviz) or another "
                "workspace may use it; a mistyped name or a missing remapping "
                "would look the same"
            ),
        ),
    )


def parameter_value_violated(
    path: str, span: Span, subject: str, rule: str, declared: Declared, *notes: str
) -> Diagnostic:
    """RF101 for a parameter's value: a default in code, or a value in a parameter
    file, outside the declared range or refinement; `notes` (the empty ones left
    out): how ROS read the value, when its text does not say, and why it fails."""
    return Diagnostic(
        rules.REFINEMENT_VIOLATED,
        path,
        span,
        f"{subject} violates {rule}{_owner(declared)}",
        _notes(declared, notes),
    )


def parameter_value_type(
    path: str,
    span: Span,
    subject: str,
    got: str,
    expected: str,
    declared: Declared,
    *notes: str,
) -> Diagnostic:
    """RF401 for a value in a parameter file of another type than declared;
    `notes` as for RF101."""
    return Diagnostic(
        rules.BASE_TYPE_MISMATCH,
        path,
        span,
        f"{subject} is {got}, but the parameter is declared {expected}",
        _notes(declared, notes),
    )


def parameter_refinement_unchecked(
    path: str, span: Span, subject: str, rule: str, declared: Declared, why: str
) -> Diagnostic:
    """RF102 as a note: a value in a parameter file that a refinement of its
    parameter cannot be evaluated for (it names what only the running code knows),
    said rather than passed over."""
    return Diagnostic(
        rules.REFINEMENT_UNPROVEN,
        path,
        span,
        f"{subject} is not checked against {rule}{_owner(declared)}: {why}",
        _notes(declared, ()),
        level=Severity.NOTE,
    )


def _notes(declared: Declared, notes: tuple[str, ...]) -> tuple[Note, ...]:
    return (declared.note(), *(Note(n) for n in notes if n))


def _owner(declared: Declared) -> str:
    return f" ({declared.owner})" if declared.owner else ""


def _join(items: list[str]) -> str:
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def _article(word: str) -> str:
    return "an" if word[:1] in "aeiou" else "a"
