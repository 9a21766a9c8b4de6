"""The result cache's file is the same whatever the hash seed: the order in which a
run asked things (a set of imports walks in the seed's order) is not written."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import robotfix

MODULES = 12  # each imports every other one: one import cycle, many ways to walk it
PROBE = """\
import sys
from robotfix import cache, discovery, run
from robotfix.cli import main
from robotfix.project import modules
for module in (cache, discovery, run, modules):
    module.RACY_NS = 0  # the files are new: their stamps trusted at once
main(["check", sys.argv[1], "-j", "1", "--cache-dir", sys.argv[2]])
"""


def test_two_runs_under_different_hash_seeds_write_the_same_cache(
    tmp_path: Path,
) -> None:
    package = tmp_path / "src" / "demo"
    (package / "demo").mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>demo</name></package>")
    (package / "demo" / "__init__.py").write_text("")
    for i in range(MODULES):
        imports = "".join(f"from demo import m{j}\n" for j in range(MODULES) if j != i)
        (package / "demo" / f"m{i}.py").write_text(
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
