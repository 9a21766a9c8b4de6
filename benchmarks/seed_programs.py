"""Time RobotFix on the thesis's 40 seed programs, each run in a new process.

Prints: one seed program checked cold (new process, median of several runs), the
same with an empty machine-local cache (a first run ever), and all 40 in one
invocation. Run: python benchmarks/seed_programs.py
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SEED = ROOT / "tests" / "cases" / "seed"


def timed(args: list[str], env: dict[str, str] | None = None) -> float:
    started = time.perf_counter()
    subprocess.run(
        [sys.executable, "-m", "robotfix", *args],
        capture_output=True,
        env=env,
        check=False,
        cwd=ROOT,
    )
    return time.perf_counter() - started


def main() -> None:
    case = SEED / "t16_negative_sum"
    one = ["check", str(case / "buggy.py"), "--msg-path", str(case / "msg")]
    timed(one)  # warm the machine-local cache
    warm = [timed(one) for _ in range(7)]
    cold = []
    for _ in range(3):
        with tempfile.TemporaryDirectory() as empty:
            cold.append(timed(one, {**os.environ, "ROBOTFIX_CACHE_DIR": empty}))
    every = ["check"]
    for folder in sorted(SEED.iterdir()):
        every += [str(folder / "buggy.py"), str(folder / "fixed.py")]
    all_runs = []
    for _ in range(3):
        # one invocation, so one msg path: each case's own msg/ folder would clash
        # (they annotate Twist differently); the 40 files still parse and check.
        all_runs.append(timed(every))
    print(
        f"one seed program, new process (median of {len(warm)}): "
        f"{statistics.median(warm):.3f} s"
    )
    print(
        f"one seed program, new process, empty cache (median of {len(cold)}): "
        f"{statistics.median(cold):.3f} s"
    )
    print(
        f"all 40 seed programs in one invocation (median of {len(all_runs)}): "
        f"{statistics.median(all_runs):.3f} s"
    )


if __name__ == "__main__":
    main()
