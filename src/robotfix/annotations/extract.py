"""Turn an `Annotated[T, "..."]` node of the Python AST into a `Refinement`.

Knows the Python AST and the refinement language, nothing of the analysis: how an
expression names `typing.Annotated` or a message class is asked of the caller.
Problems (RF5xx) come back with their file position; the caller reports them.
"""

from __future__ import annotations

import ast
from collections.abc import Callable
from dataclasses import dataclass

from robotfix import rules
from robotfix.annotations import ast as A
from robotfix.annotations.parser import AnnotationSyntaxError, parse_predicate
from robotfix.annotations.units import Unit, UnitError, label, resolve
from robotfix.diagnostics import Rule

ANNOTATED = frozenset({"typing.Annotated", "typing_extensions.Annotated"})
BASE_TYPES = {"int": "int", "float": "float", "bool": "bool", "str": "str"}
SELF = "_"


@dataclass(frozen=True)
class Refinement:
    """What an annotation says of one variable, parameter or attribute."""

    base: str  # int float bool str msg other
    unit: Unit | None
    predicate: A.Expr  # the value part; the annotated thing itself is `_`
    text: str  # the annotation string as written
    line: int
    msg_type: str | None = None


@dataclass(frozen=True)
class AnnotationProblem:
    rule: Rule
    line: int
    col: int
    message: str


def extract(
    node: ast.expr,
    self_name: str,
    qualname: Callable[[ast.expr], str | None],
    msg_type: Callable[[ast.expr], str | None],
    source_segment: Callable[[ast.AST], str | None],
    col_of: Callable[[int, int], int],
    known: Callable[[str], bool] = lambda name: True,
    field_kind: Callable[[str, str], str | None] = lambda msg, path: None,
) -> tuple[Refinement | None, list[AnnotationProblem]]:
    """The refinement in `node`, if it is `Annotated[base, "predicate", ...]`.

    On a message (`Annotated[Twist, "abs(linear.x) <= 0.22"]`) names are field
    paths relative to the value, as in interface files (`_.linear.x` and
    `t.linear.x`, for `t` the annotated name, mean the same); `field_kind` says what
    a path of a message type is (None: not a field)."""
    if not isinstance(node, ast.Subscript) or qualname(node.value) not in ANNOTATED:
        return None, []
    args = node.slice.elts if isinstance(node.slice, ast.Tuple) else [node.slice]
    text_node = next(
        (
            a
            for a in args[1:]
            if isinstance(a, ast.Constant) and isinstance(a.value, str)
        ),
        None,
    )
    if text_node is None or not args:
        return None, []
    base, mtype = _base(args[0], msg_type)
    text = str(text_node.value)
    start = _text_start(text_node, source_segment, col_of)
    problems: list[AnnotationProblem] = []
    try:
        predicate = parse_predicate(text)
    except AnnotationSyntaxError as err:
        line, col = _at(start, err.offset)
        problems.append(
            AnnotationProblem(rules.ANNOTATION_SYNTAX, line, col, err.message)
        )
        return None, problems
    unit, value_parts = _split(predicate, self_name, start, problems)
    if mtype is not None:
        value_parts = [
            _relative(p, self_name)
            for p in value_parts
            if _fields_known(p, self_name, mtype, known, field_kind, start, problems)
        ]
    else:
        value_parts = [
            p for p in value_parts if _names_known(p, self_name, known, start, problems)
        ]
    renamed = A.substitute(A.conjoin(value_parts), {self_name: A.Name(SELF)})
    return Refinement(base, unit, renamed, text, node.lineno, mtype), problems


def _base(
    node: ast.expr, msg_type: Callable[[ast.expr], str | None]
) -> tuple[str, str | None]:
    if isinstance(node, ast.Name) and node.id in BASE_TYPES:
        return BASE_TYPES[node.id], None
    found = msg_type(node)
    return ("msg", found) if found else ("other", None)


def _split(
    predicate: A.Expr,
    self_name: str,
    start: tuple[int, int, bool],
    problems: list[AnnotationProblem],
) -> tuple[Unit | None, list[A.Expr]]:
    unit: Unit | None = None
    values: list[A.Expr] = []
    for part in A.conjuncts(predicate):
        if isinstance(part, A.UnitIs) and part.target in (None, SELF, self_name):
            try:
                found = (
                    resolve(part.text)
                    if part.kind == "unit"
                    else label(part.kind, part.text)
                )
            except UnitError as err:
                line, col = _at(start, part.pos)
                problems.append(
                    AnnotationProblem(rules.UNKNOWN_UNIT, line, col, err.message)
                )
                continue
            unit = found if unit is None else unit * found
        elif any(isinstance(n, A.UnitIs) for n in A.walk(part)):
            line, col = _at(start, 0)
            problems.append(
                AnnotationProblem(
                    rules.MISPLACED_UNIT,
                    line,
                    col,
                    "Unit(), Frame() and Tag() must be top-level `and` parts and name "
                    "the "
                    "annotated value",
                )
            )
        else:
            values.append(part)
    return unit, values


def _relative(part: A.Expr, self_name: str) -> A.Expr:
    """`_.linear.x` and `t.linear.x` -> `linear.x`."""
    renames: dict[str, A.Expr] = {}
    for name in A.names(part):
        root, dot, rest = name.name.partition(".")
        if dot and root in (SELF, self_name):
            renames[name.name] = A.Name(rest, name.pos)
    return A.substitute(part, renames) if renames else part


def _fields_known(
    part: A.Expr,
    self_name: str,
    msg_type: str,
    known: Callable[[str], bool],
    field_kind: Callable[[str, str], str | None],
    start: tuple[int, int, bool],
    problems: list[AnnotationProblem],
) -> bool:
    """Names in a message's refinement are its fields or names in scope."""
    for name in A.names(part):
        root, dot, rest = name.name.partition(".")
        path = rest if dot and root in (SELF, self_name) else name.name
        kind = field_kind(msg_type, path)
        if kind is not None and kind != "msg":
            continue
        if kind is None and path == name.name and known(root):
            continue
        line, col = _at(start, name.pos)
        what = (
            f"is a message in {msg_type}, not a value"
            if kind == "msg"
            else f"is not a field of {msg_type}"
        )
        problems.append(
            AnnotationProblem(rules.UNKNOWN_FIELD, line, col, f"`{path}` {what}")
        )
        return False
    return True


def _names_known(
    part: A.Expr,
    self_name: str,
    known: Callable[[str], bool],
    start: tuple[int, int, bool],
    problems: list[AnnotationProblem],
) -> bool:
    for name in A.names(part):
        root = name.name.split(".")[0]
        if root not in (SELF, self_name) and not known(root):
            line, col = _at(start, name.pos)
            problems.append(
                AnnotationProblem(
                    rules.UNKNOWN_NAME,
                    line,
                    col,
                    f"`{name.name}` is not a variable in scope here "
                    "(the annotated value is "
                    f"`_` or `{self_name}`)",
                )
            )
            return False
    return True


def _text_start(
    node: ast.Constant,
    source_segment: Callable[[ast.AST], str | None],
    col_of: Callable[[int, int], int],
) -> tuple[int, int, bool]:
    """Where the string's text starts; offsets into it are exact only for a plain
    one-line literal, otherwise every problem points at the string's start."""
    col = col_of(node.lineno, node.col_offset)
    segment = source_segment(node)
    if not segment or "\\" in segment or "\n" in segment or segment[0] not in "'\"":
        return node.lineno, col, False
    quote = 3 if segment[:3] in ('"""', "'''") else 1
    return node.lineno, col + quote, True


def _at(start: tuple[int, int, bool], offset: int) -> tuple[int, int]:
    line, col, exact = start
    return line, col + offset if exact else col
