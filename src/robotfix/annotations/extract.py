"""Turn an `Annotated[T, "..."]` node of the Python AST into a `Refinement`.

Knows the Python AST and the refinement language, nothing of the analysis: how an
expression names `typing.Annotated` or a message class is asked of the caller.
Problems (RF5xx) come back with their file position; the caller reports them.

Other libraries put strings in `Annotated` too (`Annotated[int, "const"]`), so a
string is RobotFix's only when it is blank (no refinement), or parses and compares
something, uses `Unit`/`Frame`/`Tag`, or names the annotated value (`_` or its own
name); or, when it does not parse, when it looks like a refinement or code
(`_looks_like`).
The first such string of an `Annotated` is its refinement; other strings are ignored.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Callable
from dataclasses import dataclass, replace
from fractions import Fraction

from robotfix import rules
from robotfix.annotations import ast as A
from robotfix.annotations.parser import AnnotationSyntaxError, parse_predicate
from robotfix.annotations.units import Unit, UnitError, label, resolve
from robotfix.diagnostics import Rule

ANNOTATED = frozenset({"typing.Annotated", "typing_extensions.Annotated"})
BASE_TYPES = {"int": "int", "float": "float", "bool": "bool", "str": "str"}
SELF = "_"
_HINT = re.compile(  # a comparison, a call, or `_`
    r"[<>]|[=!]=|\b(?:Unit|Frame|Tag)\s*\(|[A-Za-z_]\w*\(|(?<![\w.])_(?!\w)"
)

# Qualifiers around (or inside) `Annotated`: `Final[Annotated[float, "..."]]`.
QUALIFIERS = frozenset(
    f"{module}.{name}"
    for module in ("typing", "typing_extensions")
    for name in ("Final", "ClassVar")
)


# `list[float]`, `Sequence[float]`, `tuple[float, ...]`: a refinement on one of these
# is on its elements; `len(_)` in it is on the container's length.
CONTAINER_NAMES = {"list": "list", "tuple": "tuple"}
CONTAINER_TYPES = {
    **{f"typing.{n}": "list" for n in ("List", "Sequence", "MutableSequence")},
    **{f"collections.abc.{n}": "list" for n in ("Sequence", "MutableSequence")},
    "typing.Tuple": "tuple",
    "typing_extensions.Sequence": "list",
}


@dataclass(frozen=True)
class Refinement:
    """What an annotation says of one variable, parameter or attribute.

    For a container (`base` list or tuple), `item` is its elements' base type, `unit`
    and `predicate` are theirs, and `size` is what its length (`_`) satisfies."""

    base: str  # int float bool str msg list tuple other
    unit: Unit | None
    predicate: A.Expr  # the value part; the annotated thing itself is `_`
    text: str  # the annotation string as written
    line: int
    msg_type: str | None = None
    item: str | None = None  # a container's element base type
    size: A.Expr = A.TRUE  # a container's length, as `_`


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
) -> tuple[Refinement | None, list[AnnotationProblem]]:
    """The refinement in `node`, if it is `Annotated[base, "predicate", ...]`
    (possibly inside `Final[...]` or `ClassVar[...]`)."""
    node = _unqualified(node, qualname)
    if not isinstance(node, ast.Subscript) or qualname(node.value) not in ANNOTATED:
        return None, []
    args = node.slice.elts if isinstance(node.slice, ast.Tuple) else [node.slice]
    for text_node in args[1:]:
        if not isinstance(text_node, ast.Constant) or not isinstance(
            text_node.value, str
        ):
            continue
        text = text_node.value
        start = _text_start(text_node, source_segment, col_of)
        try:
            predicate = parse_predicate(text)
        except AnnotationSyntaxError as err:
            if not _looks_like(text, self_name):
                continue
            line, col = _at(start, err.offset)
            problem = AnnotationProblem(rules.ANNOTATION_SYNTAX, line, col, err.message)
            return None, [problem]
        if text.strip() and not _is_refinement(predicate, self_name):
            continue
        typed = _unqualified(args[0], qualname)
        scalar = isinstance(typed, ast.Name) and typed.id in BASE_TYPES
        container = None if scalar else _container(typed, qualname)
        if container is not None:
            kind, element, fixed = container
            found, problems = _refinement(
                predicate, kind, None, text, node.lineno, self_name, start, known
            )
            if found is None:
                return found, problems
            return _on_elements(found, element, fixed, self_name, start, problems)
        base, mtype = _base(typed, msg_type)
        found, problems = _refinement(
            predicate, base, mtype, text, node.lineno, self_name, start, known
        )
        if found is None or "len" not in text:  # (most never mention it)
            return found, problems
        length = A.Name("len(_)")
        parts = A.conjuncts(found.predicate)
        kept = [p for p in parts if _lengths_replaced(p, length) is p]
        if len(kept) < len(parts):
            line, col = _at(start, 0)
            problems.append(
                AnnotationProblem(
                    rules.ANNOTATION_SYNTAX,
                    line,
                    col,
                    "len(_) is the length of a list, tuple or array: annotate the "
                    'container, e.g. Annotated[list[float], "len(_) <= 10"]',
                )
            )
            found = replace(found, predicate=A.conjoin(kept))
        return found, problems
    return None, []


def _container(
    node: ast.expr, qualname: Callable[[ast.expr], str | None]
) -> tuple[str, str, int | None] | None:
    """(list or tuple, the elements' base type, a fixed length) for `list[float]`,
    `Sequence[int]`, `tuple[float, ...]`, `tuple[float, float]`, bare `list`."""
    head = node.value if isinstance(node, ast.Subscript) else node
    kind = (
        CONTAINER_NAMES.get(head.id) if isinstance(head, ast.Name) else None
    ) or CONTAINER_TYPES.get(qualname(head) or "")
    if kind is None:
        return None
    if not isinstance(node, ast.Subscript):
        return kind, "other", None
    parts = node.slice.elts if isinstance(node.slice, ast.Tuple) else [node.slice]
    fixed: int | None = None
    if kind == "tuple" and not (
        len(parts) == 2
        and isinstance(parts[1], ast.Constant)
        and parts[1].value is Ellipsis
    ):
        fixed = len(parts)
    elif len(parts) != 1 and kind != "tuple":
        return kind, "other", None
    names = {p.id if isinstance(p, ast.Name) else "" for p in parts[: fixed or 1]}
    element = BASE_TYPES.get(names.pop(), "other") if len(names) == 1 else "other"
    return kind, element, fixed


def _on_elements(
    found: Refinement,
    element: str,
    fixed: int | None,
    self_name: str,
    start: tuple[int, int, bool],
    problems: list[AnnotationProblem],
) -> tuple[Refinement | None, list[AnnotationProblem]]:
    """Split a container's refinement: parts with `len(_)` are on its length, the
    others on every element; a part that mixes the two is RF501."""
    each: list[A.Expr] = []
    size: list[A.Expr] = (
        []
        if fixed is None
        else [A.Binary("==", A.Name(SELF), A.Num(Fraction(fixed), True))]
    )
    length = A.Name("len(_)")
    for part in A.conjuncts(found.predicate):
        lengths = _lengths_replaced(part, length)
        if lengths is part:
            each.append(part)
        elif any(n.name == SELF for n in A.names(lengths)):
            line, col = _at(start, 0)
            problems.append(
                AnnotationProblem(
                    rules.ANNOTATION_SYNTAX,
                    line,
                    col,
                    "a part of a container's refinement is on its elements (`_`) or "
                    "on its length (`len(_)`), not both: split it with `and`",
                )
            )
        else:
            size.append(A.substitute(lengths, {length.name: A.Name(SELF)}))
    refined = Refinement(
        found.base,
        found.unit,
        A.conjoin(each),
        found.text,
        found.line,
        item=element,
        size=A.conjoin(size),
    )
    return refined, problems


def _lengths_replaced(expr: A.Expr, length: A.Name) -> A.Expr:
    """`expr` with every `len(_)` replaced by `length` (the same object when there is
    none)."""
    if isinstance(expr, A.Func) and expr.name == "len" and expr.args == (A.Name(SELF),):
        return length
    kids = A.children(expr)
    if not kids:
        return expr
    new = tuple(_lengths_replaced(k, length) for k in kids)
    if all(a is b for a, b in zip(new, kids, strict=True)):
        return expr
    return A.rebuild(expr, new)


def _looks_like(text: str, self_name: str) -> bool:
    """Whether text that does not parse was meant as a refinement: it compares,
    calls a function (`Unit(`, `abs(`), or names `_` or the annotated value."""
    if _HINT.search(text):
        return True
    return re.search(rf"(?<![\w.]){re.escape(self_name)}(?!\w)", text) is not None


def _is_refinement(predicate: A.Expr, self_name: str) -> bool:
    """Whether a parsed string says something RobotFix checks, rather than being a
    word or phrase another library put there (`"const"`, `"positive and small"`)."""
    for node in A.walk(predicate):
        if isinstance(node, (A.UnitIs, A.Bool)):
            return True
        if isinstance(node, A.Binary) and node.op in A.COMPARE_OPS:
            return True
        if isinstance(node, A.Name) and node.name.split(".")[0] in (SELF, self_name):
            return True
    return False


def _refinement(
    predicate: A.Expr,
    base: str,
    mtype: str | None,
    text: str,
    line: int,
    self_name: str,
    start: tuple[int, int, bool],
    known: Callable[[str], bool],
) -> tuple[Refinement | None, list[AnnotationProblem]]:
    problems: list[AnnotationProblem] = []
    unit, value_parts = _split(predicate, self_name, start, problems)
    value_parts = [
        p for p in value_parts if _names_known(p, self_name, known, start, problems)
    ]
    renamed = A.substitute(A.conjoin(value_parts), {self_name: A.Name(SELF)})
    return Refinement(base, unit, renamed, text, line, mtype), problems


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


def _unqualified(
    node: ast.expr, qualname: Callable[[ast.expr], str | None]
) -> ast.expr:
    while isinstance(node, ast.Subscript) and qualname(node.value) in QUALIFIERS:
        node = node.slice
    return node
