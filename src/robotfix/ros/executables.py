"""Which source file a package's executable runs: `ros2 run pkg exe` / a launch
entry's `package` + `executable`, ROS 1's `type=`.

Read from the package's build files, never run: `setup.py`'s
`entry_points={'console_scripts': ['exe = pkg.module:main']}` (read with `ast`:
literals, names bound once at module level, `+` and f-strings of them),
`setup.cfg`'s `[options.entry_points]`, CMake's `install(PROGRAMS ...)` and
`catkin_install_python(PROGRAMS ...)`, and then a file of that name in the
package's `scripts/`, `nodes/`, `bin/` or `src/` (rosrun runs any executable file
of the package by its name). What cannot be read is no file: unknown.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeVar

from robotfix.fs import UnreadableError, probe, read_regular, read_text, remembered
from robotfix.lazyre import lazy

MAX_BUILD_BYTES = 1024 * 1024
SCRIPT_FOLDERS = ("scripts", "nodes", "bin", "src", "")
T = TypeVar("T")
_PROGRAMS = lazy(
    r"(?:install|catkin_install_python)\s*\(\s*PROGRAMS\s+([^)]*)\)", re.IGNORECASE
)


def executable_file(
    package: Path, executable: str, memo: dict[tuple[str, Path], Any] | None = None
) -> Path | None:
    """The Python file `executable` of the package in folder `package` runs;
    `memo` keeps each package's build files as read (one run: a launch file's
    many nodes of one package read its setup.py once)."""
    if not executable or "/" in executable or executable in (".", ".."):
        return None
    memo = {} if memo is None else memo
    scripts = _once(memo, "console_scripts", package, _entry_points)
    for module in scripts.get(executable, []):
        found = module_file(package, module)
        if found is not None:
            return found
    for program in _once(memo, "programs", package, _cmake_programs):
        if program.name == executable and probe("isfile", program):
            return program
    for folder in SCRIPT_FOLDERS:
        candidate = package / folder / executable
        try:
            if probe("isfile", candidate):
                return candidate
        except (OSError, ValueError):
            return None
    return None


def _once(
    memo: dict[tuple[str, Path], Any],
    kind: str,
    package: Path,
    read: Callable[[Path], T],
) -> T:
    return remembered(memo, (kind, package), lambda: read(package))  # type: ignore[no-any-return]


def _read(path: Path) -> str | None:
    try:
        return read_text(path, MAX_BUILD_BYTES)
    except UnreadableError:
        return None


def _entry_points(package: Path) -> dict[str, list[str]]:
    """console_scripts: executable name -> `module.path` (setup.py, setup.cfg)."""
    found: dict[str, list[str]] = {}
    lines: list[str] = []
    text = _read(package / "setup.py")
    if text is not None:
        lines += _setup_py_scripts(text)
    text = _read(package / "setup.cfg")
    # most setup.cfg name no console_scripts (option names are case-blind):
    # configparser (35 M instructions to import) only for those that do
    if text is not None and "console_scripts" in text.lower():
        import configparser

        parser = configparser.ConfigParser(interpolation=None)
        try:
            parser.read_string(text)
            lines += parser.get("options.entry_points", "console_scripts").splitlines()
        except (configparser.Error, ValueError):
            pass
    for line in lines:
        name, eq, target = line.partition("=")
        if eq and target.strip():
            module = target.split(":")[0].strip()
            found.setdefault(name.strip(), []).append(module)
    return found


def _setup_py_scripts(text: str) -> list[str]:
    try:
        tree = ast.parse(text)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return []
    names: dict[str, ast.expr] = {}
    counts: dict[str, int] = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
            counts[node.id] = counts.get(node.id, 0) + 1
    for statement in tree.body:
        if isinstance(statement, ast.Assign) and len(statement.targets) == 1:
            target = statement.targets[0]
            if isinstance(target, ast.Name) and counts.get(target.id) == 1:
                names[target.id] = statement.value
    out: list[str] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.keyword) and node.arg == "entry_points":
            value = node.value
            if isinstance(value, ast.Name):
                value = names.get(value.id, value)
            if isinstance(value, ast.Dict):
                for key, item in zip(value.keys, value.values, strict=True):
                    if _string(key, names, 0) == "console_scripts":
                        if isinstance(item, ast.Name):
                            item = names.get(item.id, item)
                        if isinstance(item, (ast.List, ast.Tuple)):
                            out += [
                                s
                                for e in item.elts
                                if (s := _string(e, names, 0)) is not None
                            ]
    return out


def _string(
    node: ast.expr | None, names: dict[str, ast.expr], depth: int
) -> str | None:
    if node is None or depth > 20:
        return None
    if isinstance(node, ast.Constant):
        return node.value if isinstance(node.value, str) else None
    if isinstance(node, ast.Name) and node.id in names:
        return _string(names[node.id], names, depth + 1)
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        left = _string(node.left, names, depth + 1)
        right = _string(node.right, names, depth + 1)
        return left + right if left is not None and right is not None else None
    if isinstance(node, ast.JoinedStr):
        parts = [_string(v, names, depth + 1) for v in node.values]
        return "".join(p for p in parts if p is not None) if None not in parts else None
    if isinstance(node, ast.FormattedValue) and node.format_spec is None:
        return _string(node.value, names, depth + 1)
    return None


def module_file(package: Path, module: str) -> Path | None:
    """The file of a dotted module of the package (`pkg.node`), at its root or
    under `src/`."""
    parts = module.split(".")
    if not all(p.isidentifier() for p in parts):
        return None
    for base in (package, package / "src"):
        for candidate in (
            base.joinpath(*parts).with_suffix(".py"),
            base.joinpath(*parts, "__init__.py"),
        ):
            if probe("isfile", candidate):
                return candidate
    return None


def _cmake_programs(package: Path) -> list[Path]:
    text = _read(package / "CMakeLists.txt")
    if text is None:
        return []
    text = re.sub(r"#[^\n]*", "", text)
    found: list[Path] = []
    for match in _PROGRAMS.finditer(text):
        words = match.group(1).split()
        for word in words:
            if word.upper() in ("DESTINATION", "RENAME", "PERMISSIONS"):
                break
            if "$" not in word:
                found.append(package / word.strip("\"'"))
    return found


# -- C++: CMake targets --------------------------------------------------------
_COMMAND = lazy(r"\b([A-Za-z_][A-Za-z0-9_]*)\s*\(([^()]*)\)")
_VARIABLE = lazy(r"\$\{([A-Za-z0-9_]+)\}")
_TARGET_WORDS = frozenset(
    {
        "STATIC",
        "SHARED",
        "MODULE",
        "OBJECT",
        "INTERFACE",
        "EXCLUDE_FROM_ALL",
        "WIN32",
        "MACOSX_BUNDLE",
        "PUBLIC",
        "PRIVATE",
        "IMPORTED",
        "ALIAS",
    }
)
CMAKE_STEPS = 2 * MAX_BUILD_BYTES  # characters of commands read per CMakeLists.txt
MAX_VALUE = 4096  # a variable's value longer than this is unknown
_INCLUDE = lazy(rb'#\s*include\s*[<"]([^>"]+)[>"]')
CPP_SOURCE_SUFFIXES = (".cpp", ".cc", ".cxx", ".c++", ".hpp", ".hh", ".hxx", ".h")


Targets = dict[str, tuple[list[Path], list[str]]]


def cpp_executable_files(
    package: Path, executable: str, memo: dict[Path, Any] | None = None
) -> list[Path]:
    """The C++ files an executable of the package is built from, read from its
    CMakeLists.txt (never run): `add_executable(name src/x.cpp)`, the package's
    libraries it links (`target_link_libraries`), `rclcpp_components_register_node(
    lib ... EXECUTABLE name)`, `foreach` over a literal list (`foreach(d talker
    listener) tut(${d}) endforeach()`), and the package's headers those files
    include.
    `set()` variables and `${PROJECT_NAME}` are substituted; a word still holding a
    `${...}` is unknown (left out). `memo` keeps each package's targets for a run."""
    memo = {} if memo is None else memo
    targets: Targets = remembered(memo, package, lambda: _cmake_targets(package))
    todo = [executable]
    seen: set[str] = set()
    files: list[Path] = []
    while todo:
        name = todo.pop()
        if name in seen or name not in targets:
            continue
        seen.add(name)
        sources, links = targets[name]
        files += [s for s in sources if s not in files]
        todo += links
    return files + [h for h in _included(package, files) if h not in files]


def _cmake_targets(package: Path) -> dict[str, tuple[list[Path], list[str]]]:
    """target -> (its source files, the targets it links or is built from)."""
    text = _read(package / "CMakeLists.txt")
    if text is None:
        return {}
    text = re.sub(r"#[^\n]*", "", text)
    functions: dict[str, tuple[list[str], str]] = {}
    outside: list[str] = []  # the text outside function and macro definitions
    start, opened, head = 0, -1, [""]
    for match in _BOUNDARY.finditer(text):  # one pass: no rescanning per opening
        if match.group("end") is None and opened < 0:
            outside.append(text[start : match.start()])
            opened, head = match.end(), match.group("head").split() or [""]
        elif match.group("end") is not None and opened >= 0:
            functions[head[0].lower()] = (head[1:], text[opened : match.start()])
            start, opened = match.end(), -1
    outside.append(text[start:] if opened < 0 else "")
    text = "".join(outside)
    targets: dict[str, tuple[list[Path], list[str]]] = {}
    _cmake_run(package, text, {}, targets, functions, 0, [CMAKE_STEPS])
    return targets


# `function(name args)` / `macro(...)` and their `endfunction()` / `endmacro()`
_BOUNDARY = lazy(
    r"\b(?P<end>end)?(?:function|macro)\s*\((?P<head>[^()]*)\)", re.IGNORECASE
)


def _cmake_run(
    package: Path,
    text: str,
    variables: dict[str, str],
    targets: dict[str, tuple[list[Path], list[str]]],
    functions: dict[str, tuple[list[str], str]],
    depth: int,
    budget: list[int],
) -> None:
    """The commands of `text` that make targets, in order; a call of a function
    the file defines runs its body with its parameters bound (4 deep at most); a
    `foreach` over a list its words give runs its body once per item.
    `budget` counts the characters of the commands read, function bodies run
    included: what is left when it runs out is not read (its targets unknown)."""

    def value(m: re.Match[str]) -> str:
        found = variables.get(m.group(1))  # a value too long to be a name: unknown
        return found if found is not None and len(found) <= MAX_VALUE else m.group(0)

    at = 0
    while (match := _COMMAND.search(text, at)) is not None:
        at = match.end()
        budget[0] -= len(match.group(0))
        if budget[0] < 0:
            return
        command = match.group(1).lower()
        words = [
            part
            for w in match.group(2).split()
            for part in _VARIABLE.sub(value, w.strip("\"'")).split(";")
        ]
        if not words:
            continue
        if command == "foreach":
            body, after = _loop_body(text, at, budget)
            items = _loop_items(words, variables)
            if items is not None and after is not None:
                for item in items:  # each pass's commands count against `budget`
                    bound = {**variables, words[0]: item}
                    _cmake_run(package, body, bound, targets, functions, depth, budget)
                    if budget[0] < 0:
                        return
                at = after
        elif command in functions and depth < 4:
            params, body = functions[command]
            bound = dict(variables)
            bound.update(zip(params, words[: len(params)], strict=False))
            bound["ARGN"] = ";".join(words[len(params) :])
            _cmake_run(package, body, bound, targets, functions, depth + 1, budget)
        elif command == "cmake_parse_arguments":
            _parse_arguments(match.group(2), variables)
        elif command == "project":
            variables["PROJECT_NAME"] = words[0]
        elif command == "set" and len(words) >= 2:
            variables[words[0]] = words[1]
        elif command in ("add_executable", "add_library", "target_sources"):
            sources, _ = targets.setdefault(words[0], ([], []))
            for word in words[1:]:
                if word in _TARGET_WORDS or "$" in word:
                    continue
                if word.endswith(CPP_SOURCE_SUFFIXES):
                    path = package / word
                    if probe("isfile", path) and path not in sources:
                        sources.append(path)
        elif command == "target_link_libraries":
            _, links = targets.setdefault(words[0], ([], []))
            links += [w for w in words[1:] if w not in _TARGET_WORDS and "$" not in w]
        elif (
            command == "rclcpp_components_register_node" and "EXECUTABLE" in words[:-1]
        ):
            name = words[words.index("EXECUTABLE") + 1]
            targets.setdefault(name, ([], []))[1].append(words[0])


def _loop_body(text: str, start: int, budget: list[int]) -> tuple[str, int | None]:
    """The body of the `foreach` whose head ends at `start`, and where its
    `endforeach()` ends (None: not closed, or `budget` spent looking)."""
    depth = 1
    for match in _COMMAND.finditer(text, start):
        budget[0] -= len(match.group(0))
        if budget[0] < 0:
            break
        command = match.group(1).lower()
        depth += (command == "foreach") - (command == "endforeach")
        if depth == 0:
            return text[start : match.start()], match.end()
    return "", None


def _loop_items(words: list[str], variables: dict[str, str]) -> list[str] | None:
    """The values a `foreach` gives its variable: `foreach(x a b)`, `foreach(x IN
    ITEMS a b)`, `foreach(x IN LISTS l)`; None for any other form (`RANGE`,
    `ZIP_LISTS`) or an item still holding a `${...}` (unknown)."""
    items = words[1:]
    if items[:2] == ["IN", "ITEMS"]:
        items = items[2:]
    elif items[:2] == ["IN", "LISTS"]:
        if any(name not in variables for name in items[2:]):
            return None  # set where this file is not read
        items = [part for name in items[2:] for part in variables[name].split(";")]
    elif items[:1] in (["RANGE"], ["IN"]):
        return None
    if any("$" in item for item in items):
        return None
    return [item for item in items if item]


def _parse_arguments(raw: str, variables: dict[str, str]) -> None:
    """`cmake_parse_arguments(ARG "" "" "FILES;DEPENDENCIES" ${ARGN})`: each
    keyword's words as `ARG_FILES`."""
    found = re.findall(r'"([^"]*)"|(\S+)', raw)
    items = [a if a or not b else b for a, b in found]
    if len(items) < 5:
        return
    prefix, options, single, multi = items[:4]
    words = [
        part
        for w in items[4:]
        for part in _VARIABLE.sub(lambda m: variables.get(m.group(1), ""), w).split(";")
        if part
    ]
    keywords = {k for k in (options + ";" + single + ";" + multi).split(";") if k}
    current = None
    values: dict[str, list[str]] = {}
    for word in words:
        if word in keywords:
            current = word
            values.setdefault(word, [])
        elif current is not None:
            values[current].append(word)
    for key, listed in values.items():
        variables[f"{prefix}_{key}"] = ";".join(listed)


def _included(package: Path, files: list[Path]) -> list[Path]:
    """The package's own headers the files include (`#include "pkg/x.hpp"`)."""
    found: list[Path] = []
    own = (package / "include", package / "src")
    for path in files:
        try:
            data = read_regular(path, MAX_BUILD_BYTES * 2)
        except UnreadableError:
            continue
        bases = (*own, path.parent)
        for match in _INCLUDE.finditer(data):
            name = match.group(1).decode("utf-8", "replace")
            for base in bases:
                candidate = base / name
                try:
                    if probe("isfile", candidate) and candidate not in found:
                        found.append(candidate)
                        break
                except (OSError, ValueError):
                    break
    return found
