"""Every rule has a page under docs/rules/, and every page's examples behave as marked.

In a page, the `## Example` and `## Use instead` sections are separate worlds: their
```msg blocks become interface files, their ```python blocks are checked against them
with inline `# error: RFxxx` markers (strict, as in tests/cases), markers in msg lines
are matched against interface-file problems, and a ```python-bad block must produce
exactly the page's own code. A ```pyi block is a stub named by its first line
(`# my_lib.pyi`) in the section's stub path; its markers are matched against RF512.

Examples about files rather than code: a ```python-bytes block is the bytes of
`example.py` (`\xff` escapes) and must produce exactly the page's own code; a
```links block makes each `LINK -> TARGET` a symlink to a folder holding a Python
file (an absolute target is placed under the section's folder); a ```console block's
`$ robotfix check ...` lines are run in the section's folder, and the diagnostic lines
they print (`--format concise`, the folder's path left out) must be the lines below;
a ```files block writes the files a console block checks (each begins with a line
`--- path/in/the/folder`).
Every page's example is run, except RF901's and RF902's (`NOT_RUN`).
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import sys
from pathlib import Path

import pytest

from robotfix import cli, rules
from robotfix.api import catalog_problems, check_file, check_source, stub_problems
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


EXECUTED = {"python", "python-bad", "python-bytes", "console", "msg", "pyi"}
# examples that are prose: what exhausts a work budget depends on the budgets, which
# are being changed (the rules are tested in test_reliability_analysis.py and
# test_adversarial.py)
NOT_RUN = {
    "RF901": "the solver's budget is being changed (test_reliability_analysis.py)",
    "RF902": "the analysis budget is being changed (test_adversarial.py)",
}


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.stem)
def test_every_example_is_run(page: Path) -> None:
    if page.stem in NOT_RUN:
        pytest.skip(f"example not run: {NOT_RUN[page.stem]}")
    text = page.read_text(encoding="utf-8")
    example = next(
        s for s in re.split(r"^## ", text, flags=re.M) if s.startswith("Example")
    )
    assert {language for language, _ in BLOCK.findall(example)} & EXECUTED


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
            expected = read_expectations(body)
            if sys.version_info >= (
                3,
                12,
            ):  # RF005: syntax newer than RobotFix's Python
                expected = [e for e in expected if e.code != "RF005"]
            mismatches = compare(expected, found)
            assert not mismatches, f"{code}: {mismatches}\n{body}"
        elif language == "python-bad":
            found = check_source(body, "example.py", config, catalog)
            assert [d.code for d in found] == [code], body
        elif language == "python-bytes":
            data = body.encode("ascii").decode("unicode_escape").encode("latin-1")
            (folder / "example.py").write_bytes(data)
            found = check_file("example.py", data, catalog)
            assert [d.code for d in found] == [code], body
        elif language == "links":
            for line in body.splitlines():
                link, target = line.split(" -> ")
                place = folder / target.lstrip("/")
                place.mkdir(parents=True)
                (place / "node.py").write_text("x = 1\n")
                (folder / link).parent.mkdir(parents=True, exist_ok=True)
                (folder / link).symlink_to(place, target_is_directory=True)
        elif language == "files":
            for chunk in re.split(r"^--- ", body, flags=re.M)[1:]:
                name, _, content = chunk.partition("\n")
                (folder / name.strip()).parent.mkdir(parents=True, exist_ok=True)
                (folder / name.strip()).write_text(content, encoding="utf-8")
        elif language == "console":
            assert run_console(body, folder) == [
                line for line in body.splitlines() if not line.startswith("$ ")
            ], body


def run_console(body: str, folder: Path) -> list[str]:
    """The diagnostic lines the block's `$ robotfix check` commands print."""
    shown = []
    for line in body.splitlines():
        if line.startswith("$ robotfix check "):
            args = line.split()[3:]
            out = io.StringIO()
            cwd = Path.cwd()
            os.chdir(folder)
            try:
                with contextlib.redirect_stdout(out):
                    cli.main(["check", "--no-cache", "--format", "concise", *args])
            finally:
                os.chdir(cwd)
            printed = out.getvalue().replace(str(folder), "").splitlines()
            shown += [p for p in printed if re.match(r"\S+:\d+:\d+: ", p)]
        else:
            assert not line.startswith("$"), f"not a robotfix check command: {line}"
    return shown
