"""A whole run: find the files, reuse cached results, check the rest (in parallel
processes with -j), and gather the diagnostics in a deterministic order.
"""

from __future__ import annotations

import gc
import hashlib
import json
import os
import signal
import sys
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from robotfix import GC_THRESHOLDS, messages
from robotfix.api import (
    InternalError,
    Result,
    check_file,
    finish,
    interface_problems,
    make_project,
    raw_interface_problems,
    stub_problems,
)
from robotfix.cache import ResultCache, discovery_key, run_key
from robotfix.config import Config
from robotfix.diagnostics import Diagnostic
from robotfix.discovery import Discovery, Trace, discover, install_space
from robotfix.fs import (
    RACY_NS,
    Noted,
    UnreadableError,
    answering,
    asked,
    noting,
    read_regular,
    stamp,
)
from robotfix.ros.api_model import ENDPOINT_WORDS
from robotfix.ros.catalog import MsgCatalog
from robotfix.ros.install import InstallSpace
from robotfix.ros.package import package_folder

if TYPE_CHECKING:
    from concurrent.futures import Future, ProcessPoolExecutor

if TYPE_CHECKING:  # the analysis is imported only when a file is checked
    from robotfix.analysis.paramsummary import Summary as ParamSummary
    from robotfix.api import Contract
    from robotfix.cppparams import CppParams
    from robotfix.faults import Fault as ParamFault
    from robotfix.launchcheck import Imports, LaunchRun, Read
    from robotfix.paramcheck import Known as ParamKnown
    from robotfix.project.summary import Known, Project
    from robotfix.ros.graph.model import FileGraph
    from robotfix.source import SourceFile

MIN_PARALLEL = 16  # fewer files are checked faster in one process than by a pool
# and so is less source: starting a pool costs about 0.1-0.2 s, what one process
# spends on about 5,000 lines of real code (12,000 lines, 0.5 MB, take 0.3 s)
MIN_PARALLEL_BYTES = 512 * 1024
CHUNKS_PER_JOB = 4  # a task holds at most 1/(jobs * 4) of the source: balance


@dataclass
class FileResult:
    """One file's check: its diagnostics and what the run keeps of it."""

    path: str
    diagnostics: list[Diagnostic] = field(default_factory=list)
    error: InternalError | None = None
    types: list[str] = field(default_factory=list)  # message types it looked up
    fingerprint: str = ""  # the catalog's fingerprint of `types`, as the check saw it
    # the module summaries it consulted (`project/summary.py`): key -> fingerprint
    modules: dict[str, str] = field(default_factory=dict)
    # the summaries its process built since its last result: file -> fingerprints
    summaries: dict[str, Known] = field(default_factory=dict)
    # what it declares and reads of parameters (`analysis/parameters.py`), from the
    # tree the check parsed, for `paramcheck` (None: not asked, or no mention)
    parameters: ParamSummary | None = None
    # which of `paramcheck.MENTIONS`' words its bytes hold (None: not asked)
    mentions: tuple[bytes, ...] | None = None
    # a worker's module index answers since its last result (`ModuleIndex.fresh`),
    # for the result cache: the next run resolves nothing the workers did
    answers: dict[str, Any] | None = None
    # the same for the catalog's digests (`MsgCatalog.fresh_digests`)
    digests: dict[str, tuple[str, tuple[str, ...]]] | None = None
    # its graph endpoints (`ros.graph.model.dump`), from the tree the check parsed
    # (None: none), kept in the result cache with its entry
    graph: list[Any] | None = None


def check_paths(
    paths: list[Path],
    config: Config,
    progress: Callable[[int, int, str], None] | None = None,
    jobs: int = 1,
    use_cache: bool = False,
) -> Result:
    """Check every Python file under `paths`; interface files come from the msg paths
    and from the msg/srv/action folders of ROS packages under `paths`, then from
    the sourced install space. A problem in an interface file fails the run only
    when a checked file uses a type of that file (`api.interface_problems`)."""
    # As mypy does: the analysis makes millions of short-lived objects while large
    # ASTs stay alive, so the collector runs less often and skips what start-up made
    # (-7% CPU on real code in the performance report; -3% to -18% here, on a busy
    # machine); restored when the run ends. A young collection walks every object
    # made since the last (a file's tree): at 50,000, the 4-6 of a cold check of
    # corpus25 took 1% of its CPU to free two kinds of cycle, now broken where they
    # were made (`tests/unit/test_no_cycles.py`); at 200,000, mypy's, none runs.
    threshold = gc.get_threshold()
    gc.freeze()
    gc.set_threshold(*GC_THRESHOLDS)
    try:
        try:
            with answering():  # each path probed once (the stages share them)
                return _check_paths(paths, config, progress, jobs, use_cache)
        except Exception:
            if not use_cache:
                raise
            # a state of the result cache no validation foresaw must not fail
            # every run: the run again without reading it (it is rewritten)
            with answering():
                return _check_paths(paths, config, progress, jobs, use_cache, False)
    finally:
        gc.set_threshold(*threshold)
        gc.unfreeze()


@dataclass
class _Group:
    """The files of a run whose nearest configuration is not the run's: checked
    with their own settings (`config.by_settings`), in a run of their own over the
    same paths that reports only their files and the problems of the interface
    files only they read; the types they used count for the others'."""

    files: set[Path]
    shared: set[str]  # the run's own interface files: their problems are its
    used: set[str] = field(default_factory=set)
    graphs: dict[str, list[Any]] = field(default_factory=dict)  # its endpoints


def _check_groups(
    paths: list[Path],
    config: Config,
    found: Discovery,
    jobs: int,
    use_cache: bool,
    trusted: bool,
) -> tuple[list[Result], set[str], set[Path], dict[str, list[Any]]]:
    """Each group of files with settings of their own, checked apart: their
    results, the message types they used, their files and their graph
    endpoints."""
    from robotfix.config import by_settings

    results: list[Result] = []
    used: set[str] = set()
    grouped: set[Path] = set()
    graphs: dict[str, list[Any]] = {}
    shared = {str(p) for p in found.interface_files}
    base = config.cache_dir or config.root / ".robotfix_cache"
    for settings, files in by_settings(found.python_files, config):
        name = hashlib.sha256(str(settings.source).encode()).hexdigest()[:16]
        own = replace(settings, cache_dir=base / "configs" / name)
        group = _Group(set(files), shared)
        results.append(_check_paths(paths, own, None, jobs, use_cache, trusted, group))
        used |= group.used
        grouped |= group.files
        graphs.update(group.graphs)
    return results, used, grouped, graphs


def _check_paths(
    paths: list[Path],
    config: Config,
    progress: Callable[[int, int, str], None] | None,
    jobs: int,
    use_cache: bool,
    trusted: bool = True,
    group: _Group | None = None,
) -> Result:
    started = time.perf_counter()
    result = Result()
    cache = (
        ResultCache(
            config.cache_dir or config.root / ".robotfix_cache",
            run_key(config),
            trusted,
        )
        if use_cache
        else None
    )
    found = _discover(paths, config, cache)
    everything = found.python_files
    if group is not None:  # only its files; the run reports what is run-wide
        found = replace(found, python_files=[f for f in everything if f in group.files])
        found.notices = []
    groups: list[Result] = []
    used: set[str] = set()  # the message types the checked files looked up
    grouped: set[Path] = set()
    grouped_graphs: dict[str, list[Any]] = {}
    if group is None and config.flags is not None:
        groups, used, grouped, grouped_graphs = _check_groups(
            paths, config, found, jobs, use_cache, trusted
        )
        found = replace(found, python_files=[f for f in everything if f not in grouped])
    result.diagnostics.extend(found.notices)
    result.diagnostics.extend(stub_problems(config))
    interfaces = _Interfaces(
        found.interface_files,
        found.package_interface_files,
        found.installed,
        tuple(paths),
    )
    catalog = _catalog(interfaces, config)
    project = make_project(paths, config, catalog)
    project.records = cache is not None  # what only the cache reads
    files = found.python_files
    result.files = len(files)
    result.checked = [str(file) for file in files]
    # the same interface files as last time: their digests and problems are known
    snapshot = _catalog_key(interfaces, config) if cache is not None else None
    known = cache.catalog(snapshot) if cache is not None and snapshot else None
    if known is not None:
        catalog.preload_digests(known[0])
        if known[2] is not None:  # a type is read from its own file when needed
            catalog.preload_outline(known[2])
    if cache is not None:
        # a module whose summary a cached result needs, parsed for it, keeps its
        # tree if it is then checked (`Project.expect`, `take`)
        project.expect(files)
        project.known = dict(cache.summaries)
        project.sha_of = cache.sha  # the stat fast path for imported modules too
        project.index.restore(cache.resolution())  # the module index's answers
    # file -> the parameter words it mentions and its parameters, as checked
    parameters: dict[str, ParamKnown] = {}
    graphs: dict[str, list[Any]] = {}  # file -> its graph endpoints, dumped
    # without the cache, a file is read when it is checked (None here), so that
    # the bytes of every file are not all held at once
    todo: list[tuple[Path, bytes | None]] = []
    for index, file in enumerate(files, start=1):
        if cache is None:
            todo.append((file, None))
            continue
        # with the cache, an unchanged file (by its stat) is not even read
        digest = cache.sha(file) if cache is not None else None
        cached = (
            cache.get(file, digest, config, catalog, project)
            if cache is not None and digest is not None
            else None
        )
        if cached is None:
            try:  # a FIFO or a device: refused, never blocks
                data = cache.take(file) if cache is not None else read_regular(file)
            except UnreadableError as err:
                reason = f"cannot read: {err.reason}"
                result.diagnostics.append(messages.unreadable(str(file), reason))
                continue
        if cached is not None:
            result.diagnostics.extend(cached)
            used.update(cache.types(file) if cache else ())
            kept = cache.graph(file) if cache else None
            if kept is not None:
                graphs[str(file)] = kept
            result.from_cache += 1
            if progress is not None:
                progress(index, len(files), str(file))
        else:
            todo.append((file, data))
    done = len(files) - len(todo)
    contents = {path: data for path, data in todo if data is not None}
    if todo and (
        found.parameter_files or found.parameter_definitions or found.launch_files
    ):
        from robotfix.paramcheck import MENTIONS  # not on a fully cached run

        project.parameter_words = tuple(w for ws in MENTIONS.values() for w in ws)
    global _READS_LAUNCHES
    _READS_LAUNCHES = bool(found.launch_files)
    _IMPORTS.clear()
    checks = _check_all(todo, interfaces, config, catalog, project, jobs, cache)
    for outcome in checks:
        failed = outcome.error is not None and outcome.error.summary != LOST
        if failed and cache is not None:
            outcome = _check_clean(outcome, contents, interfaces, config, cache)
        done += 1
        if progress is not None:
            progress(done, len(files), outcome.path)
        result.diagnostics.extend(outcome.diagnostics)
        used.update(outcome.types)
        if outcome.mentions is not None:
            parameters[outcome.path] = (outcome.mentions, outcome.parameters)
        if outcome.graph is not None:
            graphs[outcome.path] = outcome.graph
        if outcome.answers is not None:
            project.index.merge(outcome.answers)
        if outcome.digests:
            catalog.preload_digests(outcome.digests)
        if outcome.error is not None:
            result.internal_errors.append(outcome.error)
        elif cache is not None:
            cache.put(
                Path(outcome.path),
                contents[Path(outcome.path)],
                config,
                outcome.diagnostics,
                outcome.types,
                outcome.fingerprint,
                outcome.modules,
                outcome.graph,
            )
        if cache is not None:
            cache.remember_summaries(outcome.summaries)
    if cache is not None:  # those built here to see whether a cached result holds
        cache.remember_summaries(project.fresh_summaries())
    problems = known[1] if known is not None else raw_interface_problems(catalog)
    interface = interface_problems(catalog, used, problems)
    if group is not None:  # the run reports the problems of its own files
        group.used |= used
        interface = [d for d in interface if d.path not in group.shared]
    result.diagnostics.extend(interface)
    if cache is not None and snapshot:
        cache.put_catalog(snapshot, catalog.digest_table(), problems, catalog.outline())
    if group is not None:  # its files' graph endpoints, for the run's graph
        group.graphs.update(graphs)
    if group is None:
        where = paths[0] if paths else config.root
        graphs.update(grouped_graphs)
        workspace = any(os.path.isdir(p) for p in paths)  # it has a graph
        stage = _Stage(found, everything, cache, where, result)
        if cache is not None:
            stage.look_up(_stage_key(found, everything, graphs, cache, workspace))
        result.diagnostics.extend(
            _parameter_problems(
                found,
                everything,
                config,
                cache,
                parameters,
                project,
                result.internal_errors,
                stage,
            )
        )
        result.files += len(found.parameter_files)
        if stage.known is not None:
            result.diagnostics += [
                d
                for d in stage.known[1]
                if not config.silences(d.path, d.code, d.rule.name)
            ]
        elif workspace:
            result.diagnostics.extend(
                _graph_problems(
                    graphs,
                    stage,
                    config,
                    catalog,
                    project,
                    where,
                    result.internal_errors,
                )
            )
        else:
            stage.graph = []
        stage.keep()
    for other in groups:
        _merge(result, other)
    if groups:
        result.checked = [str(file) for file in everything]
    _READS_LAUNCHES = False
    _IMPORTS.clear()
    result.diagnostics = finish(result.diagnostics)
    if cache is not None:
        cache.put_resolution(project.index.keep())
        cache.prune(paths, files)
        cache.save()
    catalog.save()
    units = sys.modules.get("robotfix.annotations.units")
    if units is not None:  # not imported: no unit was read, nothing to keep
        units.save_cache()
    result.seconds = time.perf_counter() - started
    return result


def _merge(result: Result, other: Result) -> None:
    """A group's result into the run's (`finish` sorts the diagnostics)."""
    result.diagnostics.extend(other.diagnostics)
    result.files += other.files
    result.from_cache += other.from_cache
    result.internal_errors.extend(other.internal_errors)


def _discover(
    paths: list[Path], config: Config, cache: ResultCache | None
) -> Discovery:
    """`discover`, or with the cache, what the last run found when nothing it looked
    at changed (`discovery.Trace`): an unchanged tree stats its folders instead of
    walking them."""
    key = discovery_key(paths, config) if cache is not None else None
    if cache is None or key is None:
        return discover(paths, config)
    known = cache.discovery(key)
    if known is not None:
        known.installed = install_space()
        return known
    trace = Trace()
    found = discover(paths, config, trace=trace)
    for source in config.nested_sources():  # their `exclude` counts too
        trace.stamp(source)
    cache.put_discovery(key, found, trace)
    return found


class _Stage:
    """The run's launch files, read once for the parameter check and the graph
    (`read`), and with the cache, what reading them and checking the graph
    gave an earlier run (`cache.stage`): when the launch files, the code files,
    the graph endpoints (`_stage_key`) and every file and path the reading and
    the graph's check looked at (a `discovery.Trace`, `fs.noting`) are as they
    were, neither is done again: the parameter check's key takes the files the
    launch check depends on from there (the parameter check, cached under that
    key, reads the launch files only when its key changed), the run the graph's
    findings."""

    def __init__(
        self,
        found: Discovery,
        files: list[Path],
        cache: ResultCache | None,
        where: Path | None = None,
        result: Result | None = None,
    ) -> None:
        """`where`, `result`: where a fault reading the C++ files goes."""
        self.found, self.files, self.cache = found, files, cache
        self.where, self.result = where, result
        self._cpp: dict[str, FileGraph] | None = None
        self.cpp_faulted = False
        self.key: str | None = None
        self.known: tuple[list[str], list[Diagnostic]] | None = None
        # what the reading and the graph's check looked at: for the cache only
        self.trace = Trace() if cache is not None else None
        self.launches: tuple[LaunchRun, list[ParamFault]] | None = None
        self.was_read = False
        self.graph: list[Diagnostic] | None = None  # the findings to keep
        self._params: CppParams | None = None

    def look_up(self, key: str) -> None:
        assert self.cache is not None
        self.key, self.known = key, self.cache.stage(key)

    def read(self) -> tuple[LaunchRun, list[ParamFault]] | None:
        if not self.was_read:
            self.was_read = True
            with noting(self.trace):
                self.launches = _launches(self.found, self.files, self.cache)
        return self.launches

    def cpp(self) -> dict[str, FileGraph]:
        """The C++ files' graphs (`_cpp_graphs`), read when first asked: a run
        whose parameter check and graph are kept reads none."""
        if self._cpp is None:
            result = self.result or Result()
            before = len(result.internal_errors)
            self._cpp = _cpp_graphs(
                self.found, self.cache, self.where or Path("."), result
            )
            self.cpp_faulted = len(result.internal_errors) > before
        return self._cpp

    def cpp_nodes(self) -> CppParams:
        """The C++ nodes' names and parameters (`cppparams`), with the code each
        launch entry starts."""
        if self._params is None:
            self._params = _cpp_params(self.cpp(), self.read(), self.where or Path("."))
        return self._params

    def touched(self) -> list[str]:
        if self.known is not None:
            return self.known[0]
        read = self.read()
        return sorted(read[0].touched()) if read is not None else []

    def keep(self) -> None:
        """Into the cache, when this run read the launch files without a fault
        and checked the graph without one (or has none)."""
        if self.cache is None or self.key is None or self.known is not None:
            return
        read = self.read()
        if self.graph is None or self.cpp_faulted or (read is not None and read[1]):
            return
        assert self.trace is not None
        self.cache.put_stage(self.key, self.trace.folded(), self.touched(), self.graph)


def _stage_key(
    found: Discovery,
    files: list[Path],
    graphs: dict[str, list[Any]],
    cache: ResultCache,
    workspace: bool,
) -> str:
    """What the launch files' reading and the graph's findings depend on besides
    the files and paths their trace notes: the launch and code files the run
    found, each Python file's endpoints, each C++ file's bytes (its endpoints
    are a function of them), the current folder. (The findings are kept before
    `per-file-ignores`, applied to them as they are used: `Config.silences`.)"""
    parts = {
        "cwd": os.getcwd(),
        "workspace": workspace,
        "launch": [str(p) for p in found.launch_files],
        "code": [str(p) for p in [*files, *found.summary_files]],
        "graphs": sorted(graphs.items()),
        "cpp": [[str(p), cache.sha(p)] for p in found.cpp_files],
    }
    text = json.dumps(parts, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode("utf-8", "surrogateescape")).hexdigest()


class _KeptReads:
    """Each launch file's reading kept in the cache (`launchcheck.Kept`), with
    the trace of what it read and probed (its includes' files, the packages'
    build files, the nodes' code, the parameter files it looked for)."""

    def __init__(self, cache: ResultCache) -> None:
        self.cache = cache

    def get(self, path: str, context: str) -> tuple[Noted, Read] | None:
        from robotfix.launchcheck import Read
        from robotfix.ros.launch.model import NodeEntry, load

        raw = self.cache.launch_read(path, context)
        if raw is None:
            return None
        trace, (problem, started, reading) = raw
        entries = []
        try:
            for dumped, files in started:
                entry = load(dumped)
                if not isinstance(entry, NodeEntry):
                    return None
                entries.append((entry, files))
        except (ValueError, TypeError):
            return None
        if not trace.holds(self.cache.same_bytes):
            return None
        if trace.renewed:
            self.cache.renew_launch_read(path, trace)
        return trace, Read(problem, entries, reading)

    def put(self, path: str, context: str, noted: Noted, read: Read) -> None:
        from robotfix.ros.launch.model import dump

        taken = Trace()
        taken.take(noted)
        trace = taken.folded()
        if trace.spoiled:
            return
        try:
            started = [[dump(entry), files] for entry, files in read.started]
        except ValueError:
            return
        raw = [read.problem, started, read.reading]
        self.cache.put_launch_read(path, context, trace, raw)


def _launches(
    found: Discovery, files: list[Path], cache: ResultCache | None = None
) -> tuple[LaunchRun, list[ParamFault]] | None:
    """The run's launch files, read (with the cache, a file whose reading was
    kept and what it read holds is not read again)."""
    if not found.launch_files:
        return None
    from robotfix.launchcheck import LaunchRun

    faults: list[ParamFault] = []
    code = [*files, *found.summary_files]
    kept = _KeptReads(cache) if cache is not None else None
    run = LaunchRun(found.launch_files, code, faults, _IMPORTS, kept)
    # read: the entries' code is found, the import statements are not read again
    # (1.2 MB on corpus25, else held through the C++ files' reading, the peak)
    _IMPORTS.clear()
    return run, faults


def _cpp_graphs(
    found: Discovery, cache: ResultCache | None, where: Path, result: Result
) -> dict[str, FileGraph]:
    """The run's C++ files' graphs (`graphcheck.read_cpp_files`), read once for
    the parameter check (their node names, RF602) and the graph; a fault of ours
    is an internal error of `where`, the run's first path."""
    if not found.cpp_files:
        return {}
    from robotfix.faults import Fault, guard
    from robotfix.graphcheck import read_cpp_files

    faults: list[Fault] = []
    with guard(where, result.diagnostics, faults):
        return read_cpp_files(found.cpp_files, cache)
    errors = [InternalError(f.path, f.summary, f.detail) for f in faults]
    result.internal_errors += errors
    return {}


def _cpp_params(
    cpp: dict[str, FileGraph],
    launches: tuple[LaunchRun, list[ParamFault]] | None,
    where: Path,
) -> CppParams:
    """The C++ nodes' parameters (`cppparams`), with the code each launch entry
    starts (as the graph finds it; a fault of ours there: `where`'s)."""
    from robotfix.cppparams import CppParams
    from robotfix.graphcheck import started_entries

    run = launches[0] if launches else None
    return CppParams(cpp, lambda: started_entries(run, cpp), str(where))


def _graph_problems(
    graphs: dict[str, list[Any]],
    stage: _Stage,
    config: Config,
    catalog: MsgCatalog,
    project: Project,
    where: Path,
    errors: list[InternalError],
) -> list[Diagnostic]:
    """The findings of the run's static ROS graph (`graphcheck.py`), and what
    publishers violate of their subscribers' contracts (issue 23 §3). A fault
    of ours is an internal error (of `where`, the run's first path, or of the
    publisher's file whose contracts were checked): the rest is reported. The
    graph's findings are kept in `stage` (for the cache) when no fault came and
    no contract is checked (that analyses the publisher's file: not kept)."""
    cpp = stage.cpp()
    if not graphs and not cpp:
        stage.graph = []
        return []
    from robotfix.faults import Fault, guard
    from robotfix.graphcheck import check_graph, code_graphs
    from robotfix.graphcheck import contracts as graph_contracts

    out: list[Diagnostic] = []
    faults: list[Fault] = []
    with guard(where, out, faults):
        code = code_graphs(graphs, cpp)
        launches = stage.read()
        with noting(stage.trace):  # `per-file-ignores` after: not in the trace
            result = check_graph(code, launches[0] if launches else None)
        out += [
            d
            for d in result.diagnostics()
            if not config.silences(d.path, d.code, d.rule.name)
        ]
        found = sorted(graph_contracts(result).items())
        if not found and not faults:
            stage.graph = result.diagnostics()
        for path, contracts in found:
            with guard(path, out, faults):
                out += _contract_problems(
                    Path(path), contracts, config, catalog, project
                )
    errors += [InternalError(f.path, f.summary, f.detail) for f in faults]
    return out


def _contract_problems(
    path: Path,
    contracts: list[Contract],
    config: Config,
    catalog: MsgCatalog,
    project: Project,
) -> list[Diagnostic]:
    """A publisher's file analysed again with its subscribers' contracts
    (`api.check_contracts`)."""
    from robotfix.api import check_contracts
    from robotfix.stubs.load import stub_set

    try:
        data = read_regular(path)
    except UnreadableError:
        return []  # its own check says why
    return check_contracts(
        str(path),
        data,
        catalog,
        contracts,
        config.ignored_codes(path),
        stub_set(config.stub_paths),
        project.resolver(path),
    )


def _parameter_problems(
    found: Discovery,
    files: list[Path],
    config: Config,
    cache: ResultCache | None = None,
    parameters: dict[str, ParamKnown] | None = None,
    project: Project | None = None,
    errors: list[InternalError] | None = None,
    stage: _Stage | None = None,
) -> list[Diagnostic]:
    """Parameter files and launch files against the parameters the code declares,
    and the run's C++ nodes (`stage.cpp_nodes`, `cppparams`: names, declarations);
    cached as a whole, under a key that hashes every input (`_params_key`);
    `parameters`: what the checks found of the files they read (the others are
    read there). Launch files are read first (`launchcheck.LaunchRun`): what
    they touch is part of the key. A fault of ours on one file (a parameter
    file, a launch file) is an internal error of that file (in `errors`), the
    others are checked, and nothing is cached."""
    if not (found.parameter_files or found.parameter_definitions or found.launch_files):
        return []
    python_files = [*files, *found.summary_files]
    stage = stage or _Stage(found, files, cache)
    inputs = _params_inputs(found, python_files, config, cache) if cache else []
    key = _params_key(config, cache, stage.touched(), inputs) if cache else None
    faulty = stage.launches is not None and bool(stage.launches[1])
    if cache is not None and key is not None and not faulty:
        known = cache.params(key)
        if known is not None:
            return known
    read = stage.read()
    launches, faults = read if read is not None else (None, [])
    from robotfix.paramcheck import check_parameter_files

    parts = (
        _ParamParts(found, python_files, config, cache, launches, inputs)
        if cache is not None and not faults
        else None
    )

    out = check_parameter_files(
        found.parameter_files,
        found.parameter_definitions,
        python_files,
        found.named_parameter_files,
        config,
        parameters,
        project,
        faults,
        launches,
        stage.cpp_nodes(),
        parts,
    )
    if errors is not None:
        errors += [InternalError(f.path, f.summary, f.detail) for f in faults]
    if cache is not None and key is not None and not faults and not stage.cpp_faulted:
        cache.put_params(key, out)
    return out


class _ParamParts:
    """The parameter check's parts kept in the cache (`paramcheck.Parts`), each
    under a key of what it depends on, so an edit re-checks only what it
    touches: the parameter files' findings and RF602 ("fixed": what
    `_params_key` hashes but the launch files, with what the launch files add to
    the table instead: the names they give nodes and the code those start, the
    parameter files they name), and each launch file's entries' findings (its
    bytes, the entries as read, the bytes of the code they start with what its
    check consulted, of the parameter files they name, of the definitions)."""

    def __init__(
        self,
        found: Discovery,
        python_files: list[Path],
        config: Config,
        cache: ResultCache,
        launches: LaunchRun | None,
        inputs: list[str],
    ) -> None:
        self.found, self.python_files, self.config = found, python_files, config
        self.cache, self.launches, self.inputs = cache, launches, inputs
        self._shared: str | None = None  # what every launch file's key holds
        self._keys: dict[str, str] = {}
        self._real: dict[str, list[Path]] | None = None
        self._files: dict[tuple[str, str], str] = {}  # many keys name one file

    def _file(self, label: str, path: Path | str) -> str:
        name = (label, str(path))
        if name not in self._files:
            file = Path(path)
            ignored = ",".join(sorted(self.config.ignored_codes(file)))
            where = package_folder(file)
            self._files[name] = (
                f"{label}\0{path}\0{self.cache.sha(file)}\0{ignored}\0{where}"
            )
        return self._files[name]

    def _key(self, name: str, parts: list[str]) -> str:
        text = "\n".join([name, *parts]).encode("utf-8", "surrogateescape")
        self._keys[name] = hashlib.sha256(text).hexdigest()
        return self._keys[name]

    def fixed(self) -> tuple[list[Diagnostic], list[Diagnostic]] | None:
        launches = self.launches
        parts = list(self.inputs)
        if launches is not None:
            parts.append(f"entries\0{bool(launches.entries)}")
            parts += [f"name\0{n}" for n in sorted(launches.names)]
            for name, files in sorted(launches.renamed.items()):
                parts.append("\0".join(["renamed", name, *sorted(files)]))
            parts += [self._file("file", p) for p in launches.files]
            for started in launches.started:  # RF602 at an entry: what it passes
                entry = started.entry
                passed = [getattr(p, "path", None) for p in entry.parameters]
                parts.append(
                    f"passes\0{entry.place!r}\0{entry.name}\0{entry.namespace}"
                )
                parts += [f"passed\0{p}" for p in passed if p is not None]
        found = self.cache.param_part("fixed", self._key("fixed", parts))
        return (found[0], found[1]) if found is not None and len(found) == 2 else None

    def launch_file(self, path: str, entries: list[Any]) -> list[Diagnostic] | None:
        if self._real is None:
            self._real = {}
            for file in self.python_files:  # real paths: the run's answers
                real = asked("realpath", os.fspath(file))
                self._real.setdefault(real, []).append(file)
        parts = [self._file("launch", path)]
        for started in entries:
            parts.append(f"entry\0{started.entry!r}\0{sorted(started.files)}")
            for real in sorted(started.files):
                for file in self._real.get(real, []):
                    parts.append(self._file("code", file))
                    parts += [f"reads\0{k}\0{v}" for k, v in self.cache.consulted(file)]
            for parameter in started.entry.parameters:
                if getattr(parameter, "path", None) is not None:
                    parts.append(self._file("param", parameter.path))
        parts.append(self.shared())
        found = self.cache.param_part(f"launch:{path}", self._key(path, parts))
        return found[0] if found is not None and len(found) == 1 else None

    def shared(self) -> str:
        """What every launch file's key holds, hashed once (not joined and
        hashed again for each of 328 launch files: 1,528 C++ files): the
        parameter definitions, the files read only for their declarations, and
        the C++ nodes an entry may start, their declarations (`cppparams`)."""
        if self._shared is None:
            parts = [
                self._file("definitions", p) for p in self.found.parameter_definitions
            ]
            parts += [self._file("summary", p) for p in self.found.summary_files]
            parts += [p for p in self.inputs if p.startswith(("cpp\0", "cmake\0"))]
            text = "\n".join(parts).encode("utf-8", "surrogateescape")
            self._shared = f"shared\0{hashlib.sha256(text).hexdigest()}"
        return self._shared

    def keep(
        self,
        fixed: tuple[list[Diagnostic], list[Diagnostic]] | None,
        launch: dict[str, list[Diagnostic]],
    ) -> None:
        if fixed is not None and "fixed" in self._keys:
            self.cache.put_param_part("fixed", self._keys["fixed"], *fixed)
        for path, found in launch.items():
            if path in self._keys:
                self.cache.put_param_part(f"launch:{path}", self._keys[path], found)


def _params_key(
    config: Config, cache: ResultCache, touched: list[str], inputs: list[str]
) -> str:
    """The key of the parameter check as a whole: its `inputs` (`_params_inputs`)
    and every file the launch files' reading touched (launch files, the parameter
    files and build files they lead to, the nodes' code, by its bytes)."""
    parts = list(inputs)
    for name in touched:
        file = Path(name)
        ignored = ",".join(sorted(config.ignored_codes(file)))
        parts.append(f"launch\0{name}\0{cache.sha(file)}\0{ignored}")
    text = "\n".join(parts).encode("utf-8", "surrogateescape")
    return hashlib.sha256(text).hexdigest()


def _params_inputs(
    found: Discovery,
    python_files: list[Path],
    config: Config,
    cache: ResultCache,
) -> list[str]:
    """Everything `paramcheck` reads (and the C++ files, by their bytes: their
    nodes' names and declarations count, with the CMakeLists.txt of their
    packages, which says what an executable is built from), the
    parameter and definitions files (bytes, per-file ignores, package folder), and
    each Python file that mentions a parameter word (`cache.MENTION_WORDS`; the
    others are skipped unread there) with its bytes, the file it really is, its
    package folder and what its check consulted of other modules (an alias its
    refinement imports: the entry holds each record's fingerprint as it is now, or
    the file was checked again). A file read only for its declarations
    (`summary_files`, no check) counts with every other such file's bytes: they are
    the modules it can import (the launch files apart: `_params_key`,
    `_ParamParts`)."""
    parts = [f"cpp\0{path}\0{cache.sha(path)}" for path in found.cpp_files]
    builds = {package_folder(path) for path in found.cpp_files}
    for folder in sorted(f for f in builds if f is not None):  # (cppparams)
        cmake = folder / "CMakeLists.txt"  # what an executable is built from
        parts.append(f"cmake\0{cmake}\0{cache.sha(cmake) if cmake.is_file() else ''}")
    groups = (
        ("yaml", found.parameter_files),
        ("definitions", found.parameter_definitions),
        ("named", found.named_parameter_files),
    )
    for label, group in groups:
        for path in group:
            ignored = ",".join(sorted(config.ignored_codes(path)))
            where = package_folder(path)
            parts.append(f"{label}\0{path}\0{cache.sha(path)}\0{ignored}\0{where}")
    checked = set(python_files) - set(found.summary_files)
    for path in python_files:
        mentions = cache.mentions(path)
        if mentions or path not in checked:
            real = asked("realpath", os.fspath(path))  # the run's answer
            where = package_folder(path)
            parts.append(f"py\0{path}\0{real}\0{cache.sha(path)}\0{where}")
            parts += [f"reads\0{k}\0{v}" for k, v in cache.consulted(path)]
    return parts


def _catalog_key(interfaces: _Interfaces, config: Config) -> str | None:
    """What the catalog is read from, by stat (as `ResultCache.sha`): its interface
    files' names and stamps (`fs.stamp`: with the ctime), and the settings that shape
    it; None when that is not all (an install space is sourced: its files are read
    on demand) or a file changed too recently to trust its stamp."""
    if interfaces.installed is not None:
        return None
    now = time.time_ns()
    parts = [
        f"rep103 {config.rep103} suffixes {config.unit_suffixes} {config.ros_distro}"
    ]
    parts += [f"preferred {p}" for p in interfaces.preferred]
    for path in interfaces.files:
        found = stamp(path)
        if found is None:
            parts.append(f"missing {path}")
            continue
        if now - max(found[:2]) < RACY_NS:
            return None
        parts.append(f"file {path} {found}")
    text = "\n".join(parts).encode("utf-8", "surrogateescape")
    return hashlib.sha256(text).hexdigest()


@dataclass(frozen=True)
class _Interfaces:
    """What a catalog is built from, in the main process and in every worker."""

    files: list[Path]
    preferred: list[Path]  # the checked packages' files: they win over msg paths'
    installed: InstallSpace | None
    roots: tuple[Path, ...] = ()  # the checked paths: where modules are found


def _catalog(interfaces: _Interfaces, config: Config) -> MsgCatalog:
    return MsgCatalog(
        interfaces.files,
        rep103=config.rep103,
        unit_suffixes=config.unit_suffixes,
        distro=config.ros_distro,
        installed=interfaces.installed,
        preferred=interfaces.preferred,
    )


def _check_all(
    todo: list[tuple[Path, bytes | None]],
    interfaces: _Interfaces,
    config: Config,
    catalog: MsgCatalog,
    project: Project,
    jobs: int,
    cache: ResultCache | None = None,
) -> Iterator[FileResult]:
    """Each file's result, as it comes. With jobs > 1, in worker processes: at most
    one per core and per file; if the pool cannot start (no process or file
    descriptor left), the files are checked here instead. Without a `cache`, no
    check makes what only the cache keeps (`Project.records`), nor does a worker
    send it. `-j 1` asks nothing of the cores (their affinity and control group
    quotas: 4.7 M instructions)."""
    if jobs > 1:
        jobs = min(jobs, default_jobs(), len(todo))
    size = sum(_size(path, data) for path, data in todo)
    if jobs <= 1 or len(todo) < MIN_PARALLEL or size < MIN_PARALLEL_BYTES:
        # in this order, all here: a package's summaries go once it is checked
        project.expect([path for path, _ in todo], release=True)
        for path, data in todo:
            yield _check_one(path, data, catalog, config, project)
        return
    import multiprocessing  # only with a pool: about 10 ms of start-up otherwise
    from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
    from concurrent.futures.process import BrokenProcessPool

    chunks = _chunks(todo, jobs)
    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
    pool: ProcessPoolExecutor | None = None
    pending: dict[Future[list[FileResult]], list[tuple[Path, bytes | None]]] = {}
    global _WORKER
    try:
        if method == "fork":  # read the interface files once: the workers share them
            catalog.prepare()
            _WORKER = (catalog, config, project)
        pool = ProcessPoolExecutor(
            max_workers=jobs,
            mp_context=multiprocessing.get_context(method),
            initializer=_start_worker,
            initargs=(
                (None, config, project.records)
                if method == "fork"
                else (interfaces, config, project.records)
            ),
        )
        unsent: list[list[tuple[Path, bytes | None]]] = []
        for chunk in chunks:
            if unsent:
                unsent.append(chunk)
                continue
            try:
                pending[pool.submit(_worker_check, chunk)] = chunk
            except BrokenProcessPool:
                if not pending:
                    raise  # the pool never ran a chunk: check here instead
                # a worker died (a crash, the OOM killer) before the last chunk was
                # sent: the chunks sent are lost below; the others are checked
                # here, never the one that may have killed it
                unsent.append(chunk)
    except (OSError, BrokenProcessPool):  # EMFILE, EAGAIN: check here instead
        _stop(pool)
        _WORKER = None
        project.expect([path for path, _ in todo])
        for path, data in todo:
            yield _check_one(path, data, catalog, config, project)
        return
    finally:
        if method == "fork":
            _WORKER = None  # the workers have their copy; the parent needs none
    try:
        while pending:
            done, _ = wait(pending, return_when=FIRST_COMPLETED)
            for future in sorted(done, key=lambda f: str(pending[f][0][0])):
                chunk = pending.pop(future)
                try:
                    yield from future.result()
                except BrokenProcessPool:
                    yield from (_lost(path) for path, _ in chunk)
    except BaseException:  # Ctrl-C, or the caller stopped: no waiting for chunks
        _stop(pool)
        raise
    pool.shutdown(wait=True)
    if unsent:
        project.expect([path for chunk in unsent for path, _ in chunk])
    for chunk in unsent:
        for path, data in chunk:
            yield _check_one(path, data, catalog, config, project)


def _chunks(
    todo: list[tuple[Path, bytes | None]], jobs: int
) -> list[list[tuple[Path, bytes | None]]]:
    """The worker tasks: the files of one ROS package (or folder) stay together, so
    the summaries of the modules they import are built by one worker, not by each
    (-j 2 on corpus2: 886 summaries built for 569 modules with chunks of 8 files);
    a task holds at most 1/(jobs * CHUNKS_PER_JOB) of the source, and the largest
    go first, so the workers finish together. Which worker checks a file changes
    no output (`project/summary.py`)."""
    sized = [(path, data, _size(path, data)) for path, data in todo]
    cap = max(1, sum(size for _, _, size in sized) // (jobs * CHUNKS_PER_JOB))
    chunks: list[list[tuple[Path, bytes | None]]] = []
    current: list[tuple[Path, bytes | None]] = []
    held, group = 0, None
    sizes: dict[int, int] = {}
    packages: dict[Path, Path] = {}  # folder -> its package (or itself): one walk up
    for path, data, size in sized:
        key = packages.get(path.parent)
        if key is None:
            key = packages[path.parent] = package_folder(path) or path.parent
        if current and (key != group or held + size > cap):
            chunks.append(current)
            sizes[id(current)] = held
            current, held = [], 0
        current.append((path, data))
        held += size
        group = key
    if current:
        chunks.append(current)
        sizes[id(current)] = held
    return sorted(chunks, key=lambda c: -sizes[id(c)])


def _stop(pool: ProcessPoolExecutor | None) -> None:
    """Shut a pool down without waiting: pending chunks are cancelled and the
    workers ended, so the process can exit at once."""
    if pool is None:
        return
    # `_processes` is private: used only to end the workers sooner, if it is there
    processes = list((getattr(pool, "_processes", None) or {}).values())
    pool.shutdown(wait=False, cancel_futures=True)
    for process in processes:
        if process.is_alive():
            process.terminate()


LOST = "the worker process checking it stopped (killed, or out of memory)"


def _lost(path: Path) -> FileResult:
    return FileResult(str(path), [], InternalError(str(path), LOST, LOST))


def _size(path: Path, data: bytes | None) -> int:
    """A file's size in bytes: of what was read, or else by its stat."""
    if data is not None:
        return len(data)
    try:
        return os.stat(path).st_size
    except OSError:
        return 0  # it says why when it is read


def _check_clean(
    failed: FileResult,
    contents: dict[Path, bytes],
    interfaces: _Interfaces,
    config: Config,
    cache: ResultCache,
) -> FileResult:
    """A file whose check failed in a run that used the result cache, checked again
    with nothing of it (a catalog and a project of its own): a state of the cache
    no validation foresaw must not fail a file on every run. When that check
    succeeds, the cache was the cause: it is dropped (`ResultCache.drop`)."""
    path = Path(failed.path)
    catalog = _catalog(interfaces, config)
    project = make_project(list(interfaces.roots), config, catalog)
    again = _check_one(path, contents.get(path), catalog, config, project)
    if again.error is not None:
        return failed
    cache.drop()
    return again


def _check_one(
    path: Path,
    data: bytes | None,
    catalog: MsgCatalog,
    config: Config,
    project: Project,
) -> FileResult:
    if data is None:  # read only now: one file's bytes held at a time
        try:  # a FIFO or a device: refused, never blocks
            data = read_regular(path)
        except UnreadableError as err:
            reason = f"cannot read: {err.reason}"
            return FileResult(str(path), [messages.unreadable(str(path), reason)])
    from robotfix.source import SourceFile
    from robotfix.stubs.load import stub_set

    catalog.touched = set()
    try:
        resolver = project.resolver(path)
        ignored = config.ignored_codes(path)
        stubs = stub_set(config.stub_paths)
        parsed = project.take(path, data)  # parsed once, for a summary, if imported
        if _READS_LAUNCHES:  # its import statements are kept (`_keep_imports`)
            parsed = parsed or SourceFile.from_bytes(str(path), data)
        parameters = None
        mentions = tuple(w for w in project.parameter_words if w in data)
        if mentions:
            from robotfix.analysis.parameters import summarize

            parsed = parsed or SourceFile.from_bytes(str(path), data)
            if parsed.tree is None:  # it declares nothing: not parsed again there
                mentions = ()
            try:  # a fault here is paramcheck's to meet, as without this
                parameters = (
                    summarize(parsed, resolver=resolver, stubs=stubs)
                    if parsed.tree is not None
                    else None
                )
            except Exception:
                parameters = None
        endpoints = any(w in data for w in ENDPOINT_WORDS)
        if endpoints and parsed is None:
            parsed = SourceFile.from_bytes(str(path), data)
        found = check_file(str(path), data, catalog, ignored, stubs, resolver, parsed)
        graph = _graph_of(parsed) if endpoints and parsed is not None else None
        if _READS_LAUNCHES and parsed is not None:
            _keep_imports(str(path), parsed)
        types = sorted(catalog.touched)
        catalog.touched = None
        return FileResult(
            str(path),
            found,
            None,
            types,
            # what the result cache keeps of the types (a run without it: none)
            catalog.fingerprint_types(types) if project.records else "",
            dict(resolver.consulted),
            project.fresh_summaries(),
            parameters,
            mentions if project.parameter_words else None,
            graph=graph,
        )
    except Exception as err:  # a fault of ours: report it, go on with the others
        import traceback  # only here: 2 ms of every start otherwise

        summary = f"{type(err).__name__}: {err}"
        return FileResult(
            str(path), [], InternalError(str(path), summary, traceback.format_exc())
        )
    finally:
        catalog.touched = None


def _graph_of(parsed: Any) -> list[Any] | None:
    """A checked file's graph endpoints (`ros.graph.python`), dumped; None when it
    makes none (or its tree is not there). The calls and imports its check's
    index found spare the reading most of the walk, and all of it in a file
    none of whose calls makes an endpoint."""
    if parsed.tree is None:
        return None
    from robotfix.analysis.index import built
    from robotfix.ros.graph.model import dump
    from robotfix.ros.graph.python import read_python

    index = built(parsed.tree)
    try:  # a fault here costs the graph this file's endpoints, not its check
        found = (
            read_python(parsed.tree)
            if index is None
            else read_python(
                parsed.tree,
                index.calls,
                index.import_statements,
                len(index.class_scopes),
                endpoints_only=True,
            )
        )
    except (RecursionError, MemoryError):
        return None
    return dump(found) if found.endpoints else None


def _keep_imports(path: str, parsed: SourceFile) -> None:
    """The import statements the check's index found, as plain data (none kept
    when the check built no index: the launch reading parses the file if it
    needs them). Nothing of the tree is kept: it goes with the check."""
    from robotfix.analysis.index import built
    from robotfix.launchcheck import import_lines

    index = built(parsed.tree) if parsed.tree is not None else None
    if index is not None:
        text = parsed.text
        lines = import_lines(index.import_statements)
        _IMPORTS[path] = (len(text), hash(text), lines)


# (catalog, config, project): `project.records` off, the run keeps no cache
_WORKER: tuple[MsgCatalog, Config, Project] | None = None
# a run with launch files: every checked file's import statements
# (`launchcheck.Imports`, plain data), which their reading (`launchcheck.LaunchRun`)
# then uses, so a node's code is not parsed again for them (dropped once they are
# read: `_launches`); the launch files' trees are not kept (their reading parses
# them, one at a time)
_READS_LAUNCHES = False
_IMPORTS: Imports = {}


def _start_worker(
    interfaces: _Interfaces | None, config: Config, records: bool
) -> None:
    """In a worker: the same interface files as the main process (a forked worker
    has the main process's catalog already: `interfaces` is None); Ctrl-C is the
    main process's to handle (it ends the workers), so no traceback here."""
    global _WORKER
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    if _WORKER is not None:  # forked: what the main process knows is not news
        _WORKER[2].index.handed_out()
        _WORKER[0].fresh_digests()
    if interfaces is not None:
        catalog = _catalog(interfaces, config)
        project = make_project(list(interfaces.roots), config, catalog)
        project.records = records
        _WORKER = (catalog, config, project)


def _worker_check(chunk: list[tuple[Path, bytes | None]]) -> list[FileResult]:
    assert _WORKER is not None
    catalog, config, project = _WORKER
    project.expect([path for path, _ in chunk])
    results = [_check_one(path, data, catalog, config, project) for path, data in chunk]
    for result in results:
        if result.parameters is not None:
            result.parameters = _portable(result.parameters)
    if results and project.records:  # for the cache, which the main process saves
        results[-1].answers = project.index.fresh()
        results[-1].digests = catalog.fresh_digests()
    return results


def _portable(parameters: ParamSummary) -> ParamSummary | None:
    """A worker's parameter summary as the main process gets it: without `by_node`
    (ids of this process's nodes, read only by the analysis), so that paramcheck
    does not parse the file again (0.6 s of a 4.6 s `-j 2` run on corpus2); None,
    and so parsed there, if it does not pickle."""
    import dataclasses
    import pickle

    portable = dataclasses.replace(parameters, by_node={})
    try:
        pickle.dumps(portable)
    except Exception:  # an object of the analysis in it: paramcheck parses the file
        return None
    return portable


def default_jobs() -> int:
    """The cores this process may use, its control group's CPU quota counted
    (`cores`): `-j` is never more."""
    from robotfix.cores import available

    return available()
