"""The editor's analysis kept across edits, per top-level unit (issue 13 item 2).

A keystroke in one function should not interpret the file's other functions again.
`UnitMemo` (one per open document, kept by the language server next to its
`ProofMemo`) keeps, for each item `analyze_module`'s pending loop analyses (a
function, a method, a class body, a nested function or lambda), what analysing it
did, and replays that when the item's inputs are the same.

Key of an item (`Check.analyze`):
- the module's *skeleton*: its whole text with positions, except that the numeric
  literals inside function bodies are blanked (`skeleton`) where no other unit's
  analysis can read them: not inside a call (parameter declarations, timer periods,
  `sys.exit(1)`), not in a helper its callers evaluate (`def f(v): return v /
  3.6`, `analysis/inline.py`), not the value of a store to an attribute or subscript
  (`self.x = 0.5`, `r.from_value = 0.0`), not an `if`/`while` test, not an
  annotation or anything in a `def` header. A literal's length is kept when text
  follows it on its line, so every other token's position is in the key. An edit
  of one line that holds a comment or blanks only, before and after, lying
  between statements (no expression or simple statement spans it) and holding
  none of the words the analysis looks for in the text (`skeleton.TEXT_WORDS`),
  leaves the skeleton counted as it was (`comment_only`): nothing reads such a
  line but the text of the statements around it, which keys their items. The
  module phase (index, constants, module body, `collect`, statics) reads function
  bodies only syntactically through names, calls and attribute stores, and a body's
  analysis reads other functions only through their signatures (def headers) and
  syntactic facts (`ends`, may-raise: statements, not numbers). After an edit of
  a kept number in a method whose text holds none of `TEXT_WORDS`
  (`skeleton.method_number`), the skeleton with it blanked keys the check (a
  `_METHOD` base): other items read it only through the type model (asked
  again) or what its method's items wrote, so every key of such a check holds
  every item before it that wrote (`_all`), and an item outside every
  statement turns the memo off;
- the exact text, with its first line number, of the top-level statement holding
  the item, and the item's position in it; for an item of a method of a
  top-level class (a node's callbacks share their class), the method's own text
  instead, with the text, place and type-model answers of every item of the
  class run before it that wrote what another item can read (`_wrote`: its exit
  fingerprint differs, or it asked z3); the rest of the class (its header,
  constants, the methods' headers) is in the skeleton. A class body's own item
  is keyed by its class's text without its methods' bodies (`_class_text`),
  which it does not run;
- what the type model answered the item (`Record.reads`, any item): the model
  reads other functions' bodies (what a function returns, what `self.x` is
  assigned; `t[1]` of a tuple is a number the skeleton blanks), so the questions
  are logged with their answers while the item runs (`unitreads.Reads`) and asked again,
  in their order, before a replay (`unitreads.same_reads`; an answer the model
  keeps once asked is taken from an earlier replay of the same check);
- the identities of the catalog, the stubs and the discharger's kind (a change
  clears the memo), and what the resolver answered so far (`consulted`: every
  imported module and member with its fingerprint); what the item itself resolved
  is asked again on a replay and must fingerprint alike (`_still`).

Then, before a replay, the *entering state* must equal the one recorded
(`_fingerprint`): the fresh-symbol counter and question counter (symbols a replayed
item made keep their numbers, so everything after it numbers alike), the sizes of
every container of the context and the program (not their memos, `_MEMOS`), the
statics, the parameter and frame facts and the index, the number of functions whose
signature is not built yet, the solver session's existence, and each `once` key
the item asked about (`already`/`report`) that was set before it, with its answer.

An item is kept only when analysing it wrote nothing another item can read:
its exit fingerprint equals its entering one but for the writes replay performs,
it reused no derived symbol, sub-message id or first read made by an earlier item
(`FileContext.unit_shared`; those of the module phase are a function of the key),
it asked no solver (see below), it did not raise, and every node id in its `once`
keys is one of its own nodes (translated by walk order).

Writes of an item (read from the code), and what happens to each on a replay:
- `ctx.diagnostics` / `ctx._reported`: every `report(diag, once)` and `report_once`
  call is logged in order and replayed through the same calls (same de-duplication);
- `ctx.dropped`: compared only within one call (`CallEvaluator.inline_call`), never
  replayed;
- `ctx.budget` (the file's work budget, RF901/RF902): the steps the item spent,
  its solver questions' included, are spent again; a replay that would cross the
  budget runs the item instead; `ctx._next` / `_question_ids`: advanced by the
  count used;
- the solver: an item that asked z3 (or was charged a kept verdict's work) is not
  kept, since z3's models for later questions depend on what its session was asked
  before;
- `ctx.sym_names`, `_derived`, `_sub_ids`, `unchanged`, `_first_reads`, `sizes`:
  entries keyed by the item's own fresh symbols only (a hit on an older entry made
  by another item makes it unkept), never looked up by another item;
- `program.ends`, `program.augmented`, `program.reading_calls`,
  `ctx._invariants`, `ctx.follow_lists`,
  the creation of `ctx.parameters` / `ctx.frame_facts`: caches of pure functions of
  the tree (their contents, which items do change, are in the fingerprint);
- the item's own signature (`program.signature`, `_function_for`): built by the
  prologue, which runs on a replay too; the signatures it built of other
  functions (a method defined below that it calls): logged by key and built
  again on a replay, in their order (`_Signing`), when building each changed
  nothing else (`_quiet`: no report, symbol, question, work step or table); a
  build that did makes the item unkept (the count of signatures not built is in
  the fingerprint);
- `pending`: the nested items it spawned, recorded by position and found again.
Everything else (program tables, statics, parameter handles and reads, frames of
instance attributes, metadata notes, `uses_refinements`, index scopes, resolver
consultations) is in the fingerprint, so a write to it makes the item unkept.
Hovers and unit flows (`robotfix suggest`) are never memoised.
"""

from __future__ import annotations

import ast
import bisect
import hashlib
import itertools
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from robotfix.analysis.context import Scope
from robotfix.analysis.skeleton import (
    comment_only,
    first_place,
    lines_of,
    method_number,
    numbers_only,
    region,
    same_skeleton,
    skeleton,
)
from robotfix.analysis.unitreads import Reads, same_reads
from robotfix.astwalk import walk

if TYPE_CHECKING:
    from robotfix.analysis.context import FileContext
    from robotfix.analysis.program import Function, Program
    from robotfix.analysis.values import Value
    from robotfix.diagnostics import Diagnostic

MAX_ENTRIES = 4_000  # items per document
# the start of a base made with a kept number blanked (`method_number`): its
# checks key every item with what every item before it that wrote was
_METHOD = "method:"

Run = Callable[[ast.AST, Scope], list[tuple[ast.AST, Scope]]]
Prologue = Callable[[ast.AST, Scope], tuple[Scope, Any]]


@dataclass
class Record:
    entering: tuple[object, ...]
    answers: tuple[tuple[object, bool], ...]  # once keys set before the item
    events: tuple[tuple[Diagnostic | None, object], ...]  # report / report_once
    steps: int  # of the file's work budget, its questions' included
    fresh: int
    questions: int
    spawned: tuple[tuple[tuple[object, ...], bool], ...]  # locator, own scope
    walked: bool  # some once key names a node (by walk index)
    consulted: tuple[tuple[str, object], ...]  # what imports it resolved
    reads: tuple[tuple[tuple[object, ...], object], ...]  # of the type model
    signed: tuple[str, ...]  # signatures it built, built again on a replay


class UnitMemo:
    def __init__(self, max_entries: int = MAX_ENTRIES) -> None:
        self._table: OrderedDict[tuple[object, ...], Record] = OrderedDict()
        self._max = max_entries
        self._identity: tuple[object, ...] = ()
        self._path = ""  # of the document
        self._bases: dict[str, int] = {}  # skeleton digest -> its items in the table
        self._last = ""  # the skeleton digest of the check before ("": not made)
        self._text: str | None = None  # the text of the check before
        # where the number `_last` was made without is in that text (`method_number`)
        self._also: tuple[int, int, int] | None = None
        self.hits = 0
        self.misses = 0

    def __len__(self) -> int:
        return len(self._table)

    def begin(
        self,
        ctx: FileContext,
        program: Program,
        tree: ast.Module,
        statics: dict[str, Value],
    ) -> Check | None:
        """The memo's view of one check, after the module phase; None when this
        check cannot use it."""
        discharge = ctx.discharge
        if (
            ctx.hovers is not None
            or ctx.unit_flows is not None
            or not hasattr(discharge, "solver_calls")
        ):
            return None
        # the catalog, stubs and discharger by identity; the path by its value
        # (the server makes a new string of it at each keystroke)
        identity = (ctx.catalog, ctx.stubs, type(discharge))
        if (
            ctx.source.path != self._path
            or len(identity) != len(self._identity)
            or any(a is not b for a, b in zip(identity, self._identity, strict=True))
        ):
            self._table.clear()
            self._bases.clear()
            self._identity, self._path = identity, ctx.source.path
        # Every key holds the skeleton, which an edit of the code (not of a number
        # in a body) changes at every keystroke: then no item can hit. Such an
        # edit is told from the text alone (the skeleton is not made), and items
        # are recorded only once a skeleton is checked twice in a row.
        text, before = ctx.source.text, self._text
        self._text = text
        same: bool | None = None
        also = None  # a kept number only its method's items read (`method_number`)
        if before is not None:
            where = region(before, text)  # found once, asked by each test below
            if numbers_only(before, text, where):
                # one number changed: whether the skeleton did is told from where
                # it is (on a 791-line node making the skeleton takes 4 ms); a kept
                # number changed it, so no item can hit (but in a skeleton checked
                # before), unless only its method's items read it: then the
                # skeleton with it blanked keys the items (a base of its own,
                # `_METHOD`, where every key holds every item that wrote)
                same = same_skeleton(tree, before, text, where)
                if same is False:
                    also = method_number(tree, before, text, where)
                    same = None if also is not None else False
            else:
                # a comment line between statements: the skeleton counts as the
                # one before (no analysis reads it; the items whose text holds it
                # are keyed by that text)
                same = comment_only(tree, before, text, where) or False
        if same is False:
            self._last, self._also = "", None
            return None
        lines = lines_of(text)  # as ast numbers them
        if same and self._last:
            base = self._last  # and the number `_also` is where it was
        elif (
            also is not None
            and self._also == (*also[:2], also[2] + len(before) - len(text))  # type: ignore[arg-type]
        ):
            # the same number edited again: blanked in both (`_also` is set just
            # when `_last` is a `_METHOD` base)
            base = self._last
            self._also = also
        else:
            made = hashlib.sha1(skeleton(tree, lines, also).encode()).hexdigest()
            base = made if also is None else _METHOD + made
            self._also = also
        last, self._last = self._last, base
        if base != last and base not in self._bases and also is None:
            return None  # (a number typed in a method is likely typed again)
        return Check(self, ctx, program, tree, statics, lines, base)

    def get(self, key: tuple[object, ...]) -> Record | None:
        found = self._table.get(key)
        if found is not None:
            self._table.move_to_end(key)
        return found

    def put(self, key: tuple[object, ...], record: Record) -> None:
        if key not in self._table:
            self._count(key, 1)
        self._table[key] = record
        self._table.move_to_end(key)
        while len(self._table) > self._max:
            self._count(self._table.popitem(last=False)[0], -1)

    def _count(self, key: tuple[object, ...], change: int) -> None:
        base = str(key[0])
        left = self._bases.get(base, 0) + change
        if left > 0:
            self._bases[base] = left
        else:
            self._bases.pop(base, None)


def _resolver_state(ctx: FileContext) -> object:
    consulted = getattr(ctx.resolver, "consulted", None)
    return None if consulted is None else tuple(consulted.items())


class Check:
    """One check of the document: keys its items and records or replays them."""

    def __init__(
        self,
        memo: UnitMemo,
        ctx: FileContext,
        program: Program,
        tree: ast.Module,
        statics: dict[str, Value],
        lines: list[str],
        base: str,
    ) -> None:
        self.memo = memo
        self.ctx = ctx
        self.program = program
        self.statics = statics
        self.tree = tree
        self.lines = lines
        self.base = base  # the skeleton's digest (`skeleton`)
        self.starts: list[tuple[int, int]] = []
        self.roots: list[ast.stmt] = []
        for statement in tree.body:
            self.starts.append(first_place(statement))
            self.roots.append(statement)
        self._root_text: dict[tuple[int, bool], str] = {}  # (index, class body)
        # a top-level class's methods, each an item's unit (`_unit`)
        self._methods: dict[int, tuple[list[tuple[int, int]], list[ast.stmt]]] = {}
        self._unit_text: dict[int, str] = {}
        # per top-level class: what its items not kept, run so far, were (`_wrote`)
        self._writers: dict[int, tuple[object, ...]] = {}
        self._whole = False  # an item outside every statement ran: no unit keys
        # a base with a kept number blanked (`method_number`): what that number is
        # may reach any later item through what its method's items wrote, so
        # every key holds every item that wrote so far (`_wrote`), and an item
        # outside every statement turns the memo off
        self.method_edit = base.startswith(_METHOD)
        self._answered: dict[tuple[object, ...], object] = {}  # `same_reads`
        self._all: tuple[object, ...] = ()
        # symbols made by the module phase: the same for the same skeleton
        ctx.unit_base = ctx._next

    # -- keys ----------------------------------------------------------------
    def _root(self, node: ast.AST) -> int | None:
        where = (getattr(node, "lineno", 0), getattr(node, "col_offset", 0))
        index = bisect.bisect_right(self.starts, where) - 1
        if index < 0:
            return None
        root = self.roots[index]
        end = (root.end_lineno or 0, root.end_col_offset or 0)
        return index if where <= end else None

    def _text(self, statement: ast.stmt) -> str:
        first = first_place(statement)[0]
        text = "".join(self.lines[first - 1 : statement.end_lineno])
        return f"{first}\0{text}"

    def _unit(self, node: ast.AST, index: int) -> ast.stmt | None:
        """The method of a top-level class that holds `node` (None: the class
        body itself, or anything else), whose text keys the item in place of
        its class's."""
        root = self.roots[index]
        if not isinstance(root, ast.ClassDef) or node is root or self._whole:
            return None
        methods = self._methods.get(index)
        if methods is None:
            chosen: list[ast.stmt] = [
                s
                for s in root.body
                if isinstance(s, (ast.FunctionDef, ast.AsyncFunctionDef))
            ]
            methods = ([first_place(s) for s in chosen], chosen)
            self._methods[index] = methods
        where = (getattr(node, "lineno", 0), getattr(node, "col_offset", 0))
        at = bisect.bisect_right(methods[0], where) - 1
        if at < 0:
            return None
        method = methods[1][at]
        end = (method.end_lineno or 0, method.end_col_offset or 0)
        return method if where <= end else None

    def _key(self, node: ast.AST, index: int) -> tuple[object, ...]:
        key: tuple[object, ...]
        unit = self._unit(node, index)
        if unit is not None:
            # the method's own text; its siblings' bodies are read through the
            # type model (`Record.reads`, asked again on a replay) and through what
            # those not kept wrote (`_writers`); the rest of the class is in the
            # skeleton
            text = self._unit_text.get(id(unit))
            if text is None:
                text = self._unit_text[id(unit)] = self._text(unit)
            writers = self._writers.get(index, ())
            key = (self.base, text, _locator(node), _resolver_state(self.ctx), writers)
        else:
            root = self.roots[index]
            # the class body, and an item of it outside its methods, by the class's
            # text but its methods' bodies; a method (`_whole`) by the whole text
            body = isinstance(root, ast.ClassDef) and (node is root or not self._whole)
            text = self._root_text.get((index, body))
            if text is None:
                text = self._class_text(root) if body else self._text(root)  # type: ignore[arg-type]
                self._root_text[(index, body)] = text
            key = (self.base, text, _locator(node), _resolver_state(self.ctx))
        return (*key, self._all) if self.method_edit else key

    def _class_text(self, root: ast.ClassDef) -> str:
        """The text keying a class body's item: the class's lines but its methods'
        bodies, which the class body does not run (their syntax is in the
        skeleton; their blanked numbers and comments only their own items read),
        so that an edit in one method leaves the class body, and the keys of the
        methods after it (`_writers`), alike."""
        first = first_place(root)[0]
        skipped: set[int] = set()
        for statement in root.body:
            if isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef)):
                end = statement.end_lineno or statement.lineno
                skipped.update(range(statement.body[0].lineno, end + 1))
        lines = self.lines[first - 1 : root.end_lineno]
        kept = [t for n, t in enumerate(lines, start=first) if n not in skipped]
        return f"{first}\0{''.join(kept)}"

    def _walked(self, node: ast.AST, index: int) -> ast.stmt:
        """The statement whose walk numbers the nodes an item's `once` keys name:
        the one whose text keys it (a method's, not its whole class's)."""
        return self._unit(node, index) or self.roots[index]

    def _wrote(
        self, index: int | None, key: tuple[object, ...] | None, reads: object
    ) -> None:
        """An item ran and wrote what a later item of its class may read (or
        raised, or was not keyed), so those items' keys hold what it was (its text and
        place, and the type model's answers it got; the skeleton and what the
        resolver answered are in their keys already)."""
        if index is None or key is None:
            self._whole = True
            return
        entry = (key[1], key[2], reads)
        if isinstance(self.roots[index], ast.ClassDef):
            self._writers[index] = (*self._writers.get(index, ()), entry)
        if self.method_edit:
            self._all = (*self._all, entry)

    # -- one item ------------------------------------------------------------
    def analyze(
        self, node: ast.AST, parent: Scope, prologue: Prologue, run: Callable[..., Any]
    ) -> list[tuple[ast.AST, Scope]]:
        scope, function = prologue(node, parent)
        ctx = self.ctx
        index = self._root(node)
        if index is None or ctx.muted or (self._whole and self.method_edit):
            self._wrote(index, None if index is None else self._key(node, index), None)
            return run(node, parent, scope, function)  # type: ignore[no-any-return]
        key = self._key(node, index)
        record = self.memo.get(key)
        entering = self._fingerprint()
        if record is not None:
            spawned = self._replay(record, entering, index, node, parent, scope)
            if spawned is not None:
                self.memo.hits += 1
                return spawned
        self.memo.misses += 1
        return self._record(key, entering, index, node, parent, scope, function, run)

    def _replay(
        self,
        record: Record,
        entering: tuple[object, ...],
        index: int,
        node: ast.AST,
        parent: Scope,
        scope: Scope,
    ) -> list[tuple[ast.AST, Scope]] | None:
        ctx = self.ctx
        if record.entering != entering or not ctx.budget.affords(record.steps):
            return None
        nodes = list(walk(self._walked(node, index))) if record.walked else []
        answers = record.answers
        if record.walked:
            answers = tuple((_from_walk(o, nodes), w) for o, w in answers)
        if any((once in ctx._reported) != was for once, was in answers):
            return None
        spawned: list[tuple[ast.AST, Scope]] = []
        if record.spawned:
            where = {_locator(n): n for n in walk(node)}
            for locator, own in record.spawned:
                found = where.get(locator)
                if found is None:
                    return None
                spawned.append((found, scope if own else parent))
        if record.consulted and not _still(ctx, record.consulted):
            return None
        if record.reads and not same_reads(self.program, record.reads, self._answered):
            return None
        signed = [self.program.functions.get(k) for k in record.signed]
        if any(f is None or f.scope is not None for f in signed):
            return None
        for function in signed:
            self.program.signature(ctx, function)  # type: ignore[arg-type]
        ctx.budget.spend(record.steps)
        ctx._next += record.fresh
        for _ in range(record.questions):
            next(ctx._question_ids)
        for diag, once in record.events:
            if record.walked:
                once = _from_walk(once, nodes)
            if diag is None:
                ctx.report_once(once)  # type: ignore[arg-type]
            else:
                ctx.report(diag, once)  # type: ignore[arg-type]
        return spawned

    def _record(
        self,
        key: tuple[object, ...],
        entering: tuple[object, ...],
        index: int,
        node: ast.AST,
        parent: Scope,
        scope: Scope,
        function: Any,
        run: Callable[..., Any],
    ) -> list[tuple[ast.AST, Scope]]:
        ctx = self.ctx
        steps, fresh = ctx.budget.used, ctx._next
        calls = ctx.discharge.solver_calls()  # type: ignore[attr-defined]
        questions = _count(ctx._question_ids)
        log: list[tuple[Diagnostic | None, object]] = []
        answers: dict[object, bool] = {}
        ctx.unit_log, ctx.unit_answers = log, answers
        ctx.unit_floor, ctx.unit_shared = fresh, False
        consulted = getattr(ctx.resolver, "consulted", None)
        before = dict(consulted) if consulted else {}
        model = self.program.types
        reads = Reads(model, self.program)
        self.program.types = reads  # type: ignore[assignment]
        signing = _Signing(self, self.program.signature)
        self.program.signature = signing  # type: ignore[method-assign]
        try:
            spawned: list[tuple[ast.AST, Scope]] = run(node, parent, scope, function)
        except BaseException:
            self._wrote(index, key, None)
            raise
        finally:
            self.program.types = model
            del self.program.signature  # the class's again
            ctx.unit_log = ctx.unit_answers = None
            shared, ctx.unit_shared = ctx.unit_shared, False
        # it wrote what another item can read: the fingerprint changed (but the
        # counters and the resolver's record, checked again on a replay, and the
        # signatures it built that a replay builds again), or z3 was asked (its
        # later models may depend on this ask)
        leaving = self._fingerprint()
        signed = tuple(signing.signed) if not signing.impure else ()
        wrote = (
            leaving[3:-1] != entering[3:-1]
            or leaving[2] != entering[2] - len(signed)  # type: ignore[operator]
            or ctx.discharge.solver_calls() != calls  # type: ignore[attr-defined]
        )
        record = None
        if not (wrote or shared or reads.unknown):
            record = self._replayable(index, node, parent, scope, spawned, log, answers)
        if record is None:
            if wrote:
                self._wrote(index, key, tuple(reads.log))
            return spawned
        events, kept_answers, spawns, walked = record
        self.memo.put(
            key,
            Record(
                entering,
                kept_answers,
                events,
                ctx.budget.used - steps,
                ctx._next - fresh,
                _count(ctx._question_ids) - questions,
                spawns,
                walked,
                tuple(
                    (k, v) for k, v in (consulted or {}).items() if before.get(k) != v
                ),
                tuple(reads.log),
                signed,
            ),
        )
        return spawned

    def _replayable(
        self,
        index: int,
        node: ast.AST,
        parent: Scope,
        scope: Scope,
        spawned: list[tuple[ast.AST, Scope]],
        log: list[tuple[Diagnostic | None, object]],
        answers: dict[object, bool],
    ) -> tuple[tuple[Any, ...], tuple[Any, ...], tuple[Any, ...], bool] | None:
        """The item's reports, `once` answers and spawned items as a replay finds
        them again (node ids as walk indexes), and whether any names a node; None
        when one cannot be found again."""
        own = {id(n) for n in walk(node)} if spawned else set()
        kept: list[tuple[tuple[object, ...], bool]] = []
        for child, where in spawned:
            if id(child) not in own or where not in (scope, parent):
                return None
            kept.append((_locator(child), where is scope))
        ids: dict[int, int] = {}
        walked = any(_has_int(once) for _, once in log) or any(
            _has_int(once) for once in answers
        )
        if walked:
            ids = {id(n): i for i, n in enumerate(walk(self._walked(node, index)))}
        events = []
        for diag, once in log:
            translated = _to_walk(once, ids) if walked else once
            if translated is _UNKEPT:
                return None
            events.append((diag, translated))
        kept_answers = []
        for once, was in answers.items():
            translated = _to_walk(once, ids) if walked else once
            if translated is _UNKEPT:
                return None
            kept_answers.append((translated, was))
        return tuple(events), tuple(kept_answers), tuple(kept), walked

    # -- the state other items can see ---------------------------------------
    def _fingerprint(self) -> tuple[object, ...]:
        ctx, program = self.ctx, self.program
        parts: list[object] = [
            ctx._next,
            _count(ctx._question_ids),
            sum(1 for f in program.functions.values() if f.scope is None),
        ]
        for name, value in vars(ctx).items():
            if name not in _OWN_CTX and name not in _MEMOS:
                parts.append(_shape(value))
        for name, value in vars(program).items():
            if name not in _OWN_PROGRAM and name not in _MEMOS:
                parts.append(_shape(value))
        parts.append(sum(len(t) for t in program.attributes.values()))
        parts.append(len(self.statics))
        parts.append(_inner(ctx.parameters))
        parts.append(_inner(ctx.frame_facts))
        parts.append(_inner(ctx.index))
        parts.append(_inner(ctx.constants))
        parts.append(ctx.discharge.work_state())  # type: ignore[attr-defined]
        parts.append(_resolver_state(ctx))
        return tuple(parts)


class _Signing:
    """`program.signature` as an item's run sees it: the signatures it builds of
    other functions (a method defined below it that it calls) are logged by key,
    to be built again on a replay, when building one changed nothing else (no
    report, symbol, work step or table of the context: `_quiet`); else the item
    wrote what it did (`impure`)."""

    def __init__(self, check: Check, build: Callable[..., Scope]) -> None:
        self.check = check
        self.build = build
        self.signed: list[str] = []
        self.impure = False

    def __call__(self, ctx: FileContext, function: Function) -> Scope:
        if function.scope is not None:
            return self.build(ctx, function)
        check = self.check
        before = _quiet(check)
        scope: Scope = self.build(ctx, function)
        if (
            _quiet(check) != before
            or check.program.functions.get(function.key) is not function
        ):
            self.impure = True
        else:
            self.signed.append(function.key)
        return scope


def _quiet(check: Check) -> tuple[object, ...]:
    """What building a signature must leave alone to be built again on a replay:
    the fingerprint but the count of signatures not built, the sizes of what the
    context keeps per item (`_OWN_CTX`), and the work spent."""
    ctx = check.ctx
    own = tuple(
        _shape(v) for k, v in vars(ctx).items() if k in _OWN_CTX and k != "budget"
    )
    return (check._fingerprint()[3:], own, ctx.budget.used, _count(ctx._question_ids))


# written only as the docstring says (logged, counted, or keyed by own symbols)
_OWN_CTX = frozenset(
    {
        "diagnostics",
        "_reported",
        "sym_names",
        "_next",
        "_question_ids",
        "_sub_ids",
        "_derived",
        "unchanged",
        "_first_reads",
        "sizes",
        "budget",
        "dropped",
        "_invariants",
        "follow_lists",
        "parameters",
        "frame_facts",
        "unit_memo",
        "unit_log",
        "unit_answers",
        "unit_floor",
        "unit_base",
        "unit_shared",
    }
)
_OWN_PROGRAM = frozenset({"ends", "augmented", "reading_calls", "types"})
_MEMOS = frozenset({"_type_names", "module_attributes"})  # same for any asker
_UNKEPT = object()


def _still(ctx: FileContext, consulted: tuple[tuple[str, object], ...]) -> bool:
    """Whether the imports an item resolved resolve alike now: asked again, as its
    analysis did (which records them for the file as that would), and compared."""
    resolver = ctx.resolver
    record = getattr(resolver, "consulted", None)
    if resolver is None or record is None:
        return False
    for key, _ in consulted:
        parts = key.split("\0")
        if parts[0] != str(getattr(resolver, "path", "")):
            continue  # what a summary it read stood on: asked again through it
        if len(parts) == 2:
            resolver.module(parts[1])
        elif len(parts) == 3:
            summary = resolver.module(parts[1])
            if summary is not None:
                member = getattr(resolver, "member", None)
                if member is None:
                    return False
                member(parts[1], summary, parts[2])
    return all(record.get(key) == value for key, value in consulted)


_SIZED = (dict, list, set, frozenset, tuple)
_SCALARS = (bool, int, float, str)


def _shape(value: object) -> object:
    kind = type(value)  # the exact types first: ~50 of these per item
    if kind in _SIZED:
        return len(value)  # type: ignore[arg-type]
    if value is None or kind in _SCALARS:
        return value
    if isinstance(value, _SIZED):
        return len(value)
    if isinstance(value, _SCALARS):
        return value
    return kind.__name__


def _inner(value: object) -> object:
    """The sizes of an object's containers (0s for an absent one, created empty)."""
    if value is None:
        return None
    found = vars(value)
    return tuple(
        len(found[k]) for k in sorted(found) if isinstance(found[k], (dict, list, set))
    )


def _count(counter: itertools.count[int]) -> int:
    """How many question ids were handed out (`count(-1, -1)` reads `count(-n, -1)`)."""
    shown = repr(counter)  # `count(-n, -1)`
    found = shown[6 : shown.find(",")] if shown.startswith("count(") else ""
    return -int(found) if found.lstrip("-").isdigit() else 0


def _locator(node: ast.AST) -> tuple[object, ...]:
    return (
        type(node).__name__,
        getattr(node, "lineno", 0),
        getattr(node, "col_offset", 0),
        getattr(node, "end_lineno", 0),
        getattr(node, "end_col_offset", 0),
    )


def _has_int(key: object) -> bool:
    if isinstance(key, tuple):
        return any(_has_int(k) for k in key)
    return isinstance(key, int) and not isinstance(key, bool) and key > 1 << 20


def _to_walk(key: object, ids: dict[int, int]) -> object:
    """A `once` key with its node ids (large ints) as walk indexes; `_UNKEPT` when
    a large int is not one of the statement's nodes."""
    if isinstance(key, tuple):
        out = []
        for k in key:
            t = _to_walk(k, ids)
            if t is _UNKEPT:
                return _UNKEPT
            out.append(t)
        return tuple(out)
    if isinstance(key, int) and not isinstance(key, bool) and key > 1 << 20:
        found = ids.get(key)
        return _UNKEPT if found is None else _Walk(found)
    return key


@dataclass(frozen=True)
class _Walk:
    index: int


def _from_walk(key: object, nodes: list[ast.AST]) -> object:
    if isinstance(key, tuple):
        return tuple(_from_walk(k, nodes) for k in key)
    if isinstance(key, _Walk):
        return id(nodes[key.index])
    return key
