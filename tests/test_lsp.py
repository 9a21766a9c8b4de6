"""A real client session with `robotfix lsp` over stdio: diagnostics, hover, and a
server that survives syntax errors and Python 2 files."""

from __future__ import annotations

import asyncio
import sys
from pathlib import Path

import pytest

pytest.importorskip("pygls")
from lsprotocol import types
from pygls.lsp.client import LanguageClient

SOURCE = """from typing import Annotated
from geometry_msgs.msg import Twist

timeout: Annotated[int, "_ < 200"] = 200
speed: Annotated[float, "Unit('km/h')"] = 3
cmd = Twist()
cmd.linear.x = speed
"""


async def session(tmp_path: Path) -> dict[str, object]:
    client = LanguageClient("robotfix-test", "1")
    published: asyncio.Queue[types.PublishDiagnosticsParams] = asyncio.Queue()

    @client.feature(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    def on_diagnostics(params: types.PublishDiagnosticsParams) -> None:
        published.put_nowait(params)

    await client.start_io(sys.executable, "-m", "robotfix", "lsp")
    path = tmp_path / "node.py"
    path.write_text(SOURCE)
    uri = path.as_uri()
    await client.initialize_async(
        types.InitializeParams(
            capabilities=types.ClientCapabilities(), root_uri=tmp_path.as_uri()
        )
    )
    client.initialized(types.InitializedParams())
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(
            types.TextDocumentItem(
                uri=uri, language_id="python", version=1, text=SOURCE
            )
        )
    )
    opened = await asyncio.wait_for(published.get(), 60)
    hover = await client.text_document_hover_async(
        types.HoverParams(
            types.TextDocumentIdentifier(uri), types.Position(line=6, character=11)
        )
    )
    broken = SOURCE + "def f(:\n"
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            types.VersionedTextDocumentIdentifier(uri=uri, version=2),
            [types.TextDocumentContentChangeWholeDocument(text=broken)],
        )
    )
    after_syntax_error = await asyncio.wait_for(published.get(), 60)
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            types.VersionedTextDocumentIdentifier(uri=uri, version=3),
            [types.TextDocumentContentChangeWholeDocument(text='print "py2"\n')],
        )
    )
    after_python2 = await asyncio.wait_for(published.get(), 60)
    client.text_document_did_save(
        types.DidSaveTextDocumentParams(types.TextDocumentIdentifier(uri))
    )
    await client.shutdown_async(None)
    client.exit(None)
    await client.stop()
    return {
        "opened": opened,
        "hover": hover,
        "syntax": after_syntax_error,
        "python2": after_python2,
    }


def test_language_server_session(tmp_path: Path) -> None:
    result = asyncio.run(session(tmp_path))
    opened = result["opened"]
    assert isinstance(opened, types.PublishDiagnosticsParams)
    found = sorted(
        (d.code, d.range.start.line, d.range.start.character, d.range.end.line)
        for d in opened.diagnostics
    )
    assert found == [("RF101", 3, 0, 3), ("RF201", 6, 0, 6)]
    rf201 = next(d for d in opened.diagnostics if d.code == "RF201")
    assert rf201.source == "robotfix" and "divide by 3.6" in rf201.message
    assert rf201.code_description is not None
    hover = result["hover"]
    assert isinstance(hover, types.Hover)
    assert "**linear.x** of `geometry_msgs/Twist`" in hover.contents.value  # type: ignore[union-attr]
    assert "m/s" in hover.contents.value  # type: ignore[union-attr]
    syntax = result["syntax"]
    assert [d.code for d in syntax.diagnostics] == ["RF001"]  # type: ignore[attr-defined]
    python2 = result["python2"]
    assert [d.code for d in python2.diagnostics] == ["RF002"]  # type: ignore[attr-defined]
