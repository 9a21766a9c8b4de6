"""`robotfix lsp`: diagnostics on open, change and save, hovers with units and
refinements, over stdio with pygls. A thin adapter over `api`: no analysis here.

Interface files and settings come from the nearest `pyproject.toml` of each document
and from the ROS package around it (`_interface_folders`). A catalog is rebuilt when an
interface file is added, removed or changed (its path, size, times or inode) or its
editor buffer changes, so an edited `.msg` counts before it is saved. An open
interface file shows its own problems. When one changes (typed, saved, closed, or
changed on disk: the server asks a client that allows it to watch interface files),
the open Python documents that use its types are checked again; when a Python module
is saved or changed on disk, the open documents that import it (see
`robotfix.dependents`). A document the editor never opened is read from disk only
through `fs.read_regular` (a FIFO or `/dev/zero` gets no answer, not a hang).
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path
from urllib.parse import unquote

from lsprotocol import types
from pygls.lsp.server import LanguageServer
from pygls.uris import to_fs_path

from robotfix import __version__, api, config, dependents, discovery, fs, source
from robotfix.diagnostics import Diagnostic, Severity
from robotfix.ros.catalog import MsgCatalog
from robotfix.smt.memo import ProofMemo

SEVERITIES = {
    Severity.ERROR: types.DiagnosticSeverity.Error,
    Severity.WARNING: types.DiagnosticSeverity.Warning,
    Severity.NOTE: types.DiagnosticSeverity.Information,
}
INTERFACE_GLOB = "**/*.{msg,srv,action}"
MAX_CATALOGS = 32  # catalogs kept (one per set of interface files and settings)
MAX_MEMOS = 8  # documents, most recently checked, whose proofs are kept

server = LanguageServer(
    "robotfix", __version__, text_document_sync_kind=types.TextDocumentSyncKind.Full
)
# interface files and settings -> (their stat stamps and open buffers, the catalog)
_catalogs: dict[tuple[object, ...], tuple[tuple[object, ...], MsgCatalog]] = {}
_INSTALLED = discovery.install_space()
# document URI -> its verdicts by normalised VC, so a keystroke in one function does
# not prove the others again (`smt.memo`); least recently checked documents go first
_memos: dict[str, ProofMemo] = {}


def serve() -> None:
    server.start_io()


def _interface_folders(path: Path, settings: config.Config) -> list[Path]:
    """Where the interface files of a document are, found as the CLI finds them for
    that one file: `msg-paths`, then its ROS package's msg/, srv/ and action/."""
    return list(settings.msg_paths) + api.ros_interface_folders([path])


def _catalog(ls: LanguageServer, path: Path) -> MsgCatalog:
    try:
        settings = config.load(path)
    except config.ConfigError:
        settings = config.Config()
    files = api.interface_files(_interface_folders(path, settings))
    if _is_interface(path) and path not in files:
        files.append(path)  # a loose interface file still shows its own problems
    texts = _open_texts(ls, files)
    key = (tuple(files), settings.rep103, settings.ros_distro, settings.unit_suffixes)
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


def _memo(uri: str) -> ProofMemo:
    memo = _memos.pop(uri, None) or ProofMemo()
    _memos[uri] = memo  # the most recent last
    while len(_memos) > MAX_MEMOS:
        del _memos[next(iter(_memos))]
    return memo


def _open_texts(ls: LanguageServer, files: list[Path]) -> dict[Path, str]:
    """The editor's text of those `files` it has open."""
    wanted = set(files)
    return {
        path: ls.workspace.text_documents[unquote(uri)].source
        for uri, path in _open_documents(ls)
        if path in wanted
    }


def _open_documents(ls: LanguageServer) -> list[tuple[str, Path]]:
    """(URI as the client wrote it, path) of every open document."""
    uris = sorted(doc.uri for doc in ls.workspace.text_documents.values())
    return [(uri, Path(to_fs_path(uri) or uri)) for uri in uris]


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


def _document(ls: LanguageServer, uri: str) -> tuple[str, Path] | None:
    """The editor's text of an open document; else the file's text, read only if it
    is a regular file of bounded size; None when there is none."""
    fs_path = to_fs_path(uri)
    opened = ls.workspace.text_documents.get(unquote(uri))
    if opened is not None:
        return opened.source, Path(fs_path or uri)
    if fs_path is None:
        return None
    try:
        return source.decode(fs.read_regular(fs_path)), Path(fs_path)
    except (fs.UnreadableError, SyntaxError, UnicodeDecodeError, LookupError):
        return None


def _publish(ls: LanguageServer, uri: str) -> None:
    document = _document(ls, uri)
    if document is None:
        return
    text, path = document
    try:
        if _is_interface(path):
            found = api.catalog_problems(_catalog(ls, path))
        else:
            found = api.check_source(
                text, str(path), catalog=_catalog(ls, path), memo=_memo(uri)
            )
    except Exception as err:  # never take the editor session down
        _log_error(ls, f"robotfix: internal error on {path}: {err}")
        return
    lines = source.split_lines(text)
    diagnostics = [_diagnostic(d, lines) for d in found if d.path == str(path)]
    ls.text_document_publish_diagnostics(
        types.PublishDiagnosticsParams(uri=uri, diagnostics=diagnostics)
    )


def _log_error(ls: LanguageServer, message: str) -> None:
    ls.window_log_message(types.LogMessageParams(types.MessageType.Error, message))


def _dependents(ls: LanguageServer, changed: Path) -> list[str]:
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


def _text_of(ls: LanguageServer, path: Path) -> str:
    """The editor's text of a file, else its text on disk, else "" (gone)."""
    for uri, opened in _open_documents(ls):
        if opened == path:
            text: str = ls.workspace.text_documents[unquote(uri)].source
            return text
    try:
        return fs.read_regular(path).decode("utf-8")
    except (fs.UnreadableError, UnicodeDecodeError):
        return ""


def _publish_dependents(ls: LanguageServer, changed: Iterable[Path]) -> None:
    uris = {uri for path in changed for uri in _dependents(ls, path)}
    for uri in sorted(uris):
        _publish(ls, uri)


def _diagnostic(d: Diagnostic, lines: list[str]) -> types.Diagnostic:
    start = types.Position(d.span.line - 1, _utf16(lines, d.span.line, d.span.col))
    end = types.Position(
        d.span.end_line - 1, _utf16(lines, d.span.end_line, d.span.end_col)
    )
    return types.Diagnostic(
        range=types.Range(start, end),
        message=d.message + "".join(f"\n{n.message}" for n in d.notes),
        severity=SEVERITIES[d.severity],
        code=d.code,
        code_description=types.CodeDescription(href=d.rule.docs_url),
        source="robotfix",
    )


def _utf16(lines: list[str], line: int, col: int) -> int:
    """LSP columns count UTF-16 code units; ours count characters."""
    if not 1 <= line <= len(lines):
        return col
    prefix = lines[line - 1][:col]
    return len(prefix.encode("utf-16-le")) // 2 + max(0, col - len(lines[line - 1]))


def _char(lines: list[str], line: int, utf16: int) -> int:
    if not 1 <= line <= len(lines):
        return utf16
    units = 0
    for index, char in enumerate(lines[line - 1]):
        if units >= utf16:
            return index
        units += 2 if ord(char) > 0xFFFF else 1
    return len(lines[line - 1])


@server.feature(types.INITIALIZED)
def initialized(ls: LanguageServer, params: types.InitializedParams) -> None:
    """Ask to hear of interface files changed outside the editor, if the client
    lets a server register file watchers."""
    workspace = ls.client_capabilities.workspace
    watched = workspace.did_change_watched_files if workspace else None
    if watched is None or not watched.dynamic_registration:
        return
    watchers = [types.FileSystemWatcher(glob_pattern=INTERFACE_GLOB)]
    ls.client_register_capability(
        types.RegistrationParams(
            [
                types.Registration(
                    id="robotfix-interface-files",
                    method=types.WORKSPACE_DID_CHANGE_WATCHED_FILES,
                    register_options=types.DidChangeWatchedFilesRegistrationOptions(
                        watchers
                    ),
                )
            ]
        )
    )


@server.feature(types.TEXT_DOCUMENT_DID_OPEN)
def did_open(ls: LanguageServer, params: types.DidOpenTextDocumentParams) -> None:
    _publish(ls, params.text_document.uri)


@server.feature(types.TEXT_DOCUMENT_DID_CHANGE)
def did_change(ls: LanguageServer, params: types.DidChangeTextDocumentParams) -> None:
    uri = params.text_document.uri
    _publish(ls, uri)
    path = Path(to_fs_path(uri) or uri)
    if _is_interface(path):  # an imported module counts when it is saved
        _publish_dependents(ls, [path])


@server.feature(types.TEXT_DOCUMENT_DID_SAVE)
def did_save(ls: LanguageServer, params: types.DidSaveTextDocumentParams) -> None:
    uri = params.text_document.uri
    _publish(ls, uri)
    _publish_dependents(ls, [Path(to_fs_path(uri) or uri)])


@server.feature(types.TEXT_DOCUMENT_DID_CLOSE)
def did_close(ls: LanguageServer, params: types.DidCloseTextDocumentParams) -> None:
    """An interface file's unsaved edits no longer count: its users see the disk."""
    path = Path(to_fs_path(params.text_document.uri) or params.text_document.uri)
    if _is_interface(path):
        _publish_dependents(ls, [path])


@server.feature(types.WORKSPACE_DID_CHANGE_WATCHED_FILES)
def did_change_watched_files(
    ls: LanguageServer, params: types.DidChangeWatchedFilesParams
) -> None:
    changed = [Path(to_fs_path(c.uri) or c.uri) for c in params.changes]
    _publish_dependents(
        ls, [p for p in changed if _is_interface(p) or p.suffix == ".py"]
    )


@server.feature(types.TEXT_DOCUMENT_HOVER)
def hover(ls: LanguageServer, params: types.HoverParams) -> types.Hover | None:
    document = _document(ls, params.text_document.uri)
    if document is None:
        return None
    text, path = document
    line = params.position.line + 1
    col = _char(source.split_lines(text), line, params.position.character)
    try:
        markdown = api.hover(text, str(path), line, col, _catalog(ls, path))
    except Exception:
        return None
    if markdown is None:
        return None
    return types.Hover(
        contents=types.MarkupContent(types.MarkupKind.Markdown, markdown)
    )
