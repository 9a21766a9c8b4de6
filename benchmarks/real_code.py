"""Issue 13, item 1: RobotFix on real (unannotated) ROS code against the parse floor.

Usage: python benchmarks/real_code.py [--pairs N] [--mypy] FOLDER [FOLDER ...]

Point it at checked-out ROS repositories (e.g. /work/corpus2, `benchmarks/corpus.md`);
nothing is committed or downloaded by this script. Each measurement is a fresh
process, so neither side pays for a heap the other one grew:

- the floor: a process that reads and `ast.parse`s the same files;
- RobotFix: `robotfix check FOLDERS --no-cache -j 1 --format concise`.

- with --mypy, mypy with its default checks, cold (`--no-incremental
  --ignore-missing-imports --follow-imports=silent --explicit-package-bases
  --namespace-packages --cache-dir=/dev/null .`, the performance report's command);
  all three then run on one copy of the folders' Python files whose folder names are
  made valid module names (`ros2+demos` -> `ros2_demos`), since mypy stops at a
  "duplicate module" otherwise. Issue 25: RobotFix never takes more CPU than mypy.

They run in pairs (triples with --mypy), alternating (A B A B ...; 3 unless told), so
load on a shared machine hits every side alike. Wall time and CPU time (user + sys, from
`os.wait4`) are the medians over the pairs; the ratio is RobotFix's over the floor's.
Peak memory is RobotFix's largest maxrss.
"""

from __future__ import annotations

import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from robotfix.api import python_files

# read + ast.parse, nothing else: the floor every checker stands on
FLOOR = """\
import ast, sys, warnings
warnings.simplefilter("ignore")
names = open(sys.argv[1], encoding="utf-8", errors="surrogateescape").read()
for name in names.split("\\n"):
    if name:
        try:
            ast.parse(open(name, "rb").read())
        except (SyntaxError, ValueError, OSError):
            pass
"""


def timed(
    command: list[str],
    env: dict[str, str],
    statuses: tuple[int, ...] = (0,),
    cwd: Path | None = None,
) -> tuple[float, float, float]:
    """Wall seconds, CPU seconds (user + sys) and maxrss (MB) of one process, which
    must end with one of `statuses` (a failed run is not timed)."""
    with tempfile.TemporaryFile() as errors:  # a file: a pipe could fill and block
        started = time.perf_counter()
        process = subprocess.Popen(
            command, stdout=subprocess.DEVNULL, stderr=errors, env=env, cwd=cwd
        )
        _, status, usage = os.wait4(process.pid, 0)
        process.returncode = os.waitstatus_to_exitcode(status)  # reaped by wait4
        wall = time.perf_counter() - started
        if process.returncode not in statuses:
            errors.seek(0)
            shown = errors.read().decode(errors="replace")[-2000:]
            raise SystemExit(f"{command[1:4]} exited {process.returncode}:\n{shown}")
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024


MYPY = [
    "-m",
    "mypy",
    "--no-incremental",
    "--ignore-missing-imports",
    "--follow-imports=silent",
    "--explicit-package-bases",
    "--namespace-packages",
    "--cache-dir=/dev/null",
    ".",
]


def module_tree(files: list[Path], folders: list[Path], into: Path) -> list[Path]:
    """Copies of the files under `into`, each folder name made a valid module name
    (mypy derives module names from the folders with --explicit-package-bases)."""
    copies = []
    for file in files:
        top = next(f for f in folders if file.is_relative_to(f))
        parts = [top.resolve().name, *file.relative_to(top).parts]
        names = [re.sub(r"\W", "_", p) for p in parts[:-1]]
        names = ["_" + n if n[:1].isdigit() else n for n in names]
        copy = into.joinpath(*names, parts[-1])
        copy.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(file, copy)
        copies.append(copy)
    return copies


def main(argv: list[str]) -> None:
    pairs, with_mypy = 3, False
    while argv[:1] in (["--pairs"], ["--mypy"]):
        if argv[0] == "--mypy":
            with_mypy, argv = True, argv[1:]
        else:
            pairs, argv = int(argv[1]), argv[2:]
    folders = [Path(a) for a in argv] or [Path(".")]
    files = python_files(folders)
    lines = sum(f.read_bytes().count(b"\n") for f in files)
    with tempfile.TemporaryDirectory() as tmp:
        if with_mypy:  # all three tools on one tree mypy can take
            tree = Path(tmp, "tree")
            files = module_tree(files, folders, tree)
            folders = [tree]
        listing = Path(tmp, "files.txt")
        listing.write_text(
            "\n".join(str(f) for f in files), encoding="utf-8", errors="surrogateescape"
        )
        floor_script = Path(tmp, "floor.py")
        floor_script.write_text(FLOOR, encoding="utf-8")
        env = dict(os.environ)
        env.setdefault("ROBOTFIX_CACHE_DIR", str(Path(tmp, "machine-cache")))
        # as installed (pip writes bytecode): with PYTHONDONTWRITEBYTECODE set, an
        # edited checkout would compile its changed modules again in every run
        env.pop("PYTHONDONTWRITEBYTECODE", None)
        floor = [sys.executable, str(floor_script), str(listing)]
        check = [sys.executable, "-m", "robotfix", "check", *map(str, folders)]
        check += ["--no-cache", "-j", "1", "--format", "concise"]
        found = (0, 1)  # robotfix check: no errors, errors found (2: a failure)
        timed(check, env, found)  # warm-up: bytecode and the machine cache written
        floors, checks, mypys = [], [], []
        for _ in range(pairs):
            floors.append(timed(floor, env))
            checks.append(timed(check, env, found))
            if with_mypy:  # 0: clean, 1: type errors found (2: it stopped)
                mypy = [sys.executable, *MYPY]
                mypys.append(timed(mypy, env, (0, 1), cwd=folders[0]))
    floor_wall = statistics.median(w for w, _, _ in floors)
    floor_cpu = statistics.median(c for _, c, _ in floors)
    check_wall = statistics.median(w for w, _, _ in checks)
    check_cpu = statistics.median(c for _, c, _ in checks)
    peak = max(m for _, _, m in checks)
    print(f"files: {len(files)}  lines: {lines}  pairs: {pairs} (medians)")
    print(
        f"floor (read + ast.parse, own process): {floor_wall:.2f} s wall, "
        f"{floor_cpu:.2f} s CPU"
    )
    print(
        f"robotfix check --no-cache -j 1:        {check_wall:.2f} s wall, "
        f"{check_cpu:.2f} s CPU  ({lines / check_wall:,.0f} lines/s)"
    )
    print(
        f"ratio: {check_wall / floor_wall:.2f}x wall, "
        f"{check_cpu / floor_cpu:.2f}x CPU "
        "(issue 25: at most 5.5x, then 4.5x)"
    )
    print(f"robotfix peak memory (maxrss): {peak:.0f} MB")
    if mypys:
        mypy_wall = statistics.median(w for w, _, _ in mypys)
        mypy_cpu = statistics.median(c for _, c, _ in mypys)
        print(
            f"mypy (default checks, cold):            {mypy_wall:.2f} s wall, "
            f"{mypy_cpu:.2f} s CPU, {max(m for _, _, m in mypys):.0f} MB; "
            f"robotfix / mypy: {check_cpu / mypy_cpu:.2f}x CPU (target: at most 1)"
        )
        for (_, check, _), (_, mypy, _) in zip(checks, mypys, strict=True):
            print(f"  triple: robotfix / mypy {check / mypy:.2f}x CPU")
    for (fw, fc, _), (cw, cc, cm) in zip(floors, checks, strict=True):
        print(
            f"  pair: floor {fw:.2f} s / {fc:.2f} s CPU, "
            f"robotfix {cw:.2f} s / {cc:.2f} s CPU, {cm:.0f} MB"
        )


if __name__ == "__main__":
    main(sys.argv[1:])
