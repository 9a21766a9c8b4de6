"""Issue 25 target 1 in instructions: a cold check against the parse floor, counted by
callgrind, which a shared machine's load does not move (time moved 30% between
batches of the same command here).

Usage: python benchmarks/instruction_ratio.py FOLDER [FOLDER ...]

Runs, each in its own process under `valgrind --tool=callgrind` (valgrind must be on
PATH; about 50x slower than the runs themselves):

- the floor: `benchmarks/real_code.py`'s, a process that reads and `ast.parse`s the
  files `robotfix check` would check;
- RobotFix: `robotfix check FOLDERS --no-cache -j 1 --format concise`, after one run
  outside callgrind that writes the bytecode of RobotFix's own modules (so neither
  side counts compiling Python it imports).

and prints both totals (every instruction of the process: start-up, imports, exit)
and their ratio. `PYTHONHASHSEED=0` keeps the counts repeatable. Instructions are not
time: the floor is C code that runs more instructions per cycle than the analysis, so
the ratio in CPU time (`real_code.py`) is higher than this one.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from real_code import FLOOR  # the same floor as the timed benchmark

from robotfix.api import python_files

TOTALS = re.compile(r"^==\d+== Collected : (\d+)", re.MULTILINE)


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
    folders = [Path(p) for p in argv]
    if not folders or shutil.which("valgrind") is None:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        print("(valgrind must be on PATH)", file=sys.stderr)
        return 2
    files = python_files(folders)
    env = dict(os.environ, PYTHONHASHSEED="0")
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    with tempfile.TemporaryDirectory() as tmp:
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
        floor = instructions(
            [sys.executable, str(floor_script), str(names)], env, Path(tmp, "cg.floor")
        )
        ours = instructions(check, env, Path(tmp, "cg.check"))
    print(f"files: {len(files)}")
    print(f"floor (read + ast.parse, own process): {floor / 1e6:,.1f} M instructions")
    print(f"robotfix check --no-cache -j 1:        {ours / 1e6:,.1f} M instructions")
    print(f"ratio: {ours / floor:.2f}x (issue 25: at most 5.5x, then 4.5x)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
