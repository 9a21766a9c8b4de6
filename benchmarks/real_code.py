"""Lines per second on real (unannotated) ROS code, next to Python's own ast.parse.

Usage: python benchmarks/real_code.py FOLDER [FOLDER ...]
Point it at checked-out ROS repositories (e.g. ros2/demos, ros2/rclpy, ros/ros_comm);
nothing is committed or downloaded by this script. Prints files, lines, seconds for
ast.parse alone and for a full RobotFix check (in-process, after one warm-up run so
imports and caches are not counted), lines per second, the ratio, and peak memory.
"""

from __future__ import annotations

import resource
import sys
import time
from pathlib import Path

from peers import parse_seconds

from robotfix.api import check_paths, python_files
from robotfix.config import Config


def main(folders: list[Path]) -> None:
    files = python_files(folders)
    texts = [f.read_bytes() for f in files]
    lines = sum(t.count(b"\n") for t in texts)
    parse = parse_seconds(texts)
    check_paths(folders, Config())  # warm-up: imports, unit and message caches
    started, cpu = time.perf_counter(), time.process_time()
    result = check_paths(folders, Config())
    check = time.perf_counter() - started
    check_cpu = time.process_time() - cpu
    cpu = time.process_time()
    parse_seconds(texts)
    parse_cpu = time.process_time() - cpu
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(
        f"files: {len(files)}  lines: {lines}  diagnostics: {len(result.diagnostics)}"
    )
    print(f"ast.parse: {parse:.2f} s  ({lines / parse:,.0f} lines/s)")
    print(
        f"robotfix:  {check:.2f} s  ({lines / check:,.0f} lines/s, "
        f"{check / parse:.1f}x ast.parse)"
    )
    print(
        f"CPU time (steadier on a shared machine): ast.parse {parse_cpu:.2f} s, "
        f"robotfix {check_cpu:.2f} s, {check_cpu / parse_cpu:.2f}x"
    )
    print(f"peak memory: {peak:.0f} MB")


if __name__ == "__main__":
    main([Path(a) for a in sys.argv[1:]] or [Path(".")])
