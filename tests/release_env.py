"""Fresh virtual environments for the slow tests (`-m slow`), built once per session.

`tools`: build, twine, colcon-common-extensions, pytest, pre-commit, flake8 and
ament-lint from the package index, plus RobotFix from the wheel built here. `fresh`:
nothing but `robotfix[lsp]` from that wheel, so a dependency or a data file missing
from the wheel shows. When the index cannot be reached the slow tests are skipped,
except under CI (`CI` set), where they must run.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
TOOLS = [
    "build",
    "twine",
    "colcon-common-extensions",
    "pytest",
    "pre-commit",
    "flake8",
    "flake8-quotes",
    "flake8-import-order",
    "ament-lint",  # ament's own `linter` marker plugin, beside ours
]


@dataclass(frozen=True)
class Release:
    sdist: Path
    wheel: Path
    tools: Path  # a venv's bin/ folder
    fresh: Path  # a venv's bin/ folder
    home: Path  # a scratch folder for caches

    def env(self, bin_dir: Path, **extra: str) -> dict[str, str]:
        """The environment of a user whose PATH starts with `bin_dir`: none of this
        test run's PYTHONPATH (the checkout's sources) leaks in."""
        keep = {
            k: v
            for k, v in os.environ.items()
            if not k.startswith(("PYTHON", "PIP_", "VIRTUAL_ENV", "COLCON", "ROBOTFIX"))
        }
        return {
            **keep,
            "PATH": f"{bin_dir}{os.pathsep}{os.environ.get('PATH', '')}",
            "VIRTUAL_ENV": str(bin_dir.parent),
            "PIP_DISABLE_PIP_VERSION_CHECK": "1",
            "ROBOTFIX_CACHE_DIR": str(self.home / "robotfix-cache"),
            "COLCON_HOME": str(self.home / "colcon"),
            "PRE_COMMIT_HOME": str(self.home / "pre-commit"),
            **extra,
        }


_BUILT: dict[str, Release] = {}


def release(tmp_path_factory: pytest.TempPathFactory) -> Release:
    if "release" not in _BUILT:
        _BUILT["release"] = _build(tmp_path_factory.mktemp("release"))
    return _BUILT["release"]


def run(
    cmd: list[str | Path], env: dict[str, str], cwd: Path, timeout: int = 900
) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [str(c) for c in cmd],
        env=env,
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=timeout,
        check=False,
    )


def _build(base: Path) -> Release:
    if not (ROOT / "pyproject.toml").is_file():
        pytest.skip("not a checkout of RobotFix: nothing to build")
    home = base / "home"
    home.mkdir()
    tools = _venv(base / "tools")
    fresh = _venv(base / "fresh")
    draft = Release(Path(), Path(), tools, fresh, home)
    env = draft.env(tools)
    installed = run([tools / "pip", "install", "-q", *TOOLS], env, base)
    if installed.returncode != 0:
        _unavailable(
            "cannot install from the package index: " + installed.stderr[-800:]
        )
    dist = base / "dist"
    built = run([tools / "python", "-m", "build", "--outdir", dist, ROOT], env, base)
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    (sdist,) = dist.glob("robotfix-*.tar.gz")
    (wheel,) = dist.glob("robotfix-*.whl")
    installs = [  # both at once: mostly waiting for downloads
        subprocess.Popen(
            [bin_dir / "pip", "install", "-q", f"{wheel}{extra}"],
            env=draft.env(bin_dir),
            cwd=base,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
        )
        for bin_dir, extra in ((tools, ""), (fresh, "[lsp]"))
    ]
    for install in installs:
        output, _ = install.communicate(timeout=900)
        assert install.returncode == 0, output[-3000:]
    return Release(sdist, wheel, tools, fresh, home)


def _venv(folder: Path) -> Path:
    """A new venv from the Python running the tests (its base interpreter)."""
    made = subprocess.run(
        [sys.executable, "-m", "venv", str(folder)],
        capture_output=True,
        text=True,
        check=False,
    )
    if made.returncode != 0 or not (folder / "bin" / "pip").exists():
        shutil.rmtree(folder, ignore_errors=True)
        _unavailable(f"cannot make a virtual environment: {made.stderr[-500:]}")
    return folder / "bin"


def _unavailable(reason: str) -> None:
    """Skip where the slow tests cannot run; under CI they must."""
    if os.environ.get("CI"):
        pytest.fail(reason)
    pytest.skip(reason)
