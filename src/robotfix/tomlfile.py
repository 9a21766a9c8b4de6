"""TOML texts, parsed by tomllib (tomli before 3.11): the one module that imports
it, and only when a text is read. Most runs read none (no pyproject.toml; the
shipped tables are read as JSON, `ros/catalog.table`), and the import is 5 ms of a
150 ms one-file check."""

from __future__ import annotations

import sys
from typing import Any


class TomlError(ValueError):
    """A text that is not TOML; the message names the line, as tomllib's does."""


def loads(text: str) -> Any:
    if sys.version_info >= (3, 11):
        import tomllib
    else:  # pragma: no cover
        import tomli as tomllib
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as err:
        raise TomlError(str(err)) from None
