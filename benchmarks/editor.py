"""Editor latency: what one keystroke costs in `robotfix lsp`, and its cold start.

Per-edit latency is measured in-process, calling `api.check_source` exactly as the
server's `_publish` does (the document's settings, the server's catalog and kept
module summaries, the full text each time, the document's proof memo asked for
at each edit), after WARMUP edits; each edit changes one literal inside one
function in the middle of the file, so the text, and that function's proofs, differ
from every earlier edit. Each edit is also checked without the memo, the two in
alternating order, so that both columns see the same machine load, and the two
outputs are compared. Wall and CPU (process) times are printed: on a shared machine
the CPU time is the one that does not depend on the other jobs. Three files,
generated so nothing is fetched:

- unannotated 1,000-line node: the generated module with its refinements removed;
- annotated 300-line node and annotated 1,000-line file:
  benchmarks/generate_annotated.py.

Cold start spawns `python -m robotfix lsp`, sends initialize, initialized and didOpen
of the 300-line annotated node over stdio, and times the first publishDiagnostics
(median of COLD_RUNS fresh processes after one untimed start, and the median CPU
time of those processes), with bytecode as an installed wheel has it and in this
environment as it is.

Usage: python benchmarks/editor.py [EDITS] [COLD_RUNS] [REAL_NODE.py ...]
A real node given on the command line (for example navigation2's
nav2_simple_commander/robot_navigator.py, 1,294 lines) is measured too, twice: with a
comment line edited at its middle (an edit of text the memo keys on: nothing can be
replayed), and with the number nearest its middle inside a function body changed
(`name@number`: the edit the memo replays the other functions around, when the
skeleton blanks that number or it lies in a method: `skeleton.method_number`),
and with the number nearest its middle that the
skeleton blanks changed (`name@blanked`: one the memo can always replay around).
"""

from __future__ import annotations

import ast
import json
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from generate_annotated import generate

WARMUP = 5


def unannotated(lines: int) -> str:
    """The generated module without a refinement: plain floats and ints."""
    text = generate(lines)
    text = re.sub(r'Annotated\[(\w+), "[^"]*"\]', r"\1", text)
    return text.replace("from typing import Annotated\n", "")


def edited(text: str, n: int) -> str:
    """The text with a keystroke inside one function in the middle: one literal of
    its body (a value that reaches a refinement) changed."""
    blocks = text.split("\ndef on_scan_")
    middle = len(blocks) // 2
    block = blocks[middle]
    value = f"0.{500 + n % 400}"  # stays a valid distance, changes every edit
    blocks[middle] = block.replace("= 0.5\n", f"= {value}\n", 1)
    return "\ndef on_scan_".join(blocks)


def _server_catalog(path: Path) -> object:
    """The catalog `server._catalog` builds for a document no other buffer affects."""
    from robotfix import api, config
    from robotfix.lsp import server
    from robotfix.ros.catalog import MsgCatalog

    settings = config.load(path)
    files = api.interface_files(server._interface_folders(path, settings))
    return MsgCatalog(
        files,
        rep103=settings.rep103,
        unit_suffixes=settings.unit_suffixes,
        distro=settings.ros_distro,
        texts={},
        installed=server._INSTALLED,
    )


def _server_inputs(path: Path) -> Callable[[Path], tuple[object, object, object]]:
    """What `server._check` passes `api.check_source` besides the text at each
    keystroke: the document's settings, the catalog and the module summaries the
    server keeps (`server._project`), asked for again at each edit, as there."""
    from robotfix.lsp import server

    catalog = _server_catalog(path)

    def inputs(path: Path) -> tuple[object, object, object]:
        settings = server._settings(path)
        return settings, catalog, server._project(catalog, path, settings)

    return inputs


def edited_real(text: str, n: int) -> str:
    """A real node with a keystroke in a comment line inserted at its middle."""
    lines = text.splitlines(keepends=True)
    middle = len(lines) // 2
    indent = re.match(r"[ \t]*", lines[middle]).group(0)  # type: ignore[union-attr]
    return "".join([*lines[:middle], f"{indent}# edit {n}\n", *lines[middle:]])


def edited_real_number(text: str, n: int) -> str:
    """A real node with the number nearest its middle that a function body holds
    changed (a gain, a period, a limit tuned): the memo replays the other
    functions around it when the skeleton blanks that number, or when it lies in
    a method whose text holds no word the analysis reads (on nav2's file it is a
    timeout in a call's arguments in a method: `skeleton.method_number`)."""
    tree = ast.parse(text)
    middle = len(text.splitlines()) // 2
    numbers = [
        node
        for function in ast.walk(tree)
        if isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef))
        for statement in function.body
        for node in ast.walk(statement)
        if isinstance(node, ast.Constant)
        and type(node.value) in (int, float)
        and node.lineno == node.end_lineno
    ]
    if not numbers:
        return edited_real(text, n)
    target = min(numbers, key=lambda c: (abs(c.lineno - middle), c.col_offset))
    return _changed(text, target, n)


def edited_real_blanked(text: str, n: int) -> str:
    """A real node with the number nearest its middle that the memo's skeleton
    blanks changed (a local's value, an index, a return; not a call's argument,
    which other items may read), to another of the same length (a literal
    followed by more code keeps its length in the skeleton) and different at
    every edit (at least two digits): the edit after which the memo can replay
    the other items. A comment edit when the file has no such number."""
    from robotfix.analysis.skeleton import skeleton

    lines = text.splitlines(keepends=True)
    kept = skeleton(ast.parse(text), lines).splitlines(keepends=True)
    middle = len(lines) // 2
    numbers = [
        node
        for node in ast.walk(ast.parse(text))
        if isinstance(node, ast.Constant)
        and type(node.value) in (int, float)
        and node.lineno == node.end_lineno
        and kept[node.lineno - 1].encode()[node.col_offset :].startswith(b"#")
        and sum(c.isdigit() for c in _literal(lines, node)) >= 2
    ]
    if not numbers:
        return edited_real(text, n)
    target = min(numbers, key=lambda c: (abs(c.lineno - middle), c.col_offset))
    literal = _literal(lines, target)
    digits = [i for i, c in enumerate(literal) if c.isdigit()]
    value = int("".join(literal[i] for i in digits))
    low = 10 ** (len(digits) - 1) if type(target.value) is int else 0
    value = low + (value - low + n + 1) % (10 ** len(digits) - low)
    chars = list(literal)
    for i, c in zip(digits, f"{value:0{len(digits)}d}", strict=True):
        chars[i] = c
    line = lines[target.lineno - 1].encode()
    lines[target.lineno - 1] = (
        line[: target.col_offset]
        + "".join(chars).encode()
        + line[target.end_col_offset :]
    ).decode()
    return "".join(lines)


def _literal(lines: list[str], node: ast.Constant) -> str:
    raw = lines[node.lineno - 1].encode()
    return raw[node.col_offset : node.end_col_offset].decode()


def _changed(text: str, target: ast.Constant, n: int) -> str:
    value = target.value + (n % 9 + 1) * (0.125 if type(target.value) is float else 1)
    lines = text.splitlines(keepends=True)
    line = lines[target.lineno - 1]
    start = len(line.encode()[: target.col_offset].decode())
    end = len(line.encode()[: target.end_col_offset].decode())
    lines[target.lineno - 1] = line[:start] + repr(value) + line[end:]
    return "".join(lines)


def per_edit(
    name: str, text: str, edits: int, folder: Path, edit: object = None
) -> dict[str, object]:
    from robotfix import api
    from robotfix.lsp import server

    path = folder / f"{name}.py"
    path.write_text(text)
    as_server = _server_inputs(path)
    uri = path.as_uri()
    # the document's proof memo, as `server._publish` passes it (none before it
    # was): asked for at each edit, and the path a new string each time, as there
    kept: dict[str, object] = {"memo": True} if hasattr(server, "_memo") else {}

    def once(n: int, extra: dict[str, object]) -> tuple[float, float, list[object]]:
        source = (edit or edited)(text, n)  # type: ignore[operator]
        started, cpu = time.perf_counter(), time.process_time()
        memo = {"memo": server._memo(uri)} if extra else {}
        found = api.check_source(source, str(Path(path)), *as_server(path), **memo)  # type: ignore[arg-type]
        wall = (time.perf_counter() - started) * 1000
        return wall, (time.process_time() - cpu) * 1000, found

    for n in range(WARMUP):
        once(n, kept)
        once(n, {})
    times: list[float] = []
    plain: list[float] = []  # the same edits checked without the memo, paired
    cpu_times: list[float] = []
    cpu_plain: list[float] = []
    counts: set[int] = set()
    same = True
    for n in range(WARMUP, WARMUP + edits):
        pair = [(kept, times, cpu_times), ({}, plain, cpu_plain)]
        found = []
        for extra, into, cpu_into in pair if n % 2 else pair[::-1]:
            seconds, cpu, diagnostics = once(n, extra)
            into.append(seconds)
            cpu_into.append(cpu)
            found.append(diagnostics)
        counts.add(len(found[0]))
        same = same and repr(found[0]) == repr(found[1])
    times.sort()
    plain.sort()
    # made by the first check that is given the memo (read after the edits)
    units = getattr(server._memos.get(uri), "units", None)
    return {
        "file": name,
        "lines": text.count("\n"),
        "p50_ms": round(statistics.median(times), 1),
        "p90_ms": round(times[int(0.9 * (len(times) - 1))], 1),
        "p50_without_memo_ms": round(statistics.median(plain), 1),
        "p90_without_memo_ms": round(plain[int(0.9 * (len(plain) - 1))], 1),
        "cpu_p50_ms": round(statistics.median(cpu_times), 1),
        "cpu_p50_without_memo_ms": round(statistics.median(cpu_plain), 1),
        "diagnostics": sorted(counts),
        # items of the file replayed from the document's unit memo, per edit
        "unit_hits_per_edit": round(getattr(units, "hits", 0) / (WARMUP + edits), 1),
        "same_output_as_without_memo": same,
    }


def _frame(message: dict[str, object]) -> bytes:
    body = json.dumps(message).encode()
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


def _read_message(stream: object) -> dict[str, object]:
    length = 0
    while True:
        line = stream.readline()  # type: ignore[attr-defined]
        if not line:
            raise EOFError("the server closed its output")
        if line in (b"\r\n", b"\n"):
            break
        if line.lower().startswith(b"content-length:"):
            length = int(line.split(b":")[1])
    return json.loads(stream.read(length))  # type: ignore[attr-defined,no-any-return]


def cold_start(path: Path, env: dict[str, str]) -> float:
    """Seconds from spawning `robotfix lsp` to its first publishDiagnostics."""
    uri = path.as_uri()
    started = time.perf_counter()
    proc = subprocess.Popen(
        [sys.executable, "-m", "robotfix", "lsp"],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        env=env,
    )
    assert proc.stdin is not None and proc.stdout is not None
    init = {
        "processId": os.getpid(),
        "rootUri": path.parent.as_uri(),
        "capabilities": {},
    }
    proc.stdin.write(
        _frame({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": init})
    )
    proc.stdin.write(_frame({"jsonrpc": "2.0", "method": "initialized", "params": {}}))
    document = {
        "uri": uri,
        "languageId": "python",
        "version": 1,
        "text": path.read_text(),
    }
    proc.stdin.write(
        _frame(
            {
                "jsonrpc": "2.0",
                "method": "textDocument/didOpen",
                "params": {"textDocument": document},
            }
        )
    )
    proc.stdin.flush()
    try:
        while True:
            message = _read_message(proc.stdout)
            if message.get("method") == "textDocument/publishDiagnostics":
                return time.perf_counter() - started
    finally:
        proc.kill()
        proc.wait()


def main(edits: int, cold_runs: int, real: list[Path]) -> None:
    files = {
        "unannotated_1000": unannotated(1000),
        "annotated_300": generate(300),
        "annotated_1000": generate(1000),
    }
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        for name, text in files.items():
            print(json.dumps(per_edit(name, text, edits, folder)), flush=True)
        for node in real:
            row = per_edit(node.stem, node.read_text(), edits, folder, edited_real)
            print(json.dumps(row), flush=True)
            name, text = f"{node.stem}@number", node.read_text()
            row = per_edit(name, text, edits, folder, edited_real_number)
            print(json.dumps(row), flush=True)
            name = f"{node.stem}@blanked"
            row = per_edit(name, text, edits, folder, edited_real_blanked)
            print(json.dumps(row), flush=True)
        node = folder / "cold_node.py"
        node.write_text(files["annotated_300"])
        # as installed (a wheel has .pyc files; a checkout run with
        # PYTHONDONTWRITEBYTECODE=1 compiles every module on each start): bytecode
        # kept under a private prefix, written by one start before the timed ones
        installed = {
            **{k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"},
            "PYTHONPYCACHEPREFIX": str(folder / "pycache"),
        }
        for mode, env in (("as_installed", installed), ("this_env", dict(os.environ))):
            if cold_runs:
                cold_start(node, env)
            cold, cpu = [], []
            for _ in range(cold_runs):
                before = resource.getrusage(resource.RUSAGE_CHILDREN)
                cold.append(cold_start(node, env))
                after = resource.getrusage(resource.RUSAGE_CHILDREN)
                cpu.append(
                    after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
                )
            cold.sort()
            if not cold:
                return
            row = {
                "cold_start_to_first_diagnostics_ms": round(
                    statistics.median(cold) * 1000
                ),
                # the server's user + sys until it is killed: what does not depend
                # on the other jobs of a shared machine
                "cpu_p50_ms": round(statistics.median(cpu) * 1000),
                "min_ms": round(cold[0] * 1000),
                "max_ms": round(cold[-1] * 1000),
                "runs": cold_runs,
                "bytecode": mode,
            }
            print(json.dumps(row), flush=True)


if __name__ == "__main__":
    main(
        int(sys.argv[1]) if len(sys.argv) > 1 else 30,
        int(sys.argv[2]) if len(sys.argv) > 2 else 5,
        [Path(a) for a in sys.argv[3:]],
    )
