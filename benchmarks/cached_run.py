"""Cached runs over a large unchanged tree, as on every save (issue 13 item 5).

Usage: python benchmarks/cached_run.py [CORPUS] [--copies N] [--jobs N] [--tree DIR]
Copies CORPUS (default /work/corpus: checked-out ROS repositories, with their
config/ parameter YAML) N times (default: until the tree has 200,000 lines of
Python) into a folder under /tmp, then runs `robotfix check` on it as a user would,
each in a fresh process: cold (empty cache), warm (unchanged tree), warm after
`touch`ing every file (same bytes, new mtimes), and warm after editing one helper
module that 14 nodes of each copy import (nav2_simple_commander's
robot_navigator.py, in the first copy only). Prints wall and CPU seconds
(medians, then each run's CPU), how many files were re-checked, and whether each
output equals the cold run's (the edit adds no diagnostic: all must be equal).
Nothing is committed or downloaded by this script; the tree is removed at the end
unless --tree is given.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

# under the navigation2 checkout, whatever its folder is called (`owner+repo`)
HELPER_FILE = Path("nav2_simple_commander/nav2_simple_commander/robot_navigator.py")
TARGET_LINES = 200_000

# In a child process: api.check_paths wrapped to keep each run's result in `seen`
# (also benchmarks/graph_workspace.py's).
COUNT_RUNS = """
from robotfix import api
real = api.check_paths
seen = []
def counted(*args, **kwargs):
    result = real(*args, **kwargs)
    seen.append(result)
    return result
api.check_paths = counted
"""
# The child process: the CLI, counting the files whose results came from the cache
# (stats go to stderr, the report to stdout).
DRIVER = (
    """
import sys, time
started, cpu = time.perf_counter(), time.process_time()
from robotfix import cli
"""
    + COUNT_RUNS
    + """
status = cli.main(sys.argv[1:])
r = seen[0]
print(f"STATS {len(r.checked)} {r.from_cache} {time.perf_counter() - started:.3f} "
      f"{time.process_time() - cpu:.3f}", file=sys.stderr)
sys.exit(status)
"""
)


def python_lines(folder: Path) -> int:
    return sum(p.read_bytes().count(b"\n") for p in folder.rglob("*.py") if p.is_file())


def make_tree(corpus: Path, tree: Path, copies: int) -> int:
    per_copy = python_lines(corpus)
    if copies <= 0:
        copies = -(-TARGET_LINES // per_copy)
    for n in range(1, copies + 1):
        shutil.copytree(corpus, tree / f"copy{n}", symlinks=True)
    return per_copy * copies


def run(tree: Path, cache: Path, jobs: int) -> tuple[str, dict[str, float]]:
    env = dict(os.environ, ROBOTFIX_CACHE_DIR=str(cache))
    env.pop("PYTHONDONTWRITEBYTECODE", None)  # as installed: bytecode kept
    command = [sys.executable, "-c", DRIVER, "check", str(tree), "-j", str(jobs)]
    command += ["--format", "concise", "--cache-dir", str(cache)]
    before = os.times()
    started = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True, env=env)
    wall = time.perf_counter() - started
    after = os.times()
    cpu = (after.children_user - before.children_user) + (
        after.children_system - before.children_system
    )
    stats = [
        line.split() for line in done.stderr.splitlines() if line.startswith("STATS")
    ]
    if not stats or done.returncode not in (0, 1):  # 2: a failure, or unchecked files
        raise SystemExit(f"robotfix failed ({done.returncode}):\n{done.stderr}")
    _, files, cached, inner, _ = stats[-1]
    return done.stdout, {
        "wall": wall,
        "cpu": cpu,
        "files": int(files),
        "rechecked": int(files) - int(cached),
        "inner": float(inner),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("corpus", nargs="?", type=Path, default=Path("/work/corpus"))
    parser.add_argument("--copies", type=int, default=0)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--repeat", type=int, default=3, help="warm runs per step")
    parser.add_argument("--tree", type=Path, help="build the tree here and keep it")
    args = parser.parse_args()
    base = args.tree or Path(tempfile.mkdtemp(prefix="rf-cached-run-"))
    tree, cache = base / "tree", base / "cache"
    try:
        if tree.exists():
            shutil.rmtree(tree)
        if cache.exists():
            shutil.rmtree(cache)
        lines = make_tree(args.corpus, tree, args.copies)
        print(f"tree: {tree}  python lines: {lines:,}")
        cold, stats = run(tree, cache, args.jobs)
        report("cold", [stats], stats["files"], True)

        def step(name: str) -> None:
            results = [run(tree, cache, args.jobs) for _ in range(args.repeat)]
            same = all(out == cold for out, _ in results)
            report(name, [s for _, s in results], stats["files"], same)

        step("warm, unchanged")
        now = time.time()
        for path in tree.rglob("*"):
            if path.is_file() and not path.is_symlink():
                os.utime(path, (now - 5, now - 5))
        step("warm, every file touched (same bytes)")
        helper = next((tree / "copy1").glob(f"*/{HELPER_FILE}"))
        text = helper.read_text()
        helper.write_text(text + "\n\ndef _edited_for_benchmark():\n    return 1\n")
        edit_out, edit = run(tree, cache, args.jobs)
        report(
            "warm, one helper edited (first run)",
            [edit],
            stats["files"],
            edit_out == cold,
        )
        step("warm, after the edit (unchanged again)")
    finally:
        if args.tree is None:
            shutil.rmtree(base, ignore_errors=True)


def report(name: str, runs: list[dict[str, float]], files: float, same: bool) -> None:
    wall = sorted(r["wall"] for r in runs)[len(runs) // 2]
    cpu = sorted(r["cpu"] for r in runs)[len(runs) // 2]
    rechecked = "/".join(str(int(r["rechecked"])) for r in runs)
    each = "/".join(f"{r['cpu']:.2f}" for r in runs)
    print(
        f"{name:42s} wall {wall:6.2f} s  cpu {cpu:6.2f} s ({each})  "
        f"re-checked {rechecked} of {int(files)} .py  "
        f"output {'identical to cold' if same else 'DIFFERS from cold'}"
    )


if __name__ == "__main__":
    main()
