"""Where a cold run's CPU goes, stage by stage, against the parse floor (issue 25
target 1: at most 5.5x the floor).

Usage: python benchmarks/stage_breakdown.py [--runs N] FOLDER [FOLDER ...]
Runs `robotfix check FOLDERS --no-cache -j 1` in this process N times (default 3)
with a timer around each stage function below, and prints each stage's median
*exclusive* CPU seconds (a stage's time without the stages it calls: a summary
built while a body is analysed is the summary's), its share of the run, and what
the run would be against the floor without it. The floor is `ast.parse` of the same
files, timed here too. Timers add a little to every stage; read the shares.
Nothing of the analysis is changed; a stage that no longer exists stops the script.
"""

from __future__ import annotations

import argparse
import ast
import contextlib
import os
import statistics
import sys
import time
import warnings
from collections import Counter
from collections.abc import Callable
from pathlib import Path
from typing import Any

from robotfix import cli, run, source
from robotfix.analysis import constants, index, interpreter, parameters, relevance
from robotfix.api import python_files
from robotfix.project import summary

# (owner, attribute, stage name); the order is the order of the printout
STAGES: list[tuple[Any, str, str]] = [
    (source.SourceFile, "from_bytes", "parse (every parse of a Python file)"),
    (relevance, "skippable", "skip rule"),
    (index, "index_of", "index"),
    (constants, "scan", "constants"),
    (summary, "summarize", "summaries of imported modules"),
    (interpreter, "analyze_module", "module code, scopes, set-up"),
    (interpreter, "_analyze_body", "function and class bodies"),
    (parameters, "summarize", "parameter summaries"),
    (run, "_launches", "launch files"),
    (run, "_cpp_graphs", "C++ graphs"),
    (run, "_graph_of", "Python graphs"),
    (run, "_parameter_problems", "parameter check"),
    (run, "_graph_problems", "graph check"),
    (run, "_discover", "discovery"),
    (run, "check_file", "per-file rest (diagnostics, suppressions)"),
]


class Timers:
    """Exclusive CPU per stage: a stage's time minus that of the stages it calls."""

    def __init__(self) -> None:
        self.spent: Counter[str] = Counter()
        self._stack: list[list[Any]] = []

    def wrap(self, owner: Any, name: str, label: str) -> None:
        real = getattr(owner, name)  # AttributeError: the stage was renamed
        if isinstance(owner, type):
            real = owner.__dict__[name]
            inner: Callable[..., Any] = getattr(real, "__func__", real)
        else:
            inner = real

        def timed(*args: Any, **kwargs: Any) -> Any:
            started = time.process_time()
            self._stack.append([label, 0.0])
            try:
                return inner(*args, **kwargs)
            finally:
                _, nested = self._stack.pop()
                took = time.process_time() - started
                self.spent[label] += took - nested
                if self._stack:
                    self._stack[-1][1] += took

        if isinstance(owner, type) and isinstance(real, staticmethod):
            setattr(owner, name, staticmethod(timed))
        else:
            setattr(owner, name, timed)


def floor(files: list[Path]) -> float:
    started = time.process_time()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for path in files:
            with contextlib.suppress(SyntaxError, ValueError, OSError):
                ast.parse(path.read_bytes())
    return time.process_time() - started


def main(argv: list[str]) -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("folders", nargs="+", type=Path)
    args = parser.parse_args(argv)
    files = python_files(args.folders)
    timers = Timers()
    for owner, name, label in STAGES:
        timers.wrap(owner, name, label)
    totals, floors, per_stage = [], [], []
    for _ in range(args.runs):
        floors.append(floor(files))
        timers.spent.clear()
        started = time.process_time()
        with open(os.devnull, "w") as quiet, contextlib.redirect_stdout(quiet):
            cli.main(["check", *map(str, args.folders), "--no-cache", "-j", "1"])
        totals.append(time.process_time() - started)
        per_stage.append(dict(timers.spent))
    total, ground = statistics.median(totals), statistics.median(floors)
    print(
        f"{len(files)} files; run {total:.2f} s CPU, floor {ground:.2f} s: "
        f"{total / ground:.2f}x (median of {args.runs})"
    )
    labels = [label for _, _, label in STAGES]
    timed = 0.0
    for label in labels:
        spent = statistics.median(run.get(label, 0.0) for run in per_stage)
        timed += spent
        print(
            f"  {spent:6.2f} s {100 * spent / total:5.1f}%  without it "
            f"{(total - spent) / ground:5.2f}x  {label}"
        )
    rest = total - timed
    print(f"  {rest:6.2f} s {100 * rest / total:5.1f}%  (not in a stage above)")


if __name__ == "__main__":
    main(sys.argv[1:])
