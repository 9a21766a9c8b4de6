"""A rule's page, `docs/rules/RFxxx.md`: shipped inside the wheel as
`robotfix/rule_docs/` (pyproject.toml), read from `docs/rules/` in a source checkout.

Diagnostics link to it with a `file://` URI (the language server's
`codeDescription.href`, SARIF's `helpUri`): RobotFix has no web site, and the page
installed beside the checker is the one that describes this version of the rule.
"""

from __future__ import annotations

from functools import cache
from importlib import resources
from pathlib import Path


@cache
def path(code: str) -> Path | None:
    """The page's file, or None when neither the wheel nor a checkout has it."""
    try:
        shipped = resources.files("robotfix").joinpath("rule_docs", f"{code}.md")
        if isinstance(shipped, Path) and shipped.is_file():
            return shipped.resolve()
    except (OSError, ModuleNotFoundError):
        pass
    source = Path(__file__).resolve().parents[2] / "docs" / "rules" / f"{code}.md"
    return source if source.is_file() else None


def text(code: str) -> str | None:
    found = path(code)
    return None if found is None else found.read_text(encoding="utf-8")


def uri(code: str) -> str | None:
    """The page as a `file://` URI (percent-encoded), or None without a page."""
    found = path(code)
    return None if found is None else found.as_uri()
