"""Which files a run parses more than once, and who parses them (issue 25 target 1:
the parse is about a sixth of an unannotated run).

Usage: python benchmarks/parsed_twice.py [--top N] FOLDER [FOLDER ...]
Checks the folders in-process like `robotfix check FOLDER... --no-cache -j 1` and
prints the characters of Python parsed (each file once), then those parsed again,
by the pair of parsers (the RobotFix functions that asked: `where` is the nearest
frames, innermost first, without `SKIPPED`). `compile` is wrapped; nothing of the
analysis is changed.
"""

from __future__ import annotations

import argparse
import builtins
import os
import sys
import traceback
from collections import Counter
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

DEPTH = 3  # frames of RobotFix named per parser
SKIPPED = ("source.", "fs.", "reader.<lambda>")  # frames that say nothing of who


def where(depth: int = DEPTH) -> str:
    """The innermost RobotFix frames of the current stack (but the reading's
    helpers: `SKIPPED`)."""
    frames = [
        name
        for f in reversed(traceback.extract_stack(limit=24))
        if f"{os.sep}robotfix{os.sep}" in f.filename
        and not (name := f"{Path(f.filename).stem}.{f.name}").startswith(SKIPPED)
    ]
    return " < ".join(frames[:depth])


@contextmanager
def counting() -> Iterator[tuple[Counter[tuple[str, str]], dict[str, int]]]:
    """While in force: (characters parsed again by (first, again) parser, each
    parsed file's characters)."""
    again: Counter[tuple[str, str]] = Counter()
    sizes: dict[str, int] = {}
    first: dict[str, str] = {}
    original: Callable[..., Any] = builtins.compile

    def compile_(source: Any, filename: Any, mode: str, *rest: Any, **kw: Any) -> Any:
        name = os.path.abspath(str(filename))
        if str(filename).endswith(".py") and isinstance(source, str):
            sizes[name] = len(source)
            if name in first:
                again[(first[name], where())] += len(source)
            else:
                first[name] = where()
        return original(source, filename, mode, *rest, **kw)

    builtins.compile = compile_
    try:
        yield again, sizes
    finally:
        builtins.compile = original


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--top", type=int, default=12)
    parser.add_argument("folders", nargs="+", type=Path)
    args = parser.parse_args(argv)
    from robotfix.api import check_paths
    from robotfix.config import Config

    with counting() as (again, sizes):
        check_paths(args.folders, Config(), jobs=1, use_cache=False)
    print(f"parsed {sum(sizes.values()):,} characters in {len(sizes)} files")
    print(f"parsed again {sum(again.values()):,}")
    for (first, second), size in again.most_common(args.top):
        print(f"{size:>10,}  first {first}\n{'':>12}again {second}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
