"""`robotfix lsp`: diagnostics on open, change and save, hovers with units and
refinements, over stdio with pygls. A thin adapter over `api`: no analysis here.

Interface files and settings come from the nearest `pyproject.toml` of each document
and from ROS packages around it; a catalog is rebuilt when an interface file is
added, removed or changed (its path, size, times or inode), so an edited `.msg` counts
without a restart. A document the editor never opened is read from disk only
through `fs.read_regular` (a FIFO or `/dev/zero` gets no answer, not a hang).
"""

from __future__ import annotations

import os
from pathlib import Path
from urllib.parse import unquote

from lsprotocol import types
from pygls.lsp.server import LanguageServer
from pygls.uris import to_fs_path

from robotfix import __version__, api, config, discovery, fs, source
from robotfix.diagnostics import Diagnostic, Severity
from robotfix.ros.catalog import MsgCatalog

SEVERITIES = {
    Severity.ERROR: types.DiagnosticSeverity.Error,
    Severity.WARNING: types.DiagnosticSeverity.Warning,
    Severity.NOTE: types.DiagnosticSeverity.Information,
}

server = LanguageServer(
    "robotfix", __version__, text_document_sync_kind=types.TextDocumentSyncKind.Full
)
# settings -> (the interface files' stat stamps, the catalog built from them)
_catalogs: dict[tuple[object, ...], tuple[tuple[object, ...], MsgCatalog]] = {}
_INSTALLED = discovery.install_space()


def serve() -> None:
    server.start_io()


def _catalog(path: Path) -> MsgCatalog:
    try:
        settings = config.load(path)
    except config.ConfigError:
        settings = config.Config()
    folders = list(settings.msg_paths) + api.ros_interface_folders([path])
    key = (tuple(folders), settings.rep103, settings.ros_distro)
    files = api.interface_files(folders)
    stamp = tuple(_stamp(file) for file in files)
    cached = _catalogs.get(key)
    if cached is not None and cached[0] == stamp:
        return cached[1]
    catalog = MsgCatalog(
        files,
        rep103=settings.rep103,
        distro=settings.ros_distro,
        installed=_INSTALLED,  # the install space the editor's environment sourced
    )
    _catalogs[key] = (stamp, catalog)
    return catalog


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
        found = api.check_source(text, str(path), catalog=_catalog(path))
    except Exception as err:  # never take the editor session down
        ls.window_log_message(
            types.LogMessageParams(
                types.MessageType.Error, f"robotfix: internal error on {path}: {err}"
            )
        )
        return
    lines = source.split_lines(text)
    diagnostics = [_diagnostic(d, lines) for d in found if d.path == str(path)]
    ls.text_document_publish_diagnostics(
        types.PublishDiagnosticsParams(uri=uri, diagnostics=diagnostics)
    )


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


@server.feature(types.TEXT_DOCUMENT_DID_OPEN)
def did_open(ls: LanguageServer, params: types.DidOpenTextDocumentParams) -> None:
    _publish(ls, params.text_document.uri)


@server.feature(types.TEXT_DOCUMENT_DID_CHANGE)
def did_change(ls: LanguageServer, params: types.DidChangeTextDocumentParams) -> None:
    _publish(ls, params.text_document.uri)


@server.feature(types.TEXT_DOCUMENT_DID_SAVE)
def did_save(ls: LanguageServer, params: types.DidSaveTextDocumentParams) -> None:
    _publish(ls, params.text_document.uri)


@server.feature(types.TEXT_DOCUMENT_HOVER)
def hover(ls: LanguageServer, params: types.HoverParams) -> types.Hover | None:
    document = _document(ls, params.text_document.uri)
    if document is None:
        return None
    text, path = document
    line = params.position.line + 1
    col = _char(source.split_lines(text), line, params.position.character)
    try:
        markdown = api.hover(text, str(path), line, col, _catalog(path))
    except Exception:
        return None
    if markdown is None:
        return None
    return types.Hover(
        contents=types.MarkupContent(types.MarkupKind.Markdown, markdown)
    )
