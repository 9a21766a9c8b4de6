"""Time `robotfix check` on the thesis's 40 seed programs, each run a new process.

Every timed run reads no result cache (a fresh `--cache-dir` per run, so nothing is
replayed) and is verified: the exit status and the diagnostics must be exactly what
tests/cases/seed's assertions expect (benchmarks/seeds.py), or the benchmark stops.
Prints the medians of:

- one seed program (t16, with its msg/) checked cold: a new process, an empty result
  cache, the machine-local unit and catalog cache already filled;
- the same as a first run ever: an empty machine-local cache too
  (`ROBOTFIX_CACHE_DIR`, a fresh folder per run);
- all 20 seeds, buggy and fixed, one process per seed with its own msg/ folder, as
  tests/test_cases.py checks them (the 20 processes' total);
- all 40 files in one invocation, with every seed's msg/ folder: one catalog, so a
  type several seeds define (Twist) takes the first folder's definition (an RF510
  note for each other one); the findings are still the tests' 21.

Run: python benchmarks/seed_programs.py [RUNS]   (RUNS: 7 unless given; the three
whole-workload measurements use half of it, at least 1)
"""

from __future__ import annotations

import os
import statistics
import sys
import tempfile
from pathlib import Path

from seeds import ROOT, SEED, checked, folders, msg_args, programs

from robotfix.testing.expectations import read_expectations


def fresh(args: list[str], files: list[Path], machine_cache: bool = True) -> float:
    """One verified run with an empty result cache (and, unless `machine_cache`, an
    empty machine-local cache)."""
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(os.environ)
        if not machine_cache:
            env["ROBOTFIX_CACHE_DIR"] = str(Path(tmp, "machine"))
        cache = ["--cache-dir", str(Path(tmp, "results"))]
        return checked([*args, *cache], files, ROOT, env)


def main(runs: int) -> None:
    seed = SEED / "t16_negative_sum"
    one = [str(seed / "buggy.py"), *msg_args([seed])]
    fresh(one, [seed / "buggy.py"])  # untimed: fills the machine-local cache
    cold = [fresh(one, [seed / "buggy.py"]) for _ in range(runs)]
    first = [fresh(one, [seed / "buggy.py"], False) for _ in range(runs)]
    rounds = max(1, runs // 2)
    each = [
        sum(
            fresh([*map(str, programs([s])), *msg_args([s])], programs([s]))
            for s in folders()
        )
        for _ in range(rounds)
    ]
    every = programs(folders())
    together = [str(p) for p in every] + msg_args(folders())
    whole = [fresh(together, every) for _ in range(rounds)]
    print(
        f"one seed program, new process, empty result cache (median of {runs}): "
        f"{statistics.median(cold):.3f} s"
    )
    print(
        f"the same, a first run ever (empty machine cache too, median of {runs}): "
        f"{statistics.median(first):.3f} s"
    )
    print(
        f"all 20 seeds, a process per seed with its msg/ (total, median of {rounds}): "
        f"{statistics.median(each):.3f} s"
    )
    print(
        f"all 40 files in one invocation, every msg/ (median of {rounds}): "
        f"{statistics.median(whole):.3f} s"
    )
    expected = sum(len(read_expectations(p.read_text(encoding="utf-8"))) for p in every)
    print(f"every run's exit status and findings were the tests' ({expected} in all)")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 7)
