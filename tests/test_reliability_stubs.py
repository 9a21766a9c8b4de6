"""Stub paths and stub files are never skipped without a word (reliability report
2, N15): a stub path that is not a folder, a stub file that is a FIFO, a name
reached through star imports deeper than RobotFix follows them."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from robotfix.api import check_paths
from robotfix.config import Config
from robotfix.stubs import load
from tests.test_cli import run as cli

posix = pytest.mark.skipif(os.name != "posix", reason="FIFOs")
SET_SPEED = (
    "from typing import Annotated\n"
    'def set_speed(v: Annotated[float, "_ <= 1"]) -> None: ...\n'
)


@posix
@pytest.mark.parametrize("kind", ["fifo", "file"])
def test_a_stub_path_that_is_not_a_folder_is_an_error(
    tmp_path: Path, kind: str
) -> None:
    """As a missing one is: exit 2 and why, not a silent run without the stubs."""
    (tmp_path / "a.py").write_text("x = 1\n")
    if kind == "fifo":
        os.mkfifo(tmp_path / "stubs")
    else:
        (tmp_path / "stubs").write_text("")
    result = cli("check", "a.py", "--stub-path", "stubs", "--no-cache", cwd=tmp_path)
    assert result.returncode == 2
    assert "--stub-path stubs: not a folder" in result.stderr
    (tmp_path / "pyproject.toml").write_text(
        '[tool.robotfix]\nstub-paths = ["stubs"]\n'
    )
    result = cli("check", "a.py", "--no-cache", cwd=tmp_path)
    assert result.returncode == 2 and "stub-paths" in result.stderr


@posix
def test_a_fifo_stub_is_rf512_and_never_blocks(tmp_path: Path) -> None:
    stubs = tmp_path / "stubs"
    stubs.mkdir()
    os.mkfifo(stubs / "drv.pyi")
    (tmp_path / "a.py").write_text("import drv\ndrv.set_speed(5.0)\n")
    result = check_paths(
        [tmp_path / "a.py"], Config(root=tmp_path, stub_paths=(stubs,))
    )
    assert [(d.path, d.code) for d in result.diagnostics] == [
        (str(stubs / "drv.pyi"), "RF512")
    ]
    assert "not a regular file" in result.diagnostics[0].message


def star_chain(stubs: Path, length: int) -> None:
    """drv.pyi -> m1.pyi -> ... -> m{length}.pyi (which defines set_speed)."""
    stubs.mkdir()
    (stubs / "drv.pyi").write_text("from m1 import *\n")
    for i in range(1, length):
        (stubs / f"m{i}.pyi").write_text(f"from m{i + 1} import *\n")
    (stubs / f"m{length}.pyi").write_text(SET_SPEED)


def test_star_imports_are_followed(tmp_path: Path) -> None:
    stubs = tmp_path / "stubs"
    star_chain(stubs, load.MAX_STAR_DEPTH)
    (tmp_path / "a.py").write_text("import drv\ndrv.set_speed(5.0)\n")
    result = check_paths(
        [tmp_path / "a.py"], Config(root=tmp_path, stub_paths=(stubs,))
    )
    assert [(Path(d.path).name, d.code) for d in result.diagnostics] == [
        ("a.py", "RF101")
    ]


def test_a_star_chain_too_deep_is_rf512_at_its_head(tmp_path: Path) -> None:
    """A 3,000-deep chain: the name is not found, and RF512 at `drv.pyi` says
    from where on nothing is loaded (once, not at each of the 3,000 stubs)."""
    stubs = tmp_path / "stubs"
    star_chain(stubs, 3000)
    (tmp_path / "a.py").write_text("import drv\ndrv.set_speed(5.0)\n")
    result = check_paths(
        [tmp_path / "a.py"], Config(root=tmp_path, stub_paths=(stubs,))
    )
    assert [(Path(d.path).name, d.span.line, d.code) for d in result.diagnostics] == [
        ("drv.pyi", 1, "RF512")
    ]
    message = result.diagnostics[0].message
    assert f"further than {load.MAX_STAR_DEPTH} modules from `drv`" in message
    assert f"`m{load.MAX_STAR_DEPTH + 1}`" in message
