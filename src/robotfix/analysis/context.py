"""Per-file analysis context: fresh symbols and heap ids, imports, reports, scopes.

One `FileContext` per checked file; nothing here outlives the check of that file.
"""

from __future__ import annotations

import ast
import builtins
import itertools
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

from robotfix import messages, rules
from robotfix.analysis.consistency import consistent_invariants, contradictory
from robotfix.analysis.constants import ConstantNames
from robotfix.analysis.imported import absolute_imports, dotted_name
from robotfix.analysis.index import FileIndex, index_scope
from robotfix.analysis.values import Value, sort_of, unknown
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Alias, Names, Refinement, extract
from robotfix.annotations.units import UnitError, resolve
from robotfix.budget import Budget
from robotfix.diagnostics import Diagnostic, Span
from robotfix.ros.catalog import Invariant, MsgCatalog, MsgSpec
from robotfix.source import SourceFile
from robotfix.stubs.load import StubSet
from robotfix.vc import VC, Verdict

if TYPE_CHECKING:
    from robotfix.analysis.imported import Resolver

MSG_MODULES = ("msg", "srv", "action")
ROS_CLIENTS = ("rclpy", "rospy")
# Python packages only ROS 1 has: a file importing one (and not rclpy) is ROS 1 code.
ROS1_PACKAGES = frozenset({"rospy", "roslib", "actionlib", "rosbag", "tf"})
# ROS 1 generates AddTwoIntsRequest, FibonacciGoal...; ROS 2 nests AddTwoInts.Request.
SECTION_SUFFIXES = ("Request", "Response", "Goal", "Result", "Feedback")


@dataclass
class Scope:
    """A module, class or function body: what it declares and what it binds."""

    kind: str  # module, class, function
    name: str
    node: ast.AST
    parent: Scope | None = None
    decls: dict[str, Refinement] = field(default_factory=dict)
    local_names: set[str] = field(default_factory=set)
    global_names: set[str] = field(default_factory=set)

    def module(self) -> Scope:
        return self if self.parent is None else self.parent.module()


# Deterministic limits (work counted, not time measured): a pathological file turns
# into an RF902 warning instead of taking the run down. The file's work budget
# (`robotfix.budget`) counts a step per statement and expression interpreted and per
# character of an annotation read, with the solver's work.
TERM_LIMIT = 400  # nodes in one solver term; beyond it the value becomes unknown


# the `once` key of the RF901 that says a solver question spent the file's budget
SOLVER_BUDGET: tuple[object, ...] = ("solver budget",)


class BudgetExceededError(Exception):
    def __init__(self, line: int) -> None:
        super().__init__(line)
        self.line = line


class FileContext:
    def __init__(
        self,
        source: SourceFile,
        catalog: MsgCatalog,
        discharge: Callable[[VC], Verdict],
        resolver: Resolver | None = None,
        budget: Budget | None = None,
    ) -> None:
        self.source = source
        # the file's work, shared with `discharge` when it is given the same one
        self.budget = budget if budget is not None else Budget()
        # the other modules of the tree (`analysis/imported.py`); None: none known
        self.resolver = resolver
        self.catalog = catalog
        # (`msg` or `interface`, a dotted name) -> what `msg_type_named` or
        # `interface_named` says: the catalog does not change during a file's check,
        # and the types it looked up are in its `touched` from the first time
        self._type_names: dict[tuple[str, str | None], str | None] = {}
        self.discharge = discharge
        self.diagnostics: list[Diagnostic] = []
        self.sym_names: dict[int, str | ast.AST] = {}  # text, or a node to quote
        self._next = 0
        self._sub_ids: dict[tuple[int, str], int] = {}
        # `derived` values, or the symbols `derived_term` made alone
        self._derived: dict[tuple[object, ...], Value | A.Sym] = {}
        # symbol of a read of an object that code may have changed -> the same read
        # before any change (`possible_unchanged` asks as if nothing changed)
        # (and the id of the object read)
        self.unchanged: dict[int, tuple[A.Sym, object]] = {}
        self._first_reads: dict[object, A.Sym] = {}
        self.sizes: dict[int, int] = {}  # symbol of a list, set or dict display -> len
        # symbol of an integer field of a received message -> its type's range, a
        # fact added only to the questions that name the symbol (`Checker.ranges`)
        self.ranged: dict[int, tuple[int, int]] = {}
        self.index = FileIndex()
        self.imports: dict[str, str] = {}  # local name -> qualified name
        # `ros_code` of these imports (asked at every annotation read; a summary's
        # context is handed the imports of another, so kept with the dict asked of)
        self._ros_code: tuple[dict[str, str] | None, bool] = (None, False)
        self.star_import = False
        self.ros1 = False  # ROS 1 code: standard messages have no default values
        self.constants = ConstantNames()  # which names are constants, and their values
        # whether to keep what local lists hold element by element (decided once,
        # when first needed)
        self.follow_lists: bool | None = None
        self._reported: set[tuple[object, ...]] = set()
        # reports a later one at the same statement may replace (`defer`)
        self.deferred: dict[tuple[object, ...], Diagnostic] = {}
        # RF511 notes, kept only if the file turns out RobotFix-like (`metadata_notes`)
        self._metadata_notes: list[Diagnostic] = []
        self.uses_refinements = False  # some annotation of the file is a refinement
        self.stubs: StubSet | None = None  # the run's stubs (None: the shipped ones)
        # what a publisher's subscribers assume of what it publishes (issue 23 §3,
        # `graphcheck.contracts`): the publisher's holder (`self.pub`) -> what its
        # `publish` argument is checked against, each named for its notes ("the
        # message to `/odom`"); empty in a file's own check
        self.obligations: dict[str, list[tuple[str, Refinement]]] = {}
        # Per-file state of parts above this module, which alone know its type
        # (this module imports none of them): None until its part makes it.
        # `parameters.ParamContext`, at the first parameter call
        self.parameters: object = None
        self.frame_facts: object = None  # `frames.FrameFacts`, when asked
        # symbols of satisfiability questions: never those of `fresh`
        self._question_ids = itertools.count(-1, -1)
        self._invariants: dict[str, list[Invariant]] = {}
        self.muted = 0  # > 0: checks go on, their reports are dropped
        self.dropped = 0  # reports dropped so far (a muted helper call reported)
        # (span, markdown) for names and fields, kept only for editor hovers
        self.hovers: list[tuple[Span, str]] | None = None
        # where unannotated names flow (analysis/flows.py), for `robotfix suggest`;
        # None when not asked for
        self.unit_flows: object = None  # a `flows.FlowLog`
        # while analysis/unitmemo.py records one item: its reports in order, the
        # `once` keys it touched with whether they were set before it, the first
        # symbol it made, and whether it reused a cache entry of an earlier item
        self.unit_memo: object = None  # the editor's `UnitMemo`, per document
        self.unit_log: list[tuple[Diagnostic | None, object]] | None = None
        self.unit_answers: dict[object, bool] | None = None
        self.unit_floor = 0
        self.unit_base = 0
        self.unit_shared = False

    # -- symbols and ids -----------------------------------------------------
    def fresh_id(self) -> int:
        self._next += 1
        return self._next

    def derived(
        self, key: tuple[object, ...], kind: str, description: str | ast.AST
    ) -> Value:
        """An unknown value that is a function of `key` (`x is None` for one value
        of x): the same symbol wherever it is asked for."""
        found = self._derived.get(key)
        if isinstance(found, A.Sym):  # made for its term alone: now its value
            if self.unit_log is not None:
                self._shared(found)
            value = self._derived[key] = Value(kind, found)
            return value
        if found is not None:
            if self.unit_log is not None:
                self._shared(found.term)
            return found
        value = self._derived[key] = self.fresh(kind, description)
        self._tie_first(key, kind, description, value.term)  # type: ignore[arg-type]
        return value

    def derived_term(
        self, key: tuple[object, ...], kind: str, description: str | ast.AST
    ) -> A.Expr:
        """`derived(key, kind, description).term`, for a caller that reads the term
        alone (`x is None`, `if x:`, the ties of a join: 23k of the 42k derived
        symbols of corpus25): no value is made for it, only its symbol, which is
        the value's term if `derived` asks for that key later."""
        found = self._derived.get(key)
        if found is not None:
            term = found.term if type(found) is Value else found
            if self.unit_log is not None:
                self._shared(term)
            return term  # type: ignore[return-value]
        ident = self.fresh_id()  # (`fresh`'s numbering and name, without the value)
        self.sym_names[ident] = description
        sym = self._derived[key] = A.Sym(ident, sort_of(kind))
        self._tie_first(key, kind, description, sym)
        return sym

    def _tie_first(
        self, key: tuple[object, ...], kind: str, description: str | ast.AST, sym: A.Sym
    ) -> None:
        """`sym`, just made for `key`, is a later read of the object read first
        under another key (`_first_version`): `unchanged` maps it to that read."""
        first, read = _first_version(key, self.unchanged)
        if first is not key:
            base = self.derived_term(first, kind, description)
            if isinstance(base, A.Sym):
                self.unchanged[sym.ident] = (base, read)

    def first_read(self, read: object, sym: A.Sym) -> None:
        """`sym` is a read of `read` (`self.flag`), maybe again after a call that
        may have changed it: `unchanged` maps it to the first read."""
        first = self._first_reads.setdefault(read, sym)
        if self.unit_log is not None:
            self._shared(first)
        if first is not sym and first != sym:  # (the first read: no comparison)
            self.unchanged[sym.ident] = (first, read)

    def sub_id(self, parent: int, name: str) -> int:
        """The id of the sub-message in field `name` of message `parent`: the same on
        every path, so that paths that each touched it join field by field."""
        found = self._sub_ids.get((parent, name))
        if found is not None and self.unit_log is not None:
            self.unit_shared = self.unit_shared or (
                self.unit_base < found <= self.unit_floor
            )
        if found is None:
            found = self._sub_ids[(parent, name)] = self.fresh_id()
        return found

    def _shared(self, term: object) -> None:
        """An entry made before the item being recorded: not replayable."""
        ident = term.ident if isinstance(term, A.Sym) else self.unit_floor
        if self.unit_base < ident <= self.unit_floor or not isinstance(term, A.Sym):
            self.unit_shared = True

    def _touch(self, once: tuple[object, ...]) -> None:
        if self.unit_answers is not None and once not in self.unit_answers:
            self.unit_answers[once] = once in self._reported

    def last_id(self) -> int:
        """The newest symbol or heap id: those made later have larger ids."""
        return self._next

    def fresh(
        self, kind: str, description: str | ast.AST, unit: object = None
    ) -> Value:
        """An unknown value of `kind`, named `description` (or the source of a node)
        in counterexamples."""
        self._next += 1  # `fresh_id`, inline: ~180k unknowns on 240k lines
        ident = self._next
        self.sym_names[ident] = description
        return unknown(kind, ident, unit)  # type: ignore[arg-type]

    def describe(self, ident: int) -> str:
        found = self.sym_names.get(ident)
        if isinstance(found, ast.AST):
            text = self.source.segment(found) or ""
            return (
                f"`{text}`"
                if text and len(text) < 40 and "\n" not in text
                else "an expression"
            )
        return found or f"value #{ident}"

    @contextmanager
    def quiet(self) -> Iterator[None]:
        """Analysis whose reports, hovers and unit flows are dropped: a helper
        evaluated at its call, a loop's first iteration run again."""
        hovers, flows = self.hovers, self.unit_flows
        self.hovers = self.unit_flows = None
        self.muted += 1
        try:
            yield
        finally:
            self.hovers, self.unit_flows = hovers, flows
            self.muted -= 1

    def step(self, node: ast.AST, steps: int = 1) -> None:
        """Count `steps` of the file's work at `node`; past its budget, stop."""
        budget = self.budget
        budget.used += steps  # `Budget.spend`, inline: a call per expression
        if budget.used > budget.limit:
            raise BudgetExceededError(getattr(node, "lineno", 1))

    # -- reporting -----------------------------------------------------------
    def already(self, once: tuple[object, ...]) -> bool:
        if self.unit_log is not None:
            self._touch(once)
        return once in self._reported

    def report_once(self, once: tuple[object, ...]) -> None:
        """Mark `once` as reported (for a diagnostic keyed by something else)."""
        if self.unit_log is not None:
            self._touch(once)
            self.unit_log.append((None, once))
        self._reported.add(once)

    def report(self, diag: Diagnostic, once: tuple[object, ...] | None = None) -> None:
        if self.muted:
            self.dropped += 1
            return
        if self.unit_log is not None:
            if once is not None:
                self._touch(once)
            self.unit_log.append((diag, once))
        if once is not None:
            if once in self._reported:
                return
            self._reported.add(once)
        self.diagnostics.append(diag)

    def defer(self, diag: Diagnostic, once: tuple[object, ...]) -> None:
        """Report `diag` at the end of the statement (`flush`), unless a report
        with the same `once` key comes first: one bug, one diagnostic, the one
        that knows most (`math.degrees(deg)` stored into rad: "use
        `math.radians()`", not "drop the call")."""
        self.dropped += bool(self.muted)
        if not self.muted and once not in self._reported:
            self.deferred.setdefault(once, diag)

    def flush(self) -> None:
        """Report what `defer` kept and nothing replaced."""
        if self.deferred:
            waiting, self.deferred = self.deferred, {}
            for once, diag in waiting.items():
                self.report(diag, once=once)

    # -- names ---------------------------------------------------------------
    def record_imports(self, index: FileIndex) -> None:
        self.index = index
        package = self.resolver.package if self.resolver is not None else None
        self.imports = absolute_imports(index, package)
        self.star_import = index.star_import
        roots = {q.split(".")[0] for q in self.imports.values()}
        self.ros1 = bool(roots & ROS1_PACKAGES) and "rclpy" not in roots

    def absolute(self, level: int, module: str | None) -> str | None:
        """The absolute module of a relative import (None outside a package)."""
        from robotfix.analysis.imported import absolute

        package = self.resolver.package if self.resolver is not None else None
        return absolute(package, level, module)

    def qualname(self, node: ast.expr) -> str | None:
        """`t.Annotated` -> `typing.Annotated`, when the names come from imports."""
        return dotted_name(node, self.imports)

    def msg_type_named(self, qualified: str | None) -> str | None:
        """`geometry_msgs.msg.Twist`, `std_msgs.Int32` or `pkg.srv.AddTwoIntsRequest`
        -> the catalog's `pkg/Name`, if it is a known message; ROS 2's nested
        section `pkg.srv.AddTwoInts.Request` -> `pkg/AddTwoInts_Request`."""
        key = ("msg", qualified)
        if key not in self._type_names:
            self._type_names[key] = self._msg_type_named(qualified)
        return self._type_names[key]

    def _msg_type_named(self, qualified: str | None) -> str | None:
        found = self._split(qualified) or _section(qualified)
        if found is None:
            return None
        package, name = found
        candidates = [name]
        if name.endswith(SECTION_SUFFIXES):  # (most names end in none: no loop)
            candidates += [
                f"{name[: -len(s)].rstrip('_')}_{s}"
                for s in SECTION_SUFFIXES
                if name.endswith(s) and len(name) > len(s)
            ]
        for candidate in candidates:
            spec = self.catalog.lookup(f"{package}/{candidate}")
            if spec is not None:
                return spec.name
        return None

    def interface_named(self, qualified: str | None) -> str | None:
        """`pkg.srv.AddTwoInts` or `pkg.action.Fibonacci` -> `pkg/AddTwoInts`, when the
        catalog knows its sections."""
        key = ("interface", qualified)
        if key not in self._type_names:
            self._type_names[key] = self._interface_named(qualified)
        return self._type_names[key]

    def _interface_named(self, qualified: str | None) -> str | None:
        found = self._split(qualified)
        if found is None:
            return None
        package, name = found
        name = name[: -len("Action")] if name.endswith("Action") else name
        for section in ("Request", "Goal"):
            if self.catalog.lookup(f"{package}/{name}_{section}") is not None:
                return f"{package}/{name}"
        return None

    def interface_of(self, node: ast.expr) -> str | None:
        """A message, service or action type named in code, as `pkg/Name`."""
        qualified = self.qualname(node)
        return self.msg_type_named(qualified) or self.interface_named(qualified)

    @staticmethod
    def _split(qualified: str | None) -> tuple[str, str] | None:
        if not qualified or "." not in qualified:
            return None
        module, _, name = qualified.rpartition(".")
        parts = module.split(".")
        if (len(parts) == 2 and parts[1] in MSG_MODULES) or len(parts) == 1:
            return parts[0], name
        return None

    def _field_units_declared(
        self, found: Refinement, msg_type: str, text: ast.expr
    ) -> None:
        """`Unit(field) == "u"` on a value names a field whose interface gives
        it another unit: RF507 (the interface's is kept)."""
        for part in found.field_units:
            declared = self.catalog.unit_at(msg_type, part.target or "")
            if declared is None or _same_unit(declared, part.text):
                continue
            message = (
                f"`{part.target}` of {msg_type} is in {declared}, as its interface "
                f"declares: Unit({part.target}) == '{part.text}' on a value gives "
                "a unit only to a field whose interface gives none"
            )
            self.report(
                messages.annotation_problem(
                    self.source.path,
                    text.lineno,
                    self.source.char_col(text.lineno, text.col_offset),
                    rules.MISPLACED_UNIT,
                    message,
                ),
                once=("field unit", text.lineno, part.target, part.text),
            )

    def msg_type_of(self, node: ast.expr) -> str | None:
        return self.msg_type_named(self.qualname(node))

    def refinement(
        self,
        annotation: ast.expr,
        self_name: str,
        known: Callable[[str], bool] = lambda name: True,
    ) -> Refinement | None:
        # reading a refinement is work: a step per character of the annotation
        self.step(annotation, 1 + self._length(annotation))
        found, problems = extract(
            annotation,
            self_name,
            self.qualname,
            self.msg_type_of,
            self.source.segment,
            self.source.char_col,
            known,
            self.alias_of,
            self._field_kind,
            self.ros_code,
        )
        self.uses_refinements = self.uses_refinements or found is not None
        for problem in problems:
            if problem.rule is rules.UNUSED_METADATA:
                self._metadata_notes.append(
                    messages.unused_metadata(
                        self.source.path,
                        problem.line,
                        problem.col,
                        problem.message,
                        problem.why,
                        problem.hint,
                    )
                )
                continue
            self.report(
                messages.annotation_problem(
                    self.source.path,
                    problem.line,
                    problem.col,
                    problem.rule,
                    problem.message,
                ),
                once=("annotation", problem.line, problem.col, problem.message),
            )
        if found is not None and found.field_units and found.msg_type:
            self._field_units_declared(found, found.msg_type, _text_node(annotation))
        if found is not None and self._contradictory(found):
            text = _text_node(annotation)
            self.report(
                messages.contradictory_refinement(
                    self.source.path,
                    text.lineno,
                    self.source.char_col(text.lineno, text.col_offset),
                    A.show(A.substitute(found.predicate, {"_": A.Name(self_name)})),
                    f"`{self_name}`",
                ),
                once=("contradictory", text.lineno, text.col_offset),
            )
            found = replace(found, predicate=A.TRUE)  # as if it had none
        return found

    def _length(self, annotation: ast.expr) -> int:
        """The characters of an annotation's source (UTF-8 bytes on one line)."""
        line = getattr(annotation, "lineno", None)
        if line is not None and getattr(annotation, "end_lineno", None) == line:
            end = getattr(annotation, "end_col_offset", None) or 0
            return max(0, end - annotation.col_offset)
        return len(self.source.segment(annotation) or "")

    def alias_of(self, node: ast.expr) -> Alias | None:
        """A type alias or string constant of this module (a module summary could
        hand over another module's, with that module's `Names`)."""
        if not isinstance(node, ast.Name) or node.id not in self.index.aliases:
            return self._imported_alias(node)
        found = self.index.aliases.get(node.id)
        if found is None or node.id in self.constants.changed_globals:
            return None
        return Alias(found, self.names())

    def _imported_alias(self, node: ast.expr) -> Alias | None:
        """`Meters` of `from .units import Meters`, `units.Meters`: the alias of
        the module of the tree that defines it."""
        if self.resolver is None:
            return None
        from robotfix.analysis.imported import alias

        return alias(self.resolver, self.qualname(node))

    def names(self) -> Names:
        return Names(
            self.qualname,
            self.msg_type_of,
            self.source.segment,
            self.source.char_col,
            self.alias_of,
            self.source.path,
            constraints=self.ros_code,
        )

    @property
    def ros_code(self) -> bool:
        """Whether the file imports a ROS interface package, rclpy or rospy."""
        imports, known = self._ros_code
        if imports is not self.imports:
            imports = self.imports
            known = any(
                (len(parts) >= 3 and parts[1] in MSG_MODULES) or parts[0] in ROS_CLIENTS
                for parts in (q.split(".") for q in imports.values())
            )
            self._ros_code = (imports, known)
        return known

    def metadata_notes(self) -> None:
        """RF511, only in files that are RobotFix's business: ROS code (`ros_code`)
        or files that use refinements. Plain Python stays silent."""
        if self.ros_code or self.uses_refinements:
            for diag in self._metadata_notes:
                self.report(diag, once=("metadata", diag.span.line, diag.span.col))
        self._metadata_notes.clear()

    def _contradictory(self, found: Refinement) -> bool:
        own = sort_of(found.base)
        return contradictory(
            self.discharge,
            found.predicate,
            lambda name: own if name == "_" else "real",
            self._question_ids,
            self.budget,
        )

    def invariants(self, spec: MsgSpec) -> list[Invariant]:
        """The invariants of a message type that can hold together (the others are
        RF509, reported once on the interface file)."""
        if spec.name not in self._invariants:
            self._invariants[spec.name] = consistent_invariants(
                self.discharge, self.catalog, spec, self._question_ids, self.budget
            )[0]
        return self._invariants[spec.name]

    def _field_kind(self, msg_type: str, path: str) -> str | None:
        found = self.catalog.field_at(msg_type, path)
        return None if found is None else ("msg" if found.kind == "msg" else "value")


# Keys of `derived` values whose last element is the version of the object read.
VERSIONED = frozenset({"attribute", "truthy", "len", "isinstance", "hasattr"})


def _first_version(
    key: tuple[object, ...], unchanged: dict[int, tuple[A.Sym, object]]
) -> tuple[tuple[object, ...], object]:
    """The key of the same read of the object as it first was (`self.flag` before
    calls that may have changed it); `key` itself when it is that read."""
    if len(key) < 2:
        return key, None
    head = key[1]  # an object's symbol, or its id
    ident = head.ident if isinstance(head, A.Sym) else head
    if not isinstance(ident, int):
        return key, None
    last = key[-1]  # (most reads: an object read first, at its first version)
    if ident not in unchanged and not (
        len(key) > 2 and isinstance(last, int) and last and key[0] in VERSIONED
    ):
        return key, ident
    rest, changed = key[2:], False
    read: object = ident
    if ident in unchanged:
        (first, read), changed = unchanged[ident], True
        head = first if isinstance(head, A.Sym) else first.ident
    if key[0] in VERSIONED and rest and isinstance(rest[-1], int) and rest[-1]:
        rest, changed = (*rest[:-1], 0), True
    return ((key[0], head, *rest) if changed else key), read


def build_scope(
    ctx: FileContext, kind: str, name: str, node: ast.AST, parent: Scope | None
) -> Scope:
    """Collect the names a body binds and the refinements it declares."""
    scope = Scope(kind, name, node, parent)
    known = ctx.index.scopes.get(id(node)) or index_scope(ctx.index, node)
    scope.local_names = set(known.local_names)
    scope.global_names = set(known.global_names)
    annotated = sorted(known.annotated, key=lambda a: (a[0].lineno, a[0].col_offset))
    scope.local_names -= scope.global_names
    for annotation, target in annotated:
        if target not in scope.decls:
            found = ctx.refinement(
                annotation, target, lambda n: _in_scope(ctx, scope, n)
            )
            if found is not None:
                scope.decls[target] = found
    return scope


def _same_unit(declared: str, written: str) -> bool:
    """Whether an interface's unit text and a `Unit()`'s are one unit."""
    try:
        return resolve(declared).same_as(resolve(written))
    except UnitError:
        return declared == written  # a label (`frame:map`) or reported elsewhere


def _text_node(annotation: ast.expr) -> ast.expr:
    """The refinement string in `Annotated[T, "..."]` (the annotation if none)."""
    if isinstance(annotation, ast.Subscript):
        args = annotation.slice
        for arg in args.elts[1:] if isinstance(args, ast.Tuple) else []:
            if isinstance(arg, ast.Constant) and isinstance(arg.value, str):
                return arg
    return annotation


def _in_scope(ctx: FileContext, scope: Scope, name: str) -> bool:
    current: Scope | None = scope
    while current is not None:
        if name in current.local_names or name in current.global_names:
            return True
        current = current.parent
    return name in ctx.imports or ctx.star_import or hasattr(builtins, name)


def _section(qualified: str | None) -> tuple[str, str] | None:
    """`pkg.srv.AddTwoInts.Request` -> (`pkg`, `AddTwoInts_Request`)."""
    parts = (qualified or "").split(".")
    if len(parts) == 4 and parts[1] in MSG_MODULES and parts[3] in SECTION_SUFFIXES:
        return parts[0], f"{parts[2]}_{parts[3]}"
    return None
