"""`robotfix lsp`: diagnostics on open, change and save, hovers with units and
refinements, over stdio (`lsp/rpc.py`, the JSON-RPC layer; `lsp/documents.py`, the
open documents, synced incrementally). A thin adapter over `api`: no analysis here.

Interface files and settings come from the nearest configuration of each document
(`config.find`: all its settings, as a run gives that file) and from the ROS package
around it (`_interface_folders`). A catalog is rebuilt when an
interface file is added, removed or changed (its path, size, times or inode) or its
editor buffer changes, so an edited `.msg` counts before it is saved. An open
interface file shows its own problems. When one changes (typed, saved, closed, or
changed on disk: the server asks a client that allows it to watch interface files),
the open Python documents that use its types are checked again; when a Python module
is saved or changed on disk, the open documents that import it (see
`robotfix.dependents`); when a `.pyi` stub is, every open Python document, its
stubs read again. A document the editor never opened is read from disk only
through `fs.read_regular` (a FIFO or `/dev/zero` gets no answer, not a hang).

The modules a document imports are summarised once per catalog (`_project`), not on
every keystroke, and summarised again when a file they were read from, or a folder
around them, changes (stamps, as for interface files), or a Python file is saved or
reported changed.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterable
from functools import partial
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any

from robotfix import (
    __version__,
    api,
    config,
    dependents,
    discovery,
    fs,
    rulepages,
    source,
)
from robotfix.diagnostics import Diagnostic, Fix, Note, Severity
from robotfix.lsp import actions, rpc
from robotfix.lsp.documents import (
    Documents,
    InvalidChangeError,
    char,
    path_of,
    to_path,
)
from robotfix.ros.catalog import MsgCatalog
from robotfix.smt.memo import ProofMemo

if TYPE_CHECKING:
    from robotfix.project.summary import Project

SEVERITIES = {Severity.ERROR: 1, Severity.WARNING: 2, Severity.NOTE: 3}
LOG_ERROR = 1  # window/logMessage's MessageType.Error
SYNC_INCREMENTAL = 2  # TextDocumentSyncKind (documents.py says why)
INTERFACE_GLOB = "**/*.{msg,srv,action,pyi}"  # and the user's stubs
MAX_CATALOGS = 32  # catalogs kept (one per set of interface files and settings)
MAX_MEMOS = 8  # documents, most recently checked, whose proofs are kept
MAX_PROJECTS = 8  # module summaries kept, one set per catalog
QUICKFIX, REWRITE = "quickfix", "refactor.rewrite"  # CodeActionKind
AUTOMATIC = 2  # CodeActionTriggerKind: a client asking at a cursor move (a lightbulb)

# interface files and settings -> (their stat stamps and open buffers, the catalog)
_catalogs: dict[tuple[object, ...], tuple[tuple[object, ...], MsgCatalog]] = {}
_INSTALLED = discovery.install_space()
# document URI -> its verdicts by normalised VC, so a keystroke in one function does
# not prove the others again (`smt.memo`); least recently checked documents go first
_memos: dict[str, ProofMemo] = {}
# id of a catalog -> (the catalog, the project built with it, the stamps of the
# files and folders the project read)
_projects: dict[int, tuple[MsgCatalog, Project, dict[Path, tuple[object, ...]]]] = {}


class Session:
    """The server's side of one editor session: the connection (none in tests
    that only ask for a catalog), the open documents, what the client can do."""

    def __init__(self, endpoint: rpc.Endpoint | None = None) -> None:
        self.endpoint = endpoint
        self.documents = Documents()
        self.capabilities: dict[str, Any] = {}
        # URI -> the text last checked and its diagnostics, for code actions
        self.found: dict[str, tuple[str, list[Diagnostic]]] = {}
        self.verdicts: dict[str, actions.Verdicts] = {}  # URI -> fixes tried

    def related(self) -> bool:
        """Whether the client shows a diagnostic's notes as links of their own."""
        text = self.capabilities.get("textDocument")
        published = text.get("publishDiagnostics") if isinstance(text, dict) else None
        return (
            isinstance(published, dict) and published.get("relatedInformation") is True
        )

    def notify(self, method: str, params: object) -> None:
        if self.endpoint is not None:
            self.endpoint.notify(method, params)


def serve(reader: IO[bytes] | None = None, writer: IO[bytes] | None = None) -> int:
    """Serve one session over stdio (or the given streams); the exit code."""
    if writer is None:
        writer = sys.stdout.buffer
        sys.stdout = sys.stderr  # a stray print must not corrupt the protocol
    endpoint = rpc.Endpoint(reader or sys.stdin.buffer, writer)
    ls = Session(endpoint)
    endpoint.on_error = lambda message: _log_error(ls, message)
    for method, handler in REQUESTS.items():
        endpoint.requests[method] = _bind(ls, handler)
    for method, handler in NOTIFICATIONS.items():
        endpoint.notifications[method] = _bind(ls, handler)
    return endpoint.serve()


def _bind(ls: Session, handler: Callable[[Session, Any], Any]) -> rpc.Handler:
    def bound(params: Any) -> Any:
        try:
            return handler(ls, params)
        except InvalidChangeError as err:
            raise rpc.InvalidParamsError(str(err)) from None

    return bound


def _get(params: Any, *names: str) -> Any:
    """params[names[0]][names[1]]..., raising InvalidParamsError when it is missing."""
    value = params
    for name in names:
        if not isinstance(value, dict) or name not in value:
            raise rpc.InvalidParamsError(f"missing {'.'.join(names)}")
        value = value[name]
    return value


def _uri(params: Any) -> str:
    uri = _get(params, "textDocument", "uri")
    if not isinstance(uri, str):
        raise rpc.InvalidParamsError("textDocument.uri must be a string")
    return uri


def _interface_folders(path: Path, settings: config.Config) -> list[Path]:
    """Where the interface files of a document are, found as the CLI finds them for
    that one file: `msg-paths`, then its ROS package's msg/, srv/ and action/."""
    return list(settings.msg_paths) + api.ros_interface_folders([path])


def _settings(path: Path) -> config.Config:
    try:
        return config.load(path)
    except config.ConfigError:
        return config.Config()


def _catalog(ls: Session, path: Path) -> MsgCatalog:
    settings = _settings(path)
    files = api.interface_files(_interface_folders(path, settings))
    if _is_interface(path) and path not in files:
        files.append(path)  # a loose interface file still shows its own problems
    texts = _open_texts(ls, files)
    key = (
        tuple(files),
        settings.rep103,
        settings.ros_distro,
        settings.unit_suffixes,
        settings.python_paths,  # one module summary set per catalog (`_project`)
        id(_INSTALLED),  # its catalogs hold it: no other install space gets its id
    )
    stamp = (tuple(_stamp(file) for file in files), tuple(sorted(texts.items())))
    cached = _catalogs.get(key)
    if cached is not None and cached[0] == stamp:
        return cached[1]
    catalog = MsgCatalog(
        files,
        rep103=settings.rep103,
        unit_suffixes=settings.unit_suffixes,
        distro=settings.ros_distro,
        texts=texts,
        installed=_INSTALLED,  # the install space the editor's environment sourced
    )
    if len(_catalogs) >= MAX_CATALOGS:
        _catalogs.clear()
    _catalogs[key] = (stamp, catalog)
    return catalog


def _project(
    catalog: MsgCatalog, path: Path, settings: config.Config | None = None
) -> Project:
    """The module summaries for documents checked with `catalog`, kept across
    keystrokes. Built again when a file a summary was read from changes (its stamp)
    or a folder around one, or on `path`'s search path, does (a module added or
    removed); `_forget_projects` drops them all when a Python file is saved."""
    cached = _projects.get(id(catalog))
    if cached is not None and cached[0] is catalog:
        _, project, stamps = cached
        if all(_stamp(f) == stamp for f, stamp in stamps.items()):
            _record(project, stamps, path)
            return project
    project = api.make_project([], settings or config.Config(), catalog)
    if len(_projects) >= MAX_PROJECTS:
        _projects.clear()
    stamps = {}
    _projects[id(catalog)] = (catalog, project, stamps)
    _record(project, stamps, path)
    return project


def _record(
    project: Project, stamps: dict[Path, tuple[object, ...]], path: Path
) -> None:
    """Stamp what `project` read that is not stamped yet: every file it read (the
    summarised ones and those parsed only for their import edges), their folders,
    the folders its module index listed or probed, and the folders `path` imports
    from."""
    files = sorted(project.read_files())
    wanted = [
        *project.index.search_path(path),
        *files,
        *{f.parent for f in files},
        *(Path(f) for f in sorted(project.index.listed_folders())),
    ]
    for file in wanted:
        if file not in stamps:
            stamps[file] = _stamp(file)


def _forget_projects() -> None:
    _projects.clear()


def _memo(uri: str) -> ProofMemo:
    # `is None`, not `or`: a memo that kept no proof is empty, so false, and its
    # analysis kept per item (`memo.units`) would be dropped at every keystroke
    memo = _memos.pop(uri, None)
    if memo is None:
        memo = ProofMemo()
    _memos[uri] = memo  # the most recent last
    while len(_memos) > MAX_MEMOS:
        del _memos[next(iter(_memos))]
    return memo


def _open_texts(ls: Session, files: list[Path]) -> dict[Path, str]:
    """The editor's text of those `files` it has open."""
    wanted = set(files)
    found = {}
    for document in ls.documents.all():
        path = path_of(document.uri)
        if path in wanted:
            found[path] = document.text
    return found


def _open_documents(ls: Session) -> list[tuple[str, Path]]:
    """(URI as the client wrote it, path) of every open document."""
    return [(d.uri, path_of(d.uri)) for d in ls.documents.all()]


def _is_interface(path: Path) -> bool:
    return path.suffix in api.INTERFACE_SUFFIXES


def _stamp(file: Path) -> tuple[object, ...]:
    """What changes when a file is edited or replaced (an editor's atomic save
    changes the inode), without reading it."""
    try:
        info = os.stat(file)
    except OSError:
        return (str(file),)
    return (str(file), info.st_mtime_ns, info.st_ctime_ns, info.st_size, info.st_ino)


def _document(ls: Session, uri: str) -> tuple[str, Path] | None:
    """The editor's text of an open document; else the file's text, read only if it
    is a regular file of bounded size; None when there is none."""
    opened = ls.documents.get(uri)
    if opened is not None:
        return opened.text, path_of(uri)
    fs_path = to_path(uri)
    if fs_path is None:
        return None
    try:
        return source.decode(fs.read_regular(fs_path)), fs_path
    except (fs.UnreadableError, SyntaxError, UnicodeDecodeError, LookupError):
        return None


def _publish(ls: Session, uri: str) -> None:
    document = _document(ls, uri)
    if document is None:
        return
    text, path = document
    try:
        found = _check(ls, uri, path)(text)
    except Exception as err:  # never take the editor session down
        _log_error(ls, f"robotfix: internal error on {path}: {err}")
        return
    ls.found[uri] = (text, found)
    lines = source.split_lines(text)
    related = ls.related()
    diagnostics = [_diagnostic(d, lines, related) for d in found]
    ls.notify(
        "textDocument/publishDiagnostics", {"uri": uri, "diagnostics": diagnostics}
    )


def _check(ls: Session, uri: str, path: Path) -> actions.Checker:
    """What checking a text as document `uri` finds in it."""
    catalog = _catalog(ls, path)

    def check(text: str) -> list[Diagnostic]:
        if _is_interface(path):
            found = api.catalog_problems(catalog)
        else:
            settings = _settings(path)  # the nearest configuration's, as a run's
            project = _project(catalog, path, settings)
            found = api.check_source(
                text, str(path), settings, catalog, project, memo=_memo(uri)
            )
            _record(project, _projects[id(catalog)][2], path)
        return [d for d in found if d.path == str(path)]

    return check


def _log_error(ls: Session, message: str) -> None:
    ls.notify("window/logMessage", {"type": LOG_ERROR, "message": message})


def _dependents(ls: Session, changed: Path) -> list[str]:
    """The open Python documents whose diagnostics may change with file `changed`:
    those that use a type of a changed interface file, or import a changed module."""
    if _is_interface(changed):
        kinds = dependents.interface_types(changed, _text_of(ls, changed))

        def depends(text: str, path: Path) -> bool:
            return dependents.uses_interface(text, path, _catalog(ls, path), kinds)

    else:

        def depends(text: str, path: Path) -> bool:
            return dependents.imports_module(text, path, changed)

    found = []
    for uri, path in _open_documents(ls):
        document = _document(ls, uri)
        if path == changed or _is_interface(path) or document is None:
            continue
        try:
            if depends(document[0], path):
                found.append(uri)
        except Exception as err:  # never take the editor session down
            _log_error(ls, f"robotfix: internal error on {path}: {err}")
    return found


def _text_of(ls: Session, path: Path) -> str:
    """The editor's text of a file, else its text on disk, else "" (gone)."""
    for document in ls.documents.all():
        if path_of(document.uri) == path:
            return document.text
    try:
        return fs.read_regular(path).decode("utf-8")
    except (fs.UnreadableError, UnicodeDecodeError):
        return ""


def _publish_dependents(ls: Session, changed: Iterable[Path]) -> None:
    uris = {uri for path in changed for uri in _dependents(ls, path)}
    for uri in sorted(uris):
        _publish(ls, uri)


def _diagnostic(
    d: Diagnostic, lines: list[str], related: bool = False
) -> dict[str, object]:
    """`related`: notes with a place also go in `relatedInformation` (links). They
    stay in the message: Neovim announces `relatedInformation` but shows only the
    message."""
    linked = [n for n in d.notes if related and n.path is not None]
    found: dict[str, object] = {
        "range": actions.lsp_range(lines, d.span),
        "message": d.message + "".join(f"\n{n.message}" for n in d.notes),
        "severity": SEVERITIES[d.severity],
        "code": d.code,
        "source": "robotfix",
    }
    page = rulepages.uri(d.code)  # the installed rule page: RobotFix has no site
    if page is not None:
        found["codeDescription"] = {"href": page}
    if linked:
        found["relatedInformation"] = [_related(n) for n in linked]
    return found


def _related(note: Note) -> dict[str, object]:
    assert note.path is not None  # only notes with a place are linked
    line = max((note.line or 1) - 1, 0)
    point = {"line": line, "character": 0}
    return {
        "location": {
            "uri": Path(note.path).absolute().as_uri(),
            "range": {"start": point, "end": point},
        },
        "message": note.message,
    }


# -- handlers ----------------------------------------------------------------------


def initialize(ls: Session, params: Any) -> dict[str, object]:
    capabilities = params.get("capabilities") if isinstance(params, dict) else None
    ls.capabilities = capabilities if isinstance(capabilities, dict) else {}
    return {
        "capabilities": {
            "textDocumentSync": {
                "openClose": True,
                "change": SYNC_INCREMENTAL,
                "save": {"includeText": False},
            },
            "hoverProvider": True,
            "codeActionProvider": {"codeActionKinds": [QUICKFIX, REWRITE]},
        },
        "serverInfo": {"name": "robotfix", "version": __version__},
    }


def initialized(ls: Session, params: Any) -> None:
    """Ask to hear of interface files changed outside the editor, if the client
    lets a server register file watchers."""
    workspace = ls.capabilities.get("workspace")
    watched = (
        workspace.get("didChangeWatchedFiles") if isinstance(workspace, dict) else None
    )
    if not isinstance(watched, dict) or watched.get("dynamicRegistration") is not True:
        return
    registration = {
        "id": "robotfix-interface-files",
        "method": "workspace/didChangeWatchedFiles",
        "registerOptions": {"watchers": [{"globPattern": INTERFACE_GLOB}]},
    }
    if ls.endpoint is not None:
        ls.endpoint.request(
            "client/registerCapability", {"registrations": [registration]}
        )


def did_open(ls: Session, params: Any) -> None:
    uri = _uri(params)
    text = _get(params, "textDocument", "text")
    if not isinstance(text, str):
        raise rpc.InvalidParamsError("textDocument.text must be a string")
    version = params["textDocument"].get("version")
    ls.documents.open(uri, text, version if isinstance(version, int) else None)
    _publish(ls, uri)


def did_change(ls: Session, params: Any) -> None:
    uri = _uri(params)
    changes = _get(params, "contentChanges")
    if not isinstance(changes, list):
        raise rpc.InvalidParamsError("contentChanges must be a list")
    version = params["textDocument"].get("version")
    ls.documents.change(uri, version if isinstance(version, int) else None, changes)
    _publish(ls, uri)
    path = path_of(uri)
    if _is_interface(path):  # an imported module counts when it is saved
        _publish_dependents(ls, [path])


def did_save(ls: Session, params: Any) -> None:
    uri = _uri(params)
    path = path_of(uri)
    if path.suffix == ".py":
        _forget_projects()  # a module on disk changed: summaries built again
    if path.suffix == ".pyi":
        _stubs_changed(ls)
    _publish(ls, uri)
    _publish_dependents(ls, [path])


def _stubs_changed(ls: Session) -> None:
    """A `.pyi` saved or changed on disk: any document may call into it, so the
    stubs are read again and every open Python document is checked again."""
    api.forget_stubs()
    _forget_projects()
    for uri, path in _open_documents(ls):
        if path.suffix == ".py":
            _publish(ls, uri)


def did_close(ls: Session, params: Any) -> None:
    """An interface file's unsaved edits no longer count: its users see the disk."""
    uri = _uri(params)
    ls.documents.close(uri)
    ls.found.pop(uri, None)
    ls.verdicts.pop(uri, None)
    path = path_of(uri)
    if _is_interface(path):
        _publish_dependents(ls, [path])


def did_change_watched_files(ls: Session, params: Any) -> None:
    events = _get(params, "changes")
    if not isinstance(events, list):
        raise rpc.InvalidParamsError("changes must be a list")
    changed = [path_of(_get(event, "uri")) for event in events]
    if any(p.suffix == ".py" for p in changed):
        _forget_projects()
    if any(p.suffix == ".pyi" for p in changed):
        _stubs_changed(ls)
    _publish_dependents(
        ls, [p for p in changed if _is_interface(p) or p.suffix == ".py"]
    )


def hover(ls: Session, params: Any) -> dict[str, object] | None:
    uri = _uri(params)
    line = _get(params, "position", "line")
    character = _get(params, "position", "character")
    if not isinstance(line, int) or not isinstance(character, int):
        raise rpc.InvalidParamsError("a position needs an integer line and character")
    document = _document(ls, uri)
    if document is None:
        return None
    text, path = document
    col = char(source.split_lines(text), line + 1, character)
    try:
        catalog = _catalog(ls, path)
        settings = _settings(path)  # its stub-paths too
        project = _project(catalog, path, settings)
        markdown = api.hover(text, str(path), line + 1, col, catalog, settings, project)
        _record(project, _projects[id(catalog)][2], path)
    except Exception:
        return None
    if markdown is None:
        return None
    return {"contents": {"kind": "markdown", "value": markdown}}


def code_action(ls: Session, params: Any) -> list[dict[str, object]]:
    """Quick fixes for the diagnostics on the lines asked about, and the unit
    annotations `robotfix suggest` proposes there (not when the client asks on its
    own, at a cursor move: suggest runs an analysis of its own), each checked first
    (`lsp/actions.py`)."""
    uri = _uri(params)
    first = _get(params, "range", "start", "line")
    last = _get(params, "range", "end", "line")
    if not isinstance(first, int) or not isinstance(last, int):
        raise rpc.InvalidParamsError("a range needs integer lines")
    document = ls.documents.get(uri)
    path = path_of(uri)
    if document is None or _is_interface(path):
        return []
    text = document.text
    try:
        check = _check(ls, uri, path)
        found = ls.found.get(uri)
        before = found[1] if found is not None and found[0] == text else check(text)
        verdicts = ls.verdicts.get(uri)
        if verdicts is None or verdicts.text != text:
            verdicts = ls.verdicts[uri] = actions.Verdicts(text)
        verdicts.budget = actions.MAX_TRIED
        context = params.get("context")
        context = context if isinstance(context, dict) else {}
        only = context.get("only")
        lines = source.split_lines(text)
        offered = []
        for d in before if _wanted(QUICKFIX, only) else ():
            if d.span.line - 1 > last or d.span.end_line - 1 < first:
                continue
            for fix in actions.candidates(text, d):
                key = (d.code, d.span, d.message, fix)
                tried = partial(actions.verified, text, before, fix, check, d)
                if verdicts.holds(key, tried):
                    shown = _diagnostic(d, lines, ls.related())
                    offered.append(_action(uri, lines, fix, QUICKFIX, shown))
        # suggest analyses the file again: not at a client's own request (a cursor move)
        if _wanted(REWRITE, only) and context.get("triggerKind") != AUTOMATIC:
            offered.extend(
                _suggested(ls, uri, path, text, before, check, verdicts, first, last)
            )
    except Exception as err:  # never take the editor session down
        _log_error(ls, f"robotfix: internal error on {path}: {err}")
        return []
    return offered


def _suggested(
    ls: Session,
    uri: str,
    path: Path,
    text: str,
    before: list[Diagnostic],
    check: actions.Checker,
    verdicts: actions.Verdicts,
    first: int,
    last: int,
) -> list[dict[str, object]]:
    """The `Unit(...)` annotations suggest proposes on lines first..last (0-based),
    one action each, those whose edited text adds no diagnostic (each tried when
    first asked for)."""
    from robotfix import suggest  # only when a client asks for code actions

    catalog = _catalog(ls, path)
    if verdicts.suggested is None:
        settings = _settings(path)  # what a check of the file sees, as `suggest`
        project = _project(catalog, path, settings)
        verdicts.suggested = api.unit_suggestions(
            text, str(path), catalog, settings, project
        )
    lines = source.split_lines(text)
    offered = []
    for s in verdicts.suggested:
        if not first <= s.line - 1 <= last:
            continue
        key = ("suggest", s)

        def annotated(s: api.Suggestion = s, key: tuple[object, ...] = key) -> bool:
            try:
                new = suggest.annotate(text, str(path), catalog, suggestions=[s])
            except suggest.UnsafeEditError:
                return False
            fix = Fix(
                f"Annotate `{s.name}` with Unit('{s.unit}')",
                actions.diff_edits(text, new),
            )
            verdicts.edits[key] = fix
            return new != text and actions.verified(text, before, fix, check, None)

        if verdicts.holds(key, annotated):
            offered.append(_action(uri, lines, verdicts.edits[key], REWRITE, None))
    return offered


def _wanted(kind: str, only: object) -> bool:
    """Whether a client that asked for the kinds `only` (all when None) wants
    actions of `kind` (`refactor` covers `refactor.rewrite`)."""
    if not isinstance(only, list):
        return True
    return any(kind == o or kind.startswith(f"{o}.") for o in only)


def _action(
    uri: str,
    lines: list[str],
    fix: Fix,
    kind: str,
    diagnostic: dict[str, object] | None,
) -> dict[str, object]:
    edits = [
        {"range": actions.lsp_range(lines, e.span), "newText": e.text}
        for e in fix.edits
    ]
    action: dict[str, object] = {
        "title": f"RobotFix: {fix.title}",
        "kind": kind,
        "edit": {"changes": {uri: edits}},
    }
    if diagnostic is not None:
        action["diagnostics"] = [diagnostic]
    return action


REQUESTS: dict[str, Callable[[Session, Any], Any]] = {
    "initialize": initialize,
    "textDocument/hover": hover,
    "textDocument/codeAction": code_action,
}
NOTIFICATIONS: dict[str, Callable[[Session, Any], None]] = {
    "initialized": initialized,
    "textDocument/didOpen": did_open,
    "textDocument/didChange": did_change,
    "textDocument/didSave": did_save,
    "textDocument/didClose": did_close,
    "workspace/didChangeWatchedFiles": did_change_watched_files,
}
