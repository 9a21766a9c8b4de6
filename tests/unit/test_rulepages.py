"""Diagnostics link to the rule's page installed beside the checker (the language
server's codeDescription, SARIF's helpUri): a file that exists, for every rule."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from urllib.parse import urlparse
from urllib.request import url2pathname

import pytest

from robotfix import rulepages
from robotfix.rules import ALL_RULES


@pytest.fixture(autouse=True)
def fresh_lookup() -> Iterator[None]:
    rulepages.path.cache_clear()
    yield
    rulepages.path.cache_clear()


@pytest.mark.parametrize("code", sorted(ALL_RULES))
def test_every_rule_links_to_its_page(code: str) -> None:
    uri = rulepages.uri(code)
    assert uri is not None and uri.startswith("file:///")
    page = Path(url2pathname(urlparse(uri).path))
    title = f"# {code} `{ALL_RULES[code].name}`"
    assert page.read_text(encoding="utf-8").startswith(title)
    assert rulepages.text(code) == page.read_text(encoding="utf-8")


def test_the_page_shipped_in_the_wheel_comes_first(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "rule_docs").mkdir()
    shipped = tmp_path / "rule_docs" / "RF101.md"
    shipped.write_text("# RF101 `refinement-violated` (installed)\n")
    monkeypatch.setattr(rulepages.resources, "files", lambda _: tmp_path)
    assert rulepages.uri("RF101") == shipped.resolve().as_uri()
    assert rulepages.uri("RF999") is None  # no page: no link rather than a dead one
