"""Issue 25 target 1 in instructions: a cold check against the parse floor, counted by
callgrind, which a shared machine's load does not move (time moved 30% between
batches of the same command here).

Usage: python benchmarks/instruction_ratio.py [--layouts N] [--python]
           FOLDER [FOLDER ...]

Runs, each in its own process under `valgrind --tool=callgrind` (valgrind must be on
PATH; about 50x slower than the runs themselves):

- the floor: `benchmarks/real_code.py`'s, a process that reads and `ast.parse`s the
  files `robotfix check` would check;
- RobotFix: `robotfix check FOLDERS --no-cache -j 1 --format concise`, after one run
  outside callgrind that writes the bytecode of RobotFix's own modules (so neither
  side counts compiling Python it imports).

and prints both totals (every instruction of the process: start-up, imports, exit)
and their ratio. With `--python` both count on a copy of the folders' Python files
only (`real_code.py --mypy`'s tree: no C++, launch or parameter files beside them):
the corpus issue 25's target 1 names ("public ROS Python"), where without it the
check's reading of C++ for the ROS graph counts against a floor that parses only
Python. Instructions are not time: the floor is C code that runs more
instructions per cycle than the analysis, so the ratio in CPU time (`real_code.py`)
is higher than this one.

`PYTHONHASHSEED=0` makes a count repeat only in the same surroundings. CPython's
cache of type attributes is indexed by the address of each attribute's name, so the
length of the working folder's name, of an environment variable or of the callgrind
file moves every later object and, with them, which names collide there: the same
process counted 825.8 M, 827.2 M, 840.5 M or 845.4 M instructions as only such a
length changed (up to 2.4%; on corpus25 the floor spread 7,225-7,387 M). A change to
RobotFix's code moves the objects too, so two versions counted once each differ by
up to 2% for no reason of theirs. `--layouts N` counts each side N times, the
environment padded by a different length each time, and prints every count and
the ratio of the medians.
"""

from __future__ import annotations

import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

from real_code import FLOOR, module_tree  # the same floor and tree as the timed one

from robotfix.api import python_files

TOTALS = re.compile(r"^==\d+== Collected : (\d+)", re.MULTILINE)
PAD = "ROBOTFIX_BENCHMARK_PAD"  # read by nobody: it only moves the process's objects


def layout(env: dict[str, str], number: int) -> dict[str, str]:
    """`env` for the `number`th layout: the first as given, each next one padded by a
    different length (lengths that moved the counts of a test process)."""
    padded = dict(env)
    padded.pop(PAD, None)
    if number:
        padded[PAD] = (
            "x" * (8, 24, 333, 1000, 4096)[(number - 1) % 5] * (1 + (number - 1) // 5)
        )
    return padded


def summary(floors: list[int], checks: list[int]) -> list[str]:
    """The lines that report counts made in one or more layouts."""
    floor, check = statistics.median(floors), statistics.median(checks)
    lines = [
        f"floor (read + ast.parse, own process): {floor / 1e6:,.1f} M instructions",
        f"robotfix check --no-cache -j 1:        {check / 1e6:,.1f} M instructions",
        f"ratio: {check / floor:.2f}x (issue 25: at most 5.5x, then 4.5x)",
    ]
    if len(floors) > 1:
        pairs = list(zip(floors, checks, strict=True))
        each = ", ".join(f"{c / 1e6:,.1f}/{f / 1e6:,.1f}" for f, c in pairs)
        ratios = sorted(c / f for f, c in pairs)
        lines[0] = lines[0].replace("floor", f"floor, median of {len(floors)}", 1)
        lines[1] = lines[1].replace(":       ", f", median of {len(checks)}:", 1)
        lines.append(f"each layout, check/floor M: {each}")
        lines.append(f"ratio in one layout: {ratios[0]:.2f}x to {ratios[-1]:.2f}x")
    return lines


def instructions(command: list[str], env: dict[str, str], out: Path) -> int:
    """Instructions callgrind counted for `command` (its whole process)."""
    done = subprocess.run(
        ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", *command],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        env=env,
        text=True,
        check=False,
    )
    found = TOTALS.search(done.stderr)
    if found is None:
        sys.exit(f"callgrind printed no total for {command[:4]}: {done.stderr[-400:]}")
    return int(found.group(1))


def main(argv: list[str]) -> int:
    layouts, python_only = 1, False
    while argv[:1] in (["--layouts"], ["--python"]):
        if argv[0] == "--python":
            python_only, argv = True, argv[1:]
        elif len(argv) > 1 and argv[1].isdigit():
            layouts, argv = max(1, int(argv[1])), argv[2:]
        else:
            break
    folders = [Path(p) for p in argv]
    if not folders or shutil.which("valgrind") is None:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        print("(valgrind must be on PATH)", file=sys.stderr)
        return 2
    files = python_files(folders)
    env = dict(os.environ, PYTHONHASHSEED="0")
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    with tempfile.TemporaryDirectory() as tmp:
        if python_only:
            files = module_tree(files, folders, Path(tmp, "tree"))
            folders = [Path(tmp, "tree")]
        env.setdefault("ROBOTFIX_CACHE_DIR", str(Path(tmp, "machine-cache")))
        names = Path(tmp, "names.txt")
        names.write_text("".join(f"{f}\n" for f in files), "utf-8", "surrogateescape")
        floor_script = Path(tmp, "floor.py")
        floor_script.write_text(FLOOR, "utf-8")
        check = [sys.executable, "-m", "robotfix", "check", *map(str, folders)]
        check += ["--no-cache", "-j", "1", "--format", "concise"]
        warm = subprocess.run(check, env=env, stdout=subprocess.DEVNULL, check=False)
        if warm.returncode not in (0, 1):  # 2: a failed run, nothing to count
            sys.exit(f"robotfix check exited {warm.returncode}: not counted")
        floors, checks = [], []
        for number in range(layouts):
            padded = layout(env, number)
            floor = [sys.executable, str(floor_script), str(names)]
            floors.append(instructions(floor, padded, Path(tmp, "cg.floor")))
            checks.append(instructions(check, padded, Path(tmp, "cg.check")))
    print(f"files: {len(files)}")
    print("\n".join(summary(floors, checks)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
