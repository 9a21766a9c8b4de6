"""What a syntactic statement-level demand rule would spare (issue 25, step 3).

Usage: python benchmarks/demand_rule.py [--generous] [--runs N] FOLDER [FOLDER ...]

`demand_bound.py` bounds any demand rule with an oracle that watches the values
each statement makes. This script measures a *rule*: a slice of each function body
computed from its syntax alone, before the body runs, as step 3 of the issue asks.
A statement is *hot* when it can matter:
  - it returns, raises, yields, awaits, breaks, declares a global, defines a
    function or class, imports, asserts, opens a `with` or `try`;
  - it reads a name that is not the function's own (a module name, an import, a
    builtin outside a short list of plain ones), or calls anything but those
    builtins and methods of the function's own names;
  - it reads a name a hot statement binds or changes (forward: the value may carry
    a unit, a message), or binds or changes a name a hot statement reads
    (backward: `x = 5` before `msg.x = x`); the parameters are bound by the call
    (hot: a callback's message, `self`);
  - a compound statement is hot when any statement it holds is.
The rest are *plain*. A plain statement is skipped with nothing done (nothing hot
reads what it binds); a hot compound statement runs, and its plain statements are
skipped in turn. `--generous` drops two conditions no sound rule can drop (the
parameters and the module's names count as cold) to show what the syntax could
give at best.

Prints the statements planned and skipped, the CPU of three runs in this process
(the check as it is; the plan made but nothing skipped; the plan applied: medians
of N), and whether the skipping run's output is byte-identical. For instructions,
run it under `valgrind --tool=callgrind` with `--mode plain|plan|skip` (one mode).
Nothing of the analysis is changed outside this process.
"""

from __future__ import annotations

import argparse
import ast
import contextlib
import io
import statistics
import sys
import time
from pathlib import Path
from typing import Any

from robotfix import cli
from robotfix.analysis import interpreter

PLAIN_BUILTINS = frozenset(
    (
        *("len", "range", "str", "int", "float", "abs", "min", "max", "round"),
        *("enumerate", "zip", "isinstance", "bool", "print", "sum", "sorted", "list"),
        *("dict", "tuple", "set", "repr", "format", "any", "all", "reversed"),
        *("hasattr", "getattr", "type", "id", "hash", "ord", "chr", "divmod", "pow"),
        *("None", "True", "False"),
    )
)
_DEFS = (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda)
HOT_NODES = (
    ast.Return, ast.Raise, ast.Yield, ast.YieldFrom, ast.Await, ast.Break,
    ast.Continue, ast.Global, ast.Nonlocal, ast.Delete, ast.Import, ast.ImportFrom,
    ast.Assert, ast.With, ast.AsyncWith, ast.Try, ast.NamedExpr, ast.Starred,
    ast.Match, *_DEFS, *((ast.TryStar,) if hasattr(ast, "TryStar") else ()),
)  # fmt: skip


def _root(node: ast.expr) -> ast.expr:
    while isinstance(node, (ast.Attribute, ast.Subscript)):
        node = node.value
    return node


class Rule:
    def __init__(self, generous: bool) -> None:
        self.generous = generous
        self.plans: dict[int, tuple[ast.AST, frozenset[int]]] = {}
        self.modules: dict[int, tuple[Any, set[str]]] = {}
        self.counts = {"functions": 0, "statements": 0, "plain": 0, "skipped": 0}

    def _facts(
        self, parts: list[Any], own: set[str], module: set[str]
    ) -> tuple[set[str], set[str], bool]:
        """(names read, names bound or changed, hot by itself) of a statement's
        own parts (a compound statement's head: not the blocks it holds)."""
        reads: set[str] = set()
        writes: set[str] = set()
        hot = False
        stack = list(parts)
        while stack:
            node = stack.pop()
            if isinstance(node, HOT_NODES):
                hot = True
                if isinstance(node, _DEFS):  # what it reads of this function's names
                    reads |= {n.id for n in ast.walk(node) if isinstance(n, ast.Name)}
                    continue
            if isinstance(node, ast.Name):
                if isinstance(node.ctx, ast.Store):
                    writes.add(node.id)
                    continue
                reads.add(node.id)
                if node.id not in own and not self.generous:
                    hot = hot or node.id not in PLAIN_BUILTINS or node.id in module
                continue
            if isinstance(node, ast.Call):
                func = node.func
                if isinstance(func, ast.Attribute):  # a method may change its owner
                    root = _root(func)
                    if isinstance(root, ast.Name):
                        writes.add(root.id)
                elif not isinstance(func, ast.Name) or (
                    func.id not in PLAIN_BUILTINS or func.id in own or func.id in module
                ):
                    hot = True
            elif isinstance(node, (ast.Attribute, ast.Subscript)) and isinstance(
                node.ctx, (ast.Store, ast.Del)
            ):
                root = _root(node)
                if isinstance(root, ast.Name) and root.id in own:
                    writes.add(root.id)
                    reads.add(root.id)
                else:
                    hot = True
            stack.extend(ast.iter_child_nodes(node))
        return reads, writes, hot

    def module_names(self, scope: Any) -> set[str]:
        known = self.modules.get(id(scope))
        if known is None or known[0] is not scope:
            names = scope.local_names | scope.global_names | set(scope.decls)
            known = self.modules[id(scope)] = (scope, names)
        return known[1]

    def plan(self, function: ast.AST, module: set[str]) -> frozenset[int]:
        """The ids of the plain statements of a function body, at any depth."""
        known = self.plans.get(id(function))
        if known is not None and known[0] is function:
            return known[1]
        assert isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef))
        args = function.args
        params = {
            a.arg
            for a in (*args.posonlyargs, *args.args, *args.kwonlyargs, args.vararg,
                      args.kwarg)
            if a is not None
        }  # fmt: skip
        own = set(params)
        for node in ast.walk(function):
            if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
                own.add(node.id)
            elif isinstance(node, ast.ExceptHandler) and node.name:
                own.add(node.name)
        info: dict[int, tuple[set[str], set[str], list[int]]] = {}
        hot: set[int] = set()

        def visit(body: list[ast.stmt]) -> list[int]:
            ids = []
            for stmt in body:
                kids: list[int] = []
                if isinstance(stmt, (ast.If, ast.While, ast.For, ast.AsyncFor)):
                    head: list[Any] = (
                        [stmt.test]
                        if isinstance(stmt, (ast.If, ast.While))
                        else [stmt.target, stmt.iter]
                    )
                    reads, writes, self_hot = self._facts(head, own, module)
                    self_hot = self_hot or isinstance(stmt, ast.AsyncFor)
                    kids = visit(stmt.body) + visit(stmt.orelse)
                else:
                    reads, writes, self_hot = self._facts([stmt], own, module)
                info[id(stmt)] = (reads, writes, kids)
                if self_hot:
                    hot.add(id(stmt))
                ids.append(id(stmt))
            return ids

        visit(function.body)
        tainted = set() if self.generous else set(params)
        changed = True
        while changed:
            changed = False
            needed: set[str] = set()
            for key in hot:
                needed |= info[key][0]
                tainted |= info[key][1]
            for key, (reads, writes, kids) in info.items():
                if key not in hot and (
                    reads & tainted or writes & needed or any(k in hot for k in kids)
                ):
                    hot.add(key)
                    changed = True
        plain = frozenset(info.keys() - hot)
        self.counts["functions"] += 1
        self.counts["statements"] += len(info)
        self.counts["plain"] += len(plain)
        self.plans[id(function)] = (function, plain)
        return plain

    def install(self, skip: bool) -> Any:
        """Replace `Interpreter.exec_block` in this process; returns the original."""
        real = interpreter.Interpreter.exec_block
        rule = self

        def exec_block(self: Any, body: Any, state: Any, flush: bool = True) -> Any:
            function = self.function
            if (
                function is None
                or self.inlined
                or isinstance(function.node, ast.Lambda)
            ):
                return real(self, body, state, flush)
            plain = rule.plan(function.node, rule.module_names(self.scope.module()))
            if not skip or not plain:
                return real(self, body, state, flush)
            run: list[ast.stmt] = []
            for stmt in body:
                if id(stmt) not in plain:
                    run.append(stmt)
                    continue
                rule.counts["skipped"] += 1
                self.ctx.budget.used += 1  # the step the statement would have cost
            return real(self, run, state, flush) if run else state

        interpreter.Interpreter.exec_block = exec_block
        return real


def check(folders: list[Path]) -> tuple[str, float]:
    out = io.StringIO()
    started = time.process_time()
    with contextlib.redirect_stdout(out):
        cli.main(["check", *map(str, folders), "--no-cache", "-j", "1",
                  "--format", "json"])  # fmt: skip
    took = time.process_time() - started
    text = "\n".join(x for x in out.getvalue().splitlines() if '"seconds"' not in x)
    return text, took


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--generous", action="store_true")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--mode", choices=("plain", "plan", "skip"))
    parser.add_argument("folders", nargs="+", type=Path)
    args = parser.parse_args(argv)
    if args.mode:  # one run, for callgrind
        if args.mode != "plain":
            Rule(args.generous).install(skip=args.mode == "skip")
        check(args.folders)
        return 0
    seconds: dict[str, list[float]] = {"plain": [], "plan": [], "skip": []}
    outputs: dict[str, str] = {}
    rule = Rule(args.generous)
    for _ in range(args.runs):
        for mode in seconds:
            real = interpreter.Interpreter.exec_block
            if mode != "plain":
                rule = Rule(args.generous)
                rule.install(skip=mode == "skip")
            try:
                outputs[mode], took = check(args.folders)
            finally:
                interpreter.Interpreter.exec_block = real
            seconds[mode].append(took)
    counts = rule.counts
    print(
        f"{counts['functions']} function bodies planned, {counts['statements']} "
        f"statements, {counts['plain']} plain; {counts['skipped']} skipped in a run"
    )
    plain, planned, skipped = (statistics.median(seconds[m]) for m in seconds)
    print(
        f"CPU (median of {args.runs}): check {plain:.2f} s; plan made {planned:.2f} s; "
        f"plan applied {skipped:.2f} s: the skipping spares {planned - skipped:.2f} s "
        f"({100 * (planned - skipped) / plain:.1f}% of the check)"
    )
    same = outputs["skip"] == outputs["plain"]
    print("output " + ("byte-identical" if same else "DIFFERENT"))
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
