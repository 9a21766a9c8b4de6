"""Where building imported modules' summaries spends its CPU, and how much of it
a module's own check does again (issue 25 step 4: "a module's summary is taken from
its own check").

Usage: python benchmarks/summary_stages.py [--runs N] FOLDER [FOLDER ...]
Checks each folder in-process like `robotfix check FOLDER --no-cache -j 1` (a run
per folder, N rounds) and prints, per kind of summarised module, the median CPU
seconds of each stage of `project.summary._build` -> `summarize` (a nested build's
time is its own module's, not its importer's), and of the module phase of its own
check (scan, scopes, `collect`, module body, top-level class bodies). Kinds: checked
later in the run (its check `take`s the parse: parse and index are not done twice),
checked earlier (its check's parse is gone: all of it is done twice), and neither
(outside the run, or skipped by the file rule). Timers wrap the stage functions;
nothing of the analysis is changed.
"""

from __future__ import annotations

import argparse
import ast
import os
import statistics
import sys
import time
from collections import defaultdict
from collections.abc import Callable
from pathlib import Path
from typing import Any

from robotfix.analysis import binder, constants, context, index, interpreter, program
from robotfix.api import check_paths
from robotfix.config import Config
from robotfix.project import summary

STAGES = (
    "parse",
    "graph",
    "index",
    "scan",
    "scope",
    "collect",
    "body",
    "classes",
    "build",
)
RENAMED = {"setup": "build", "statics": "classes"}  # as the table shows them
clock = time.process_time


class Frames:
    """A stack of timed frames (a summary being built, a file's check); the CPU
    since the last mark goes to the top frame's current stage."""

    def __init__(self) -> None:
        self.stack: list[list[Any]] = []  # [kind, path, stage]
        self.spent: dict[tuple[str, str, str], float] = defaultdict(float)
        self.mark = clock()

    def charge(self) -> None:
        now = clock()
        if self.stack:
            kind, path, stage = self.stack[-1]
            self.spent[(kind, path, stage)] += now - self.mark
        self.mark = now

    def stage(self, name: str) -> None:
        """The top frame enters stage `name`."""
        if self.stack:
            self.charge()
            self.stack[-1][2] = name

    def frame(self, kind: str, path: str, run: Callable[[], Any]) -> Any:
        self.charge()
        self.stack.append([kind, path, "setup" if kind == "summary" else "phase"])
        try:
            return run()
        finally:
            self.charge()
            self.stack.pop()


def install(frames: Frames, checked: dict[str, int], built: dict[str, int]) -> None:
    """Wrap the stage functions (`summarize` looks each up when it is called)."""

    def around(
        owner: Any, name: str, stage: str, after: tuple[str, ...], then: str = ""
    ) -> None:
        """A summary frame is in `stage` from when `owner.name` is called in a stage
        of `after` (any, if empty: then only while it runs, back to the stage it
        was called in) until it returns and goes on to `then`, or else until the
        next wrapped call moves it on."""
        original = getattr(owner, name)

        def wrapped(*args: Any, **kwargs: Any) -> Any:
            top = frames.stack[-1] if frames.stack else None
            was = top[2] if top is not None else None
            enter = top is not None and top[0] == "summary"
            enter = enter and (not after or was in after)
            if enter:
                frames.stage(stage)
            try:
                return original(*args, **kwargs)
            finally:
                if enter and (then or not after):
                    frames.stage(then or str(was))

        setattr(owner, name, wrapped)

    # the order of `summarize`: each stage ends where the next begins
    around(summary.Project, "_parse", "parse", ())
    around(summary.Project, "reaches", "graph", ())
    around(index, "index_of", "index", ("setup",))
    around(constants, "scan", "scan", ("index",))
    around(context, "build_scope", "scope", ("scan",))
    around(program, "collect", "collect", ("scope",), "body")
    around(binder, "module_statics", "statics", ("body",), "classes")
    around(constants.ConstantNames, "module_constants", "build", ("classes",))
    original_build = summary.Project._build

    def build(self: summary.Project, path: Path) -> Any:
        key = os.path.abspath(path)
        built.setdefault(key, len(built) + len(checked))
        return frames.frame("summary", key, lambda: original_build(self, path))

    summary.Project._build = build  # type: ignore[method-assign]
    original_module = interpreter.analyze_module

    def analyze_module(ctx: context.FileContext) -> None:
        key = os.path.abspath(ctx.source.path)
        checked.setdefault(key, len(built) + len(checked))
        frames.frame("check", key, lambda: original_module(ctx))

    interpreter.analyze_module = analyze_module
    original_body = interpreter._analyze_body

    def analyze_body(
        ctx: Any, prog: Any, node: ast.AST, parent: Any, *rest: Any
    ) -> Any:
        top_class = isinstance(node, ast.ClassDef) and parent.parent is None
        frames.stage("phase" if top_class else "functions")
        try:
            return original_body(ctx, prog, node, parent, *rest)
        finally:
            frames.stage("functions")

    interpreter._analyze_body = analyze_body


def one_round(
    folders: list[str], frames: Frames, checked: dict[str, int], built: dict[str, int]
) -> tuple[dict[str, dict[str, float]], float]:
    rows: dict[str, dict[str, float]] = defaultdict(lambda: defaultdict(float))
    total = 0.0
    for folder in folders:
        checked.clear()
        built.clear()
        frames.spent.clear()
        start = clock()
        check_paths([Path(folder)], Config(), jobs=1, use_cache=False)
        total += clock() - start
        for (kind, path, stage), spent in frames.spent.items():
            if path in checked and path in built:
                later = built[path] < checked[path]
                group = "checked later" if later else "checked earlier"
            else:
                group = "neither" if path in built else "unsummarised"
            if kind == "summary":
                rows[group][RENAMED.get(stage, stage)] += spent
            elif stage == "phase":
                rows[group]["own check's module phase"] += spent
        for group in ("checked later", "checked earlier", "neither"):
            rows[group]["modules"] += sum(
                1
                for p in built
                if group
                == (
                    ("checked later" if built[p] < checked[p] else "checked earlier")
                    if p in checked
                    else "neither"
                )
            )
    return rows, total


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runs", type=int, default=1)
    parser.add_argument("folders", nargs="+")
    args = parser.parse_args()
    rounds = []
    frames = Frames()
    checked: dict[str, int] = {}
    built: dict[str, int] = {}
    install(frames, checked, built)
    for _ in range(args.runs):
        rounds.append(one_round(args.folders, frames, checked, built))
    columns = ("modules", *STAGES, "own check's module phase")
    print("kind".ljust(16), " ".join(c.split("'")[0][:9].rjust(9) for c in columns))
    for group in ("checked later", "checked earlier", "neither"):
        cells = [statistics.median(r[0][group][c] for r in rounds) for c in columns]
        shown = [f"{cells[0]:9.0f}"] + [f"{c:9.3f}" for c in cells[1:]]
        print(group.ljust(16), " ".join(shown))
    print(f"total CPU (median): {statistics.median(t for _, t in rounds):.2f} s")
    sys.stdout.flush()


if __name__ == "__main__":
    main()
