"""A file's resolver keeps what each dotted name stands for (`imported.resolve`):
the analysis asks most names again (7 of 10 on real code), and each asked the
module index and the project for every prefix of the name again."""

from __future__ import annotations

from pathlib import Path

import pytest

from robotfix.analysis import imported
from robotfix.api import make_project
from robotfix.config import Config
from robotfix.project.summary import FileResolver
from robotfix.ros.catalog import MsgCatalog

PACKAGE = Path(__file__).parent / "cases" / "packages" / "ros2_pkg"


def test_a_name_is_resolved_once_per_file(monkeypatch: pytest.MonkeyPatch) -> None:
    project = make_project([PACKAGE], Config(root=PACKAGE), MsgCatalog([]))
    resolver = project.resolver(PACKAGE / "my_pkg" / "driver.py")
    asked: list[str] = []
    module = FileResolver.module

    def counting(self: FileResolver, name: str):  # type: ignore[no-untyped-def]
        if self is resolver:  # not the resolvers of the summaries it builds
            asked.append(name)
        return module(self, name)

    monkeypatch.setattr(FileResolver, "module", counting)
    first = imported.resolve(resolver, "my_pkg.limits.MAX_SPEED")
    assert isinstance(first, imported.Value)
    assert asked == ["my_pkg.limits.MAX_SPEED", "my_pkg.limits"]
    records = dict(resolver.consulted)
    assert any(k.endswith("\0my_pkg.limits\0MAX_SPEED") for k in records)
    asked.clear()
    assert imported.resolve(resolver, "my_pkg.limits.MAX_SPEED") is first
    assert imported.resolve(resolver, "my_pkg.nothing") is None
    assert imported.resolve(resolver, "my_pkg.nothing") is None
    assert asked == ["my_pkg.nothing", "my_pkg"]  # each name once
    assert resolver.consulted.items() >= records.items()  # kept, unchanged
