"""How an entry of the result cache keeps what its check consulted (issue 13 item
5): a record made from the file itself is kept without the file's name, and still
stands for the same question, however the file was spelled."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from robotfix import cli
from robotfix.config import Config
from robotfix.run import check_paths
from tests.test_cached_run import LIMITS, age, tree, write

__all__ = ["tree"]  # the fixture, shared with test_cached_run

LIMITS_NEEDS_SPEED = LIMITS.replace('"_ <= 3.0"', '"_ <= 1.0"')


def run(root: Path, paths: list[Path], cache: bool = True) -> tuple[str, int, int]:
    result = check_paths(paths, Config(root=root), use_cache=cache)
    return cli.render(result, "concise", 1, 0), len(result.checked), result.from_cache


def entries(root: Path) -> dict[str, dict[str, object]]:
    data = json.loads((root / ".robotfix_cache" / "results.json").read_text())
    found: dict[str, dict[str, object]] = data["entries"]
    return found


def test_own_records_are_kept_without_the_file_name(tree: Path) -> None:
    run(tree, [tree / "src"])
    driver = str(tree / "src" / "demo" / "demo" / "driver.py")
    modules = entries(tree)[driver]["modules"]
    assert isinstance(modules, dict)
    assert any(key.startswith("\0demo.limits") for key in modules)
    assert not any(key.startswith(driver) for key in modules)


def test_a_read_member_changed_still_rechecks_its_reader(tree: Path) -> None:
    cold = run(tree, [tree / "src"])
    assert run(tree, [tree / "src"]) == (cold[0], cold[1], cold[1])
    write(tree / "src" / "demo" / "demo" / "limits.py", LIMITS_NEEDS_SPEED)
    age(tree / "src" / "demo" / "demo")
    text, files, cached = run(tree, [tree / "src"])
    assert cached == files - 2  # limits.py and the driver, which reads clamp
    assert text == run(tree, [tree / "src"], cache=False)[0]
    assert "driver.py" in cold[0] and "driver.py" not in text  # clamp now fits


@pytest.mark.parametrize("spelled", ["src", "./src/../src"])
def test_relative_spellings_read_the_same(
    tree: Path, spelled: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tree)
    fresh = run(tree, [Path(spelled)], cache=False)
    cold = run(tree, [Path(spelled)])
    assert cold[0] == fresh[0] and cold[2] == 0
    assert run(tree, [Path(spelled)]) == (fresh[0], fresh[1], fresh[1])
    # the same files named absolutely: other entries' spellings, same answers
    assert run(tree, [tree / "src"])[0] == run(tree, [tree / "src"], cache=False)[0]


def test_the_run_key_follows_robotfixs_own_code(tmp_path: Path) -> None:
    # installed from a checkout, every commit is 0.1.0: a cache keyed on the version
    # alone replayed the results of older analysis code after `git pull`
    import shutil
    import subprocess
    import sys

    import robotfix

    copy = tmp_path / "src" / "robotfix"
    package = Path(robotfix.__file__).parent
    shutil.copytree(package, copy, ignore=shutil.ignore_patterns("__pycache__"))
    probe = "from robotfix import cache; print(cache.own_digest())"

    def digest() -> str:
        env = {**os.environ, "PYTHONPATH": str(tmp_path / "src")}
        out = subprocess.run(
            [sys.executable, "-c", probe], env=env, capture_output=True, text=True
        )
        assert out.returncode == 0, out.stderr
        return out.stdout.strip()

    before = digest()
    assert before == digest()
    checks = copy / "analysis" / "checks.py"
    checks.write_text(checks.read_text().replace("<=", "< ", 1))  # same size
    assert digest() != before


def test_the_run_key_holds_the_own_digest(monkeypatch: pytest.MonkeyPatch) -> None:
    from robotfix import cache

    first = cache.run_key(Config())
    monkeypatch.setattr(cache, "own_digest", lambda: "another build")
    assert cache.run_key(Config()) != first


DIAMOND = {  # `a` imports `p` and `q`, `q` imports `p`; the node imports `a`
    "demo/p.py": "LIMIT = 2.0\n",
    "demo/q.py": "from demo.p import LIMIT\n\nSCALE = LIMIT * 2\n",
    "demo/a.py": (
        "from demo.p import LIMIT\nfrom demo.q import SCALE\n\nBOTH = LIMIT + SCALE\n"
    ),
    "demo/_node.py": (  # checked first: it asks for `a` before `a.py` does
        "from typing import Annotated\n\nfrom demo.a import BOTH\n\n\n"
        'def speed() -> Annotated[float, "_ <= 5.0"]:\n    return BOTH\n'
    ),
}


def test_a_diamond_of_imports_is_not_built_again(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The kept summaries of a diamond hold on a cached run: `p`, met under
    `q` while it waited on the stack under `a`, was taken for a cycle and built
    again on every cached run (six of the corpus's, and the analysis imported
    for them). An edit of `p` still reaches the node through both ways."""
    from robotfix.project import summary

    demo = tmp_path / "src" / "demo"
    write(demo / "package.xml", "<package><name>demo</name></package>\n")
    write(demo / "demo" / "__init__.py", "")
    for name, text in DIAMOND.items():
        write(demo / name, text)
    age(demo / "demo")
    cold = run(tmp_path, [tmp_path / "src"])
    assert "_node.py" in cold[0]  # 2 + 4 > 5
    built: list[Path] = []
    real = summary.Project._build
    monkeypatch.setattr(
        summary.Project, "_build", lambda self, p: built.append(p) or real(self, p)
    )
    assert run(tmp_path, [tmp_path / "src"]) == (cold[0], cold[1], cold[1])
    assert built == []
    write(demo / "demo" / "p.py", "LIMIT = 1.0\n")
    age(demo / "demo")
    text = run(tmp_path, [tmp_path / "src"])[0]
    assert (
        "_node.py" not in text and text == run(tmp_path, [tmp_path / "src"], False)[0]
    )
