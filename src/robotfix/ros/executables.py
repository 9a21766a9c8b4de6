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
import configparser
import re
from pathlib import Path

from robotfix.fs import UnreadableError, read_text

MAX_BUILD_BYTES = 1024 * 1024
SCRIPT_FOLDERS = ("scripts", "nodes", "bin", "src", "")
_PROGRAMS = re.compile(
    r"(?:install|catkin_install_python)\s*\(\s*PROGRAMS\s+([^)]*)\)", re.IGNORECASE
)


def executable_file(package: Path, executable: str) -> Path | None:
    """The Python file `executable` of the package in folder `package` runs."""
    if not executable or "/" in executable or executable in (".", ".."):
        return None
    for module in _entry_points(package).get(executable, []):
        found = module_file(package, module)
        if found is not None:
            return found
    for program in _cmake_programs(package):
        if program.name == executable and program.is_file():
            return program
    for folder in SCRIPT_FOLDERS:
        candidate = package / folder / executable
        try:
            if candidate.is_file():
                return candidate
        except (OSError, ValueError):
            return None
    return None


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
    if text is not None:
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
            if candidate.is_file():
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
