"""The graph stage on a workspace built from fetched repositories (issue 23, speed).

Usage: python benchmarks/graph_workspace.py [CORPUS] [--jobs N] [--tree DIR]
Copies CORPUS (default /work/corpus: checked-out ROS repositories, 140 packages)
into a folder under /tmp as one workspace's `src/`, then, each in a fresh process:
a cold `robotfix check -j N` (empty cache) with the time its graph stage took
(`run._graph_problems`: C++ files read with tree-sitter, launch entries, names,
findings); `robotfix graph` alone (discovery, Python files that may make an
endpoint parsed, C++ read, the graph); a warm check (unchanged tree); a warm check
after editing one launch file. Prints wall and CPU seconds, the graph's share,
the workspace's packages, Python, C++ and launch files, the graph's size, and
whether each warm output equals the cold one. Nothing is committed or downloaded;
the tree is removed at the end unless --tree is given.
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from cached_run import COUNT_RUNS

# The child process: the CLI, with the graph stage and check_paths timed.
DRIVER = (
    """
import sys, time
started, cpu = time.perf_counter(), time.process_time()
from robotfix import cli, run
spent = [0.0, 0.0]
real_graph = run._graph_problems
def timed(*args, **kwargs):
    t, c = time.perf_counter(), time.process_time()
    try:
        return real_graph(*args, **kwargs)
    finally:
        spent[0] += time.perf_counter() - t
        spent[1] += time.process_time() - c
run._graph_problems = timed
"""
    + COUNT_RUNS
    + """
status = cli.main(sys.argv[1:])
checked = len(seen[0].checked) if seen else 0
cached = seen[0].from_cache if seen else 0
print(f"STATS {checked} {cached} {time.perf_counter() - started:.3f} "
      f"{time.process_time() - cpu:.3f} {spent[0]:.3f} {spent[1]:.3f}", file=sys.stderr)
sys.exit(status)
"""
)


def child(args: list[str], cwd: Path) -> tuple[str, list[float]]:
    done = subprocess.run(
        [sys.executable, "-c", DRIVER, *args],
        cwd=cwd,
        capture_output=True,
        text=True,
        check=False,
    )
    stats = [line for line in done.stderr.splitlines() if line.startswith("STATS")]
    if not stats:
        raise SystemExit(f"the run failed:\n{done.stderr[-3000:]}")
    return done.stdout, [float(x) for x in stats[-1].split()[1:]]


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("corpus", nargs="?", default="/work/corpus", type=Path)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--tree", type=Path, default=None)
    options = parser.parse_args()
    base = options.tree or Path(tempfile.mkdtemp(prefix="robotfix-graph-"))
    src = base / "src"
    if not src.exists():
        shutil.copytree(options.corpus, src, symlinks=True)
    try:
        packages = sum(1 for _ in src.rglob("package.xml"))
        from robotfix.config import Config
        from robotfix.discovery import discover

        found = discover([src], Config(root=base))
        print(
            f"workspace {src}: {packages} packages, {len(found.python_files)} Python "
            f"files, {len(found.cpp_files)} C++ files, {len(found.launch_files)} "
            "launch files"
        )
        check = ["check", "src", "-j", str(options.jobs), "--format", "concise"]
        cold, c = child(check, base)
        print(
            f"cold check -j {options.jobs}: {c[2]:.2f} s wall, {c[3]:.2f} s CPU (main "
            f"process); graph stage {c[4]:.2f} s wall ({100 * c[4] / c[2]:.1f}%), "
            f"{c[5]:.2f} s CPU; {int(c[0])} Python files checked"
        )
        graph, g = child(["graph", "src", "--format", "json"], base)
        import json

        data = json.loads(graph)
        print(
            f"robotfix graph: {g[2]:.2f} s wall, {g[3]:.2f} s CPU; "
            f"{len(data['nodes'])} nodes, {len(data['endpoints'])} endpoints, "
            f"{len(data['findings'])} findings"
        )
        warm, w = child(check, base)
        print(
            f"warm check: {w[2]:.2f} s wall ({int(w[1])}/{int(w[0])} from the cache); "
            f"graph stage {w[4]:.2f} s; same output: {warm == cold}"
        )
        launch = next(p for p in sorted(found.launch_files) if p.suffix == ".py")
        launch.write_text(launch.read_text() + "\n# edited\n")
        edited, e = child(check, base)
        print(
            f"warm check after editing {launch.relative_to(base)}: {e[2]:.2f} s wall "
            f"({int(e[1])}/{int(e[0])} from the cache); graph stage {e[4]:.2f} s; "
            f"same output: {edited == cold}"
        )
    finally:
        if options.tree is None:
            shutil.rmtree(base, ignore_errors=True)


if __name__ == "__main__":
    main()
