"""The file-level skip (`robotfix/analysis/relevance.py`) changes no output.

Usage: python benchmarks/skip_identical.py FOLDER [FOLDER ...]
Checks the folders twice in-process, `-j 1` without a cache, with the skip and with
it turned off, and compares the concise output byte for byte. Prints how many files
the skip spared, the CPU seconds of each run and the first differences, if any; the
exit status is 1 when the outputs differ.
"""

from __future__ import annotations

import difflib
import sys
import time
from pathlib import Path

from robotfix.analysis import relevance
from robotfix.api import check_paths, python_files
from robotfix.config import Config
from robotfix.report.text import render_concise


def run(folders: list[Path], skip: bool) -> tuple[str, float, int]:
    relevance.ENABLED = skip
    calls = 0
    original = relevance.skippable

    def counted(*args: object, **kwargs: object) -> bool:
        nonlocal calls
        found = original(*args, **kwargs)  # type: ignore[arg-type]
        calls += found
        return found

    relevance.skippable = counted  # type: ignore[assignment]
    try:
        cpu = time.process_time()
        result = check_paths(folders, Config())
        seconds = time.process_time() - cpu
    finally:
        relevance.skippable = original  # type: ignore[assignment]
    return render_concise(result.diagnostics), seconds, calls


def main(folders: list[Path]) -> int:
    files = python_files(folders)
    lines = sum(p.read_bytes().count(b"\n") for p in files)
    check_paths(folders, Config())  # warm-up: imports, unit and message caches
    with_skip, fast, skipped = run(folders, True)
    without, slow, _ = run(folders, False)
    relevance.ENABLED = True
    print(f"files: {len(files)}  lines: {lines}  skipped: {skipped}")
    print(f"CPU: skip on {fast:.2f} s, off {slow:.2f} s ({fast / slow:.2f}x)")
    if with_skip == without:
        print(f"identical output ({len(without.splitlines())} lines)")
        return 0
    diff = difflib.unified_diff(
        without.splitlines(), with_skip.splitlines(), "no skip", "skip", lineterm=""
    )
    print("\n".join(list(diff)[:60]))
    return 1


if __name__ == "__main__":
    sys.exit(main([Path(a) for a in sys.argv[1:]] or [Path(".")]))
