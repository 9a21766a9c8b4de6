"""Deep import chains (reliability report 2, N9): module m_i imports from m_{i-1}.

What a run keeps grows linearly with the chain (each file's cache entry and each
summary hold their own records, and a module's fingerprint stands for what its
summary was built on), a change at the bottom still re-checks every module above
it, and a summary is the same however deep the stack was when it was asked for
(a chain deeper than Python's recursion limit is built by a loop)."""

from __future__ import annotations

import json
import os
import time
from pathlib import Path

import pytest

from robotfix import cli
from robotfix import run as run_module
from robotfix.config import Config
from robotfix.run import check_paths


def _chain(root: Path, length: int, top_first: bool = False) -> list[Path]:
    """pkg/m0 holds LIMIT = 1.0; each module above imports the one below, binds
    its LIMIT again and calls a function refined by it with 2.0 (an error in
    every module but m0). `top_first`: names sort from the top of the chain down,
    so a run meets the deepest summary first."""

    def name(level: int) -> str:
        return f"q{length - level:05d}" if top_first else f"m{level}"

    (root / "pkg").mkdir(parents=True)
    (root / "pyproject.toml").write_text("")
    (root / "pkg" / "__init__.py").write_text("")
    files = [root / "pkg" / f"{name(0)}.py"]
    files[0].write_text("LIMIT = 1.0\n")
    for level in range(1, length):
        files.append(root / "pkg" / f"{name(level)}.py")
        files[-1].write_text(
            "from typing import Annotated\n\n"
            f"from pkg.{name(level - 1)} import LIMIT as L\n\n"
            "LIMIT = L\n\n\n"
            'def h(x: Annotated[float, "_ <= LIMIT"]) -> None:\n'
            "    pass\n\n\n"
            "def g() -> None:\n"
            "    h(2.0)\n"
        )
    return files


def _run(root: Path, cache: bool = True, jobs: int = 1) -> tuple[list[str], int]:
    """The output lines and how many files were checked (not taken from the cache)."""
    result = check_paths([root], Config(root=root), jobs=jobs, use_cache=cache)
    assert not result.internal_errors
    lines = cli.render(result, "concise", 1, 0).splitlines()
    return lines, len(result.checked) - result.from_cache


def _found(lines: list[str]) -> tuple[int, int]:
    """How many errors and warnings the output lines show."""
    return sum("error[" in x for x in lines), sum("warning[" in x for x in lines)


def _edit(path: Path, old: str, new: str) -> None:
    path.write_text(path.read_text().replace(old, new))
    past = time.time() - 10  # older than the cache's racy window
    os.utime(path, (past, past))


def _kept(root: Path) -> tuple[int, int]:
    """The records the result cache keeps (every file's entry and every summary's),
    and the most any one file's entry keeps."""
    data = json.loads((root / ".robotfix_cache" / "results.json").read_text())
    entries = [len(e["modules"]) for e in data["entries"].values()]
    summaries = [
        sum(len(part) for part in known[2:] if isinstance(part, dict))
        for known in data["summaries"].values()
    ]
    return sum(entries) + sum(summaries), max(entries)


def test_what_the_cache_keeps_grows_linearly_with_the_chain(tmp_path: Path) -> None:
    """Each file kept a copy of every record below it (n^2 / 2 for the chain:
    1.1 GB and 75 s for 1,000 modules); now its own records only."""
    short, long = tmp_path / "short", tmp_path / "long"
    _chain(short, 120)
    _chain(long, 240)
    assert _found(_run(short)[0]) == (119, 0)
    assert _found(_run(long)[0]) == (239, 0)
    (total_short, most_short), (total_long, most_long) = _kept(short), _kept(long)
    assert total_long < 2.5 * total_short  # twice the modules: about twice the records
    assert most_long <= most_short + 2  # one file's records do not grow with the chain


def test_a_summary_is_the_same_however_deep_it_was_asked_for(tmp_path: Path) -> None:
    """Checked from its top, a 150-module chain was summarised by a recursion as
    deep as the chain: Python's limit cut it, the module it cut there was left
    empty, and the 90-odd modules above it lost their LIMIT (RF102 warnings
    instead of the RF101 errors, and a different answer in another order)."""
    _chain(tmp_path, 150, top_first=True)
    lines, _ = _run(tmp_path, cache=False)
    assert _found(lines) == (149, 0)
    assert sum("error[RF101]: `h(2.0)` violates" in line for line in lines) == 149


def test_a_change_at_the_bottom_rechecks_the_top(tmp_path: Path) -> None:
    files = _chain(tmp_path, 60, top_first=True)
    first, checked = _run(tmp_path)
    assert checked == 61 and _found(first) == (59, 0)
    assert _run(tmp_path) == (first, 0)
    # the middle: the 30 modules above it are checked again, those below are not
    _edit(files[30], "LIMIT = L\n", "LIMIT = L + 2.0\n")
    middle, checked = _run(tmp_path)
    assert checked == 30 and middle == _run(tmp_path, cache=False)[0]
    assert _found(middle) == (29, 0)  # levels 1-29; LIMIT is 3.0 from level 30 up
    # the bottom: every module above it, its own check too
    _edit(files[0], "LIMIT = 1.0", "LIMIT = 3.0")
    bottom, checked = _run(tmp_path)
    assert checked == 60 and bottom == _run(tmp_path, cache=False)[0]
    assert _found(bottom) == (0, 0)
    _edit(files[0], "LIMIT = 3.0", "LIMIT = 1.0")
    assert _run(tmp_path) == (middle, 60)


def test_workers_see_the_chain_as_one_process_does(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(run_module, "MIN_PARALLEL", 1)
    monkeypatch.setattr(run_module, "MIN_PARALLEL_BYTES", 0)
    _chain(tmp_path, 120, top_first=True)
    one = _run(tmp_path, cache=False)[0]
    assert _run(tmp_path, cache=False, jobs=2)[0] == one
    assert _found(one) == (119, 0)
