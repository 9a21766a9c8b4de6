"""Regular expressions compiled when first used (issue 25: a one-file check paid
for ~50 patterns at import that it never matched with; `re` compiles in Python).

`lazy(pattern)` stands for `re.compile(pattern)`: the first use of a method
(`search`, `match`...) compiles the pattern and keeps that method on the object,
so later uses cost what they cost on the compiled pattern."""

from __future__ import annotations

import re
from typing import Any, cast


class _Lazy:
    def __init__(self, pattern: Any, flags: int) -> None:  # str or bytes
        self._pattern = pattern
        self._flags = flags

    def __getattr__(self, name: str) -> Any:  # only for names not yet kept
        found = getattr(re.compile(self._pattern, self._flags), name)
        setattr(self, name, found)
        return found


def lazy(pattern: str | bytes, flags: int = 0) -> re.Pattern[Any]:
    """`re.compile(pattern, flags)`, compiled at the first use."""
    return cast("re.Pattern[Any]", _Lazy(pattern, flags))
