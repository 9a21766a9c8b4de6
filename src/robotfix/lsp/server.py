"""`robotfix lsp`: diagnostics on open, change and save, hovers with units and
refinements, over stdio with pygls. A thin adapter over `api`: no analysis here.

Interface files and settings come from the nearest `pyproject.toml` of each document
and from ROS packages around it; the catalog is built once per settings.
"""

from __future__ import annotations

from pathlib import Path

from lsprotocol import types
from pygls.lsp.server import LanguageServer
from pygls.uris import to_fs_path

from robotfix import __version__, api, config
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
_catalogs: dict[tuple[object, ...], MsgCatalog] = {}


def serve() -> None:
    server.start_io()


def _catalog(path: Path) -> MsgCatalog:
    try:
        settings = config.load(path)
    except config.ConfigError:
        settings = config.Config()
    folders = list(settings.msg_paths) + api.ros_interface_folders([path])
    key = (tuple(folders), settings.rep103, settings.ros_distro)
    if key not in _catalogs:
        _catalogs[key] = MsgCatalog(
            api.interface_files(folders),
            rep103=settings.rep103,
            distro=settings.ros_distro,
        )
    return _catalogs[key]


def _document(ls: LanguageServer, uri: str) -> tuple[str, Path]:
    document = ls.workspace.get_text_document(uri)
    return document.source, Path(to_fs_path(uri) or uri)


def _publish(ls: LanguageServer, uri: str) -> None:
    text, path = _document(ls, uri)
    try:
        found = api.check_source(text, str(path), catalog=_catalog(path))
    except Exception as err:  # never take the editor session down
        ls.window_log_message(
            types.LogMessageParams(
                types.MessageType.Error, f"robotfix: internal error on {path}: {err}"
            )
        )
        return
    lines = text.splitlines()
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
    text, path = _document(ls, params.text_document.uri)
    line = params.position.line + 1
    col = _char(text.splitlines(), line, params.position.character)
    try:
        markdown = api.hover(text, str(path), line, col, _catalog(path))
    except Exception:
        return None
    if markdown is None:
        return None
    return types.Hover(
        contents=types.MarkupContent(types.MarkupKind.Markdown, markdown)
    )
