"""`-j`'s default and cap count the control group's CPU quota (issue 25 target 2):
two workers under a one-CPU quota run slower than one process."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from robotfix import cores, run


def _own(tmp_path: Path, text: str) -> Path:
    own = tmp_path / "self_cgroup"
    own.write_text(text, encoding="utf-8")
    return own


def _write(folder: Path, **files: str) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        (folder / name.replace("_dot_", ".")).write_text(text, encoding="utf-8")


def test_cgroup_v2_quota_of_the_group_and_above(tmp_path: Path) -> None:
    root = tmp_path / "fs"
    _write(root, cpu_dot_max="max 100000\n")
    _write(root / "ci" / "job", cpu_dot_max="150000 100000\n")  # 1.5 cores
    own = _own(tmp_path, "0::/ci/job\n")
    assert cores.cpu_quota(root, own) == 1.5
    _write(root / "ci", cpu_dot_max="50000 100000\n")  # the parent allows less
    assert cores.cpu_quota(root, own) == 0.5
    assert cores.available(root, own) == 1


def test_cgroup_v1_quota(tmp_path: Path) -> None:
    root = tmp_path / "fs"
    _write(
        root / "cpu,cpuacct",
        cpu_dot_cfs_quota_us="-1\n",
        cpu_dot_cfs_period_us="100000\n",
    )
    group = root / "cpu,cpuacct" / "docker" / "abc"
    _write(group, cpu_dot_cfs_quota_us="100000\n", cpu_dot_cfs_period_us="100000\n")
    own = _own(tmp_path, "5:memory:/docker/abc\n3:cpu,cpuacct:/docker/abc\n")
    assert cores.cpu_quota(root, own) == 1.0
    assert cores.available(root, own) == 1


def test_no_quota_or_nothing_readable(tmp_path: Path) -> None:
    root = tmp_path / "fs"
    _write(root, cpu_dot_max="max 100000\n")
    affinity = len(os.sched_getaffinity(0))
    assert cores.cpu_quota(root, _own(tmp_path, "0::/\n")) is None
    assert cores.available(root, _own(tmp_path, "0::/\n")) == affinity
    assert cores.cpu_quota(root, tmp_path / "missing") is None
    _write(root, cpu_dot_max="garbage\n")
    assert cores.available(root, _own(tmp_path, "0::/\n")) == affinity


def test_the_run_caps_workers_by_the_quota(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    root = tmp_path / "fs"
    _write(root, cpu_dot_max="100000 100000\n")
    if len(os.sched_getaffinity(0)) < 2:
        pytest.skip("one core: nothing to cap")
    own = _own(tmp_path, "0::/\n")
    monkeypatch.setattr(cores.available, "__defaults__", (root, own))
    assert run.default_jobs() == 1
