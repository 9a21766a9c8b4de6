"""-j starts worker processes only for enough source (issue 13, item 6): a small
package is checked in one process, whatever -j says."""

from __future__ import annotations

import concurrent.futures
from pathlib import Path
from typing import Any, ClassVar

import pytest

from robotfix import run
from robotfix.api import check_paths
from robotfix.config import Config

NODE = """import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist


class Driver(Node):
    def __init__(self):
        super().__init__("driver")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.timer = self.create_timer(0.1, self.tick)

    def tick(self):
        self.pub.publish(Twist())
"""


def package(root: Path, files: int) -> Path:
    for index in range(files):
        (root / f"node{index:02d}.py").write_text(NODE)
    return root


class NoPool:
    started: ClassVar[list[int]] = []

    def __init__(self, max_workers: int, **_: Any) -> None:
        NoPool.started.append(max_workers)
        raise OSError("no pool here")


def test_a_small_package_is_checked_in_one_process(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(run, "MIN_PARALLEL_BYTES", 512 * 1024)
    monkeypatch.setattr(concurrent.futures, "ProcessPoolExecutor", NoPool)
    NoPool.started = []
    root = package(tmp_path, 40)  # many files, but 17 kB of source
    one = check_paths([root], Config(root=root), jobs=1)
    two = check_paths([root], Config(root=root), jobs=2)
    assert NoPool.started == []
    assert one.diagnostics == two.diagnostics and not two.internal_errors


def test_enough_source_starts_the_pool(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(run, "MIN_PARALLEL_BYTES", 10 * 1024)
    monkeypatch.setattr(run, "default_jobs", lambda: 2)
    monkeypatch.setattr(concurrent.futures, "ProcessPoolExecutor", NoPool)
    NoPool.started = []
    root = package(tmp_path, 40)
    result = check_paths([root], Config(root=root), jobs=2)
    assert NoPool.started == [2]  # asked for, refused, checked here instead
    assert not result.internal_errors
