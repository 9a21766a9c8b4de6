"""Per-file results under `.robotfix_cache/`, as ruff and mypy keep them.

An entry is reused only when the file's bytes, the path it was named by, its
per-file ignores, the run key (RobotFix's version and a digest of its own files,
the settings that change results, the unit and message libraries), the resolved
definition of every message type the file looked up (`MsgCatalog.fingerprint_types`)
and the fingerprint of everything it consulted of other modules
(`project/summary.py`: each module asked for, whose fingerprint holds what building
its summary consulted, each member of one looked up) are all unchanged: changing,
adding or moving one `.msg` re-checks exactly the files it can affect, a changed
helper module re-checks the files that import it only when a member they read of it
changed, and a cached run prints what an uncached one prints, byte for byte.
The fingerprints of summaries (the module's and each member's) are kept too, by
the hash of their file's bytes, so that a cached run over an unchanged tree parses
nothing.

Stat fast path (as ruff, mypy and git do): the hash of every file a run read is
kept with its stamp (`fs.stamp`: mtime_ns, ctime_ns, inode, device, size, mode),
and a file whose stamp is unchanged is not read again; any difference (a `touch`,
an editor's atomic save, an in-place rewrite that restores the size and the mtime,
as `cp -p` does: the ctime changes all the same) costs one read and hash, never a
wrong result. A file changed (mtime or ctime) within `RACY_NS` of being hashed is
not trusted by stat (git's "racily clean" rule): it could change again within the
same tick. The parameter files' diagnostics (`paramcheck.py`) are
kept too, under a key that hashes every input they depend on (`params_key`), and
so is the discovery, with the trace of what it looked at (`discovery.Trace`): an
unchanged tree is stat'ed, not walked.

The file is data only: JSON, read with `json.loads` into plain values, never
unpickled, imported or run. A missing, corrupt, foreign or ill-typed cache is
ignored and rebuilt: each part is used only when it is exactly what this module
writes, with the types it writes and strings that encode as UTF-8 (a lone surrogate
only where a path may hold one, as `os.fsdecode` gives a non-UTF-8 name); a part
that is not is dropped, and a check that fails in a run that used the cache is done
again without it (`run.py`), the cache then dropped. A cache that cannot be written
only costs speed. `results.json` is read only if it is a regular
file (`fs.read_regular`) and written atomically through a fresh temporary file
(`fs.atomic_write`), never through a symlink. Entries of files that no longer exist,
or that lie under the checked paths but were not checked, are dropped when saving.
"""

from __future__ import annotations

import functools
import hashlib
import json
import os
import stat
import sys
import time
from collections.abc import Collection, Iterable, Iterator
from pathlib import Path
from typing import TYPE_CHECKING, Any

from robotfix import __version__, fs, rules
from robotfix.config import Config
from robotfix.diagnostics import Diagnostic, Note, Severity, Span
from robotfix.discovery import Discovery, Trace
from robotfix.disk_cache import install_key, is_text
from robotfix.fs import RACY_NS
from robotfix.ros.graph.model import load as load_graph

if TYPE_CHECKING:
    from robotfix.project.summary import Known, Project
    from robotfix.ros.catalog import MsgCatalog, Outline

# an interface problem before `messages.interface_problem`: its diagnostic, the
# package no type of which is known (if so), the types of its file
InterfaceProblem = tuple[Diagnostic, "str | None", tuple[str, ...]]
FORMAT = 10  # 9: an entry holds the file's graph endpoints; 10: "reads" as text
# which parameter-related words a file mentions (`paramcheck.MENTIONS`, all layouts),
# kept with its hash so that an unchanged file need not be read to know
MENTION_WORDS = (b"declare_parameter", b"get_parameter", b"ParamListener", b"rospy")
MAX_BYTES = 512 * 1024 * 1024  # results.json of ~4 million files
MAX_INT = 2**31  # lines and columns; anything larger is not ours
STAMP = 6  # the length of an `fs.stamp`, which begins a stat record
TRACED_BYTES = 1024 * 1024  # larger files a trace stamped are not hashed for it
GITIGNORE = b"# Created by robotfix\n*\n"


# what of RobotFix's own files decides results (code, stubs, grammar, data tables)
_OWN_SUFFIXES = frozenset({".py", ".pyi", ".lark", ".json", ".toml"})


@functools.lru_cache(maxsize=1)
def own_digest() -> str:
    """A digest of RobotFix's own files: installed from a checkout, every commit is
    version 0.1.0, so the version alone would replay results of older code. Their
    stamps, not their bytes (a run starts on every save): a pull or a reinstall
    writes the files, which moves their ctime."""
    package = Path(__file__).resolve().parent
    found: list[tuple[str, ...]] = []  # each file's parts below the package
    for folder, folders, files in os.walk(package):  # (no symlinked folder, as rglob)
        folders[:] = [f for f in folders if f != "__pycache__"]  # bytecode: not read
        where = Path(folder).relative_to(package).parts
        found += [(*where, n) for n in files + folders if _own_suffix(n)]
    digest = hashlib.blake2b(digest_size=16)
    for parts in sorted(found):  # the order of `sorted(Path, ...)`: by parts
        stamp = fs.stamp(os.path.join(package, *parts))
        digest.update(f"{'/'.join(parts)} {stamp}".encode())
    return digest.hexdigest()


def _own_suffix(name: str) -> bool:
    return os.path.splitext(name)[1] in _OWN_SUFFIXES


def run_key(config: Config) -> str:
    parts = [
        f"robotfix {__version__} {own_digest()}",
        f"format {FORMAT}",
        f"python {sys.version_info[0]}.{sys.version_info[1]}",
        f"rep103 {config.rep103}",
        f"unit suffixes {config.unit_suffixes}",
        f"distro {config.ros_distro}",
        install_key("pint", ""),
        install_key("rosbags", ""),
        install_key("z3", ""),
    ]
    if config.stub_paths:  # results depend on what the user's stubs say
        from robotfix.stubs.load import stub_set

        parts.append(f"stubs {stub_set(config.stub_paths).fingerprint()}")
    return hashlib.sha256("\n".join(parts).encode()).hexdigest()


def entry_key(path: str | os.PathLike[str]) -> str:
    """One entry per file, whatever the cwd or spelling it was named by."""
    try:
        return os.path.abspath(path)
    except OSError:  # the cwd was deleted
        return str(path)


class ResultCache:
    def __init__(self, folder: Path, key: str, trusted: bool = True) -> None:
        """`trusted=False`: the file is not read (it is rewritten on `save`)."""
        self.path = folder / "results.json"
        self.key = key
        self._entries: dict[str, Any] = {}
        self._valid: dict[str, Any] = {}  # entries found valid (`_valid_entry`)
        # module file -> [sha256 of its bytes, its summary's fingerprint, its
        # members' fingerprints, what building it consulted]
        self.summaries: dict[str, Known] = {}
        # file -> [*fs.stamp, sha256, mentions]: `sha`'s memory
        self._stats: dict[str, list[Any]] = {}
        self._seen_stats: dict[str, list[Any]] = {}  # this run's, saved
        # an earlier record of the same bytes kept instead of a record too young
        # to trust (`_stat_record`): it still says what they were at its stamp
        self._older: dict[str, list[Any]] = {}
        self._bytes: dict[str, bytes] = {}  # the last file `sha` read, to `take`
        self._params: tuple[str, list[Any]] | None = None
        # the parameter check by part (`param_part`): "fixed" -> [key, findings,
        # RF602], a launch file -> [key, its entries' findings]
        self._parts: dict[str, Any] = {}
        # a launch file -> [key, its trace, its reading] (`launch_read`): kept
        # as the JSON text it was saved as until a run reads a launch file
        # (`_reads`; 2.7 MB of the corpus's 11.8: 37 ms to parse, 3.5 as text)
        self._reads_text: str | None = None
        self._reads_found: dict[str, Any] | None = None
        # C++ file -> [sha256, its graph endpoints dumped, or None]: what
        # `graphcheck` read of it; this run's, saved (`put_cpp`), with those of
        # files that still exist (a run whose stage holds reads none: `prune`)
        self._cpp: dict[str, Any] = {}
        self._seen_cpp: dict[str, Any] = {}
        self._catalog: dict[str, Any] | None = None
        self._discovery: dict[str, Any] | None = None  # key, trace, what was found
        # the launch files' reading and the graph's findings (`stage`)
        self._stage: dict[str, Any] | None = None
        # the module index's answers with what they depend on (`ModuleIndex.keep`)
        self._resolution: dict[str, Any] | None = None
        self._traced: list[Any] = []  # the traces kept by this run (`_record`)
        self._dirty = False
        self._dropped = False  # `drop`: nothing of this cache is saved
        self._keys: dict[object, str] = {}  # `_key`'s memory
        if not trusted:
            self._dirty = True
            return
        try:
            raw = fs.read_regular(self.path, MAX_BYTES, follow=False)
            data = json.loads(raw)
        except (fs.UnreadableError, ValueError, RecursionError):
            return
        # `save` writes ASCII (json.dumps escapes the rest): in such a file a lone
        # surrogate can only be a `\udXXX` escape, so without one every string is
        # text, and the parts only `_names_only` checks need no walk
        plain = raw.isascii() and b"\\ud" not in raw and b"\\uD" not in raw
        if (
            isinstance(data, dict)
            and data.get("key") == key
            and isinstance(data.get("entries"), dict)
        ):
            self._entries = data["entries"]
            found = data.get("summaries")
            if isinstance(found, dict):
                self.summaries = {
                    k: (v[0], v[1], v[2], v[3])
                    for k, v in found.items()
                    if _name(k)
                    and isinstance(v, list)
                    and len(v) == 4
                    and is_text(v[0])
                    and is_text(v[1])
                    and isinstance(v[2], dict)
                    and _texts(v[2])
                    and _texts(v[2].values())
                    and isinstance(v[3], dict)
                    and _texts(v[3], "surrogateescape")
                    and _texts(v[3].values())
                }
            stats = data.get("stats")
            if isinstance(stats, dict):
                self._stats = {
                    k: v for k, v in stats.items() if _name(k) and _valid_stat(v)
                }
            # read by `discovery.Trace` and `ModuleIndex.restore`, which check
            # their shapes: here, that every string is one this cache can hold
            found_discovery = data.get("discovery")
            if isinstance(found_discovery, dict) and (
                plain or _names_only(found_discovery)
            ):
                self._discovery = found_discovery
            found_resolution = data.get("resolution")
            if isinstance(found_resolution, dict) and (
                plain or _names_only(found_resolution)
            ):
                self._resolution = found_resolution
            found_stage = data.get("stage")
            if isinstance(found_stage, dict) and (plain or _names_only(found_stage)):
                self._stage = found_stage
            found_catalog = data.get("catalog")
            if isinstance(found_catalog, dict):
                self._catalog = found_catalog
            params = data.get("params")
            if (
                isinstance(params, list)
                and len(params) == 2
                and is_text(params[0])
                and isinstance(params[1], list)
                and all(_valid_diagnostic(d) for d in params[1])
            ):
                self._params = (params[0], params[1])
            reads = data.get("reads")
            if isinstance(reads, str):
                self._reads_text = reads  # parsed when first needed (`_reads`)
            parts = data.get("parts")
            if isinstance(parts, dict):
                self._parts = parts  # each entry checked when read (`param_part`)
            cpp = data.get("cpp")
            if isinstance(cpp, dict):
                self._cpp = cpp  # each entry checked when read (`cpp_graph`)

    def _key(self, path: str | os.PathLike[str]) -> str:
        """`entry_key`, once a name: a run names a file many times (its stat, its
        bytes, its entry), the cwd stays (a relative name's `abspath` asks it)."""
        key = self._keys.get(path)
        if key is None:
            key = self._keys[path] = entry_key(path)
        return key

    @property
    def _reads(self) -> dict[str, Any]:
        """The kept launch files' readings, parsed from their text when first
        needed (a run whose stage holds reads none); each entry is checked when
        read (`launch_read`), every string here (as `__init__` does the rest)."""
        if self._reads_found is None:
            text, self._reads_text = self._reads_text, None
            found: Any = None
            if text is not None:
                try:
                    found = json.loads(text)
                except (ValueError, RecursionError):
                    found = None
            plain = (
                text is not None
                and text.isascii()
                and "\\ud" not in text
                and "\\uD" not in text
            )
            if not (isinstance(found, dict) and (plain or _names_only(found))):
                found = {}
            self._reads_found = found
        return self._reads_found

    # -- the stat fast path ----------------------------------------------------
    def sha(self, path: Path) -> str | None:
        """The sha256 of the file's bytes; from the stat when it is unchanged since
        the hash was taken, else read (then `take` hands the bytes over). None when
        the file cannot be read (`fs.read_regular` says why)."""
        known = self._stat_record(path)
        return known[STAMP] if known is not None else None

    def mentions(self, path: Path) -> int | None:
        """Which of `MENTION_WORDS` the file contains (a bit each), as `sha`."""
        known = self._stat_record(path)
        return known[STAMP + 1] if known is not None else None

    def take(self, path: Path) -> bytes:
        """The bytes `sha` read (once), or the file's bytes now."""
        data = self._bytes.pop(self._key(path), None)
        return data if data is not None else fs.read_regular(path)

    def _stat_record(self, path: Path) -> list[Any] | None:
        key = self._key(path)
        if key in self._seen_stats:
            return self._seen_stats[key]
        stamp = fs.stamp(path)
        if stamp is None:
            return None
        known = self._stats.get(key)
        if known is not None and known[:STAMP] == stamp:
            self._seen_stats[key] = known
            return known
        try:
            data = fs.read_regular(path)
        except fs.UnreadableError:
            return None
        self._bytes = {key: data}  # the last file read only: memory stays flat
        mentions = sum(1 << i for i, w in enumerate(MENTION_WORDS) if w in data)
        record = [*stamp, hashlib.sha256(data).hexdigest(), mentions]
        if len(data) != stamp[4] or time.time_ns() - max(stamp[:2]) < RACY_NS:
            record[0] = -1  # changed while read, or too recent: never matches
            if known is not None and known[0] != -1 and known[STAMP] == record[STAMP]:
                self._older[key] = known  # for `same_bytes` in the next run
        self._seen_stats[key] = record
        self._dirty = True
        return record

    def same_bytes(self, name: str, was: list[int], now: list[int]) -> list[int] | None:
        """Whether the file `name`, whose stamp was `was` when a trace noted it
        and is `now`, holds the bytes it held then (`Trace.holds`): an earlier
        run hashed it at that very stamp, and it hashes alike now, with the same
        device, size and mode (what a walk or a reading sees besides its bytes);
        its mtime, ctime and inode may differ, as after a `touch`, a checkout
        that wrote it alike or a CI cache restored onto a fresh clone. The
        stamp the trace keeps for it then: `now`, or `was` while `now` is too
        recent to trust (`_stat_record`; the next run hashes it again); None
        when it differs, or is a folder or a file no run hashed."""
        if was[3:] != now[3:]:
            return None
        known = self._stats.get(self._key(name))
        if known is None or known[:STAMP] != was:
            return None
        record = self._stat_record(Path(name))
        if record is None or record[STAMP] != known[STAMP]:
            return None
        return now if record[:STAMP] == now else was

    # -- the catalog -------------------------------------------------------------
    def catalog(
        self, key: str
    ) -> (
        tuple[
            dict[str, tuple[str, tuple[str, ...]]],
            list[InterfaceProblem],
            Outline | None,
        ]
        | None
    ):
        """An earlier run's catalog digests, interface problems and outline
        (`MsgCatalog.outline`, None if it has none or it does not read), for the
        same interface files (`key`); None when there is none or it does not read."""
        raw = self._catalog
        if raw is None or raw.get("key") != key:
            return None
        digests, problems = raw.get("digests"), raw.get("problems")
        if not (isinstance(digests, dict) and isinstance(problems, list)):
            return None
        table: dict[str, tuple[str, tuple[str, ...]]] = {}
        for name, value in digests.items():
            if not (
                is_text(name)
                and isinstance(value, list)
                and len(value) == 2
                and is_text(value[0])
                and isinstance(value[1], list)
                and _texts(value[1])
            ):
                return None
            table[name] = (value[0], tuple(value[1]))
        found: list[InterfaceProblem] = []
        for item in problems:
            if not (
                isinstance(item, list)
                and len(item) == 3
                and _valid_diagnostic(item[0])
                and (item[1] is None or is_text(item[1]))
                and isinstance(item[2], list)
                and all(is_text(t) for t in item[2])
            ):
                return None
            found.append((_load(item[0]), item[1], tuple(item[2])))
        return table, found, _load_outline(raw.get("outline"))

    def put_catalog(
        self,
        key: str,
        table: dict[str, tuple[str, tuple[str, ...]]],
        problems: list[InterfaceProblem],
        outline: Outline | None = None,
    ) -> None:
        raw = {
            "key": key,
            "digests": {k: [v[0], list(v[1])] for k, v in sorted(table.items())},
            "problems": [
                [_dump(d), absent, list(types)] for d, absent, types in problems
            ],
            "outline": (
                [[p, d, [[n, f] for n, f in ss]] for p, d, ss in outline]
                if outline is not None
                else None
            ),
        }
        if raw != self._catalog:
            self._catalog = raw
            self._dirty = True

    # -- discovery ---------------------------------------------------------------
    def discovery(self, key: str) -> Discovery | None:
        """What an earlier discovery with the same `key` (`discovery_key`) found,
        when everything it looked at on disk is as it was (`Trace.holds`); its
        `installed` is left for the caller (the environment, not the disk)."""
        raw = self._discovery
        if raw is None or raw.get("key") != key:
            return None
        trace = Trace.from_json(raw.get("trace"))
        found = _load_discovery(raw.get("found"))
        if trace is None or found is None or not trace.holds(self.same_bytes):
            return None
        if trace.renewed:
            self._discovery = {**raw, "trace": trace.to_json()}
            self._dirty = True
        return found

    def put_discovery(self, key: str, found: Discovery, trace: Trace) -> None:
        """Keep a discovery with its trace (not one the trace cannot vouch for)."""
        raw = (
            None
            if trace.spoiled
            else {"key": key, "trace": trace.to_json(), "found": _dump_discovery(found)}
        )
        if raw is not None:
            self._traced.append(raw["trace"])
        if raw != self._discovery:
            self._discovery = raw
            self._dirty = True

    # -- the launch files and the graph ----------------------------------------
    def stage(self, key: str) -> tuple[list[str], list[Diagnostic]] | None:
        """What `put_stage` kept under `key` (`run._stage_key`: the launch files,
        the code files, the graph endpoints), when every file the launch files'
        reading and the graph's check read, and every path they probed, is as it
        was (`Trace.holds`): the files the launch check depends on
        (`LaunchRun.touched`) and the graph's findings."""
        raw = self._stage
        if raw is None or raw.get("key") != key:
            return None
        trace = Trace.from_json(raw.get("trace"))
        touched, graph = raw.get("touched"), raw.get("graph")
        if not (
            trace is not None
            and isinstance(touched, list)
            and all(_name(t) for t in touched)
            and isinstance(graph, list)
            and all(_valid_diagnostic(d) for d in graph)
            and trace.holds(self.same_bytes)
        ):
            return None
        if trace.renewed:
            self._stage = {**raw, "trace": trace.to_json()}
            self._dirty = True
            self._renew_reads()
        return touched, [_load(d) for d in graph]

    def _renew_reads(self) -> None:
        """The kept launch files' readings renewed as the stage was (a run whose
        stage holds reads none of them; left with the old stamps, each would be
        read again the next time the stage does not hold)."""
        for path, entry in self._reads.items():
            if not (isinstance(entry, list) and len(entry) == 3):
                continue
            trace = Trace.from_json(entry[1])
            if trace is not None and trace.holds(self.same_bytes) and trace.renewed:
                self._reads[path] = [entry[0], trace.to_json(), entry[2]]

    def put_stage(
        self, key: str, trace: Trace, touched: list[str], graph: list[Diagnostic]
    ) -> None:
        """Keep a stage with its trace (not one the trace cannot vouch for)."""
        raw = (
            None
            if trace.spoiled
            else {
                "key": key,
                "trace": trace.to_json(),
                "touched": touched,
                "graph": [_dump(d) for d in graph],
            }
        )
        if raw is not None:
            self._traced.append(raw["trace"])
        if raw != self._stage:
            self._stage = raw
            self._dirty = True

    # -- the module index ------------------------------------------------------
    def resolution(self) -> dict[str, Any] | None:
        """What an earlier run's `ModuleIndex.keep` wrote (its `restore` checks it)."""
        return self._resolution

    def put_resolution(self, raw: dict[str, Any] | None) -> None:
        if raw is not self._resolution and raw != self._resolution:
            self._resolution = raw
            self._dirty = True

    # -- parameter files -------------------------------------------------------
    def params(self, key: str) -> list[Diagnostic] | None:
        if self._params is None or self._params[0] != key:
            return None
        return [_load(d) for d in self._params[1]]

    def put_params(self, key: str, diagnostics: list[Diagnostic]) -> None:
        self._params = (key, [_dump(d) for d in diagnostics])
        self._dirty = True

    def launch_read(self, path: str, context: str) -> tuple[Trace, Any] | None:
        """A launch file's reading kept by `put_launch_read` under `context`:
        its trace, and [problem or None, [[entry dumped, files]...], files read]
        (the entries for `ros.launch.model.load`, which checks them); None when
        not exactly that."""
        entry = self._reads.get(path)
        if not (isinstance(entry, list) and len(entry) == 3 and entry[0] == context):
            return None
        trace = Trace.from_json(entry[1])
        raw = entry[2]
        if not (trace is not None and isinstance(raw, list) and len(raw) == 3):
            return None
        problem, started, reading = raw
        if not (
            (
                problem is None
                or (
                    isinstance(problem, list)
                    and len(problem) == 3
                    and _name(problem[0])
                    and _number(problem[1], 1)
                    and _number(problem[2], 0)
                )
            )
            and isinstance(started, list)
            and all(
                isinstance(s, list)
                and len(s) == 2
                and isinstance(s[1], list)
                and all(_name(f) for f in s[1])
                for s in started
            )
            and isinstance(reading, list)
            and all(_name(f) for f in reading)
        ):
            return None
        found = tuple(problem) if problem is not None else None
        return trace, [found, started, reading]

    def put_launch_read(self, path: str, context: str, trace: Trace, raw: Any) -> None:
        self._reads[path] = [context, trace.to_json(), raw]
        self._traced.append(self._reads[path][1])
        self._dirty = True

    def renew_launch_read(self, path: str, trace: Trace) -> None:
        """A kept reading's trace whose stamps `holds` renewed (`same_bytes`)."""
        entry = self._reads[path]
        self._reads[path] = [entry[0], trace.to_json(), entry[2]]
        self._dirty = True

    def param_part(self, name: str, key: str) -> list[list[Diagnostic]] | None:
        """A part of the parameter check (`run._ParamParts`) kept under `key`:
        its lists of findings."""
        entry = self._parts.get(name)
        if not (
            isinstance(entry, list)
            and len(entry) >= 2
            and entry[0] == key
            and all(
                isinstance(found, list) and all(_valid_diagnostic(d) for d in found)
                for found in entry[1:]
            )
        ):
            return None
        return [[_load(d) for d in found] for found in entry[1:]]

    def put_param_part(self, name: str, key: str, *found: list[Diagnostic]) -> None:
        self._parts[name] = [key, *([_dump(d) for d in one] for one in found)]
        self._dirty = True

    # -- C++ files' graph endpoints ---------------------------------------------
    def cpp_graph(self, path: Path, digest: str) -> tuple[bool, Any]:
        """(known, the endpoints dumped or None) of a C++ file whose bytes hash
        to `digest`, as `put_cpp` kept them."""
        key = self._key(path)
        entry = self._cpp.get(key)
        if not (
            isinstance(entry, list)
            and len(entry) == 2
            and entry[0] == digest
            and (entry[1] is None or load_graph(entry[1]) is not None)
        ):
            return False, None
        self._seen_cpp[key] = entry
        return True, entry[1]

    def put_cpp(self, path: Path, digest: str, graph: Any) -> None:
        self._seen_cpp[self._key(path)] = [digest, graph]
        self._dirty = True

    def get(
        self,
        path: Path,
        data: bytes | str,
        config: Config,
        catalog: MsgCatalog,
        project: Project | None = None,
    ) -> list[Diagnostic] | None:
        """The cached diagnostics of this file (`data`: its bytes, or their sha256
        from `sha`), or None when they may differ from a fresh check (or the entry
        is not exactly what `put` writes)."""
        entry = self._entry(path)
        if entry is None:
            return None
        if entry["file"] != _file_key(data, path, config):
            return None
        if entry["catalog"] != catalog.fingerprint_types(entry["types"]):
            return None
        spelled = os.fspath(path)
        for key, fingerprint in entry["modules"].items():
            if project is None:
                now = ""
            elif key[:1] == "\0":  # consulted from this file itself (`put`)
                now = project.fingerprint(spelled + key)
            else:
                now = project.fingerprint(key)
            if now != fingerprint:
                return None
        return [_load(d) for d in entry["diagnostics"]]

    def consulted(self, path: Path) -> list[tuple[str, str]]:
        """What the cached check of this file consulted of other modules (each
        record with its fingerprint then), sorted; [] without a valid entry."""
        entry = self._entry(path)
        return sorted(entry["modules"].items()) if entry is not None else []

    def graph(self, path: Path) -> list[Any] | None:
        """The graph endpoints the cached check of this file found (dumped)."""
        entry = self._entry(path)
        return entry["graph"] if entry is not None else None

    def types(self, path: Path) -> list[str]:
        """The message types the cached check of this file looked up."""
        entry = self._entry(path)
        return list(entry["types"]) if entry is not None else []

    def _entry(self, path: Path) -> dict[str, Any] | None:
        """This file's entry, if it is exactly what `put` writes (checked once)."""
        name = self._key(path)
        entry: Any = self._entries.get(name)
        if entry is None or self._valid.get(name) is not entry:
            if not isinstance(entry, dict) or not _valid_entry(entry):
                return None
            self._valid[name] = entry
        return entry  # type: ignore[no-any-return]

    def drop(self) -> None:
        """Forget all of this cache, and keep nothing of this run's either: a
        check failed where the cache's state may be the cause, so the next run
        starts from an empty cache."""
        self._dropped = self._dirty = True

    def put(
        self,
        path: Path,
        data: bytes,
        config: Config,
        diagnostics: list[Diagnostic],
        types: list[str],
        fingerprint: str,
        modules: dict[str, str] | None = None,
        graph: list[Any] | None = None,
    ) -> None:
        """Remember a fresh result; `fingerprint` is the catalog's
        `fingerprint_types(types)` as seen by the check that found `diagnostics`."""
        # a record made from this file itself (most are) is kept without its
        # file's name: `results.json` is a third smaller, read and written faster
        own = os.fspath(path) + "\0"
        cut = len(own) - 1
        kept = {
            key[cut:] if key.startswith(own) else key: value
            for key, value in (modules or {}).items()
        }
        self._entries[self._key(path)] = {
            "file": _file_key(data, path, config),
            "types": sorted(types),
            "catalog": fingerprint,
            "modules": dict(sorted(kept.items())),
            "diagnostics": [_dump(d) for d in diagnostics],
            "graph": graph,  # its graph endpoints (`ros.graph.model.dump`)
        }
        self._dirty = True

    def remember_summaries(self, built: dict[str, Known]) -> None:
        """Fingerprints of summaries built in this run, by their file's hash."""
        for path, known in built.items():
            if self.summaries.get(path) != known:
                self.summaries[path] = known
                self._dirty = True

    def prune(self, checked: Iterable[Path], files: Iterable[Path]) -> None:
        """Forget files that were not part of this run although they lie under one
        of the `checked` paths (deleted, renamed, now excluded), and files that no
        longer exist anywhere."""
        roots = {self._key(p) for p in checked}
        prefixes = tuple(r.rstrip(os.sep) + os.sep for r in roots)
        seen = {self._key(f) for f in files}
        stale = [
            name
            for name in self._entries
            if name not in seen
            and (name in roots or name.startswith(prefixes) or not os.path.isfile(name))
        ]
        for name in stale:
            del self._entries[name]
        for trace in self._traced:  # kept by this run: its files hashed
            self._record(trace)
        dropped = [
            name
            for name in self._stats
            if name not in self._seen_stats
            and (name.startswith(prefixes) or not os.path.isfile(name))
        ]
        if dropped:  # not those a kept trace stamped (`same_bytes`)
            traced = self._traced_files()
            dropped = [name for name in dropped if name not in traced]
        for name in dropped:
            del self._stats[name]
        stale += dropped
        gone = [name for name in self.summaries if not os.path.isfile(name)]
        for name in gone:
            del self.summaries[name]
        stale += gone
        # C++ files no longer there (the others are kept though this run read
        # none of them: the next run that needs them parses none again)
        gone_cpp = [
            name
            for name in self._cpp
            if name not in self._seen_cpp and not os.path.isfile(name)
        ]
        for name in gone_cpp:
            del self._cpp[name]
        stale += gone_cpp
        # launch files' readings (when this run looked at them) and parts of
        # deleted launch files
        readings = [] if self._reads_found is None else [(self._reads_found, "")]
        for kept, prefix in (*readings, (self._parts, "launch:")):
            dropped = [
                name
                for name in kept
                if name.startswith(prefix)
                and name != "fixed"
                and not os.path.isfile(name[len(prefix) :])
            ]
            for name in dropped:
                del kept[name]
            stale += dropped
        self._dirty = self._dirty or bool(stale)

    def _record(self, trace: Any) -> None:
        """Each file a trace this run keeps stamped hashed now, if no run has
        at that stamp (for `same_bytes`): a file read only by the walk or the
        launch files' reading (a package.xml, a CMakeLists.txt, the first line
        of a file without an extension), at most `TRACED_BYTES` long (a rosbag
        without an extension is not read for it)."""
        for name, found in _traced_stamps(trace):
            key = self._key(name)
            if key not in self._seen_stats:
                known = self._stats.get(key)
                if known is None or known[:STAMP] != found:
                    self._stat_record(Path(name))

    def _traced_files(self) -> set[str]:
        """The files the kept traces stamped (`_record`)."""
        traces: list[Any] = [self._discovery, self._stage]
        traces += [e for e in self._reads.values() if isinstance(e, list) and e[1:]]
        return {
            self._key(name)
            for t in traces
            if t is not None
            for name, _ in _traced_stamps(t["trace"] if isinstance(t, dict) else t[1])
        }

    def save(self) -> None:
        if not self._dirty:
            return
        folder = self.path.parent
        payload: dict[str, Any] = {
            "key": self.key,
            "entries": self._entries,
            "summaries": {
                k: [v[0], v[1], dict(sorted(v[2].items())), dict(sorted(v[3].items()))]
                for k, v in sorted(self.summaries.items())
            },
            "stats": {**self._stats, **self._seen_stats, **self._older},
            "params": list(self._params) if self._params is not None else None,
            "parts": self._parts,
            "reads": (
                self._reads_text
                if self._reads_found is None and self._reads_text is not None
                else json.dumps(self._reads, sort_keys=True, separators=(",", ":"))
            ),
            "catalog": self._catalog,
            "discovery": self._discovery,
            "stage": self._stage,
            "resolution": self._resolution,
            "cpp": {**self._cpp, **self._seen_cpp},
        }
        if self._dropped:
            payload = {"key": self.key, "entries": {}}
        try:
            folder.mkdir(parents=True, exist_ok=True)
            fs.create_exclusive(folder / ".gitignore", GITIGNORE)
            # compact: 4% fewer bytes, read and written on every run (6.5 MB
            # for 235k lines: 0.06 s to write with spaces, 0.04 s without)
            text = json.dumps(payload, sort_keys=True, separators=(",", ":"))
            fs.atomic_write(self.path, text.encode())
            self._dirty = False
        except (OSError, ValueError):
            pass


def discovery_key(paths: list[Path], config: Config) -> str | None:
    """Everything a discovery depends on besides what its trace notes: the paths
    as spelled, the current folder when one of them is relative, and the settings
    it reads (`Config.excluded` resolves the root); None when the current folder
    is gone."""
    spelled = [*paths, config.root, *config.msg_paths]
    try:
        parts = [
            f"discovery {FORMAT}",
            "" if all(os.path.isabs(p) for p in spelled) else os.getcwd(),
            os.fspath(config.root),
            os.path.realpath(config.root),
            [os.fspath(p) for p in paths],
            list(config.exclude),
            [os.fspath(m) for m in config.msg_paths],
        ]
    except (OSError, ValueError):
        return None
    text = json.dumps(parts).encode("utf-8", "surrogateescape")
    return hashlib.sha256(text).hexdigest()


_DISCOVERY_PATHS = (
    "python_files",
    "interface_files",
    "package_interface_files",
    "parameter_files",
    "named_parameter_files",
    "parameter_definitions",
    "summary_files",
    "launch_files",
    "cpp_files",
)


def _dump_discovery(found: Discovery) -> dict[str, Any]:
    raw: dict[str, Any] = {
        name: [os.fspath(p) for p in getattr(found, name)] for name in _DISCOVERY_PATHS
    }
    raw["notices"] = [_dump(d) for d in found.notices]
    return raw


def _load_discovery(raw: Any) -> Discovery | None:
    """What `_dump_discovery` wrote; None when `raw` is not exactly that."""
    if not isinstance(raw, dict):
        return None
    found = Discovery()
    for name in _DISCOVERY_PATHS:
        paths = raw.get(name)
        if not (isinstance(paths, list) and all(isinstance(p, str) for p in paths)):
            return None
        setattr(found, name, [Path(p) for p in paths])
    notices = raw.get("notices")
    if not (isinstance(notices, list) and all(_valid_diagnostic(d) for d in notices)):
        return None
    found.notices = [_load(d) for d in notices]
    return found


def _file_key(data: bytes | str, path: Path, config: Config) -> str:
    """`data`: the file's bytes or their sha256 (the same key either way)."""
    digest = data if isinstance(data, str) else hashlib.sha256(data).hexdigest()
    ignored = ",".join(sorted(config.ignored_codes(path)))
    spelled = os.fsencode(path)
    return hashlib.sha256(
        b"\0".join(
            [digest.encode(), spelled, ignored.encode("utf-8", "surrogateescape")]
        )
    ).hexdigest()


def _dump(d: Diagnostic) -> list[Any]:
    span = [d.span.line, d.span.col, d.span.end_line, d.span.end_col]
    notes = [[n.message, n.path, n.line] for n in d.notes]
    level = [] if d.level is None else [d.level.value]  # not the rule's severity
    return [d.code, d.path, span, d.message, notes, *level]


def _load(raw: list[Any]) -> Diagnostic:
    code, path, span, message, notes, *level = raw
    return Diagnostic(
        rules.ALL_RULES[code],
        path,
        Span(*span),
        message,
        tuple(Note(m, p, line) for m, p, line in notes),
        Severity(level[0]) if level else None,
    )


# -- the schema of an entry: exactly what `put` writes, with the types it writes ---
def _valid_entry(entry: Any) -> bool:
    return (
        isinstance(entry, dict)
        and is_text(entry.get("file"))
        and is_text(entry.get("catalog"))
        and isinstance(entry.get("types"), list)
        and _texts(entry["types"])
        and isinstance(entry.get("modules"), dict)
        and _texts(entry["modules"], "surrogateescape")
        and _texts(entry["modules"].values())
        and isinstance(entry.get("diagnostics"), list)
        and all(_valid_diagnostic(d) for d in entry["diagnostics"])
        and "graph" in entry
        and (entry["graph"] is None or load_graph(entry["graph"]) is not None)
    )


def _load_outline(raw: Any) -> Outline | None:
    """What `put_catalog` wrote of `MsgCatalog.outline`; None if not exactly that."""
    if not isinstance(raw, list):
        return None
    found: Outline = []
    for item in raw:
        if not (
            isinstance(item, list)
            and len(item) == 3
            and _name(item[0])
            and is_text(item[1])
            and isinstance(item[2], list)
            and all(
                isinstance(x, list)
                and len(x) == 2
                and is_text(x[0])
                and type(x[1]) is bool
                for x in item[2]
            )
        ):
            return None
        found.append((item[0], item[1], [(x[0], x[1]) for x in item[2]]))
    return found


def _traced_stamps(trace: Any) -> Iterator[tuple[str, list[int]]]:
    """The stamps of regular files of at most `TRACED_BYTES` a kept trace
    (`Trace.to_json`, unchecked) holds."""
    stamps = trace.get("stamps") if isinstance(trace, dict) else None
    for name, found in stamps.items() if isinstance(stamps, dict) else ():
        if (
            isinstance(name, str)
            and isinstance(found, list)
            and len(found) == STAMP
            and all(type(n) is int for n in found)
            and stat.S_ISREG(found[5])
            and found[4] <= TRACED_BYTES
        ):
            yield name, found


def _valid_stat(raw: Any) -> bool:
    return (
        isinstance(raw, list)
        and len(raw) == STAMP + 2
        and all(type(n) is int for n in raw[:STAMP])
        and is_text(raw[STAMP])
        and type(raw[STAMP + 1]) is int
    )


SEVERITIES = frozenset(s.value for s in Severity)


def _valid_diagnostic(raw: Any) -> bool:
    if not (isinstance(raw, list) and len(raw) in (5, 6)):
        return False
    code, path, span, message, notes, *level = raw
    return (
        all(v in SEVERITIES for v in level)
        and isinstance(code, str)
        and code in rules.ALL_RULES
        and _name(path)
        and isinstance(span, list)
        and len(span) == 4
        and all(_number(n, 0) for n in span)
        and span[0] >= 1
        and span[2] >= span[0]
        and _name(message)
        and isinstance(notes, list)
        and all(_valid_note(n) for n in notes)
    )


def _valid_note(raw: Any) -> bool:
    if not (isinstance(raw, list) and len(raw) == 3):
        return False
    message, path, line = raw
    return (
        _name(message)
        and (path is None or _name(path))
        and (line is None or _number(line, 1))
        and (path is None) == (line is None)  # a location, or none at all
    )


def _number(value: Any, least: int) -> bool:
    """An int (not a bool) in [least, MAX_INT)."""
    return type(value) is int and least <= value < MAX_INT


def _texts(values: Collection[Any], errors: str = "strict") -> bool:
    """`is_text` of each of `values` (`errors` as there): for the usual ASCII
    strings, one join and one test instead of a call each."""
    try:
        if "".join(values).isascii():
            return True
    except TypeError:  # not all of them strings
        return False
    return all(is_text(value, errors) for value in values)


def _name(value: Any) -> bool:
    """A path, or text that may quote one (a message): UTF-8, with at most the lone
    surrogates `os.fsdecode` gives the bytes of a non-UTF-8 name (surrogateescape)."""
    return is_text(value, "surrogateescape")


def _names_only(raw: Any) -> bool:
    """Every string in `raw` (keys too, at any depth) is a `_name`."""
    todo = [raw]
    while todo:
        item = todo.pop()
        if isinstance(item, dict):
            if not all(_name(k) for k in item):
                return False
            todo.extend(item.values())
        elif isinstance(item, list):
            todo.extend(item)
        elif isinstance(item, str) and not _name(item):
            return False
    return True
