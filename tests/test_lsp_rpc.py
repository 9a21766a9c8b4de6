"""The language server's own JSON-RPC layer (lsp/rpc.py) and document store
(lsp/documents.py): framing errors, the lifecycle, unknown methods, handlers that
raise, a 5 MB document, incremental edits in UTF-16 columns.

Most sessions run in-process (`server.serve` over byte buffers: the whole input is
read, then the output is parsed); the exit codes are checked on a real process too."""

from __future__ import annotations

import io
import json
import re
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix.lsp import documents, rpc, server
from tests.lsp_client import Client, frame

SOURCE = """from typing import Annotated
from geometry_msgs.msg import Twist

speed: Annotated[float, "Unit('km/h')"] = 3
cmd = Twist()
cmd.linear.x = speed
"""
CLEAN = SOURCE.replace("km/h", "m/s")
INIT = {"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {}}
INITIALIZED = {"jsonrpc": "2.0", "method": "initialized", "params": {}}
SHUTDOWN = {"jsonrpc": "2.0", "id": "last", "method": "shutdown"}
EXIT = {"jsonrpc": "2.0", "method": "exit"}


def parse(data: bytes) -> list[dict[str, Any]]:
    messages = []
    while data:
        header, _, rest = data.partition(b"\r\n\r\n")
        match = re.fullmatch(rb"Content-Length: (\d+)", header)
        assert match is not None, header
        length = int(match.group(1))
        messages.append(json.loads(rest[:length]))
        data = rest[length:]
    return messages


def run(*messages: bytes | dict[str, Any]) -> tuple[int, list[dict[str, Any]]]:
    """Serve `messages` (framed unless they are bytes) in-process; the exit code
    and every message the server wrote."""
    data = b"".join(m if isinstance(m, bytes) else frame(m) for m in messages)
    out = io.BytesIO()
    code = server.serve(io.BytesIO(data), out)
    return code, parse(out.getvalue())


def answer(found: list[dict[str, Any]], ident: object) -> dict[str, Any]:
    (match,) = [m for m in found if m.get("id") == ident and "method" not in m]
    return match


def published(found: list[dict[str, Any]]) -> list[list[str]]:
    return [
        [d["code"] for d in m["params"]["diagnostics"]]
        for m in found
        if m.get("method") == "textDocument/publishDiagnostics"
    ]


def did_open(path: Path, text: str) -> dict[str, Any]:
    document = {"uri": path.as_uri(), "languageId": "python", "version": 1}
    return {
        "jsonrpc": "2.0",
        "method": "textDocument/didOpen",
        "params": {"textDocument": {**document, "text": text}},
    }


def hover(ident: int, params: object) -> dict[str, Any]:
    return {
        "jsonrpc": "2.0",
        "id": ident,
        "method": "textDocument/hover",
        "params": params,
    }


def test_a_session_shuts_down_and_exits_with_0() -> None:
    code, found = run(INIT, INITIALIZED, SHUTDOWN, EXIT)
    assert code == 0
    assert answer(found, 1)["result"]["serverInfo"]["name"] == "robotfix"
    assert answer(found, "last") == {"jsonrpc": "2.0", "id": "last", "result": None}


def test_exit_without_shutdown_or_the_end_of_input_exits_with_1() -> None:
    assert run(INIT, INITIALIZED, EXIT)[0] == 1
    assert run(INIT, INITIALIZED)[0] == 1  # the client went away
    assert run(INIT, SHUTDOWN)[0] == 0  # ... after shutdown it may


def test_requests_after_shutdown_are_invalid() -> None:
    code, found = run(INIT, SHUTDOWN, hover(7, {}), EXIT)
    assert answer(found, 7)["error"]["code"] == rpc.INVALID_REQUEST
    assert code == 0


def test_malformed_json_gets_a_parse_error_and_the_server_goes_on() -> None:
    bad = b"Content-Length: 9\r\n\r\n{not json"
    code, found = run(bad, INIT, SHUTDOWN, EXIT)
    assert found[0]["id"] is None and found[0]["error"]["code"] == rpc.PARSE_ERROR
    assert "result" in answer(found, 1) and code == 0


def test_a_message_without_content_length_is_skipped() -> None:
    body = json.dumps({"jsonrpc": "2.0", "id": 9, "method": "initialize"}).encode()
    unframed = b"Content-Type: application/vscode-jsonrpc\r\n\r\n" + body
    code, found = run(unframed, INIT, SHUTDOWN, EXIT)
    assert found[0]["id"] is None and found[0]["error"]["code"] == rpc.PARSE_ERROR
    assert [m.get("id") for m in found] == [None, 1, "last"]  # 9 never ran
    assert code == 0
    bad_length = b"Content-Length: many\r\n\r\n{}"
    _, found = run(bad_length, INIT)
    assert found[0]["error"]["code"] == rpc.PARSE_ERROR and answer(found, 1)


def test_invalid_messages_and_batches_are_invalid_requests() -> None:
    _, found = run(b"Content-Length: 2\r\n\r\n[]", INIT, {"id": 3, "method": 5})
    assert found[0]["error"]["code"] == rpc.INVALID_REQUEST
    assert answer(found, 3)["error"]["code"] == rpc.INVALID_REQUEST


def test_unknown_methods_fail_as_requests_and_are_ignored_as_notifications() -> None:
    unknown = {"jsonrpc": "2.0", "id": 2, "method": "textDocument/completion"}
    cancel = {"jsonrpc": "2.0", "method": "$/cancelRequest", "params": {"id": 2}}
    other = {"jsonrpc": "2.0", "method": "workspace/didChangeConfiguration"}
    code, found = run(INIT, INITIALIZED, cancel, other, unknown, SHUTDOWN, EXIT)
    assert answer(found, 2)["error"]["code"] == rpc.METHOD_NOT_FOUND
    assert [m.get("id") for m in found] == [1, 2, "last"]  # nothing else answered
    assert code == 0


def test_a_request_before_initialize_is_refused(tmp_path: Path) -> None:
    node = tmp_path / "node.py"
    code, found = run(
        hover(4, {}), did_open(node, SOURCE), INIT, INITIALIZED, SHUTDOWN, EXIT
    )
    assert answer(found, 4)["error"]["code"] == rpc.SERVER_NOT_INITIALIZED
    assert published(found) == []  # the didOpen before initialize was dropped
    assert code == 0


def test_invalid_params_get_an_error_and_the_server_goes_on(tmp_path: Path) -> None:
    node = tmp_path / "node.py"
    no_text = {
        "jsonrpc": "2.0",
        "method": "textDocument/didOpen",
        "params": {"textDocument": {"uri": node.as_uri()}},
    }
    position = {"textDocument": {"uri": node.as_uri()}, "position": {"line": "x"}}
    _, found = run(
        INIT, INITIALIZED, no_text, hover(5, position), did_open(node, SOURCE)
    )
    assert answer(found, 5)["error"]["code"] == rpc.INVALID_PARAMS
    logged = [m for m in found if m.get("method") == "window/logMessage"]
    assert "textDocument.text" in logged[0]["params"]["message"]
    assert published(found) == [["RF201"]]


def test_a_handler_that_raises_answers_with_an_error_and_the_server_goes_on(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def boom(ls: object, params: object) -> None:
        raise RuntimeError("boom")

    monkeypatch.setitem(server.REQUESTS, "textDocument/hover", boom)
    node = tmp_path / "node.py"
    code, found = run(
        INIT, INITIALIZED, hover(2, {}), did_open(node, SOURCE), SHUTDOWN, EXIT
    )
    error = answer(found, 2)["error"]
    assert error["code"] == rpc.INTERNAL_ERROR and "boom" in error["message"]
    assert published(found) == [["RF201"]] and code == 0


def test_a_check_that_raises_is_logged_and_the_next_one_publishes(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    real = server.api.check_source
    calls = []

    def flaky(*args: Any, **kwargs: Any) -> Any:
        calls.append(1)
        if len(calls) == 1:
            raise RuntimeError("flaky")
        return real(*args, **kwargs)

    monkeypatch.setattr(server.api, "check_source", flaky)
    node = tmp_path / "node.py"
    change = {
        "jsonrpc": "2.0",
        "method": "textDocument/didChange",
        "params": {
            "textDocument": {"uri": node.as_uri(), "version": 2},
            "contentChanges": [{"text": SOURCE}],
        },
    }
    _, found = run(INIT, INITIALIZED, did_open(node, SOURCE), change)
    logged = [m["params"] for m in found if m.get("method") == "window/logMessage"]
    assert logged[0]["type"] == 1 and "flaky" in logged[0]["message"]
    assert published(found) == [["RF201"]]


def test_a_5_mb_document_and_an_incremental_edit_at_its_end(tmp_path: Path) -> None:
    filler = "# " + "x" * 998 + "\n"
    head = filler * 5000  # 5 MB of comment lines before the node
    node = tmp_path / "big.py"
    text = head + SOURCE
    assert len(text) > 5_000_000
    last = 5000 + SOURCE.count("\n")  # the empty last line
    col = SOURCE.splitlines()[3].index("km/h")
    fix = {"range": _range(5000 + 3, col, 5000 + 3, col + 4), "text": "m/s"}
    change = {
        "jsonrpc": "2.0",
        "method": "textDocument/didChange",
        "params": {
            "textDocument": {"uri": node.as_uri(), "version": 2},
            "contentChanges": [fix, {"range": _range(last, 0, last, 0), "text": "\n"}],
        },
    }
    client = Client()
    try:
        client.initialize(tmp_path)
        client.send(did_open(node, text))
        first = client.diagnostics()
        (diagnostic,) = first["diagnostics"]
        assert diagnostic["range"]["start"]["line"] == 5005
        client.send(change)
        assert client.diagnostics()["diagnostics"] == []
        assert client.stop() == 0
    finally:
        client.kill()


def test_the_command_exits_with_1_without_shutdown(tmp_path: Path) -> None:
    client = Client()
    try:
        client.initialize(tmp_path)
        client.notify("exit")
        assert client.wait() == 1
    finally:
        client.kill()


# -- the document store ------------------------------------------------------------


def _range(line: int, char: int, end_line: int, end_char: int) -> dict[str, Any]:
    return {
        "start": {"line": line, "character": char},
        "end": {"line": end_line, "character": end_char},
    }


def _position(text: str, index: int) -> tuple[int, int]:
    """The LSP position of a character index, counted independently of
    documents.py: lines by str.splitlines' LSP subset, columns in UTF-16 units."""
    before = text[:index]
    lines = re.split(r"\r\n|\r|\n", before)
    return len(lines) - 1, len(lines[-1].encode("utf-16-le")) // 2


TEXT = st.lists(
    st.sampled_from(["a", "é", "😀", "\n", "\r\n", "\r", " "]), max_size=30
).map("".join)


@settings(max_examples=200, deadline=None)
@given(TEXT, st.data(), st.text(alphabet=["b", "😀", "\n"], max_size=5))
def test_an_incremental_change_replaces_exactly_its_range(
    text: str, data: Any, new: str
) -> None:
    # indexes that are not inside a "\r\n" (no position names them)
    cuts = [
        i
        for i in range(len(text) + 1)
        if not (0 < i < len(text) and text[i - 1] == "\r" and text[i] == "\n")
    ]
    start = data.draw(st.sampled_from(cuts))
    end = data.draw(st.sampled_from([i for i in cuts if i >= start]))
    where = _range(*_position(text, start), *_position(text, end))
    assert documents.apply(text, {"range": where, "text": new}) == (
        text[:start] + new + text[end:]
    )


def test_positions_past_a_line_or_the_text_clamp_and_full_changes_replace() -> None:
    text = "ab\ncd"
    past_line = {"range": _range(0, 9, 1, 1), "text": "X"}
    assert documents.apply(text, past_line) == "abXd"
    past_text = {"range": _range(7, 0, 9, 0), "text": "!"}
    assert documents.apply(text, past_text) == "ab\ncd!"
    assert documents.apply(text, {"text": "new"}) == "new"
    with pytest.raises(documents.InvalidChangeError):
        documents.apply(text, {"range": _range(0, 0, 0, 0)})
    # a surrogate pair is two UTF-16 units: the column after it is 2
    assert documents.apply("😀x", {"range": _range(0, 2, 0, 3), "text": "y"}) == "😀y"


def test_uris_of_one_file_however_quoted_are_one_document() -> None:
    store = documents.Documents()
    store.open("file:///tmp/my%20ws/a.py", "x = 1\n", 1)
    opened = store.get("file:///tmp/my ws/a.py")
    assert opened is not None and opened.uri == "file:///tmp/my%20ws/a.py"
    assert documents.to_path("file:///tmp/my%20ws/a.py") == Path("/tmp/my ws/a.py")
    assert documents.to_path("untitled:Untitled-1") is None


def test_a_message_over_the_size_limit_is_skipped_unread(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(rpc, "MAX_BODY", 100)
    big = frame({"jsonrpc": "2.0", "id": 8, "method": "initialize", "x": "y" * 200})
    code, found = run(big, INIT, SHUTDOWN, EXIT)
    assert found[0]["id"] is None and found[0]["error"]["code"] == rpc.PARSE_ERROR
    assert [m.get("id") for m in found] == [None, 1, "last"] and code == 0


class _Gone(io.BytesIO):
    def write(self, data: Any) -> int:
        raise BrokenPipeError("the client closed its end")


def test_a_client_that_went_away_ends_the_session_quietly(tmp_path: Path) -> None:
    data = frame(INIT) + frame(INITIALIZED) + frame(did_open(tmp_path / "n.py", SOURCE))
    assert server.serve(io.BytesIO(data), _Gone()) == 1
