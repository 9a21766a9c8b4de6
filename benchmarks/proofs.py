"""Proof throughput, and the pre-pass checked verdict for verdict against z3 alone.

Usage: python benchmarks/proofs.py [LINES]   (the generated module, 10,000 lines by
default; plus the hand-written workloads: tests/cases, the thesis's seed programs and
the whole-node cases)

For each workload it checks every file twice in-process: on the fast path (the
pre-pass `smt.prepass`, and RF509's witnesses `annotations.witness`) and on z3 alone,
as before. It prints the VCs asked, how many folded without z3, how many the pre-pass
proved, how many went to z3, the CPU seconds and VCs per CPU second of each path.
It fails (exit status 1) if the diagnostics differ in any byte, if the pre-pass
proves a VC that z3 alone did not prove, or if a witness calls satisfiable a
refinement z3 found contradictory.
`tests/test_prepass.py` runs the same comparison on tests/cases.
"""

from __future__ import annotations

import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path
from typing import Any

from generate_annotated import generate

from robotfix import api
from robotfix.analysis import consistency
from robotfix.config import Config
from robotfix.ros.catalog import MsgCatalog
from robotfix.smt.fold import fold
from robotfix.smt.prepass import proves
from robotfix.vc import VC, Proved, Verdict

ROOT = Path(__file__).resolve().parent.parent
CASES = ROOT / "tests" / "cases"


@dataclass
class Tally:
    vcs: int = 0
    folded: int = 0
    prepass: int = 0
    seconds: float = 0.0
    asked: list[tuple[VC, Verdict]] = field(default_factory=list)
    witnessed: list[tuple[VC, Verdict]] = field(default_factory=list)


@contextmanager
def recording(tally: Tally, fast: bool) -> Iterator[None]:
    """fast: the pre-pass and the RF509 witnesses on; else z3 alone, and each
    question a witness would have answered is kept with z3's verdict."""
    original = api.Discharger.__call__
    witness = consistency.has_witness
    pending: list[bool] = []

    def call(self: api.Discharger, vc: VC) -> Verdict:
        verdict = original(self, vc)
        tally.vcs += 1
        if fold(vc.goal) is True:
            tally.folded += 1
        elif fast and proves(vc):
            tally.prepass += 1
        if not fast:
            tally.asked.append((vc, verdict))
            if pending and pending.pop():
                tally.witnessed.append((vc, verdict))
        return verdict

    def no_witness(predicate: Any, sort: Any, budget: Any = None) -> bool:
        pending[:] = [witness(predicate, sort)]  # the next question is its own
        return False

    api.Discharger.__call__ = call  # type: ignore[method-assign]
    api.Discharger.prepass = fast
    if not fast:
        consistency.has_witness = no_witness
    try:
        yield
    finally:
        api.Discharger.__call__ = original  # type: ignore[method-assign]
        api.Discharger.prepass = True
        consistency.has_witness = witness


@cache
def catalog_for(folder: Path) -> MsgCatalog:
    folders = [CASES / "msgs", folder / "msg"]
    return MsgCatalog(api.interface_files([f for f in folders if f.is_dir()]))


def run(files: list[tuple[str, str, Path]], prepass: bool) -> tuple[Tally, list[str]]:
    tally = Tally()
    shown: list[str] = []
    with recording(tally, prepass):
        started = time.process_time()  # CPU: steadier than wall on a busy machine
        for name, text, folder in files:
            found = api.check_source(text, name, Config(), catalog_for(folder))
            shown.extend(f"{name}: {d!r}" for d in found)
        tally.seconds = time.process_time() - started
    return tally, shown


def compare(label: str, files: list[tuple[str, str, Path]]) -> bool:
    run(files, True)  # warm-up: imports, caches, the parser
    fast, fast_out = run(files, True)
    slow, slow_out = run(files, False)
    unsound = [vc for vc, verdict in slow.asked if proves(vc) and verdict != Proved()]
    unsound += [vc for vc, verdict in slow.witnessed if verdict == Proved()]
    to_z3 = fast.vcs - fast.folded - fast.prepass
    print(
        f"{label}: {len(files)} files, {fast.vcs} VCs: {fast.folded} folded, "
        f"{fast.prepass} proved by the pre-pass, {to_z3} to z3"
    )
    print(
        f"  fast path {fast.seconds:.2f} s ({fast.vcs / fast.seconds:,.0f} VCs/s)"
        f"   z3 alone {slow.seconds:.2f} s ({slow.vcs / slow.seconds:,.0f} VCs/s, "
        f"{len(slow.witnessed)} RF509 questions a witness answers)"
    )
    same = fast_out == slow_out
    print(
        f"  diagnostics identical: {same}; answers z3 alone did not give: "
        f"{len(unsound)}"
    )
    for vc in unsound[:5]:
        print(f"    {vc}")
    return same and not unsound


def case_files(folder: Path) -> list[tuple[str, str, Path]]:
    return [
        (str(p), p.read_text(encoding="utf-8"), p.parent)
        for p in sorted(folder.rglob("*.py"))
    ]


def main(lines: int) -> int:
    generated = [("generated.py", generate(lines), CASES)]
    ok = compare(f"generated module, {lines:,} lines", generated)
    ok &= compare("tests/cases (all)", case_files(CASES))
    ok &= compare("seed programs", case_files(CASES / "seed"))
    ok &= compare("whole nodes", case_files(CASES / "nodes"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(int(sys.argv[1]) if len(sys.argv) > 1 else 10_000))
