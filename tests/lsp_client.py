"""A tiny language-server client for the tests: spawns a server, frames messages
with `Content-Length` over its pipes, and collects what it sends, plain dicts.

A thread reads the server's output into a queue, so neither side blocks on a full
pipe. The client answers the server's requests (`client/registerCapability`) with a
null result, as an editor does, and keeps them in `server_requests`."""

from __future__ import annotations

import contextlib
import json
import os
import queue
import subprocess
import sys
import threading
from pathlib import Path
from typing import Any

TIMEOUT = 120  # seconds to wait for one answer (a loaded machine is slow)


def frame(message: object) -> bytes:
    body = json.dumps(message).encode()
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


class Client:
    def __init__(
        self, command: list[str] | None = None, env: dict[str, str] | None = None
    ) -> None:
        self.proc = subprocess.Popen(
            command or [sys.executable, "-m", "robotfix", "lsp"],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            env=env if env is not None else dict(os.environ),
        )
        self.published: list[dict[str, Any]] = []  # publishDiagnostics params
        self.logged: list[dict[str, Any]] = []  # window/logMessage params
        self.server_requests: list[dict[str, Any]] = []
        self.errors: list[dict[str, Any]] = []  # responses with id null
        self._incoming: queue.Queue[dict[str, Any] | None] = queue.Queue()
        self._next_id = 0
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    # -- the wire ------------------------------------------------------------------
    def _read(self) -> None:
        stream = self.proc.stdout
        assert stream is not None
        while True:
            length = None
            while True:
                line = stream.readline()
                if not line:
                    self._incoming.put(None)
                    return
                if line in (b"\r\n", b"\n"):
                    break
                name, _, value = line.partition(b":")
                if name.strip().lower() == b"content-length":
                    length = int(value)
            assert length is not None, "the server sent a message without a length"
            self._incoming.put(json.loads(stream.read(length)))

    def send_raw(self, data: bytes) -> None:
        assert self.proc.stdin is not None
        self.proc.stdin.write(data)
        self.proc.stdin.flush()

    def send(self, message: object) -> None:
        self.send_raw(frame(message))

    def notify(self, method: str, params: object = None) -> None:
        self.send({"jsonrpc": "2.0", "method": method, "params": params})

    def request(self, method: str, params: object = None) -> dict[str, Any]:
        """Send a request; the server's response message (result or error)."""
        self._next_id += 1
        ident = self._next_id
        self.send({"jsonrpc": "2.0", "id": ident, "method": method, "params": params})
        return self.response(ident)

    def response(self, ident: object) -> dict[str, Any]:
        while True:
            message = self.next()
            if message.get("id") == ident and "method" not in message:
                return message

    def next(self) -> dict[str, Any]:
        """The server's next message, after recording it."""
        message = self._incoming.get(timeout=TIMEOUT)
        if message is None:
            raise EOFError("the server closed its output")
        method = message.get("method")
        if method == "textDocument/publishDiagnostics":
            self.published.append(message["params"])
        elif method == "window/logMessage":
            self.logged.append(message["params"])
        elif method is not None and "id" in message:
            self.server_requests.append(message)
            self.send({"jsonrpc": "2.0", "id": message["id"], "result": None})
        elif method is None and message.get("id") is None:
            self.errors.append(message)
        return message

    def diagnostics(self) -> dict[str, Any]:
        """Wait for the next publishDiagnostics; its params."""
        count = len(self.published)
        while len(self.published) == count:
            self.next()
        return self.published[count]

    # -- the session -----------------------------------------------------------------
    def initialize(
        self, root: Path, capabilities: dict[str, Any] | None = None
    ) -> dict[str, Any]:
        answer = self.request(
            "initialize",
            {
                "processId": os.getpid(),
                "rootUri": root.as_uri(),
                "capabilities": capabilities or {},
            },
        )
        self.notify("initialized", {})
        return answer

    def open(self, path: Path, text: str, language: str = "python") -> str:
        uri = path.as_uri()
        document = {"uri": uri, "languageId": language, "version": 1, "text": text}
        self.notify("textDocument/didOpen", {"textDocument": document})
        return uri

    def change(self, uri: str, version: int, *changes: dict[str, Any]) -> None:
        self.notify(
            "textDocument/didChange",
            {
                "textDocument": {"uri": uri, "version": version},
                "contentChanges": list(changes),
            },
        )

    def hover(self, uri: str, line: int, character: int) -> dict[str, Any]:
        return self.request(
            "textDocument/hover",
            {
                "textDocument": {"uri": uri},
                "position": {"line": line, "character": character},
            },
        )

    def code_action(
        self, uri: str, first: int, last: int, context: dict[str, Any]
    ) -> list[dict[str, Any]]:
        """The code actions for lines first..last (0-based), asked with `context`."""
        lines = {"line": first, "character": 0}, {"line": last, "character": 0}
        params = {
            "textDocument": {"uri": uri},
            "range": {"start": lines[0], "end": lines[1]},
            "context": context,
        }
        result: list[dict[str, Any]] = self.request("textDocument/codeAction", params)[
            "result"
        ]
        return result

    def stop(self) -> int:
        """shutdown, exit; the server's exit code."""
        answer = self.request("shutdown")
        assert answer.get("result", "missing") is None, answer
        self.notify("exit")
        return self.wait()

    def wait(self) -> int:
        assert self.proc.stdin is not None
        with contextlib.suppress(BrokenPipeError):
            self.proc.stdin.close()
        code = self.proc.wait(TIMEOUT)
        self._reader.join(TIMEOUT)
        assert self.proc.stderr is not None
        self.proc.stderr.close()
        assert self.proc.stdout is not None
        self.proc.stdout.close()
        return code

    def kill(self) -> None:
        if self.proc.poll() is None:
            self.proc.kill()
        self.wait()
