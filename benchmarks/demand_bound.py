"""The most a demand-driven evaluator could spare (issue 25, step 3), measured with
an oracle rather than a rule.

Usage: python benchmarks/demand_bound.py FOLDER [FOLDER ...]

Step 3 of issue 25's design runs only the functions, and within them the
statements, that lie on a path from a source. Any such rule must run a statement
that carries something, so whatever it spares is bounded by the time of the
statements that carry nothing. This script runs `robotfix check FOLDERS
--no-cache -j 1` twice in this process: once plain, for its CPU against the parse
floor; once watching every statement of every function body, at any depth, and
calls a statement *plain* when, while it ran, no value the evaluator made was a
message or message class, had a unit, a heap reference, a frame, an uninitialised
part or element facts, was a parameter handle, no message was made and nothing was
reported or deferred. A plain statement is spared whole (a compound one with all
it holds); of one that is not, its plain statements are. A function whose
statements are all plain is spared whole (its scope and parameters too).

The oracle is generous to the rule: a plain statement that binds a value an
interesting statement reads later (`x = 5` before `msg.x = x`) counts as spared,
and no rule's own cost is charged. What it prints is therefore a lower bound of
the run against the floor that any demand rule can reach on these files:

    run / floor * (1 - spared / watched run)

(CPU time throughout; shares of the watched run, as its watching slows every
statement alike). Nothing of the analysis is changed.
"""

from __future__ import annotations

import argparse
import ast
import contextlib
import os
import sys
import time
from collections import Counter
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from stage_breakdown import floor

from robotfix import cli
from robotfix.analysis import interpreter
from robotfix.analysis.expressions import ExpressionEvaluator
from robotfix.analysis.values import Value
from robotfix.api import python_files


class Oracle:
    def __init__(self) -> None:
        self.carried = False  # a value made since it was cleared carries something
        self.watching = 0  # > 0: inside a function body's run
        # the statements being run, outermost first: [carried, plain parts' time]
        self.frames: list[list[Any]] = []
        self.spent: Counter[str] = Counter()  # statement kind -> seconds
        self.spared: Counter[str] = Counter()
        self.functions = Counter[str]()  # "all" / "plain" / "set-up" -> seconds
        self.carrying = 0  # watched statements that were not plain so far

    def carries(self, value: Value) -> bool:
        return (
            value.kind in ("msg", "msgclass")
            or value.kind.startswith("parameter")
            or value.unit is not None
            or value.ref is not None
            or value.frame is not None
            or value.uninit is not None
            or value.items is not None
        )

    @contextlib.contextmanager
    def installed(self) -> Iterator[Oracle]:
        """The evaluator watched while in the block (its methods restored after)."""
        real_eval = ExpressionEvaluator.eval
        real_block = interpreter.Interpreter.exec_block
        real_run = interpreter._run_body
        oracle = self

        def watched_eval(self: Any, node: Any, state: Any) -> Value:
            value = real_eval(self, node, state)
            if not oracle.carried and oracle.carries(value):
                oracle.carried = True
            return value

        def reports(ctx: Any) -> tuple[int, ...]:
            return (len(ctx.diagnostics), len(ctx.deferred), len(ctx._reported))

        def watched_block(self: Any, body: Any, state: Any, flush: bool = True) -> Any:
            function = self.function
            if function is None or not oracle.watching:
                return real_block(self, body, state, flush)
            if not oracle.frames and body is not function.node.body:
                return real_block(self, body, state, flush)  # a helper's, inlined
            for stmt in body:
                if not state.reachable:
                    break
                before, heap = reports(self.ctx), len(state.heap)
                frame = [False, 0.0]  # carried, what its plain parts took
                oracle.frames.append(frame)
                oracle.carried = False
                started = time.process_time()
                try:
                    state = real_block(self, [stmt], state, flush)
                finally:
                    oracle.frames.pop()
                took, kind = time.process_time() - started, type(stmt).__name__
                carried = (
                    frame[0]
                    or oracle.carried
                    or reports(self.ctx) != before
                    or len(state.heap) != heap
                )
                spared = frame[1] if carried else took
                oracle.carried = False
                if oracle.frames:  # a statement in a compound statement's block
                    outer = oracle.frames[-1]
                    outer[0] = outer[0] or carried
                    outer[1] += spared
                else:
                    oracle.spent[kind] += took
                    oracle.spared[kind] += spared
                    oracle.carrying += carried
            return state

        def watched_run(*args: Any, **kwargs: Any) -> Any:
            if oracle.watching or args[5] is None:  # a class body: never spared
                return real_run(*args, **kwargs)
            carrying, spent = oracle.carrying, sum(oracle.spent.values())
            oracle.carried = False
            oracle.watching += 1
            started = time.process_time()
            try:
                result = real_run(*args, **kwargs)
            finally:
                oracle.watching -= 1
            took = time.process_time() - started
            oracle.functions["all"] += took
            lambda_carried = isinstance(args[2], ast.Lambda) and oracle.carried
            if oracle.carrying == carrying and not lambda_carried:
                oracle.functions["plain"] += took  # nothing in it carried anything
                oracle.functions["set-up"] += took - (
                    sum(oracle.spent.values()) - spent
                )
            return result

        ExpressionEvaluator.eval = watched_eval  # type: ignore[method-assign]
        interpreter.Interpreter.exec_block = watched_block  # type: ignore[method-assign]
        interpreter._run_body = watched_run
        try:
            yield self
        finally:
            ExpressionEvaluator.eval = real_eval  # type: ignore[method-assign]
            interpreter.Interpreter.exec_block = real_block  # type: ignore[method-assign]
            interpreter._run_body = real_run


def run(folders: list[Path]) -> float:
    started = time.process_time()
    with open(os.devnull, "w") as quiet, contextlib.redirect_stdout(quiet):
        cli.main(["check", *map(str, folders), "--no-cache", "-j", "1"])
    return time.process_time() - started


def main(argv: list[str]) -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("folders", nargs="+", type=Path)
    args = parser.parse_args(argv)
    files = python_files(args.folders)
    ground = floor(files)
    started = time.process_time()
    run(args.folders)
    plain = time.process_time() - started
    with Oracle().installed() as oracle:
        watched = run(args.folders)
    spent, spared = sum(oracle.spent.values()), sum(oracle.spared.values())
    spared_all = spared + oracle.functions["set-up"]
    print(
        f"{len(files)} files; run {plain:.2f} s CPU, floor {ground:.2f} s: "
        f"{plain / ground:.2f}x"
    )
    print(
        f"watched run {watched:.2f} s; function bodies {oracle.functions['all']:.2f} s "
        f"({100 * oracle.functions['all'] / watched:.1f}%), of which statements at "
        f"their top level {spent:.2f} s"
    )
    print(
        f"plain statements {spared:.2f} s ({100 * spared / spent:.1f}% of the "
        f"statements); functions wholly plain {oracle.functions['plain']:.2f} s "
        f"({100 * oracle.functions['plain'] / oracle.functions['all']:.1f}% of the "
        f"bodies), their set-up {oracle.functions['set-up']:.2f} s"
    )
    print(
        f"spared at most {100 * spared_all / watched:.1f}% of the run: a demand "
        f"rule reaches at best {plain / ground * (1 - spared_all / watched):.2f}x "
        "the floor"
    )
    for kind, took in oracle.spent.most_common():
        print(f"  {kind:12} {took:6.2f} s, plain {oracle.spared[kind]:6.2f} s")


if __name__ == "__main__":
    main(sys.argv[1:])
