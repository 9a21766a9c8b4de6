"""Every diagnostic's wording: one builder per kind. Checkers never format strings.

Builders take source-level facts (statement text, names, units, values) and return a
`Diagnostic`; nothing here knows about the solver or the analysis state.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from robotfix import rules
from robotfix.annotations.units import Unit
from robotfix.diagnostics import Diagnostic, Note, Rule, Span


@dataclass(frozen=True)
class Declared:
    """Where a refinement or unit was written down."""

    what: str  # "refinement of `timeout`", "unit of geometry_msgs/Twist.linear.x"
    path: str | None
    line: int | None
    source: str = ""  # e.g. "REP 103: ..."
    owner: str = ""  # the message type whose refinement this is, if any

    def note(self) -> Note:
        if self.path is not None:
            return Note(f"{self.what} declared here", self.path, self.line)
        return Note(f"{self.what}: {self.source}")


def unreadable(path: str, detail: str) -> Diagnostic:
    return Diagnostic(rules.UNREADABLE_FILE, path, Span.point(1), detail)


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
    return Diagnostic(rule, path, span, f"not valid Python 3: {detail}")


def annotation_problem(
    path: str, line: int, col: int, rule: Rule, detail: str
) -> Diagnostic:
    return Diagnostic(rule, path, Span.point(line, col), detail)


def unknown_message_class(path: str, span: Span, qualified: str) -> Diagnostic:
    package = qualified.split(".")[0]
    return Diagnostic(
        rules.UNKNOWN_MESSAGE_CLASS,
        path,
        span,
        f"`{qualified}` is not a known message type: its fields are not checked",
        (
            Note(
                f"pass the folder with {package}'s .msg files with --msg-path, or add "
                "it to msg-paths in [tool.robotfix]"
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
    notes = [declared.note()]
    if value is not None:
        notes.append(Note(f"here {subject} = {value}"))
    return Diagnostic(
        rules.REFINEMENT_VIOLATED,
        path,
        span,
        f"`{stmt}` violates `{predicate}`{_owner(declared)}",
        tuple(notes),
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


def unit_mismatch(
    path: str,
    span: Span,
    stmt: str,
    target: str,
    expected: Unit,
    got: Unit,
    declared: Declared,
) -> Diagnostic:
    message = f"`{stmt}` gives {target} a value in {got}, but {target} is in {expected}"
    fix = conversion(got, expected)
    notes = [declared.note()]
    if fix:
        message += f": {fix}"
    return Diagnostic(rules.UNIT_MISMATCH, path, span, message, tuple(notes))


def operand_units(
    path: str, span: Span, expr: str, op: str, left: Unit, right: Unit
) -> Diagnostic:
    verb = {"+": "add", "-": "subtract"}.get(op, "compare")
    message = f"`{expr}`: cannot {verb} {left} and {right}"
    fix = conversion(right, left)
    if fix:
        message += f" ({fix.replace('convert', 'convert the right side from', 1)})"
    return Diagnostic(rules.OPERAND_UNIT_MISMATCH, path, span, message)


def conversion(got: Unit, expected: Unit) -> str:
    """How to turn a value in `got` into `expected`, when only the scale differs."""
    if not got.same_dimension(expected) or expected.is_label:
        return ""
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


def used_before_assignment(
    path: str,
    span: Span,
    stmt: str,
    name: str,
    declared: bool,
    some_paths: bool = False,
) -> Diagnostic:
    if some_paths:
        detail = (
            f"`{name}`, which is not assigned on every path to this line: "
            "on the others it raises UnboundLocalError or NameError"
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


def _owner(declared: Declared) -> str:
    return f" ({declared.owner})" if declared.owner else ""


def _join(items: list[str]) -> str:
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def _article(word: str) -> str:
    return "an" if word[:1] in "aeiou" else "a"
