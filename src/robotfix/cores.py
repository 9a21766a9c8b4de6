"""How many cores this process may use: the default of `-j` and its cap.

The CPUs the process may run on (`os.sched_getaffinity`), fewer when a CPU quota
of its control group allows less (`docker run --cpus=1`, a CI runner's limit,
systemd's `CPUQuota=`): two workers under a one-CPU quota share one core's time and
run slower than one process (measured on ros_comm, 355 files: 6.0-6.4 s wall with
`-j 2` against 4.0-5.0 s with `-j 1`; docs/performance.md). Both cgroup v2
(`cpu.max`) and v1 (`cpu.cfs_quota_us` / `cpu.cfs_period_us`) are read, for the
process's own group and each group above it (the smallest quota applies); nothing
readable means no quota.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable
from pathlib import Path

CGROUP_ROOT = Path("/sys/fs/cgroup")


def available(root: Path = CGROUP_ROOT, own: Path = Path("/proc/self/cgroup")) -> int:
    """The cores this process may use, at least 1."""
    cores = (
        len(os.sched_getaffinity(0))
        if hasattr(os, "sched_getaffinity")
        else (os.cpu_count() or 1)
    )
    quota = cpu_quota(root, own)
    if quota is not None:
        cores = min(cores, max(1, math.ceil(quota)))
    return max(1, cores)


def cpu_quota(
    root: Path = CGROUP_ROOT, own: Path = Path("/proc/self/cgroup")
) -> float | None:
    """The smallest CPU quota (in cores) of this process's control group and the
    groups above it, or None when there is none (or nothing can be read)."""
    try:
        lines = own.read_text(encoding="utf-8").splitlines()
    except (OSError, ValueError):
        return None
    found: list[float] = []
    for line in lines:
        parts = line.split(":", 2)
        if len(parts) != 3:
            continue
        _, controllers, group = parts
        if controllers == "":  # cgroup v2: one unified hierarchy
            found += _quotas(root, group, _v2)
        elif "cpu" in controllers.split(","):
            for mount in (controllers, "cpu", "cpu,cpuacct"):
                if (root / mount).is_dir():
                    found += _quotas(root / mount, group, _v1)
                    break
    return min(found) if found else None


def _quotas(
    mount: Path, group: str, read: Callable[[Path], float | None]
) -> list[float]:
    """Each readable quota from `group` up to the hierarchy's root."""
    out = []
    folder = Path(group.strip() or "/")
    for level in (folder, *folder.parents):
        quota = read(mount / str(level).lstrip("/"))
        if quota is not None:
            out.append(quota)
    return out


def _v2(folder: Path) -> float | None:
    try:
        quota, period = (folder / "cpu.max").read_text(encoding="utf-8").split()[:2]
        return None if quota == "max" else int(quota) / int(period)
    except (OSError, ValueError, ZeroDivisionError):
        return None


def _v1(folder: Path) -> float | None:
    try:
        quota = int((folder / "cpu.cfs_quota_us").read_text(encoding="utf-8"))
        period = int((folder / "cpu.cfs_period_us").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return quota / period if quota > 0 and period > 0 else None
