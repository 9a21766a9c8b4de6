"""The result cache's file is the same whatever the hash seed: the order in which a
run asked things (a set of imports walks in the seed's order) is not written."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import robotfix

sys.path.insert(0, str(Path(__file__).parent))
from test_start_up import TRUSTED, demo_package

MODULES = 12  # each imports every other one: one import cycle, many ways to walk it
PROBE = (
    TRUSTED
    + """\
import sys
from robotfix.cli import main
main(["check", sys.argv[1], "-j", "1", "--cache-dir", sys.argv[2]])
"""
)


def test_two_runs_under_different_hash_seeds_write_the_same_cache(
    tmp_path: Path,
) -> None:
    package = demo_package(tmp_path)
    for i in range(MODULES):
        imports = "".join(f"from demo import m{j}\n" for j in range(MODULES) if j != i)
        (package / f"m{i}.py").write_text(
            f"{imports}import helper{i}\n\n\ndef f{i}() -> int:\n    return {i}\n"
        )
    written = []
    for seed in ("1", "2", "3"):
        env = {
            **os.environ,
            "PYTHONPATH": str(Path(robotfix.__file__).parent.parent),
            "PYTHONHASHSEED": seed,
        }
        cache = tmp_path / f"cache{seed}"
        done = subprocess.run(
            [sys.executable, "-c", PROBE, str(tmp_path / "src"), str(cache)],
            capture_output=True,
            text=True,
            env=env,
            cwd=tmp_path,
            check=False,
        )
        assert "No problems found" in done.stdout, done.stdout + done.stderr
        written.append((cache / "results.json").read_bytes())
    assert b'"resolved"' in written[0]  # the module index's answers are kept
    assert written[1] == written[0] and written[2] == written[0]
