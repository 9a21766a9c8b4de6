"""Editor latency with a real client: where each millisecond goes between opening a
file in Neovim and seeing its diagnostics, and after an edit.

Headless Neovim (`nvim`, 0.7 or later; `apt install neovim`) runs
benchmarks/nvim_latency.lua: it opens the file, starts the server with its built-in
client (`vim.lsp.start_client`, as the documented snippet's `vim.lsp.start` does),
waits for the first diagnostics, edits one line RUNS times, asks for a hover and for
code actions. The server runs under benchmarks/nvim_server.py, which logs the time
(and its process CPU time) of each phase; Neovim logs its own with
`vim.loop.hrtime`, the same monotonic clock, so the two sides line up. Each run
starts Neovim and the server afresh, with an empty `XDG_CACHE_HOME`.

Usage:
  python benchmarks/nvim_latency.py [FILE] [--runs N] [--debounce MS]
         [--edit LINE TEXT_A TEXT_B] [--at LINE,COL]
Without FILE, the 300-line annotated node of benchmarks/generate_annotated.py, with
a literal of a function in its middle edited. Medians of the runs are printed, in ms.
For bytecode as an installed wheel has it in a checkout with PYTHONDONTWRITEBYTECODE
set, give PYTHONPYCACHEPREFIX a folder (and run once to fill it).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from generate_annotated import generate

HERE = Path(__file__).parent


def session(file: Path, args: argparse.Namespace, scratch: Path) -> dict[str, float]:
    times, out = scratch / "server.jsonl", scratch / "nvim.json"
    times.unlink(missing_ok=True)
    env = dict(
        os.environ,
        RF_FILE=str(file),
        RF_OUT=str(out),
        RF_TIMES=str(times),
        RF_CMD=json.dumps([sys.executable, str(HERE / "nvim_server.py")]),
        RF_DEBOUNCE=str(args.debounce),
        RF_AT=args.at,
        XDG_CACHE_HOME=str(scratch / "cache"),
    )
    if args.edit:
        env.update(
            RF_EDIT_LINE=args.edit[0], RF_EDIT_A=args.edit[1], RF_EDIT_B=args.edit[2]
        )
    lua = f"luafile {HERE / 'nvim_latency.lua'}"
    spawned = time.monotonic()
    subprocess.run(
        ["nvim", "--headless", "-u", "NONE", "-i", "NONE", "-n", "-c", lua],
        env=env,
        stdin=subprocess.DEVNULL,
        timeout=300,
        check=True,
    )
    nvim = json.loads(out.read_text())
    log = [json.loads(line) for line in times.read_text().splitlines()]

    def at(what: str, n: int = 0) -> dict[str, float]:
        return [e for e in log if e["what"] == what][n]

    def ms(a: float, b: float) -> float:
        return (b - a) * 1000

    process, opened = at("process"), at("recv textDocument/didOpen")
    published = at("sent textDocument/publishDiagnostics")
    row = {
        "client: Neovim start to init script": ms(spawned, nvim["lua"]),
        "client: start_client to the server's first line (exec, Python start)": ms(
            nvim["start"], process["t0"]
        ),
        "server: CLI imported": ms(process["t0"], at("cli imported")["t"]),
        "server: language server imported": ms(
            at("cli imported")["t"], at("server imported")["t"]
        ),
        "client: initialize, initialized, didOpen sent": ms(
            at("server imported")["t"], opened["t"]
        )
        - ms(at("recv initialize")["t"], at("done initialize")["t"]),
        "server: catalog": ms(at("recv catalog")["t"], at("done catalog")["t"]),
        "server: first check (its imports, analysis, z3)": ms(
            at("recv check")["t"], at("done check")["t"]
        ),
        "server: didOpen to diagnostics sent": ms(opened["t"], published["t"]),
        "client: diagnostics received": ms(published["t"], nvim["opened"]),
        "cold total: Neovim start to diagnostics": ms(spawned, nvim["opened"]),
        "cold server share (first line to diagnostics sent)": ms(
            process["t0"], published["t"]
        ),
        "cold server CPU (process, at diagnostics sent)": published["cpu"] * 1000,
        "  CPU: Python start (to the first line)": process["cpu"] * 1000,
        "  CPU: CLI imported": (at("cli imported")["cpu"] - process["cpu"]) * 1000,
        "  CPU: language server imported": (
            at("server imported")["cpu"] - at("cli imported")["cpu"]
        )
        * 1000,
        "  CPU: first check": (at("done check")["cpu"] - at("recv check")["cpu"])
        * 1000,
        "modules the first check imported": at("done check")["modules"],
    }
    changes = [e for e in log if e["what"] == "recv textDocument/didChange"]
    sends = [e for e in log if e["what"] == "sent textDocument/publishDiagnostics"]
    edits = []
    for edit, change in zip(nvim["edits"], changes, strict=False):
        sent = next(e for e in sends if e["t"] >= change["t"])
        edits.append(
            (
                ms(edit["sent"], change["t"]),
                ms(change["t"], sent["t"]),
                (sent["cpu"] - change["cpu"]) * 1000,
                ms(sent["t"], edit["got"]),
                ms(edit["sent"], edit["got"]),
            )
        )
    first, later = edits[0], edits[1:]
    names = ("debounce (buffer change to didChange read)", "server", "server CPU")
    for label, values in (("first edit", [first]), ("later edits", later)):
        for i, name in enumerate((*names, "client: diagnostics received", "total")):
            row[f"{label}: {name}"] = statistics.median(v[i] for v in values)
    row["hover round trip"] = ms(*nvim["hover"])
    row["code action round trip"] = ms(*nvim["action"])
    row["diagnostics at open"] = nvim["count"]
    return row


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("file", nargs="?", type=Path)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--debounce", type=int, default=150)
    parser.add_argument("--edit", nargs=3, metavar=("LINE", "TEXT_A", "TEXT_B"))
    parser.add_argument("--at", default="0,0")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        scratch = Path(folder)
        file = args.file
        if file is None:
            file = scratch / "node.py"
            text = generate(300)
            file.write_text(text)
            lines = text.splitlines()
            middle = next(
                i
                for i in range(len(lines) // 2, len(lines))
                if lines[i].endswith("= 0.5")
            )
            base = lines[middle]
            args.edit = args.edit or [str(middle + 1), base, base.replace("0.5", "0.6")]
        rows = [session(file.resolve(), args, scratch) for _ in range(args.runs)]
    load = os.getloadavg()[0]
    print(
        f"{file.name}, {args.runs} runs, debounce {args.debounce} ms, load {load:.1f}"
    )
    for key in rows[0]:
        values = [row[key] for row in rows]
        print(
            f"{key:70s} {statistics.median(values):8.1f}"
            f"  ({min(values):.1f}-{max(values):.1f})"
        )


if __name__ == "__main__":
    main()
