"""Turn an `Annotated[T, "..."]` node of the Python AST into a `Refinement`.

Knows the Python AST and the refinement language, nothing of the analysis: how an
expression names `typing.Annotated` or a message class is asked of the caller.
Problems (RF5xx) come back with their file position; the caller reports them.

Other libraries put strings in `Annotated` too (`Annotated[int, "const"]`), so a
string is RobotFix's only when it is blank (no refinement), or parses and compares
something, uses `Unit`/`Frame`/`Tag`, or names the annotated value (`_` or its own
name); or, when it does not parse, when it looks like a refinement or code
(`_looks_like`).
Every such string of an `Annotated` counts: together they are one conjunction.
Metadata that is not a string (`ValueRange(0, 1)`, a name bound to no string
constant) is reported as RF511, which the caller keeps only in RobotFix-like files.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, replace
from fractions import Fraction

from robotfix import rules
from robotfix.annotations import ast as A
from robotfix.annotations import foreign
from robotfix.annotations.parser import AnnotationSyntaxError, parse_predicate
from robotfix.annotations.units import Unit, UnitError, label, resolve
from robotfix.diagnostics import Rule
from robotfix.interface_names import interface_class

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
    optional: bool = False  # `Optional[...]`: it holds when the value is not None
    # `tuple[...]`: each element's refinement (None: unrefined); base is "tuple"
    elements: tuple[Refinement | None, ...] | None = None
    item: str | None = None  # a container's element base type
    size: A.Expr = A.TRUE  # a container's length, as `_`
    origin: str | None = None  # the file that declares it, if not the checked one
    # a message's `Unit(field) == "u"` parts: that field of this value has unit u,
    # as an interface file's `#RobotFix# Unit(field) == "u"` says of every message
    field_units: tuple[A.UnitIs, ...] = ()

    def predicates(self) -> list[A.Expr]:
        """Its predicate and its elements': where the names it mentions are."""
        found = [self.predicate]
        for part in self.elements or ():
            found += part.predicates() if part is not None else []
        return found

    @property
    def assumable(self) -> A.Expr:
        """What a read may assume: nothing when the value may be None."""
        return A.TRUE if self.optional else self.predicate


@dataclass(frozen=True)
class AnnotationProblem:
    """An annotation that cannot be read, at its place, with the rule it breaks."""

    rule: Rule
    line: int
    col: int
    message: str
    # RF511 only: why the metadata is not read, and how RobotFix writes it
    why: str | None = None
    hint: str | None = None


@dataclass(frozen=True)
class Names:
    """How one module's annotations name things: its imports (`qualname`), its
    message classes, its type aliases, and where its source text is. An alias carries
    the `Names` of the module that defines it, so a module summary can hand one
    module's aliases to another."""

    qualname: Callable[[ast.expr], str | None]
    msg_type: Callable[[ast.expr], str | None]
    source_segment: Callable[[ast.AST], str | None]
    col_of: Callable[[int, int], int]
    alias: Callable[[ast.expr], Alias | None] = lambda node: None
    path: str | None = None  # the module's file, when it may not be the checked one
    # for an alias handed to another module: its own module's constants, which the
    # text's names mean there (`"_ <= LIMIT"`); None: the text is read where written
    constants: Mapping[str, A.Expr] | None = None
    # whether annotated-types constraints (`Gt(0)`) are refinements here: in ROS
    # code, not in a web app's pydantic models
    constraints: bool = True


@dataclass(frozen=True)
class Alias:
    """What a type alias (`Speed = Annotated[...]`, `Speed: TypeAlias = ...`,
    `type Speed = ...`) or a string constant used as metadata stands for."""

    node: ast.expr
    names: Names


def extract(
    node: ast.expr,
    self_name: str,
    qualname: Callable[[ast.expr], str | None],
    msg_type: Callable[[ast.expr], str | None],
    source_segment: Callable[[ast.AST], str | None],
    col_of: Callable[[int, int], int],
    known: Callable[[str], bool] = lambda name: True,
    alias: Callable[[ast.expr], Alias | None] = lambda node: None,
    field_kind: Callable[[str, str], str | None] = lambda msg, path: None,
    constraints: bool = True,
) -> tuple[Refinement | None, list[AnnotationProblem]]:
    """The refinement in `node`: `Annotated[base, "predicate", ...]`, possibly inside
    `Final[...]`/`ClassVar[...]`, `Optional[...]`/`Union[..., None]`/`... | None`, a
    `tuple[...]` (per element), a string annotation, or behind a type alias.

    On a message (`Annotated[Twist, "abs(linear.x) <= 0.22"]`) names are field
    paths relative to the value, as in interface files (`_.linear.x` and
    `t.linear.x`, for `t` the annotated name, mean the same); `field_kind` says what
    a path of a message type is (None: not a field)."""
    names = Names(
        qualname, msg_type, source_segment, col_of, alias, constraints=constraints
    )
    reader = _Reader(self_name, known, field_kind)
    found = reader.read(node, names)
    return found, reader.problems


MAX_ALIAS_HOPS = 20  # `A = B`, `B = Optional[A]`...: a cycle ends here
MAX_STRING_ANNOTATION = 2000  # characters of a string annotation worth parsing


class _Reader:
    def __init__(
        self,
        self_name: str,
        known: Callable[[str], bool],
        field_kind: Callable[[str, str], str | None] = lambda msg, path: None,
    ) -> None:
        self.self_name = self_name
        self.known = known
        self.field_kind = field_kind
        self.problems: list[AnnotationProblem] = []
        self.hops = 0
        # nodes parsed from a string annotation, by id; kept alive with the reader so
        # that no node allocated later (another module's tree) can take a freed id
        self.synthetic: dict[int, ast.AST] = {}

    def read(self, node: ast.expr, names: Names) -> Refinement | None:
        node, names = self.form(node, names)
        inner = _optional_inner(node, names, self)
        if inner is not None:
            found = self.read(inner[0], inner[1])
            return replace(found, optional=True) if found is not None else None
        elements = _tuple_elements(node, names)
        if elements is not None:
            parts = tuple(self.read(e, names) for e in elements)
            if all(p is None for p in parts):
                return None
            text = self.segment(node, names) or "tuple"
            return Refinement("tuple", None, A.TRUE, text, node.lineno, elements=parts)
        if isinstance(node, ast.Subscript) and names.qualname(node.value) in ANNOTATED:
            return self.annotated(node, names)
        lifted = self.lifted(node, names)
        return self.annotated(lifted, names) if lifted is not None else None

    def lifted(self, node: ast.expr, names: Names) -> ast.Subscript | None:
        """`list[Annotated[float, "Unit('m')"]]` read as `Annotated[list[float],
        "Unit('m')"]`: a list's refinement is on its elements (it was ignored)."""
        if not isinstance(node, ast.Subscript) or isinstance(node.slice, ast.Tuple):
            return None
        kind = _container(_strip(node, names), names.qualname)
        inner, inner_names = self.form(node.slice, names)
        if (
            kind is None
            or kind[0] != "list"
            or inner_names is not names
            or not isinstance(inner, ast.Subscript)
            or names.qualname(inner.value) not in ANNOTATED
            or not isinstance(inner.slice, ast.Tuple)
        ):
            return None
        element, *meta = inner.slice.elts
        if not all(
            isinstance(m, ast.Constant)
            and isinstance(m.value, str)
            and "len(" not in m.value
            for m in meta
        ):
            return None  # `len(_)`, `MinLen(2)` of an element: no list's length
        listed = ast.Subscript(node.value, element, ast.Load())
        lifted = ast.Subscript(inner.value, ast.Tuple([listed, *meta], ast.Load()))
        for made in (listed, lifted, lifted.slice):
            ast.copy_location(made, node)
            self.synthetic[id(made)] = made
        return lifted

    def form(self, node: ast.expr, names: Names) -> tuple[ast.expr, Names]:
        """Strip qualifiers, parse a string annotation, follow aliases."""
        while self.hops < MAX_ALIAS_HOPS:
            if (
                isinstance(node, ast.Subscript)
                and names.qualname(node.value) in QUALIFIERS
            ):
                node = node.slice
                continue
            if isinstance(node, ast.Constant) and isinstance(node.value, str):
                parsed = self.parse_string(node, node.value)
                if parsed is None:
                    break
                node = parsed
                self.hops += 1
                continue
            found = (
                names.alias(node)
                if isinstance(node, (ast.Name, ast.Attribute))
                else None
            )
            if found is None:
                break
            node, names = found.node, found.names
            self.hops += 1
        return node, names

    def parse_string(self, node: ast.Constant, text: str) -> ast.expr | None:
        """`"Annotated[float, 'Unit(\\'m\\')']"` as an expression (parsed, never
        evaluated); every node of it sits at the string, so problems point there."""
        if len(text) > MAX_STRING_ANNOTATION or not (
            "[" in text or text.strip().isidentifier()
        ):
            return None
        try:
            parsed = ast.parse(text.strip(), mode="eval").body
        except (SyntaxError, ValueError, RecursionError, MemoryError):
            return None
        for child in ast.walk(parsed):
            if isinstance(child, ast.expr):
                ast.copy_location(child, node)
                self.synthetic[id(child)] = child
        return parsed

    def segment(self, node: ast.AST, names: Names) -> str | None:
        return None if id(node) in self.synthetic else names.source_segment(node)

    def annotated(self, node: ast.Subscript, names: Names) -> Refinement | None:
        args = node.slice.elts if isinstance(node.slice, ast.Tuple) else [node.slice]
        if not args:
            return None
        base_node, base_names = self.form(args[0], names)
        nested = (
            self.annotated(base_node, base_names)
            if isinstance(base_node, ast.Subscript)
            and base_names.qualname(base_node.value) in ANNOTATED
            else None
        )
        used: list[tuple[A.Expr, str, tuple[int, int, bool], Names]] = []
        sized = (
            nested.item is not None
            if nested is not None
            else _container(_strip(base_node, base_names), base_names.qualname)
            is not None
        )
        for meta in args[1:]:
            found_text = self.foreign(meta, names, sized) or self.metadata(meta, names)
            if found_text is None:
                continue
            text, text_node, text_names = found_text
            start = self.text_start(text_node, text_names)
            constraint = isinstance(text_node, ast.Call)  # annotated-types'
            try:
                predicate = parse_predicate(text)
            except AnnotationSyntaxError as err:
                if not constraint and not _looks_like(text, self.self_name):
                    self.unit_string(text, meta, names, base_node, base_names)
                    continue
                line, col = _at(start, err.offset)
                self.problems.append(
                    AnnotationProblem(rules.ANNOTATION_SYNTAX, line, col, err.message)
                )
                return None
            if (
                not constraint
                and text.strip()
                and not _is_refinement(predicate, self.self_name)
            ):
                self.unit_string(text, meta, names, base_node, base_names)
                continue
            used.append((predicate, text, start, text_names))
        if not used:
            return nested
        item: str | None = None  # a container's elements' base type
        unknown_interface = False  # a message class the catalog does not know
        size: list[A.Expr] = []  # what a container's length satisfies
        if nested is not None:
            base, mtype = nested.base, nested.msg_type
            item = nested.item
            size.append(nested.size)
        else:
            typed = _strip(base_node, base_names)
            scalar = isinstance(typed, ast.Name) and typed.id in BASE_TYPES
            container = None if scalar else _container(typed, base_names.qualname)
            if container is not None:
                base, mtype = container[0], None
                item, fixed = container[1], container[2]
                if fixed is not None:
                    size.append(
                        A.Binary("==", A.Name(SELF), A.Num(Fraction(fixed), True))
                    )
            else:
                base, mtype = _base(typed, base_names.msg_type)
                unknown_interface = base == "other" and interface_class(
                    base_names.qualname(typed)
                )
        unit = nested.unit if nested is not None else None
        parts = [nested.predicate] if nested is not None else []
        texts = [nested.text] if nested is not None else []
        field_units: list[A.UnitIs] = []
        for predicate, text, start, text_names in used:
            found, values = _split(
                predicate, self.self_name, start, self.problems, mtype is not None
            )
            if mtype is not None:
                values = self._field_units(values, mtype, start, field_units)
            if found is not None:
                unit = found if unit is None else unit * found
            if text_names.constants is not None:
                # written in another module: its names mean that module's constants,
                # and a name unknown there is reported there (at its own line)
                constants = dict(text_names.constants)
                values = [A.substitute(v, constants) for v in values]
                values = self.known_parts(values, mtype, start, [])
            elif unknown_interface:
                # a message type the catalog lacks (RF508 says its fields are not
                # checked): a name of it is no error, the part is not used
                values = self.known_parts(values, mtype, start, [])
            else:
                values = self.known_parts(values, mtype, start, self.problems)
            for value in values:
                value = A.substitute(value, {self.self_name: A.Name(SELF)})
                if "len" not in text:  # (most never mention it)
                    parts.append(value)
                    continue
                on = _length_part(value, item is not None, start, self.problems)
                if on is not None:
                    (parts if on[0] == "each" else size).append(on[1])
            texts.append(text)
        shown = (
            " and ".join(texts)
            if len(texts) == 1
            else " and ".join(f"({t})" for t in texts)
        )
        return Refinement(
            base,
            unit,
            A.conjoin(parts),
            shown,
            node.lineno,
            mtype,
            item=item,
            size=A.conjoin([s for s in size if s != A.TRUE]),
            origin=names.path,
            field_units=tuple(field_units),
        )

    def _field_units(
        self,
        values: list[A.Expr],
        mtype: str,
        start: tuple[int, int, bool],
        found: list[A.UnitIs],
    ) -> list[A.Expr]:
        """The parts of a message's refinement that are not `Unit(field) == "u"`;
        those, on a field that holds a value, go to `found` (a path that is not
        one is reported as a refinement's unknown field is)."""
        rest: list[A.Expr] = []
        for part in values:
            if not isinstance(part, A.UnitIs):
                rest.append(part)
                continue
            target = part.target or ""
            root, dot, tail = target.partition(".")
            path = tail if dot and root in (SELF, self.self_name) else target
            kind = self.field_kind(mtype, path)
            if kind is None or kind == "msg":
                line, col = _at(start, part.pos)
                self.problems.append(_not_a_field(path, mtype, kind, line, col))
                continue
            found.append(A.UnitIs(part.kind, part.text, path, part.pos))
        return rest

    def known_parts(
        self,
        values: list[A.Expr],
        mtype: str | None,
        start: tuple[int, int, bool],
        problems: list[AnnotationProblem],
    ) -> list[A.Expr]:
        """The parts whose names are known (the others reported to `problems`); on
        a message, with field paths made relative to the value."""
        if mtype is None:
            return [
                p
                for p in values
                if _names_known(p, self.self_name, self.known, start, problems)
            ]
        return [
            _relative(p, self.self_name)
            for p in values
            if _fields_known(
                p,
                self.self_name,
                mtype,
                self.known,
                self.field_kind,
                start,
                problems,
            )
        ]

    def foreign(
        self, meta: ast.expr, names: Names, sized: bool
    ) -> tuple[str, ast.expr, Names] | None:
        """An annotated-types constraint as the refinement text it means (its node
        is `meta` itself: problems point at the call); one RobotFix cannot read is
        RF511, saying why. (`sized`: the value is a list or tuple.)"""
        found = foreign.constraint(meta, names.qualname)
        if isinstance(found, str) and "len(" in found and not sized:
            found = foreign.Unusable("only a list's or tuple's length is modelled")
        if found is not None and not names.constraints:
            found = foreign.Unusable(
                "annotated-types constraints are read in ROS code (a module that "
                "imports rclpy, rospy or an interface package)"
            )
        if isinstance(found, foreign.Unusable):
            self.note_unused(meta, names, found.why, None)
            return None
        return None if found is None else (found, meta, names)

    def unit_string(
        self,
        text: str,
        meta: ast.expr,
        names: Names,
        base_node: ast.expr,
        base_names: Names,
    ) -> None:
        """A string that is no refinement but a unit as other unit checkers write it
        (`"m"`, `"unit:m"`) on a number: RF511, saying how RobotFix writes it."""
        if not _numeric(base_node, base_names):
            return
        spelled = foreign.unit_string(text)
        if spelled is not None:
            why = "RobotFix reads a unit only inside `Unit()`"
            self.note_unused(meta, names, why, f'write "{spelled}"')

    def note_unused(
        self, meta: ast.expr, names: Names, why: str | None, hint: str | None
    ) -> None:
        shown = self.segment(meta, names) or "this metadata"
        if len(shown) > 60:
            shown = shown[:57] + "..."
        line = meta.lineno
        col = names.col_of(line, meta.col_offset)
        self.problems.append(
            AnnotationProblem(rules.UNUSED_METADATA, line, col, shown, why, hint)
        )

    def metadata(
        self, meta: ast.expr, names: Names
    ) -> tuple[str, ast.Constant, Names] | None:
        """A metadata string, also through a name bound to a string constant; other
        metadata RobotFix cannot use is RF511 (a note the caller may drop)."""
        written, written_names = meta, names  # where the note points
        if isinstance(meta, ast.Name):
            found = names.alias(meta)
            if found is not None:
                meta, names = found.node, found.names
        if isinstance(meta, ast.Constant) and isinstance(meta.value, str):
            return meta.value, meta, names
        self.note_unused(written, written_names, None, None)
        return None

    def text_start(self, node: ast.expr, names: Names) -> tuple[int, int, bool]:
        if id(node) in self.synthetic:
            return node.lineno, names.col_of(node.lineno, node.col_offset), False
        return _text_start(node, names.source_segment, names.col_of)


OPTIONAL = frozenset({"typing.Optional", "typing_extensions.Optional"})
UNION = frozenset({"typing.Union", "typing_extensions.Union"})
TUPLE = frozenset({"typing.Tuple", "typing_extensions.Tuple"})


def _numeric(node: ast.expr, names: Names) -> bool:
    """`int`, `float`, or a list or tuple of them (a unit fits these only)."""
    typed = _strip(node, names)
    if isinstance(typed, ast.Name) and typed.id in ("int", "float"):
        return True
    container = _container(typed, names.qualname)
    return container is not None and container[1] in ("int", "float")


def _optional_inner(
    node: ast.expr, names: Names, reader: _Reader
) -> tuple[ast.expr, Names] | None:
    """`X` of `Optional[X]`, `Union[X, None]`, `X | None` (either order)."""
    if isinstance(node, ast.Subscript):
        head = names.qualname(node.value)
        if head in OPTIONAL:
            return node.slice, names
        if head not in UNION or not isinstance(node.slice, ast.Tuple):
            return None
        options = list(node.slice.elts)
    elif isinstance(node, ast.BinOp) and isinstance(node.op, ast.BitOr):
        options = [node.left, node.right]
    else:
        return None
    if len(options) != 2:
        return None
    rest = [o for o in options if not _is_none(reader.form(o, names)[0])]
    return (rest[0], names) if len(rest) == 1 else None


def _is_none(node: ast.expr) -> bool:
    return isinstance(node, ast.Constant) and node.value is None


def _tuple_elements(node: ast.expr, names: Names) -> list[ast.expr] | None:
    """The element types of a fixed-length `tuple[A, B]` / `Tuple[A, B]`."""
    if not isinstance(node, ast.Subscript):
        return None
    head = node.value
    builtin = isinstance(head, ast.Name) and head.id == "tuple"
    if not builtin and names.qualname(head) not in TUPLE:
        return None
    elements = node.slice.elts if isinstance(node.slice, ast.Tuple) else [node.slice]
    if any(isinstance(e, ast.Constant) and e.value is Ellipsis for e in elements):
        return None  # tuple[X, ...]: any length
    return list(elements)


def _strip(node: ast.expr, names: Names) -> ast.expr:
    return _unqualified(node, names.qualname)


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


def _length_part(
    part: A.Expr,
    container: bool,
    start: tuple[int, int, bool],
    problems: list[AnnotationProblem],
) -> tuple[str, A.Expr] | None:
    """Where one part of a refinement goes: ("each", part) on a container's elements
    or a scalar, ("size", over `_`) when it is on a container's length (`len(_)`).
    A part that mixes the two, or `len(_)` of a scalar, is RF501 (None)."""
    length = A.Name("len(_)")
    lengths = _lengths_replaced(part, length)
    if lengths is part:
        return "each", part
    if not container:
        message = (
            "len(_) is the length of a list, tuple or array: annotate the "
            'container, e.g. Annotated[list[float], "len(_) <= 10"]'
        )
    elif any(n.name == SELF for n in A.names(lengths)):
        message = (
            "a part of a container's refinement is on its elements (`_`) or "
            "on its length (`len(_)`), not both: split it with `and`"
        )
    else:
        return "size", A.substitute(lengths, {length.name: A.Name(SELF)})
    line, col = _at(start, 0)
    problems.append(AnnotationProblem(rules.ANNOTATION_SYNTAX, line, col, message))
    return None


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
    message: bool = False,
) -> tuple[Unit | None, list[A.Expr]]:
    """The unit of the annotated value and the other parts; on a `message`,
    `Unit(field) == "u"` stays among the other parts (its unit checked here)."""
    unit: Unit | None = None
    values: list[A.Expr] = []
    for part in A.conjuncts(predicate):
        if (
            message
            and isinstance(part, A.UnitIs)
            and part.kind == "unit"
            and part.target not in (None, SELF, self_name)
        ):
            try:
                resolve(part.text)
            except UnitError as err:
                line, col = _at(start, part.pos)
                problems.append(
                    AnnotationProblem(rules.UNKNOWN_UNIT, line, col, err.message)
                )
                continue
            values.append(part)
        elif isinstance(part, A.UnitIs) and part.target in (None, SELF, self_name):
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
        problems.append(_not_a_field(path, msg_type, kind, line, col))
        return False
    return True


def _not_a_field(
    path: str, msg_type: str, kind: str | None, line: int, col: int
) -> AnnotationProblem:
    """RF505: a refinement of a `msg_type` names `path`, which is no field of it
    (`kind` None) or a message in it, not a value."""
    what = (
        f"is a message in {msg_type}, not a value"
        if kind == "msg"
        else f"is not a field of {msg_type}"
    )
    return AnnotationProblem(rules.UNKNOWN_FIELD, line, col, f"`{path}` {what}")


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
    node: ast.expr,
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
