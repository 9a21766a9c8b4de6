"""The public entry points: `check_source` for one text, `check_paths` for a run.

Here the layers meet: files are found and read, the catalog is built, the analysis
runs with a solver callback (z3 is imported only when a first VC needs it), and
diagnostics are filtered by suppressions, sorted and de-duplicated.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from robotfix import messages, rules
from robotfix.config import Config
from robotfix.diagnostics import Diagnostic, Severity
from robotfix.discovery import (  # re-exported: the walk lives in discovery.py
    INTERFACE_SUFFIXES as INTERFACE_SUFFIXES,
)
from robotfix.discovery import _hidden as _hidden
from robotfix.discovery import interface_files as interface_files
from robotfix.discovery import python_files as python_files
from robotfix.discovery import ros_interface_folders as ros_interface_folders
from robotfix.ros.launch.names import is_launch_file

if TYPE_CHECKING:  # the analysis is imported only when a file is checked
    from robotfix.analysis.context import FileContext
    from robotfix.analysis.imported import Resolver
    from robotfix.annotations.extract import Refinement
    from robotfix.budget import Budget
    from robotfix.project.summary import Project
    from robotfix.ros.catalog import MsgCatalog
    from robotfix.smt.memo import ProofMemo
    from robotfix.source import SourceFile
    from robotfix.stubs.load import StubSet
    from robotfix.vc import VC, Verdict
# so are the catalog's readers, the stubs and the parser's front end: a cached run
# needs none of them (`tests/test_cached_run.py`)


@dataclass
class InternalError:
    """A fault of RobotFix on one file: the exception, and its traceback."""

    path: str
    summary: str  # one line: the exception
    detail: str  # the traceback, shown only on request


@dataclass
class Result:
    """A run's diagnostics, counts and internal errors."""

    diagnostics: list[Diagnostic] = field(default_factory=list)
    files: int = 0
    seconds: float = 0.0
    internal_errors: list[InternalError] = field(default_factory=list)
    from_cache: int = 0  # files whose results came from .robotfix_cache/
    checked: list[str] = field(
        default_factory=list
    )  # the files, as diagnostics spell them

    def count(self, severity: Severity) -> int:
        return sum(1 for d in self.diagnostics if d.severity is severity)


class Discharger:
    """The solver callback for one file: closed goals that fold to true need no
    solver, nor do bound checks the facts' intervals prove (`smt.prepass`); z3 is
    imported, and a session started, only when a VC needs it (z3 costs ~70 ms to
    import). Every stage charges its work to `budget`, the file's (shared with
    its analysis): once that is spent, every question is undecided."""

    prepass = True  # off only to compare verdicts with z3 alone (tests, benchmarks)

    def __init__(
        self, memo: ProofMemo | None = None, budget: Budget | None = None
    ) -> None:
        from robotfix.budget import Budget

        self.budget = budget if budget is not None else Budget()
        self._session: Any = None
        self._memo = memo  # verdicts kept across checks of one document (editor)
        self._solved = False  # a kept verdict came from z3: the session would exist
        self._asked = False  # the last `_decide` asked z3
        self._calls = 0  # questions put to z3, kept verdicts of z3's included
        self._prepass: Any = None  # the file's pre-pass, made at the first VC

    def __call__(self, vc: VC) -> Verdict:
        from robotfix.budget import FACTS_PER_STEP
        from robotfix.smt.fold import fold
        from robotfix.vc import OUT_OF_BUDGET, Proved, Violated

        budget = self.budget
        if budget.spent:
            return OUT_OF_BUDGET
        budget.spend(1 + len(vc.facts) // FACTS_PER_STEP)
        folded = fold(vc.goal)
        if folded is True:
            return Proved()
        if folded is False and not vc.facts:  # no facts: no dead path to rule out
            return Violated(tuple(_constant(p) for p in vc.probes))
        if self._memo is None:
            return self._decide(vc)
        from robotfix.smt.memo import key

        keyed = key(vc)
        if keyed is None:
            return self._decide(vc)
        found = self._memo.get(*keyed)
        if found is not None and self._charge(found[1]):
            self._solved = self._solved or found[2]
            self._calls += int(found[2])
            return found[0]
        self._asked = False
        used = budget.used
        verdict = self._decide(vc)
        self._memo.put(*keyed, verdict, budget.used - used, self._asked)
        return verdict

    # -- for analysis/unitmemo.py: an item that asked z3 is not kept ----------
    def solver_calls(self) -> int:
        return self._calls

    def work_state(self) -> tuple[bool, bool]:
        """What changes how later VCs are decided: a session, a kept z3 verdict."""
        return self._session is not None, self._solved

    def _charge(self, work: int) -> bool:
        """Count a kept verdict's work against the file's budget, as deciding it
        again would; False when the budget could not pay for it (decide instead)."""
        if not self.budget.affords(work):
            return False
        self.budget.spend(work)
        return True

    def _decide(self, vc: VC) -> Verdict:
        from robotfix.vc import Proved

        if self.prepass:
            if self._prepass is None:
                from robotfix.smt.prepass import Prepass

                self._prepass = Prepass()
            prepass = self._prepass
            before = prepass.work
            proved = prepass.proves(vc)
            self.budget.spend(prepass.work - before)
            if proved:
                return Proved()
        if self._session is None:  # until z3 is needed, it may not be
            if not self._solved:  # as it would be without kept verdicts
                decided = _without_solver(vc, self.budget)
                if decided is not None:
                    return decided
            from robotfix.smt.solver import Session

            self._session = Session(budget=self.budget)
        self._asked = True
        self._calls += 1
        verdict: Verdict = self._session.check(vc)
        return verdict


def _without_solver(vc: VC, budget: Budget | None = None) -> Verdict | None:
    """A VC whose boolean skeleton decides it (`smt.propositional`): most questions
    of whether a path can run, so that z3 is loaded for a file only when a VC
    needs numbers. A question the skeleton leaves open is answered "possible"
    when values of its symbols are found that make the facts and the condition
    true, checked by exact evaluation (`annotations.witness`); "impossible" only
    ever comes from the skeleton."""
    from robotfix.annotations import ast as A
    from robotfix.annotations.witness import holds_somewhere
    from robotfix.smt.propositional import components, satisfiable
    from robotfix.vc import Proved, Unproven

    negated: bool | None = True  # groups sharing no symbol are independent
    for group in components([*vc.facts, A.Unary("not", vc.goal)], budget):
        found = satisfiable(group, budget)
        if found is False:
            return Proved()
        if found is None and not (vc.question and holds_somewhere(group, budget)):
            negated = None
    if negated is True and vc.question:
        return Unproven((), ())
    if vc.question:
        return None
    return _check_without_solver(vc, budget)


# What each witness search of a check may spend before z3 is asked instead: most
# that succeed need a few hundred nodes (tests/cases: 99% under 1,200), and one that
# fails spends all it may, where z3, asked first, would mostly prove the goal. A
# search stopped sooner finds what a longer one finds first, so only whether z3 is
# asked depends on it, never a verdict.
CHECK_WORK = 2_000


def _check_without_solver(vc: VC, budget: Budget | None) -> Verdict | None:
    """A check (its goal can fail: is it also kept?) whose answer exact evaluation
    shows: the counterexample is the one z3's session shows first (`witness.example`
    on the facts and the goal's negation, `Session._witnessed`); then values that
    keep the goal make it Unproven, and a skeleton without a model of the facts and
    the goal makes it Violated. Otherwise None: z3 decides; so too when a probe or
    a symbol has no exact value there that z3 would show alike (`shown.exact`)."""
    from robotfix.annotations import ast as A
    from robotfix.annotations.witness import example, holds_somewhere, value_at
    from robotfix.smt import shown
    from robotfix.smt.propositional import components, satisfiable
    from robotfix.vc import Unproven, Violated

    negation = [*vc.facts, A.Unary("not", vc.goal)]
    found = example(negation, budget=budget, most=CHECK_WORK)
    if found is None:
        return None
    probes = tuple(shown.exact(value_at(probe, found)) for probe in vc.probes)
    if None in probes:
        return None
    syms: list[tuple[int, str]] = []
    for sym in sorted(found, key=lambda sym: sym.ident):
        text = shown.exact(found[sym])
        if text is None:
            return None
        syms.append((sym.ident, text))
    kept = [*vc.facts, vc.goal]
    if holds_somewhere(kept, budget, most=CHECK_WORK):
        return Unproven(probes, tuple(syms))
    groups = components(kept, budget)
    if any(satisfiable(group, budget) is False for group in groups):
        return Violated(probes)
    return None


def forget_stubs() -> None:
    """The user's `.pyi` stubs changed on disk: read them again (the editor)."""
    from robotfix.stubs.load import forget

    forget()


def check_source(
    text: str,
    path: str,
    config: Config | None = None,
    catalog: MsgCatalog | None = None,
    project: Project | None = None,
    memo: ProofMemo | None = None,
) -> list[Diagnostic]:
    """Diagnostics for one Python source text; the modules it imports are found
    beside `path` and in its package (`make_project`), as a run finds them. With a
    `memo` (the editor keeps one per document), verdicts of VCs an earlier check
    proved are not asked again (`smt.memo`)."""
    from robotfix.ros.catalog import MsgCatalog
    from robotfix.source import SourceFile
    from robotfix.stubs.load import stub_set

    config = config or Config()
    if catalog is None:
        catalog = MsgCatalog(
            interface_files(list(config.msg_paths)),
            rep103=config.rep103,
            unit_suffixes=config.unit_suffixes,
        )
    stubs = stub_set(config.stub_paths)
    project = project or make_project([], config, catalog)
    resolver = project.resolver(Path(path))
    source = SourceFile.from_text(path, text)
    ignored = config.ignored_codes(Path(path))
    return finish(
        _check(source, catalog, ignored, stubs=stubs, resolver=resolver, memo=memo)
    )


def make_project(roots: list[Path], config: Config, catalog: MsgCatalog) -> Project:
    """The modules a check can import: the checked roots' and every checked file's
    tree (`project/modules.py`), each summarised when first imported."""
    from robotfix.project.modules import ModuleIndex
    from robotfix.project.summary import Project

    return Project(ModuleIndex(roots, config.python_paths), catalog, Discharger)


def hover(
    text: str,
    path: str,
    line: int,
    col: int,
    catalog: MsgCatalog,
    config: Config | None = None,
    project: Project | None = None,
) -> str | None:
    """Markdown for the innermost name or message field at (1-based line, 0-based
    character column), as the analysis sees it there (the modules it imports found
    through `project`, as `check_source` finds them, the libraries through the
    shipped stubs and `config`'s `stub-paths`)."""
    from robotfix.source import SourceFile

    source = SourceFile.from_text(path, text)
    if source.problem is not None:
        return None
    ctx = _analyze_as_checked(source, catalog, config, project, hovers=True)
    assert ctx.hovers is not None
    found = [
        (span, markdown)
        for span, markdown in ctx.hovers
        if span.line == line == span.end_line and span.col <= col < span.end_col
    ]
    if not found:
        return None
    return min(found, key=lambda item: item[0].end_col - item[0].col)[1]


def unit_suggestions(
    text: str,
    path: str,
    catalog: MsgCatalog,
    config: Config | None = None,
    project: Project | None = None,
) -> list[Suggestion]:
    """Units the analysis can pin on unannotated names from the flows they feed
    (see analysis/flows.py), seeing what a check sees: the user's stubs
    (`stub-paths`) and the modules the file imports (`make_project`)."""
    from robotfix.analysis.flows import FlowLog, path_unit, suggestions
    from robotfix.source import SourceFile

    source = SourceFile.from_text(path, text)
    if source.problem is not None or source.tree is None:
        return []
    ctx = _analyze_as_checked(source, catalog, config, project, flows=True)
    log = ctx.unit_flows
    if not isinstance(log, FlowLog) or log.program is None:
        return []
    if any(d.rule is rules.ANALYSIS_BUDGET for d in ctx.diagnostics):
        return []  # flows not seen could disagree with those seen
    assert isinstance(log, FlowLog)
    log.settle_attribute_fields(
        ctx.msg_type_of, lambda msg_type, path: path_unit(catalog, msg_type, path)
    )
    return [
        Suggestion(f.line, f.col, f.name, f.unit, f.kind)
        for f in suggestions(log, log.program)
    ]


@dataclass(frozen=True)
class Suggestion:
    """A `Unit(...)` annotation `robotfix suggest` proposes for a name."""

    line: int
    col: int  # byte column of the name
    name: str
    unit: str
    kind: str


def check_paths(
    paths: list[Path],
    config: Config,
    progress: Callable[[int, int, str], None] | None = None,
    jobs: int = 1,
    use_cache: bool = False,
) -> Result:
    """Check every Python file under `paths` (see `robotfix.run`)."""
    from robotfix.run import check_paths as run

    return run(paths, config, progress, jobs, use_cache)


def check_file(
    path: str,
    data: bytes,
    catalog: MsgCatalog,
    ignored: frozenset[str] = frozenset(),
    stubs: StubSet | None = None,
    resolver: Resolver | None = None,
    parsed: SourceFile | None = None,
) -> list[Diagnostic]:
    """Diagnostics for one file's bytes (decoded, parsed, analysed); `resolver`
    shows it the other modules of its tree; `parsed`: these bytes, already parsed
    in this run (for a module's summary)."""
    from robotfix.source import SourceFile

    source = parsed or SourceFile.from_bytes(path, data)
    return _check(source, catalog, ignored, stubs=stubs, resolver=resolver)


@dataclass(frozen=True)
class Contract:
    """What a subscription's callback assumes of the messages of a topic
    (`graphcheck.contracts`), to check at a publisher's `publish`."""

    holder: str  # where the publisher is kept: `Planner:self.pub` (class, attribute)
    text: str  # the refinement, as the subscriber wrote it
    msg_type: str  # the catalog's `pkg/Name`
    label: str  # names it in notes: "the message to `/odom`"
    path: str  # the subscriber's (the server's) file and line
    line: int
    # "service": a client's request; "response": a server's, at its callback's
    # `return` (`holder`: `return:Server.handle`); "action": a goal
    family: str = "topic"
    # the way through the graph (`/planner -> /cmd_vel -> /limiter`) and the
    # launch entry that starts the sender: shown, not part of what is checked
    # (one sender started twice is checked once)
    route: str = field(default="", compare=False)
    launch: tuple[str, int] | None = field(default=None, compare=False)


def _contract_refinement(contract: Contract, catalog: MsgCatalog) -> Refinement | None:
    """The subscriber's annotation text on the message type, read as
    `Annotated[T, "..."]` on a parameter: names are field paths of the message.
    None when it names anything else (the subscriber module's constants are not
    the publisher's to read: the contract is then not checked)."""
    import ast as _ast

    from robotfix.annotations.extract import extract

    node = _ast.parse(f"Annotated[T, {contract.text!r}]", mode="eval").body

    def qualname(name: _ast.expr) -> str | None:
        return "typing.Annotated" if getattr(name, "id", "") == "Annotated" else None

    def msg_type(name: _ast.expr) -> str | None:
        return contract.msg_type if getattr(name, "id", "") == "T" else None

    def field_kind(kind: str, path: str) -> str | None:
        found = catalog.field_at(kind, path)
        return None if found is None else ("msg" if found.kind == "msg" else "value")

    def known(name: str) -> bool:
        return field_kind(contract.msg_type, name) is not None

    refinement, problems = extract(
        node,
        "msg",
        qualname,
        msg_type,
        lambda _: None,
        lambda _, col: col,
        known,
        field_kind=field_kind,
    )
    if refinement is None or problems or refinement.base != "msg":
        return None
    return replace(refinement, line=contract.line, origin=contract.path)


def check_contracts(
    path: str,
    data: bytes,
    catalog: MsgCatalog,
    contracts: list[Contract],
    ignored: frozenset[str] = frozenset(),
    stubs: StubSet | None = None,
    resolver: Resolver | None = None,
) -> list[Diagnostic]:
    """What a publisher's file violates of its subscribers' contracts (a
    client's, of its server's): the file analysed again with each `publish` of a
    publisher they listen to (`call`, `call_async` of a client, a rospy proxy
    called, `send_goal_async` of an action client; a service callback's
    `return`, against its clients' refined responses) checked as a call of their
    callbacks would be (RF101 violated, RF102 not proved; RF201 a frame); only
    those findings, and not where suppressed."""
    from robotfix.source import SourceFile

    source = SourceFile.from_bytes(path, data)
    if source.problem is not None or source.tree is None:
        return []
    obligations: dict[str, list[tuple[str, Refinement]]] = {}
    for contract in contracts:
        refinement = _contract_refinement(contract, catalog)
        if refinement is not None:
            obligations.setdefault(contract.holder, []).append(
                (contract.label, refinement)
            )
    if not obligations:
        return []
    ctx = _analyze(
        source, catalog, stubs=stubs, resolver=resolver, obligations=obligations
    )
    labels: dict[str, Contract] = {}
    for c in contracts:
        label = f"annotation of `{c.label}`"
        first = labels.setdefault(label, c)
        if (first.route, first.launch) != (c.route, c.launch):
            # two senders of the file reach one subscriber: which one a finding
            # is at is not known here, so no way is shown
            labels[label] = replace(first, route="", launch=None)
    found = []
    for d in ctx.diagnostics:
        kept = next(
            (
                labels[label]
                for note in d.notes
                for label in labels
                if note.message.startswith(label)
            ),
            None,
        )
        if (
            kept is not None
            and not source.is_suppressed(d)
            and d.code not in ignored
            and d.rule.name not in ignored
        ):
            note = messages.contract_note(kept.family, kept.route, kept.launch)
            found.append(replace(d, notes=(*d.notes, note)))
    return found


def _check(
    source: SourceFile,
    catalog: MsgCatalog,
    ignored: frozenset[str] = frozenset(),
    stubs: StubSet | None = None,
    resolver: Resolver | None = None,
    memo: ProofMemo | None = None,
) -> list[Diagnostic]:
    if source.problem is not None:
        return [source.problem]
    from robotfix.analysis.relevance import skippable
    from robotfix.stubs.load import stub_set

    assert source.tree is not None
    stubs = stubs or stub_set()
    if skippable(source.tree, source.text, catalog, stubs, resolver):
        return _unused_suppressions(source, [])  # nothing to find: not analysed
    ctx = _analyze(source, catalog, stubs=stubs, resolver=resolver, memo=memo)
    kept = [
        d
        for d in ctx.diagnostics
        if not source.is_suppressed(d)
        and d.code not in ignored
        and d.rule.name not in ignored
    ]
    return kept + _unused_suppressions(source, ctx.diagnostics)


def _analyze(
    source: SourceFile,
    catalog: MsgCatalog,
    hovers: bool = False,
    flows: bool = False,
    stubs: StubSet | None = None,
    resolver: Resolver | None = None,
    memo: ProofMemo | None = None,
    obligations: dict[str, list[tuple[str, Refinement]]] | None = None,
) -> FileContext:
    """Run the analysis on a parsed file; a pathological file stops where its work
    budget is spent (RF902, or RF901 when a solver question spent it) and keeps
    what was found before."""
    from robotfix.analysis.context import (
        SOLVER_BUDGET,
        BudgetExceededError,
        FileContext,
    )
    from robotfix.analysis.interpreter import analyze_module
    from robotfix.stubs.load import stub_set

    discharge = Discharger(memo)
    ctx = FileContext(source, catalog, discharge, resolver, discharge.budget)
    if memo is not None:  # the editor's: a check never loads unitmemo
        from robotfix.analysis.unitmemo import UnitMemo

        if not isinstance(memo.units, UnitMemo):
            memo.units = UnitMemo()
        ctx.unit_memo = memo.units
    ctx.stubs = stubs or stub_set()
    ctx.obligations = obligations or {}
    ctx.hovers = [] if hovers else None
    if flows:
        from robotfix.analysis.flows import FlowLog

        ctx.unit_flows = FlowLog()
    try:
        analyze_module(ctx)
    except BudgetExceededError as stop:
        if not ctx.already(SOLVER_BUDGET):  # no RF901 said where it stopped
            ctx.report(
                messages.analysis_budget(
                    source.path, stop.line, "its work budget is used up"
                )
            )
    except RecursionError:
        ctx.report(messages.analysis_budget(source.path, 1, "nested too deeply"))
    return ctx


def _analyze_as_checked(
    source: SourceFile,
    catalog: MsgCatalog,
    config: Config | None,
    project: Project | None,
    hovers: bool = False,
    flows: bool = False,
) -> FileContext:
    """`_analyze` seeing what a check of the file sees: the shipped stubs and
    `config`'s `stub-paths`, the modules it imports through `project`."""
    from robotfix.stubs.load import stub_set

    config = config or Config()
    project = project or make_project([], config, catalog)
    return _analyze(
        source,
        catalog,
        hovers=hovers,
        flows=flows,
        stubs=stub_set(config.stub_paths),
        resolver=project.resolver(Path(source.path)),
    )


def _unused_suppressions(
    source: SourceFile, found: list[Diagnostic]
) -> list[Diagnostic]:
    """RF010: a `# robotfix: ignore[...]` that silences nothing, or names no rule.
    Not for the rules a later check of the run reports on this file's lines: the
    graph's (`rules.GRAPH_RULES`), and in a Python launch file the launch check's
    (`rules.LAUNCH_RULES`), which also gets its bare `ignore`s."""
    if not source.suppressions:  # most files: no launch-file test for them
        return []
    path = Path(source.path)
    launch = is_launch_file(path.parent.name, path.name)
    later = rules.GRAPH_RULES | rules.LAUNCH_RULES if launch else rules.GRAPH_RULES
    out = []
    for line, (col, codes) in sorted(source.suppressions.items()):
        on_line = [d for d in found if d.span.line == line]
        if codes is None and launch:
            continue  # a bare `ignore` may be the launch check's
        listed = sorted(c for c in codes or () if c not in later)
        if codes and not listed:
            continue  # only a later check's rules: it uses them
        unknown = [
            c
            for c in listed
            if c not in rules.ALL_RULES and c not in rules.RULES_BY_NAME
        ]
        used = [
            c for c in listed if any(d.code == c or d.rule.name == c for d in on_line)
        ]
        if (
            unknown
            or (codes is None and not on_line)
            or (codes is not None and not used)
        ):
            unused = [c for c in listed if c not in used and c not in unknown]
            out.append(
                messages.unused_suppression(source.path, line, col, unknown, unused)
            )
    return out


def stub_problems(config: Config) -> list[Diagnostic]:
    """RF512: what does not read in the user's stubs (`stub-paths`), once per run."""
    if not config.stub_paths:  # the shipped stubs are not read here
        return []
    from robotfix.stubs.load import stub_set

    return [
        messages.malformed_stub(p.path, p.line, p.col, p.message)
        for p in stub_set(config.stub_paths).problems()
    ]


def catalog_problems(catalog: MsgCatalog) -> list[Diagnostic]:
    """Every problem of the user's interface files, at its rule's severity: what
    does not read, a type that contains itself, contradictory refinements (RF509)."""
    catalog.load()
    return [
        messages.annotation_problem(p.path, p.line, p.col, p.rule, p.message, p.notes)
        for p in catalog.problems + catalog.self_containing()
    ] + _contradictions(catalog)


def interface_problems(
    catalog: MsgCatalog,
    used: set[str],
    known: list[tuple[Diagnostic, str | None, tuple[str, ...]]] | None = None,
) -> list[Diagnostic]:
    """The problems of the user's interface files, as a run reports them: with
    their rule's severity when a checked file used (looked up) a type that file
    defines, else as notes, so an interface file the checked code never uses cannot
    fail the run; a field of a package that is nowhere to be found is a warning
    (`messages.interface_problem`). `known`: `raw_interface_problems` of the same
    interface files, from the result cache (then the catalog is not loaded)."""
    found_all = raw_interface_problems(catalog) if known is None else known
    return [
        messages.interface_problem(
            found, used=bool(used.intersection(types)), absent_package=absent
        )
        for found, absent, types in found_all
    ]


def raw_interface_problems(
    catalog: MsgCatalog,
) -> list[tuple[Diagnostic, str | None, tuple[str, ...]]]:
    """Each problem of the catalog, the package it found absent (if so), and the
    types its file defines: what `interface_problems` needs of the catalog."""
    found_all = catalog_problems(catalog)  # loads the catalog
    absent = {(p.path, p.line, p.col): p.absent_package for p in catalog.problems}
    return [
        (
            found,
            absent.get((found.path, found.span.line, found.span.col)),
            catalog.types_in(found.path),
        )
        for found in found_all
    ]


def _contradictions(catalog: MsgCatalog) -> list[Diagnostic]:
    """RF509: interface-file refinements that no message satisfies (the analysis of
    each file leaves the same ones out)."""
    from robotfix.analysis.consistency import consistent_invariants

    found = []
    discharge = Discharger()
    idents = itertools.count(-1, -1)
    for spec in catalog.refined_specs():
        for bad in consistent_invariants(
            discharge, catalog, spec, idents, discharge.budget
        )[1]:
            earlier = (bad.earlier.path, bad.earlier.line) if bad.earlier else None
            found.append(
                messages.contradictory_invariant(
                    bad.origin.path, bad.origin.line, spec.name, bad.text, earlier
                )
            )
    return found


def finish(diagnostics: list[Diagnostic]) -> list[Diagnostic]:
    """Sorted, without exact duplicates, and one RF508 note per message type per run."""
    unique = {(d.sort_key(), d.notes): d for d in diagnostics}
    result: list[Diagnostic] = []
    noted: set[str] = set()
    for key in sorted(unique, key=lambda k: k[0]):
        diag = unique[key]
        if diag.rule == rules.UNKNOWN_MESSAGE_CLASS:
            if diag.message in noted:
                continue
            noted.add(diag.message)
        result.append(diag)
    return result


def _constant(term: Any) -> str | None:
    from robotfix.annotations.ast import show
    from robotfix.smt.fold import fold

    return show(term) if fold(term) is not None else None
