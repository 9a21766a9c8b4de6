"""The thesis's 20 seed programs (tests/cases/seed) as a benchmark workload, and the
check that a timed `robotfix check` found what the test suite expects of them.

A timed run that crashed, or that checked less than the tests do (a seed without its
`msg/` folder finds fewer bugs), must not be reported as a time: `checked` runs the
command with `--format json`, and stops the benchmark unless the exit status is the
one the findings call for and the diagnostics in the seeds' Python files are exactly
the `# error:` assertions the files carry (`robotfix.testing.expectations`, as
tests/test_cases.py compares them).
"""

from __future__ import annotations

import json
import subprocess
import sys
import time
from collections.abc import Iterable
from pathlib import Path

from robotfix.diagnostics import Diagnostic, Severity, Span
from robotfix.rules import ALL_RULES
from robotfix.testing.expectations import compare_files

ROOT = Path(__file__).resolve().parent.parent
SEED = ROOT / "tests" / "cases" / "seed"
FOUND, FAILED = 1, 2  # robotfix check's exit statuses: errors found; a failure


def folders() -> list[Path]:
    return sorted(p for p in SEED.iterdir() if p.is_dir())


def programs(seeds: Iterable[Path]) -> list[Path]:
    return [p for seed in seeds for p in (seed / "buggy.py", seed / "fixed.py")]


def msg_folders(seeds: Iterable[Path]) -> list[Path]:
    """Each seed's own interface files, as the tests give them."""
    return [s / "msg" for s in seeds if (s / "msg").is_dir()]


def msg_args(seeds: Iterable[Path]) -> list[str]:
    return [a for m in msg_folders(seeds) for a in ("--msg-path", str(m))]


def verify(files: list[Path], found: list[Diagnostic], status: int | None) -> None:
    """Stop unless `found` is exactly what the files' assertions expect (and, when
    `status` is given, it is the exit status those findings call for)."""
    # the programs' diagnostics; RF510 notes on a msg/ folder's clashing definitions
    problems = compare_files(files, [d for d in found if d.path.endswith(".py")])
    errors = any(d.severity is Severity.ERROR for d in found)
    if status is not None and status != (FOUND if errors else 0):
        problems.append(f"exit status {status} with{'' if errors else 'out'} errors")
    if problems:
        raise SystemExit(
            "the timed run is not the tests' check:\n" + "\n".join(problems)
        )


def checked(
    args: list[str], files: list[Path], cwd: Path, env: dict[str, str]
) -> float:
    """Seconds of one `robotfix check ARGS --format json` process, verified."""
    command = [sys.executable, "-m", "robotfix", "check", *args, "--format", "json"]
    started = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True, cwd=cwd, env=env)
    seconds = time.perf_counter() - started
    if done.returncode >= FAILED:
        raise SystemExit(f"robotfix failed ({done.returncode}):\n{done.stderr}")
    verify(
        files,
        [_diagnostic(d) for d in json.loads(done.stdout)["diagnostics"]],
        done.returncode,
    )
    return seconds


def _diagnostic(d: dict[str, object]) -> Diagnostic:
    line, col, end_line, end_col = (
        int(d[k])  # type: ignore[call-overload]
        for k in ("line", "column", "end_line", "end_column")
    )
    span = Span(line, col - 1, end_line, end_col - 1)
    rule = ALL_RULES[str(d["code"])]
    return Diagnostic(
        rule,
        str(d["path"]),
        span,
        str(d["message"]),
        level=Severity(str(d["severity"])),
    )
