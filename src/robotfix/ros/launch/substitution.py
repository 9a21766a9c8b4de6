"""Launch substitutions read statically: `$(var x)`, `$(find-pkg-share p)`,
`$(arg x)`, `$(find p)`, `$(dirname)`; and where a package's installed files are in
the checked tree.

A substitution whose value only exists at launch time (`$(env X)`, `$(eval ...)`,
`$(command ...)`, `$(anon n)`, an argument with no value) makes the whole text
unknown: `None`, never an error.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from robotfix.fs import probe

if TYPE_CHECKING:
    from robotfix.ros.launch.model import LaunchFile

# starts a path that is a folder of the checked tree (a package's, a launch
# file's), spelled as the run spells it: only such paths are looked up, since a
# relative path in a launch file depends on the folder `ros2 launch` runs in
TREE = "\x00"
MAX_TEXT = 10_000  # characters of one attribute worth expanding
MAX_DEPTH = 20  # nested substitutions


@dataclass
class Context:
    """What a launch file's values are resolved against."""

    path: Path  # the launch file
    packages: Callable[[str], Path | None]  # a package's folder in the checked tree
    args: dict[str, str | None] = field(default_factory=dict)  # launch arguments
    depth: int = 0  # how deep in includes
    # reads an included launch file with the arguments it is given (the reader's)
    follow: Callable[[Path, dict[str, str | None]], LaunchFile | None] | None = None


def share(ctx: Context, package: str | None) -> str | None:
    """`get_package_share_directory(p)`, `$(find-pkg-share p)`, `$(find p)`: the
    package's folder in the checked tree (a package installs its files under
    `share/<name>/` in the layout of its source folder), else unknown."""
    if not package:
        return None
    folder = ctx.packages(package)
    return TREE + str(folder) if folder is not None else None


def here(ctx: Context) -> str:
    """The launch file's folder (`$(dirname)`, `ThisLaunchFileDir()`)."""
    return TREE + str(ctx.path.parent)


def in_tree(ctx: Context, text: str | None) -> str | None:
    """A path a launch file names, if it is a file of the checked tree: one made
    from a package's or the launch file's folder (`TREE`)."""
    if not text or not text.startswith(TREE) or TREE in text[1:]:
        return None
    path = Path(text[1:])
    try:
        return str(path) if probe("isfile", path) else None
    except (OSError, ValueError):
        return None


def expand(text: str, ctx: Context, ros: int) -> str | None:
    """An XML or YAML launch attribute with its `$(...)` substitutions done."""
    if len(text) > MAX_TEXT:
        return None
    return _expand(text, ctx, ros, 0)


def _expand(text: str, ctx: Context, ros: int, depth: int) -> str | None:
    out: list[str] = []
    i = 0
    while i < len(text):
        start = text.find("$(", i)
        if start < 0:
            out.append(text[i:])
            break
        out.append(text[i:start])
        end = _closing(text, start + 2)
        if end < 0 or depth > MAX_DEPTH:
            return None
        inner = _expand(text[start + 2 : end], ctx, ros, depth + 1)
        if inner is None:
            return None
        value = _one(inner.split(), ctx, ros)
        if value is None:
            return None
        out.append(value)
        i = end + 1
    return "".join(out)


def _closing(text: str, i: int) -> int:
    depth = 1
    while i < len(text):
        if text.startswith("$(", i):
            depth += 1
            i += 2
            continue
        if text[i] == ")":
            depth -= 1
            if depth == 0:
                return i
        i += 1
    return -1


def _one(words: list[str], ctx: Context, ros: int) -> str | None:
    if not words:
        return None
    kind, args = words[0], [w.strip("'\"") for w in words[1:]]
    if kind in ("var", "arg") and len(args) == 1:
        return ctx.args.get(args[0])
    if kind in ("find-pkg-share", "find") and len(args) == 1:
        return share(ctx, args[0])
    if kind == "dirname" and not args:
        return here(ctx)
    if kind == "filename" and not args:
        return ctx.path.name
    return None  # env, optenv, eval, command, anon, file-content, find-exec...


def join(parts: list[str | None]) -> str | None:
    """`os.path.join`, unknown if a part is."""
    if any(p is None for p in parts) or not parts:
        return None
    return os.path.join(*[p for p in parts if p is not None])


def push_namespace(outer: str | None, inner: str | None) -> str | None:
    """A namespace inside another (`/robot1` then `arm`: `/robot1/arm`); an
    absolute inner one stays; unknown if either is."""
    if outer is None or inner is None:
        return None
    if inner.startswith("/") or not outer.strip("/"):
        return inner if inner.startswith("/") or not inner else f"/{inner.strip('/')}"
    if not inner:
        return outer
    return f"/{outer.strip('/')}/{inner.strip('/')}"
