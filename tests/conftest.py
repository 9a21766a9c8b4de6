"""Shared test settings."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robotfix import run


@pytest.fixture(autouse=True)
def small_runs_may_use_workers(monkeypatch: pytest.MonkeyPatch) -> Iterator[None]:
    """The tests' packages are tiny; a real run would check them in one process
    (`run.MIN_PARALLEL_BYTES`). In-process tests of `-j` want the pool itself."""
    monkeypatch.setattr(run, "MIN_PARALLEL_BYTES", 0)
    yield
