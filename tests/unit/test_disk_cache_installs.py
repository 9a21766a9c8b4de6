"""Two installs on one machine keep separate machine caches (issue 13, item 4)."""

from __future__ import annotations

from pathlib import Path

import pytest

from robotfix.disk_cache import JsonCache


def test_two_installs_do_not_evict_each_other(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("ROBOTFIX_CACHE_DIR", str(tmp_path))
    first = JsonCache("units", "/venv-a/pint/__init__.py:1:units-v2")
    second = JsonCache("units", "/venv-b/pint/__init__.py:2:units-v2")
    assert first.path != second.path
    first.put("m", [1])
    first.save()
    second.put("m", [2])
    second.save()
    # each install reads back its own answers: neither run rewrote the other's file
    assert JsonCache("units", first.key).entries == {"m": [1]}
    assert JsonCache("units", second.key).entries == {"m": [2]}


def test_a_stale_file_of_the_same_install_is_still_ignored(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("ROBOTFIX_CACHE_DIR", str(tmp_path))
    cache = JsonCache("units", "key-1")
    cache.put("m", [1])
    cache.save()
    # a file under this name whose stored key differs (edited, or a hash clash)
    cache.path.write_text('{"key": "key-2", "entries": {"m": [9]}}')
    assert JsonCache("units", "key-1").entries == {}
