"""The graph stage on a workspace built from fetched repositories (issue 23, speed).

Usage: python benchmarks/graph_workspace.py [CORPUS] [--jobs N] [--packages N]
                                            [--repeat N] [--tree DIR]
Copies CORPUS (default /work/corpus: checked-out ROS repositories, 140 packages)
into a folder under /tmp as one workspace's `src/` (with `--packages N`, only N of
its package folders, evenly spaced in the sorted list of them: a deterministic
choice), then, each in a fresh process: cold `robotfix check -j N` and `-j 1`
(empty cache) with the time its graph stage took (`run._graph_problems`: C++
files read with tree-sitter, launch entries, names, findings); `robotfix graph`
alone; a warm check (unchanged tree); a warm check after editing one Python launch
file that names a parameter file of the tree, and one after editing that
parameter file (each edit a new comment line, so the output must not change).
Each step runs `--repeat` times (a cold run on an emptied cache, an edit made
anew before each of its runs) and prints the median wall and CPU seconds (CPU:
the process and its workers), each run's wall, the graph stage's share, how many
Python files came from the cache, and whether each output equals the cold one.
Nothing is committed or downloaded; the tree is removed at the end unless --tree
is given.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
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


def child(args: list[str], cwd: Path) -> tuple[str, dict[str, float]]:
    before = os.times()
    started = time.perf_counter()
    done = subprocess.run(
        [sys.executable, "-c", DRIVER, *args],
        cwd=cwd,
        capture_output=True,
        text=True,
        check=False,
    )
    wall = time.perf_counter() - started
    after = os.times()
    cpu = (after.children_user - before.children_user) + (
        after.children_system - before.children_system
    )
    stats = [line for line in done.stderr.splitlines() if line.startswith("STATS")]
    if not stats:
        raise SystemExit(f"the run failed:\n{done.stderr[-3000:]}")
    checked, cached, _, _, graph, _ = (float(x) for x in stats[-1].split()[1:])
    return done.stdout, {
        "wall": wall,
        "cpu": cpu,
        "checked": checked,
        "cached": cached,
        "graph": graph,
    }


def make_workspace(corpus: Path, src: Path, packages: int) -> None:
    """CORPUS as `src`, or only `packages` of its package folders."""
    if packages <= 0:
        shutil.copytree(corpus, src, symlinks=True)
        return
    folders = sorted(
        {p.parent.relative_to(corpus) for p in corpus.rglob("package.xml")},
        key=str,
    )
    chosen = [folders[i * len(folders) // packages] for i in range(packages)]
    if len(set(chosen)) != len(chosen):
        raise SystemExit(f"{corpus} has fewer than {packages} packages")
    for folder in chosen:  # (the corpus has no package inside another)
        shutil.copytree(corpus / folder, src / folder, symlinks=True)


def median(values: list[float]) -> float:
    return sorted(values)[len(values) // 2]


def report(name: str, runs: list[tuple[str, dict[str, float]]], cold: str) -> None:
    stats = [s for _, s in runs]
    walls = "/".join(f"{s['wall']:.2f}" for s in stats)
    cached = "/".join(str(int(s["cached"])) for s in stats)
    print(
        f"{name:44s} wall {median([s['wall'] for s in stats]):5.2f} s ({walls})  "
        f"cpu {median([s['cpu'] for s in stats]):5.2f} s  "
        f"graph stage {median([s['graph'] for s in stats]):4.2f} s  "
        f"from the cache {cached} of {int(stats[0]['checked'])} .py  "
        f"same output: {all(out == cold for out, _ in runs)}"
    )


def edited_files(src: Path, base: Path) -> tuple[Path, Path | None]:
    """The first Python launch file (sorted) one of whose entries names a
    parameter file of the tree, and that parameter file."""
    from robotfix.config import Config
    from robotfix.discovery import discover
    from robotfix.launchcheck import LaunchRun
    from robotfix.ros.launch.model import FileParam

    found = discover([src], Config(root=base))
    print(
        f"workspace {src}: {sum(1 for _ in src.rglob('package.xml'))} packages, "
        f"{len(found.python_files)} Python files, {len(found.cpp_files)} C++ files, "
        f"{len(found.launch_files)} launch files"
    )
    launches = LaunchRun(found.launch_files, found.python_files)
    for started in sorted(launches.started, key=lambda s: s.entry.place.path):
        place = started.entry.place
        for parameter in started.entry.parameters:
            if (
                place.path.endswith(".py")
                and isinstance(parameter, FileParam)
                and parameter.path is not None
            ):
                return Path(place.path), Path(parameter.path)
    first = next(p for p in sorted(found.launch_files) if p.suffix == ".py")
    return first, None


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("corpus", nargs="?", default="/work/corpus", type=Path)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--packages", type=int, default=0, help="0: all")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--tree", type=Path, default=None)
    options = parser.parse_args()
    base = options.tree or Path(tempfile.mkdtemp(prefix="robotfix-graph-"))
    src = base / "src"
    if not src.exists():
        make_workspace(options.corpus.resolve(), src, options.packages)
    try:
        launch, params = edited_files(src, base)
        check = ["check", "src", "--format", "concise"]

        def cold(jobs: int) -> list[tuple[str, dict[str, float]]]:
            runs = []
            for _ in range(options.repeat):
                shutil.rmtree(base / ".robotfix_cache", ignore_errors=True)
                runs.append(child([*check, "-j", str(jobs)], base))
            return runs

        colds = cold(options.jobs)
        first = colds[0][0]
        report(f"cold check -j {options.jobs}", colds, first)
        if options.jobs != 1:
            report("cold check -j 1", cold(1), first)
        graph, _ = child(["graph", "src", "--format", "json"], base)
        data = json.loads(graph)
        print(
            f"robotfix graph: {len(data['nodes'])} nodes, "
            f"{len(data['endpoints'])} endpoints, {len(data['findings'])} findings"
        )
        warm = [*check, "-j", str(options.jobs)]
        child(warm, base)  # the cache as the last cold -j 1 run left it, again
        report("warm check", [child(warm, base) for _ in range(options.repeat)], first)
        for name, path in (("a launch file", launch), ("a parameter file", params)):
            if path is None:
                continue
            runs = []
            for n in range(options.repeat):
                with path.open("a") as out:
                    out.write(f"\n# edited {n}\n")
                runs.append(child(warm, base))
            report(f"warm after editing {name}", runs, first)
            print(f"  ({path.relative_to(base)})")
    finally:
        if options.tree is None:
            shutil.rmtree(base, ignore_errors=True)


if __name__ == "__main__":
    main()
