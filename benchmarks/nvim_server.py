"""`robotfix lsp` (through the CLI, as `robotfix lsp` starts it) with timestamps of
its phases, for benchmarks/nvim_latency.py: JSON lines appended to $RF_TIMES, each
with `time.monotonic()` (the clock of Neovim's `vim.loop.hrtime`) and the process's
CPU time so far. Nothing of the server is changed but the wrapping."""

import time

T0 = time.monotonic()

import json  # noqa: E402
import os  # noqa: E402
import sys  # noqa: E402

LOG = open(os.environ["RF_TIMES"], "a", encoding="utf-8")  # noqa: SIM115


def mark(what: str, **extra: object) -> None:
    now = {"t": time.monotonic(), "cpu": time.process_time(), "what": what}
    LOG.write(json.dumps({**now, **extra}) + "\n")
    LOG.flush()


mark("process", t0=T0)
from robotfix import cli  # noqa: E402

mark("cli imported")
from robotfix import api  # noqa: E402
from robotfix.lsp import rpc, server  # noqa: E402

mark("server imported")


def _timed(name: str, fn):  # type: ignore[no-untyped-def]
    def wrapped(*args, **kwargs):  # type: ignore[no-untyped-def]
        before = set(sys.modules)
        mark("recv " + name)
        try:
            return fn(*args, **kwargs)
        finally:
            mark("done " + name, modules=len(set(sys.modules) - before))

    return wrapped


for table in (server.REQUESTS, server.NOTIFICATIONS):
    for method, handler in list(table.items()):
        table[method] = _timed(method, handler)
server._catalog = _timed("catalog", server._catalog)
api.check_source = _timed("check", api.check_source)
_notify = rpc.Endpoint.notify
rpc.Endpoint.notify = lambda self, method, params: (
    _notify(self, method, params),
    mark("sent " + method),
)[0]
sys.argv = ["robotfix", "lsp"]
sys.exit(cli.main())
