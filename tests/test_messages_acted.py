"""Messages people act on (issue 24 item 4, newuser2 §7): each diagnostic says what
is wrong where it is wrong, in the words and units the user wrote."""

from __future__ import annotations

from pathlib import Path

from robotfix.api import check_source
from robotfix.config import Config

CASES = Path(__file__).parent / "cases"


def test_rf301_caret_is_under_the_unbound_name_at_the_line_of_the_read() -> None:
    path = CASES / "paths" / "unbound_read_located.py"
    found = check_source(path.read_text(encoding="utf-8"), str(path), Config())
    spans = [(d.code, d.span.line, d.span.col, d.span.end_col) for d in found]
    assert spans == [
        ("RF301", 15, 57, 59),  # `dt` in `... % dt`, on the line of the read
        ("RF301", 23, 12, 18),  # `period`, the second argument's line
        ("RF301", 27, 14, 19),  # `speed` in `print(speed)`
    ]
