"""JSON-RPC 2.0 over the LSP base protocol, stdlib only: `Content-Length` framed
messages on a byte stream, plain dicts on the wire.

`Endpoint` reads one message at a time and handles it before reading the next, so a
request is answered after every notification sent before it. It knows the
lifecycle every language server shares: requests before `initialize` are refused
(-32002), requests after `shutdown` are invalid (-32600), `exit` ends the loop with
0 after a `shutdown` and 1 without (as does the end of the input), `$/` notifications
such as `$/cancelRequest` are ignored. Requests to the client (`request`) are sent
with ids of their own; the client's responses are matched to them and otherwise
dropped. A handler that raises answers its request with -32603 (or -32602 for
`InvalidParamsError`) and the loop goes on; bad framing or JSON gets a -32700 error and
the reader skips to the next `Content-Length` header.

What the server does with each method is the caller's (`lsp/server.py`): this module
knows no LSP method beyond the lifecycle.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from typing import IO, Any

PARSE_ERROR = -32700
INVALID_REQUEST = -32600
METHOD_NOT_FOUND = -32601
INVALID_PARAMS = -32602
INTERNAL_ERROR = -32603
SERVER_NOT_INITIALIZED = -32002

MAX_HEADER_LINE = 1 << 16  # a longer line is not a header: skipped in pieces
HEADER = b"content-length:"
MAX_BODY = 1 << 27  # 128 MB: a longer message is skipped with a parse error

Message = dict[str, Any]
Handler = Callable[[Any], Any]


class InvalidParamsError(Exception):
    """Raised by a handler whose params do not have the shape the method needs."""


class FramingError(Exception):
    """A message whose header or body cannot be read; the reader has resynced."""


class Reader:
    """Messages from a byte stream; resyncs on the next `Content-Length` header
    after a bad one."""

    def __init__(self, stream: IO[bytes]) -> None:
        self.stream = stream

    def read(self) -> object | None:
        """The next message as decoded JSON; None at the end of the input.
        Raises FramingError for a message that could not be read."""
        length: int | None = None
        seen = False
        while True:
            line = self.stream.readline(MAX_HEADER_LINE)
            if not line:
                return None
            if line in (b"\r\n", b"\n"):
                if not seen:
                    continue  # blank lines between messages
                break
            seen = True
            at = line.lower().find(HEADER)
            if at > 0:  # the rest of an unframed body before a header: resync
                line = line[at:]
            if at >= 0:
                value = line[len(HEADER) :].strip()
                try:
                    length = int(value)
                except ValueError:
                    length = None
                else:
                    if length < 0:
                        length = None
        if length is None:
            raise FramingError("a message without a valid Content-Length header")
        if length > MAX_BODY:
            while length > 0:  # skipped, never held in memory
                chunk = self.stream.read(min(length, 1 << 20))
                if not chunk:
                    return None
                length -= len(chunk)
            raise FramingError(f"a message longer than {MAX_BODY} bytes")
        body = self.stream.read(length)
        if len(body) < length:
            return None
        try:
            message: object = json.loads(body)
        except (ValueError, UnicodeDecodeError) as err:
            raise FramingError(f"a message that is not JSON: {err}") from None
        return message


class Writer:
    def __init__(self, stream: IO[bytes]) -> None:
        self.stream = stream

    def write(self, message: Message) -> None:
        body = json.dumps(message, ensure_ascii=False, separators=(",", ":")).encode()
        self.stream.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.stream.flush()


class Endpoint:
    """One side of a connection: dispatches the peer's messages to `requests` and
    `notifications` handlers (params -> result), sends notifications and requests."""

    def __init__(self, reader: IO[bytes], writer: IO[bytes]) -> None:
        self.reader = Reader(reader)
        self.writer = Writer(writer)
        self.requests: dict[str, Handler] = {}
        self.notifications: dict[str, Handler] = {}
        self.initialized = False  # `initialize` answered
        self.shut_down = False
        self._next_id = 0
        self._pending: dict[object, Callable[[Message], None] | None] = {}
        # what a notification handler that raised is reported with (if set)
        self.on_error: Callable[[str], None] | None = None

    # -- sending ---------------------------------------------------------------
    def notify(self, method: str, params: object) -> None:
        self.writer.write({"jsonrpc": "2.0", "method": method, "params": params})

    def request(
        self,
        method: str,
        params: object,
        on_response: Callable[[Message], None] | None = None,
    ) -> None:
        """Send a request to the peer; `on_response` gets its response message."""
        self._next_id += 1
        ident = f"robotfix-{self._next_id}"
        self._pending[ident] = on_response
        self.writer.write(
            {"jsonrpc": "2.0", "id": ident, "method": method, "params": params}
        )

    def _respond(self, ident: object, result: object) -> None:
        self.writer.write({"jsonrpc": "2.0", "id": ident, "result": result})

    def _error(self, ident: object, code: int, message: str) -> None:
        self.writer.write(
            {
                "jsonrpc": "2.0",
                "id": ident,
                "error": {"code": code, "message": message},
            }
        )

    # -- the loop --------------------------------------------------------------
    def serve(self) -> int:
        """Handle messages until `exit` or the end of the input; the exit code."""
        try:
            while True:
                try:
                    message = self.reader.read()
                except FramingError as err:
                    self._error(None, PARSE_ERROR, str(err))
                    continue
                if message is None or self.handle(message) == "exit":
                    return 0 if self.shut_down else 1
        except (BrokenPipeError, ConnectionResetError):
            return 1  # the client is gone: nobody to answer

    def handle(self, message: object) -> str | None:
        """Handle one decoded message; "exit" when the peer asked to exit."""
        if not isinstance(message, dict):
            self._error(None, INVALID_REQUEST, "a message must be a JSON object")
            return None
        ident = message.get("id")
        method = message.get("method")
        has_id = "id" in message
        if method is None and has_id and ("result" in message or "error" in message):
            callback = self._pending.pop(ident, None)
            if callback is not None:
                callback(message)
            return None
        if not isinstance(method, str) or (
            has_id and not isinstance(ident, (str, int))
        ):
            self._error(
                ident if isinstance(ident, (str, int)) else None,
                INVALID_REQUEST,
                "a request needs a string method and a string or integer id",
            )
            return None
        params = message.get("params")
        if not has_id:
            return self._notification(method, params)
        self._request(ident, method, params)
        return None

    def _notification(self, method: str, params: object) -> str | None:
        if method == "exit":
            return "exit"
        handler = self.notifications.get(method)
        if handler is None or not self.initialized or self.shut_down:
            return None  # unknown, `$/...`, or before `initialize`: ignored
        try:
            handler(params)
        except Exception as err:  # the session goes on
            if self.on_error is not None:
                self.on_error(f"robotfix: internal error in {method}: {err!r}")
        return None

    def _request(self, ident: object, method: str, params: object) -> None:
        if self.shut_down:
            self._error(ident, INVALID_REQUEST, "the server was shut down")
            return
        if method == "shutdown":
            self.shut_down = True
            self._respond(ident, None)
            return
        if method != "initialize" and not self.initialized:
            self._error(ident, SERVER_NOT_INITIALIZED, "initialize comes first")
            return
        if method == "initialize" and self.initialized:
            self._error(ident, INVALID_REQUEST, "initialize was already sent")
            return
        handler = self.requests.get(method)
        if handler is None:
            self._error(ident, METHOD_NOT_FOUND, f"unknown method {method}")
            return
        try:
            result = handler(params)
        except InvalidParamsError as err:
            self._error(ident, INVALID_PARAMS, f"invalid params of {method}: {err}")
            return
        except Exception as err:  # the session goes on
            self._error(ident, INTERNAL_ERROR, f"internal error in {method}: {err!r}")
            return
        if method == "initialize":
            self.initialized = True
        self._respond(ident, result)
