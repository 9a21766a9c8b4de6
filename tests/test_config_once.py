"""A file's settings (`Config.for_file`) ask the disk once per path and per
folder: a run asks them of every checked file many times (its check, each of its
findings, the cache's key), and asked `isdir` of the file each time and
`realpath` of each folder from the root down."""

from __future__ import annotations

import os
from collections import Counter
from pathlib import Path

import pytest

from robotfix.config import Config, Flags
from robotfix.fs import answering


def _counting(monkeypatch: pytest.MonkeyPatch) -> Counter[str]:
    counted: Counter[str] = Counter()
    isdir, realpath = os.path.isdir, os.path.realpath

    def counting_isdir(path: str | os.PathLike[str]) -> bool:
        counted["isdir " + os.fspath(path)] += 1
        return isdir(path)

    def counting_realpath(path: str | os.PathLike[str], **kwargs: bool) -> str:
        counted["realpath " + os.fspath(path)] += 1
        return realpath(path, **kwargs)

    monkeypatch.setattr(os.path, "isdir", counting_isdir)
    monkeypatch.setattr(os.path, "realpath", counting_realpath)
    return counted


def test_settings_of_a_file_ask_the_disk_once(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    folder = tmp_path
    files = []
    for i in range(8):
        folder = folder / f"level{i}"
        folder.mkdir()
        for name in ("a.py", "b.py"):
            (folder / name).write_text("x = 1\n")
            files.append(folder / name)
    inner = folder / "pkg"
    inner.mkdir()
    (inner / "robotfix.toml").write_text('per-file-ignores = {"*.py" = ["RF301"]}\n')
    (inner / "c.py").write_text("x = 1\n")
    files.append(inner / "c.py")
    config = Config(root=tmp_path, flags=Flags())
    counted = _counting(monkeypatch)
    with answering():
        for _ in range(3):  # the check, a finding, the cache's key
            assert [sorted(config.ignored_codes(f)) for f in files] == [
                [] for _ in files[:-1]
            ] + [["RF301"]]
    isdirs = {k: n for k, n in counted.items() if k.startswith("isdir ") and n > 1}
    assert not isdirs, isdirs
    realpaths = [k for k in counted if k.startswith("realpath ")]
    assert len(realpaths) <= 2, realpaths  # the root's, not one per folder
