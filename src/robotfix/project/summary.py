"""Module summaries: what an importer may see of a module of the tree, computed from
its AST alone (never by importing it), once per run and only when some checked file
imports it (cf. mypy's build.State and its interface hash).

`Project` owns the run's summaries; `FileResolver` is the narrow interface one
checked file's analysis asks (`analysis/imported.py`), and records what it consulted
with its fingerprint: each module it asked for (its existence and place) and each
member of one it looked up (that member's part of the summary: a function's
signature and refinements, a class's, a constant's value and unit, an alias and the
names it reads, a re-export), so the result cache re-checks a file exactly when
something it read of another module changed: adding or changing a member no
importer uses re-checks nobody. What a summary stands on in turn is in the
module's fingerprint: its name, its file and the records its own building
consulted (a hash tree, as git's), so a change anywhere down an import chain
changes the fingerprint of every module above it, while each record names one
module and each summary keeps only its own records (a chain of n modules keeps
O(n) records, not a copy of the chain's per module).

Cycles: while the summary of P is built, a module Q from which P can be reached by
imports (syntactically) is not consulted. The answer depends on the import graph
only, never on which file a worker process happened to check first, so `-j N`
output is the same as `-j 1`.
"""

from __future__ import annotations

import ast
import dataclasses
import hashlib
import os
from collections.abc import Callable, Sequence
from dataclasses import fields, is_dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Literal

from robotfix.fs import UnreadableError, read_regular
from robotfix.project.modules import ModuleIndex, imported_names

if TYPE_CHECKING:  # the analysis is imported only when a summary is built
    from robotfix.analysis.context import FileContext, Scope
    from robotfix.analysis.imported import (
        ClassSummary,
        FunctionSummary,
        Imported,
        ModuleSummary,
    )
    from robotfix.analysis.program import Function, Program
    from robotfix.analysis.state import State
    from robotfix.analysis.typeterms import Type
    from robotfix.analysis.values import Value
    from robotfix.annotations import ast as A
    from robotfix.annotations.extract import Names, Refinement
    from robotfix.ros.catalog import MsgCatalog
    from robotfix.source import SourceFile
    from robotfix.vc import VC, Verdict

Discharge = Callable[["VC"], "Verdict"]
ABSENT = ""  # the fingerprint recorded for a name that is no module of the tree
MISSING = "-"  # the fingerprint of a name that is no member of its module
# a summary as the result cache keeps it, by its file: the sha256 of the file's
# bytes, the module's own fingerprint (its name and place, and what building it
# consulted), its members', and what building it consulted (the records made from
# the file itself without its name, as the cache's entries keep them)
Known = tuple[str, str, dict[str, str], dict[str, str]]
# source bytes of parsed modules kept for their own check later in the run (`take`);
# beyond it a module is parsed again when checked, rather than held in memory
PENDING_BYTES = 1 << 20
# summaries built one inside another's building (a module's code imports one not
# yet summarised); one asked for deeper is built first, on its own (`summary`),
# so an import chain thousands of modules deep is built by a loop, and a summary
# never depends on how deep in the stack its building started
MAX_NESTED = 8


class Project:
    """The modules of one run, found through `index`, each summarised once."""

    def __init__(
        self,
        index: ModuleIndex,
        catalog: MsgCatalog,
        discharge: Callable[[], Discharge],
    ) -> None:
        self.index = index
        self.catalog = catalog
        self._discharge = discharge
        self._summaries: dict[Path, ModuleSummary | None] = {}
        self._nested = 0  # summaries being built, one inside another's building
        self._types: dict[Path, frozenset[str]] = {}  # message types it looked up
        self._parsed: dict[Path, tuple[bytes, SourceFile] | None] = {}
        self._pending: dict[str, tuple[bytes, SourceFile]] = {}
        # each file parsed here (by `_key`) -> its path in `_parsed`: a module
        # parsed for its import edges only and not summarised yet hands its parse
        # to its own check too (`take`), rather than being parsed again
        self._spellings: dict[str, Path] = {}
        self._edges: dict[Path, frozenset[Path]] = {}
        # each module's strongly connected component of the import graph, by the
        # order in which the components were completed (`_ranked`)
        self._rank: dict[Path, int] = {}
        self._ranks = 0
        # path -> (sha256 of its bytes, fingerprints), from an earlier run's cache
        self.known: dict[str, Known] = {}
        self.built: dict[str, Known] = {}  # the same, for this run's
        self._fresh: list[str] = []  # those built since `fresh_summaries` last ran
        # a kept summary whose records all still read the same (`_holds`)
        self._holding: dict[Path, bool] = {}
        self._deciding: set[Path] = set()  # on the path `_holds` walks
        # the sha256 of a file's bytes, when the caller knows a faster way (the
        # result cache's stat fast path); None: unreadable
        self.sha_of: Callable[[Path], str | None] | None = None
        self._fingerprints: dict[tuple[int, str, str | None], str] = {}
        self._context_ids: dict[str, int] = {}
        # files this process checks and has not checked yet (by `_key`): a module
        # among them parsed for its summary keeps its tree until its check `take`s
        # it, so a run parses each file once (unless PENDING_BYTES are held)
        self.to_check: set[str] = set()
        self._pending_bytes = 0
        self.parses = 0  # files read and parsed here (tests count them)
        self._read: set[Path] = set()  # every file read: `read_files`
        # a checked file mentioning one of these has its parameters summarised
        # from the same tree, for `paramcheck` (`run.py`); () when the run has
        # no parameter file
        self.parameter_words: tuple[bytes, ...] = ()
        # with `expect(..., release=True)` (a -j 1 run): how many files still to
        # check search each folder, and the summarised or parsed modules a name
        # can reach through each folder; a module no such folder leads to any
        # longer is dropped (`_released`), so a run holds the summaries of the
        # packages still to come, not of every package it checked
        self._live: dict[str, int] = {}
        self._holders: dict[str, set[Path]] = {}
        self._ways: dict[Path, tuple[str, ...]] = {}
        self._weak = frozenset(str(root) for root in index.roots)
        self._checking: Path | None = None  # the file `take`n last
        # with `release` and no records: the files still to check that a later one
        # imports, guessed from their bytes (`foresee.py`), by `_key`
        self._foreseen: dict[str, Path] = {}
        self.released = 0  # modules dropped so (tests count them)
        # what only the result cache and the editor's memo read is made: each
        # resolver's records (`consulted`), the summaries' fingerprints, `built`;
        # a run that keeps no cache turns it off (`run.py`): nothing reads them
        self.records = True

    def resolver(self, path: Path, building: Path | None = None) -> FileResolver:
        return FileResolver(self, path, building)

    # -- summaries -----------------------------------------------------------
    def summary(self, path: Path) -> ModuleSummary | None:
        if path in self._summaries:
            return self._summaries[path]
        if self._nested:  # asked for while another summary is built
            if self._nested >= MAX_NESTED:
                raise _Deeper(path)
            return self._build(path)
        # built by a loop: one found too deep is built first, then the others again
        todo = [path]
        while todo:
            if todo[-1] in self._summaries:
                todo.pop()
                continue
            try:
                self._build(todo[-1])
            except _Deeper as deeper:
                todo.append(deeper.path)
        return self._summaries[path]

    def _build(self, path: Path) -> ModuleSummary | None:
        self._summaries[path] = None  # a guard; cycles are cut before (`reaches`)
        resolver = self.resolver(path, building=path)
        parsed = self._parse(path)
        outer, self.catalog.touched = self.catalog.touched, set()
        found = None
        self._nested += 1
        try:
            if parsed is not None:
                try:
                    found = summarize(
                        self.index.module_name(path),
                        parsed[1],
                        self.catalog,
                        self._discharge(),
                        resolver,
                    )
                except Exception:  # a fault of ours: the module stays unknown to
                    found = None  # importers; its own check reports the fault
        except _Deeper:  # built again once what it imports is (`summary`)
            del self._summaries[path]
            raise
        finally:
            self._nested -= 1
            touched, self.catalog.touched = self.catalog.touched, outer
        self._imports(path)  # its edges are known: its text is no longer needed
        self._release(path)
        self._types[path] = frozenset(touched)
        self._summaries[path] = found
        self._hold(path)
        if found is not None and parsed is not None and self.records:
            own = f"{path}\0"
            cut = len(own) - 1
            self.built[str(path)] = (
                _sha(parsed[0]),
                found.fingerprint,
                found.members,
                {  # as the cache keeps its entries' records
                    k[cut:] if k.startswith(own) else k: v
                    for k, v in resolver.consulted.items()
                },
            )
            self._fresh.append(str(path))
        return found

    def fresh_summaries(self) -> dict[str, Known]:
        """The summaries built since the last call (for the result cache: a worker
        sends each once, not all it built with every result)."""
        fresh, self._fresh = self._fresh, []
        return {name: self.built[name] for name in fresh}

    def read_files(self) -> set[Path]:
        """Every file this project read: summarised, parsed only for its import
        edges, or hashed (for the language server: a change to one of them on
        disk can change what the project answers)."""
        return set(self._read)

    def types(self, path: Path) -> frozenset[str]:
        """The message types building the summary of `path` looked up (and those
        of the summaries it consulted): every importer depends on them too."""
        return self._types.get(path, frozenset())

    def fingerprint(self, key: str) -> str:
        """What a record of `FileResolver.consulted` (`<file>\0<module>`, or
        `<file>\0<module>\0<member>`) stands for now: for the result cache (a
        summary is built only if its file changed)."""
        context, _, rest = key.partition("\0")
        name, cut, member = rest.partition("\0")
        number = self._context_ids.get(context)
        if number is None:
            number = self._context_ids[context] = self.index.search_id(context)
        # the search path decides what a name is
        memo = (number, name, member if cut else None)
        if memo not in self._fingerprints:
            self._fingerprints[memo] = self._fingerprint(context, number, name, memo[2])
        return self._fingerprints[memo]

    def _fingerprint(
        self, context: str, number: int, name: str, member: str | None
    ) -> str:
        path = self.index.find_in(number, name, context)
        if path is None:
            return ABSENT
        known = self._kept(path)
        if known is not None:
            digest = self._digest(path)
            if digest is None:
                return ABSENT
            if digest == known[0] and self._holds(path):
                if member is None:
                    return known[1]
                return known[2].get(member, MISSING)
        found = self.summary(path)
        if found is None:
            return ABSENT
        if member is None:
            return found.fingerprint
        return found.members.get(member, MISSING)

    def _kept(self, path: Path) -> Known | None:
        """The fingerprints of the summary of `path` built in this run, else in an
        earlier one (the result cache's)."""
        return self.built.get(str(path)) or self.known.get(str(path))

    def _digest(self, path: Path) -> str | None:
        self._read.add(path)
        if self.sha_of is not None:
            return self.sha_of(path)
        try:
            return _sha(read_regular(path))
        except UnreadableError:
            return None

    def _holds(self, start: Path) -> bool:
        """Whether every record the kept summary of `start` (of unchanged bytes) was
        built on reads the same now, so that its fingerprints hold. The kept
        summaries those records name are decided first, by a loop rather than
        recursion (an import chain may be thousands of modules deep): a depth-first
        walk, each module decided once all it stands on is. One met again on the
        path being walked (an import cycle, as the graph was when they were built)
        does not hold: it is built again, which is always right. (One waiting on
        the stack below, met again under another module, is decided there first:
        it was taken for a cycle, and a diamond - `a` importing `p` and `q`, `q`
        importing `p` - built `p` again on every cached run.)"""
        holding = self._holding
        if start in holding:
            return holding[start]
        if start in self._deciding:
            return False
        if str(start) in self.built:
            return True  # built in this run: from what it consulted now
        stack = [start]
        while stack:
            path = stack[-1]
            if path in holding:  # met again under another module: decided there
                stack.pop()
                continue
            known = self._kept(path)
            assert known is not None
            records = _records(path, known[3])
            if path not in self._deciding:  # first met: what it stands on first
                self._deciding.add(path)
                targets = dict.fromkeys(self._target(key) for key in records)
                stack.extend(
                    target
                    for target in targets
                    if target is not None
                    and target not in holding
                    and target not in self._deciding
                    and str(target) not in self.built
                    and (kept := self._kept(target)) is not None
                    and self._digest(target) == kept[0]
                )
                continue
            stack.pop()
            holding[path] = all(self.fingerprint(k) == v for k, v in records.items())
            self._deciding.discard(path)
        return holding[start]

    def _target(self, key: str) -> Path | None:
        """The module file a record (`fingerprint`'s key) is about, if any."""
        context, _, rest = key.partition("\0")
        name = rest.partition("\0")[0]
        number = self._context_ids.get(context)
        if number is None:
            number = self._context_ids[context] = self.index.search_id(context)
        return self.index.find_in(number, name, context)

    # -- the import graph, syntactically ------------------------------------
    def reaches(self, start: Path, goal: Path) -> bool:
        """Whether `goal` can be reached from `start` by imports of the tree: both
        in one strongly connected component, or a path down from `start` through
        components completed after `goal`'s (one completed before it cannot reach
        it). Nothing is kept per pair or per module but its component's rank, so
        a chain of n modules costs O(n), not a set of what each one reaches."""
        if start == goal:
            return True
        top, bottom = self._ranked(start), self._ranked(goal)
        if top <= bottom:
            return top == bottom
        seen = {start}
        todo = [start]
        while todo:
            for nxt in self._imports(todo.pop()):
                rank = self._rank[nxt]
                if rank == bottom:
                    return True
                if rank > bottom and nxt not in seen:
                    seen.add(nxt)
                    todo.append(nxt)
        return False

    def _ranked(self, start: Path) -> int:
        """The rank of the strongly connected component of `start` (Tarjan's
        algorithm, by a loop: an import chain may be thousands deep). Ranks follow
        completion: a component reachable from another has a lower rank. A module
        ranked by an earlier search keeps its rank: all it reaches was ranked then."""
        rank = self._rank
        if start in rank:
            return rank[start]
        order = {start: 0}
        low = {start: 0}
        stack = [start]
        work = [(start, iter(self._imports(start)))]
        while work:
            node, edges = work[-1]
            for nxt in edges:
                if nxt in rank:
                    continue  # a component completed before
                if nxt not in order:
                    order[nxt] = low[nxt] = len(order)
                    stack.append(nxt)
                    work.append((nxt, iter(self._imports(nxt))))
                    break
                low[node] = min(low[node], order[nxt])  # on the stack
            else:
                work.pop()
                if work:
                    parent = work[-1][0]
                    low[parent] = min(low[parent], low[node])
                if low[node] == order[node]:
                    self._ranks += 1
                    while True:
                        member = stack.pop()
                        rank[member] = self._ranks
                        if member == node:
                            break
        return rank[start]

    def _imports(self, path: Path) -> frozenset[Path]:
        if path not in self._edges:
            parsed = self._parse(path)
            source = parsed[1] if parsed is not None else None
            found: set[Path] = set()
            if source is not None and source.tree is not None:
                index = self.index
                number = index.search_id(path)
                asked: set[str] = set()  # `a.b.c` and `a.b.d` both ask `a.b`, `a`
                package = index.package_of(path)
                for name in imported_names(source.tree, package, source.text):
                    parts = name.split(".")
                    for cut in range(len(parts), 0, -1):
                        prefix = ".".join(parts[:cut])
                        if prefix in asked:
                            continue
                        asked.add(prefix)
                        target = index.find_in(number, prefix, path)
                        if target is not None:
                            found.add(target)
            self._edges[path] = frozenset(found)
        return self._edges[path]

    def _parse(self, path: Path) -> tuple[bytes, SourceFile] | None:
        from robotfix.source import SourceFile

        if path not in self._parsed:
            self._read.add(path)
            try:
                data = read_regular(path)
            except UnreadableError:
                self._parsed[path] = None
            else:
                self.parses += 1
                source = SourceFile.from_bytes(str(path), data)
                self._parsed[path] = (data, source) if source.tree else None
                self._spellings[_key(path)] = path
                self._hold(path)
        return self._parsed[path]

    def _release(self, path: Path) -> None:
        """A summarised module's tree is dropped, or kept for its own check."""
        parsed = self._parsed.pop(path, None)
        if parsed is None or _key(path) not in self.to_check:
            return
        if self._pending_bytes + len(parsed[0]) <= PENDING_BYTES:
            self._pending[_key(path)] = parsed
            self._pending_bytes += len(parsed[0])

    def expect(self, paths: list[Path], release: bool = False) -> None:
        """The files this process checks next (all others' trees are dropped); with
        `release`, these are all it checks, in this order: what only the files
        already checked could import is dropped as the run goes (`take`)."""
        self.to_check = {_key(p) for p in paths}
        # a tree parsed for a summary while the result cache was consulted, of a
        # file now to check, is kept for that check (the file is parsed once)
        self._pending = {k: v for k, v in self._pending.items() if k in self.to_check}
        self._pending_bytes = sum(len(v[0]) for v in self._pending.values())
        self._live.clear()
        self._holders.clear()
        self._ways.clear()
        self._checking = None
        self._foreseen = {}
        if release:
            live = self._live
            for p in paths:
                for folder in self.index.search_path(p):
                    spelled = str(folder)
                    live[spelled] = live.get(spelled, 0) + 1
            if not self.records:
                from robotfix.project.foresee import imported_later

                self._foreseen = imported_later(self.index, paths, _key)

    def _hold(self, path: Path) -> None:
        """Note the folders through which a file still to check could import
        `path` (while `expect(..., release=True)` is in force)."""
        if not self._live or path in self._ways:
            return
        ways = _ways(path)
        self._ways[path] = ways
        for folder in ways:
            self._holders.setdefault(folder, set()).add(path)

    def _released(self, path: Path) -> None:
        """`path` has been checked: the folders no file still to check searches are
        dead, and so is each module no live folder leads to. Dropping one changes no
        output: a summary depends on the import graph only, so one asked for again
        is built again, the same (cf. `-j N`)."""
        live = self._live
        # a checked root does not keep a module: a name through it spells the
        # package folders (`pkg_a.pkg_a.util` under a workspace's `src/`), which
        # real code seldom does; such a module is built again if a file asks
        weak = self._weak
        dead = []
        for folder in self.index.search_path(path):
            spelled = str(folder)
            count = live.get(spelled, 0) - 1
            if count > 0:
                live[spelled] = count
            elif spelled in live:
                del live[spelled]
                dead.append(spelled)
        for spelled in dead:
            for module in self._holders.pop(spelled, set()):
                ways = self._ways.get(module)
                if ways is None or any(w in live and w not in weak for w in ways):
                    continue
                del self._ways[module]
                self.released += 1
                self._summaries.pop(module, None)
                self._types.pop(module, None)
                self._parsed.pop(module, None)

    def take(self, path: Path, data: bytes) -> SourceFile | None:
        """The parse of `path` made for its summary (or its import edges), if these
        are its bytes; the check of `path` then owns it (nothing here holds it any
        longer)."""
        key = _key(path)
        if self._live:  # the file checked before this one is done with
            if self._checking is not None:
                self._released(self._checking)
            self._checking = path
        found = self._foreseen.pop(key, None)  # a later file imports it
        if found is not None and found not in self._summaries:
            self.summary(found)  # from the parse this check takes (`_release`)
        self.to_check.discard(key)
        parsed = self._pending.pop(key, None)
        if parsed is not None:
            self._pending_bytes -= len(parsed[0])
        else:  # parsed for its import edges, not summarised yet: built again if
            spelled = self._spellings.pop(key, None)  # some file asks later
            if spelled is not None:
                parsed = self._parsed.pop(spelled, None)
            if parsed is None:
                return None
        if parsed[0] != data:  # changed on disk in between: parse what is checked
            return None
        source, shown = parsed[1], str(path)
        if source.path != shown:
            source = dataclasses.replace(source, path=shown)
        return source


class _Deeper(BaseException):
    """Unwinds the summaries being built (past the analysis's `except Exception`)
    so that the summary of `path` is built first."""

    def __init__(self, path: Path) -> None:
        super().__init__()
        self.path = path


_UNASKED = Path("\0unasked")
_CYCLE = Path("\0cycle")


class FileResolver:
    """How one file (a checked one, or a module being summarised) sees its tree."""

    def __init__(self, project: Project, path: Path, building: Path | None) -> None:
        self.project = project
        self.path = path
        self.building = building
        # "<importing file>\0<name>" -> the fingerprint of what it resolved to
        # (nothing when the project keeps no records)
        self.consulted: dict[str, str] = {}
        self.records = project.records
        self._own = f"{path}\0"  # the records' keys start so
        self._package = project.index.package_of(path)
        self._number: int | None = None  # the index's `search_id` of `path`
        # name -> the module file it is here (_CYCLE: not consulted while building)
        self._targets: dict[str, Path | None] = {}
        # dotted name -> what it stands for (`imported.resolve`'s memo): what
        # resolving it recorded is in `consulted` already
        self.resolved: dict[str, Imported | None] = {}

    @property
    def package(self) -> str | None:
        return self._package

    def exists(self, name: str) -> bool:
        """Is `name` a module of the tree? (Recorded when it is not, as `module`
        does, so a cached result is re-checked once the module appears.)"""
        if self._find(name) is not None:
            return True
        if self.records:
            self.consulted[self._own + name] = ABSENT
        return False

    def module(self, name: str) -> ModuleSummary | None:
        project = self.project
        target = self._targets.get(name, _UNASKED)
        if target is _UNASKED:
            target = self._find(name)
            if (
                target is not None
                and self.building is not None
                and project.reaches(target, self.building)
            ):
                target = _CYCLE
            self._targets[name] = target
        if target is None:
            if self.records:
                self.consulted[self._own + name] = ABSENT
            return None
        if target is _CYCLE:
            return None  # a cycle: not consulted, whichever side is built first
        found = project.summary(target)
        if self.records:
            # its fingerprint stands for what building it read too: its members
            # may stand on any of it
            fingerprint = found.fingerprint if found is not None else ABSENT
            self.consulted[self._own + name] = fingerprint
        if project.catalog.touched is not None:
            project.catalog.touched.update(project.types(target))
        return found

    def _find(self, name: str) -> Path | None:
        """The index's `find`, its search path's number asked once per file."""
        index = self.project.index
        if self._number is None:
            self._number = index.search_id(self.path)
        return index.find_in(self._number, name, self.path)

    def member(self, module: str, summary: ModuleSummary, name: str) -> None:
        """The member `name` of `summary` (asked for as `module`) was looked up."""
        if self.records:
            key = f"{self._own}{module}\0{name}"
            self.consulted[key] = summary.members.get(name, MISSING)


def summarize(
    name: str,
    source: SourceFile,
    catalog: MsgCatalog,
    discharge: Discharge,
    resolver: FileResolver,
) -> ModuleSummary:
    """The summary of one parsed module: the pre-pass, and its module code run once
    for the values of its constants (what this reports is dropped: the module is
    checked on its own when it is part of the run)."""
    from robotfix.analysis.binder import module_statics
    from robotfix.analysis.constants import scan
    from robotfix.analysis.context import (
        BudgetExceededError,
        FileContext,
        build_scope,
    )
    from robotfix.analysis.imported import ModuleSummary
    from robotfix.analysis.index import index_of
    from robotfix.analysis.interpreter import Interpreter, class_body
    from robotfix.analysis.program import collect
    from robotfix.analysis.state import State
    from robotfix.annotations.extract import Alias

    tree = source.tree
    assert tree is not None
    path = source.path
    ctx = FileContext(source, catalog, discharge, resolver)
    ctx.record_imports(index_of(tree))
    ctx.constants = scan(
        tree, ctx.index, ctx.qualname, ":=" in source.text, source.lines, keep=True
    )
    summary = ModuleSummary(name, path)
    source_of = (name, path)
    try:
        module = build_scope(ctx, "module", "<module>", tree, None)
        program = collect(ctx, tree, module)
        state = Interpreter(ctx, program, module, {}).exec_block(tree.body, State())
        statics = module_statics(ctx, state)
        for statement in tree.body:  # class constants (`Limiter.RATE`)
            if isinstance(statement, ast.ClassDef):
                class_body(ctx, program, statement, module, statics)
    except (BudgetExceededError, RecursionError):
        return _finish(summary, resolver)
    summary.constants = ctx.constants.module_constants()
    terms = {k: v.term for k, v in summary.constants.items() if v.term is not None}
    read = {
        name: decl
        for name, node in ctx.index.aliases.items()
        if name not in ctx.constants.changed_globals
        and (decl := _clean(ctx, node)) is not False
    }
    refinements: list[Refinement | None] = [d for d in read.values() if d]
    for key, function in program.functions.items():
        if not key.startswith("<"):
            scope = program.signature(ctx, function)
            refinements += [*scope.decls.values(), function.returns]
    terms = _labelled(
        _dotted_terms(ctx, program, module, state, statics, refinements, terms)
    )
    for key, function in program.functions.items():
        if "." in key or key.startswith("<"):
            continue
        summary.functions[key] = _function(ctx, program, function, terms, source_of)
    for class_name in program.classes:
        summary.classes[class_name] = _class(ctx, program, class_name, terms, source_of)
    names = None
    for alias_name in read:
        names = names or replace(_detached(ctx), constants=terms)
        summary.aliases[alias_name] = Alias(ctx.index.aliases[alias_name], names)
    summary.reexports = _top_level_imports(tree, ctx.imports)
    return _finish(summary, resolver)


def _function(
    ctx: FileContext,
    program: Program,
    function: Function,
    terms: dict[str, A.Expr],
    source_of: tuple[str, str],
    shown: str | None = None,
) -> FunctionSummary:
    """`source_of`: the module's dotted name and its file."""
    from robotfix.analysis.imported import FunctionSummary

    module, path = source_of
    scope = program.signature(ctx, function)
    node = function.node
    params = tuple(a.arg for a in [*node.args.posonlyargs, *node.args.args])
    keywords = tuple(a.arg for a in node.args.kwonlyargs)
    decls = tuple(
        (p, _travel(scope.decls[p], terms, path))
        for p in (*params, *keywords)
        if p in scope.decls
    )
    returns = _travel(function.returns, terms, path) if function.returns else None
    return FunctionSummary(
        shown or function.name,
        params,
        keywords,
        decls,
        returns,
        function.is_method,
        "classmethod" in function.decorators,
        _typed(program, module, program.types.returns(function.key)),
    )


def _class(
    ctx: FileContext,
    program: Program,
    class_name: str,
    terms: dict[str, A.Expr],
    source_of: tuple[str, str],
) -> ClassSummary:
    from robotfix.analysis.imported import ClassSummary

    module, path = source_of
    attributes = tuple(
        (attr, _travel(decl, terms, path, own_only=True))
        for attr, decl in sorted(program.attributes.get(class_name, {}).items())
    )
    methods = tuple(
        (
            key.split(".", 1)[1],
            _function(ctx, program, function, terms, source_of, key),
        )
        for key, function in sorted(program.functions.items())
        if key.startswith(class_name + ".") and key.count(".") == 1
    )
    constants = tuple(
        (attr, value)
        for attr in sorted(ctx.constants.class_values.get(class_name, {}))
        if (value := ctx.constants.class_constant(class_name, attr)) is not None
    )
    known = program.types.class_types(class_name)
    typed = tuple(
        (attr, found)
        for attr in sorted(known)
        if (found := _typed(program, module, known[attr])) is not None
    )
    return ClassSummary(class_name, attributes, methods, constants, typed)


def _typed(program: Program, module: str, found: Type | None) -> Type | None:
    """A type as an importer names it: this module's classes by their dotted
    name."""
    from robotfix.analysis.typeterms import qualified

    return qualified(found, module, set(program.classes))


def _travel(
    decl: Refinement, terms: dict[str, A.Expr], path: str, own_only: bool = False
) -> Refinement:
    """A refinement as another module sees it: the constants of its own module put
    in, the file that declares it named (and, for an attribute, only the parts that
    speak of the value alone)."""
    from robotfix.annotations import ast as A

    def move(part: Refinement) -> Refinement:
        predicate = A.substitute(part.predicate, terms)
        if own_only:
            predicate = A.conjoin(
                [
                    c
                    for c in A.conjuncts(predicate)
                    if all(n.name == "_" for n in A.names(c))
                ]
            )
        elements = (
            tuple(move(e) if e is not None else None for e in part.elements)
            if part.elements is not None
            else None
        )
        origin = part.origin or path
        return replace(part, predicate=predicate, elements=elements, origin=origin)

    return move(decl)


def _clean(ctx: FileContext, node: ast.expr) -> Refinement | Literal[False] | None:
    """An alias travels only if it reads without a problem in its own module (its
    problems are reported there, at its own lines): its refinement (None for a
    type form without one), or False."""
    from robotfix.annotations.extract import extract

    names = ctx.names()
    found, problems = extract(
        node,
        "_",
        names.qualname,
        names.msg_type,
        names.source_segment,
        names.col_of,
        alias=names.alias,
    )
    return False if problems else found


def _dotted_terms(
    ctx: FileContext,
    program: Program,
    module: Scope,
    state: State,
    statics: dict[str, Value],
    refinements: Sequence[Refinement | None],
    terms: dict[str, A.Expr],
) -> dict[str, A.Expr]:
    """`terms` and the dotted constants the refinements name (`math.pi`,
    `Limits.MAX`), as this module's code resolves them: an importer may not import
    `math`, nor know `Limits`."""
    from robotfix.analysis.interpreter import Interpreter
    from robotfix.annotations import ast as A

    wanted = {
        ref.name
        for decl in refinements
        if decl is not None
        for predicate in decl.predicates()
        for ref in A.names(predicate)
        if "." in ref.name and ref.name.split(".")[0] in module.local_names
    }
    if not wanted:
        return terms
    reader = Interpreter(ctx, program, module, statics)
    found = dict(terms)
    for name in sorted(wanted):
        value = reader.constant_named(name, state)
        if value is not None and value.term is not None:
            found[name] = value.term
    return found


def _labelled(terms: dict[str, A.Expr]) -> dict[str, A.Expr]:
    """The constants put into a travelling refinement, each number or string
    labelled with its name as the refinement writes it: an importer's message says
    `speed <= MAX_SPEED`, as the declaring module's own does, not `speed <= 0.5`."""
    from robotfix.annotations import ast as A

    return {name: A.labelled(term, name) or term for name, term in terms.items()}


def _detached(ctx: FileContext) -> Names:
    """The `Names` an alias carries to importers, from a context that holds only
    what they read (imports, the module's aliases, its lines): `ctx.names()` would
    keep the whole file context, its AST and its index alive for the run."""
    from robotfix.analysis.context import FileContext
    from robotfix.analysis.index import FileIndex
    from robotfix.source import SourceFile

    lines = [""] * len(ctx.source.lines)  # only the aliases' own lines are read
    for node in ctx.index.aliases.values():
        end = getattr(node, "end_lineno", None) or node.lineno
        lines[node.lineno - 1 : end] = ctx.source.lines[node.lineno - 1 : end]
    source = SourceFile(ctx.source.path, "", lines=lines)
    lean = FileContext(source, ctx.catalog, ctx.discharge, ctx.resolver)
    lean.imports = ctx.imports
    lean.index = FileIndex(aliases=dict(ctx.index.aliases))
    lean.constants.changed_globals = set(ctx.constants.changed_globals)
    return lean.names()


def _top_level_imports(tree: ast.Module, imports: dict[str, str]) -> dict[str, str]:
    found: dict[str, str] = {}
    for statement in tree.body:
        if isinstance(statement, (ast.Import, ast.ImportFrom)):
            for alias in statement.names:
                local = alias.asname or alias.name.split(".")[0]
                if local in imports:
                    found[local] = imports[local]
    return found


def _finish(summary: ModuleSummary, resolver: FileResolver) -> ModuleSummary:
    """The fingerprints: the module's own (its name, its file, and what building it
    consulted, each record with its fingerprint: any member may stand on any of
    it), and each member's, from everything `imported._member` reads for that name
    (which table holds it decides what it is). An alias reads the module's other
    aliases and imports, so its fingerprint holds them too. None without records
    (nothing reads them)."""
    if not resolver.records:
        return summary
    consulted = resolver.consulted
    summary.fingerprint = _hash(
        _stable((summary.name, summary.path, sorted(consulted.items())))
    )
    aliases = sorted(
        (k, ast.dump(a.node), a.node.lineno) for k, a in summary.aliases.items()
    )
    reexports = sorted(summary.reexports.items())
    names = (
        summary.functions.keys()
        | summary.classes.keys()
        | summary.constants.keys()
        | summary.aliases.keys()
        | summary.reexports.keys()
    )
    for name in sorted(names):
        alias = summary.aliases.get(name)
        content = (
            name,
            summary.functions.get(name),
            summary.classes.get(name),
            summary.constants.get(name),
            (
                ast.dump(alias.node),
                alias.node.lineno,
                aliases,
                reexports,
                alias.names.constants,  # what the alias's names mean here
            )
            if alias is not None
            else None,
            summary.reexports.get(name),
        )
        summary.members[name] = _hash(_stable(content))
    return summary


def _records(path: Path, kept: dict[str, str]) -> dict[str, str]:
    """A kept summary's records (`Known`), with its file's name put back."""
    own = str(path)
    return {own + k if k[:1] == "\0" else k: v for k, v in kept.items()}


def _hash(text: str) -> str:
    """A fingerprint: 128 bits, short in the cache's file."""
    return hashlib.blake2b(text.encode(), digest_size=16).hexdigest()


def _stable(value: object) -> str:
    """`repr`, but the same in every process: AST nodes (whose repr is their
    address) by their kind and place, sets in sorted order. A fingerprint that
    changed from run to run re-checked every importer on every cached run."""
    if value.__class__ in _PLAIN:  # most leaves: `repr`, without the tests below
        return repr(value)
    if isinstance(value, ast.AST):
        place = [getattr(value, a, None) for a in ast_places]
        return f"<{type(value).__name__} {place}>"
    if isinstance(value, (list, tuple)):
        inner = ", ".join(_stable(v) for v in value)
        return f"[{inner}]" if isinstance(value, list) else f"({inner},)"
    if isinstance(value, (set, frozenset)):
        return "{" + ", ".join(sorted(_stable(v) for v in value)) + "}"
    if isinstance(value, dict):
        pairs = (f"{_stable(k)}: {_stable(v)}" for k, v in value.items())
        return "{" + ", ".join(pairs) + "}"
    if is_dataclass(value) and not isinstance(value, type):
        parts = (f"{f.name}={_stable(getattr(value, f.name))}" for f in fields(value))
        return f"{type(value).__name__}({', '.join(parts)})"
    return repr(value)


ast_places = ("lineno", "col_offset", "end_lineno", "end_col_offset")
_PLAIN = frozenset({str, int, float, bool, type(None)})  # exactly these: no subclass


def _key(path: Path | str) -> str:
    """One spelling of a file's path, for the run's files and the index's alike."""
    return os.path.normpath(os.path.abspath(path))


def _ways(path: Path) -> tuple[str, ...]:
    """Every folder from which some dotted name could find `path` (`a/b.py` from
    `a/..` as `a.b`, from `a` as `b`): its ancestors up to the first whose name is
    no identifier (a name spells every folder below the one searched)."""
    full = os.path.abspath(path)
    folder, name = os.path.split(full)
    if name == "__init__.py":
        folder, name = os.path.split(folder)
    elif name.endswith(".py"):
        name = name[:-3]
    found = []
    while name.isidentifier():
        found.append(folder)
        parent, name = os.path.split(folder)
        if parent == folder:
            break
        folder = parent
    return tuple(found)


def _sha(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()
