"""A run that keeps no result cache makes nothing only the cache reads
(`Project.records`): no digest of the message types a check looked up
(`MsgCatalog.fingerprint_types`), no fingerprint of a summary or of its members,
no record of what a check consulted. A cached run still makes them all, and both
report the same."""

from __future__ import annotations

import shutil
from collections import Counter
from pathlib import Path

import pytest

from robotfix.config import Config
from robotfix.project import summary as summary_module
from robotfix.ros.catalog import MsgCatalog
from robotfix.run import check_paths

PACKAGES = Path(__file__).parent / "cases" / "packages"


def _counted(monkeypatch: pytest.MonkeyPatch) -> Counter[str]:
    """Calls of the type digests and of the summaries' fingerprint hash."""
    counted: Counter[str] = Counter()
    types = MsgCatalog.fingerprint_types
    digest = summary_module._hash

    def fingerprint_types(self: MsgCatalog, names: list[str]) -> str:
        counted["types"] += 1
        return types(self, names)

    def hashed(text: str) -> str:
        counted["summaries"] += 1
        return digest(text)

    monkeypatch.setattr(MsgCatalog, "fingerprint_types", fingerprint_types)
    monkeypatch.setattr(summary_module, "_hash", hashed)
    return counted


def _shown(root: Path, use_cache: bool) -> list[str]:
    config = Config(root=root, cache_dir=root / ".cache")
    result = check_paths([root], config, use_cache=use_cache)
    assert not result.internal_errors
    return [
        f"{d.path}:{d.span.line}:{d.span.col}:{d.code}:{d.message}:{d.notes}"
        for d in result.diagnostics
    ]


def test_a_run_without_the_cache_makes_no_fingerprints(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    root = tmp_path / "ros2_pkg"  # a node importing its helpers: summaries built
    shutil.copytree(PACKAGES / "ros2_pkg", root)
    counted = _counted(monkeypatch)
    plain = _shown(root, use_cache=False)
    assert plain  # the package's cases report something: the checks ran
    assert counted == Counter()
    cached = _shown(root, use_cache=True)
    assert counted["types"] > 0 and counted["summaries"] > 0
    assert cached == plain
    counted.clear()
    assert _shown(root, use_cache=True) == plain  # from the cache


def test_a_run_without_the_cache_notes_nothing_of_what_it_reads(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The launch files' reading and the graph's check noted every file and path
    they looked at (`fs.noting`) for the cache's traces, with no cache too (the
    memos' own notes, `fs.remembered`, are not counted: a cached run replays
    them)."""
    from robotfix import fs

    root = tmp_path / "ros2_services"  # launch files, a graph
    shutil.copytree(PACKAGES.parent / "graph" / "ros2_services", root)
    noted: list[object] = []
    real = fs.noting

    def counting(trace: object):  # type: ignore[no-untyped-def]
        if trace is not None:
            noted.append(trace)
        return real(trace)

    for module in ("run", "launchcheck"):
        monkeypatch.setattr(f"robotfix.{module}.noting", counting)
    plain = _shown(root, use_cache=False)
    assert noted == []
    assert _shown(root, use_cache=True) == plain
    assert noted  # the cache's traces: the test sees them
