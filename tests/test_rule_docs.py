"""Every rule has a page under docs/rules/, and every page's examples behave as marked.

In a page, the `## Example` and `## Use instead` sections are separate worlds: their
```msg blocks become interface files, their ```python blocks are checked against them
with inline `# error: RFxxx` markers (strict, as in tests/cases), markers in msg lines
are matched against interface-file problems, and a ```python-bad block must produce
exactly the page's own code. A ```pyi block is a stub named by its first line
(`# my_lib.pyi`) in the section's stub path; its markers are matched against RF512.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from robotfix import rules
from robotfix.api import catalog_problems, check_source, stub_problems
from robotfix.config import Config
from robotfix.ros.catalog import MsgCatalog
from robotfix.testing.expectations import compare, read_expectations

DOCS = Path(__file__).parent.parent / "docs" / "rules"
PAGES = sorted(DOCS.glob("RF*.md"))
BLOCK = re.compile(r"```([\w-]+)\n(.*?)```", re.DOTALL)
MARKER = re.compile(r"#\s*(error|warning|note):\s*(RF\d{3})")


def test_every_rule_has_a_page_and_every_page_a_rule() -> None:
    assert {p.stem for p in PAGES} == set(rules.ALL_RULES)


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.stem)
def test_first_line_names_the_rule(page: Path) -> None:
    rule = rules.ALL_RULES[page.stem]
    first = page.read_text(encoding="utf-8").splitlines()[0]
    assert first == f"# {rule.code} `{rule.name}`: {rule.title}"


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.stem)
def test_examples_produce_exactly_their_markers(page: Path, tmp_path: Path) -> None:
    text = page.read_text(encoding="utf-8")
    for index, section in enumerate(re.split(r"^## ", text, flags=re.M)):
        if section.startswith(("Example", "Use instead")):
            check_section(page.stem, section, tmp_path / str(index))


def check_section(code: str, section: str, folder: Path) -> None:
    folder.mkdir()
    blocks = BLOCK.findall(section)
    msg_files = []
    for number, (language, body) in enumerate(blocks):
        if language == "msg":
            path = folder / f"m{number}.msg"
            path.write_text(body, encoding="utf-8")
            msg_files.append((path, body))
    catalog = MsgCatalog([p for p, _ in msg_files])
    problems = [(d.path, d.span.line, d.code) for d in catalog_problems(catalog)]
    expected = [
        (str(path), line, m.group(2))
        for path, body in msg_files
        for line, content in enumerate(body.splitlines(), start=1)
        for m in [MARKER.search(content)]
        if m is not None
    ]
    assert sorted(problems) == sorted(expected), section
    config = Config(stub_paths=(folder / "stubs",))
    stubs = []
    for language, body in blocks:
        if language == "pyi":
            path = folder / "stubs" / body.splitlines()[0].lstrip("# ").strip()
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(body, encoding="utf-8")
            stubs.append((path, body))
    found_stubs = [(d.path, d.span.line, d.code) for d in stub_problems(config)]
    expected_stubs = [
        (str(path), line, m.group(2))
        for path, body in stubs
        for line, content in enumerate(body.splitlines(), start=1)
        for m in [MARKER.search(content)]
        if m is not None
    ]
    assert sorted(found_stubs) == sorted(expected_stubs), section
    for language, body in blocks:
        if language == "python":
            found = check_source(body, "example.py", config, catalog)
            mismatches = compare(read_expectations(body), found)
            assert not mismatches, f"{code}: {mismatches}\n{body}"
        elif language == "python-bad":
            found = check_source(body, "example.py", config, catalog)
            assert [d.code for d in found] == [code], body
