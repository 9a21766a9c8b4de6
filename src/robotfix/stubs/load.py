"""The stubs of a run: which `.pyi` file is a module's, and what a qualified name
stands for in them.

The stubs RobotFix ships live in `stubs/data/<module path>.pyi` (`rospy.pyi`,
`rclpy/node.pyi`, `rclpy/__init__.pyi`); a user's `stub-paths` folders use the
same layout and win over the shipped ones, module by module. A module is read
(`reader.py`, which says what a stub may write) the first time the analysis asks
for one of its names, once per process; re-exports and star imports are followed,
bounded. `defined_names`: the names through which a stub can give a checked file a
unit or a refinement, for `analysis/relevance.py`.
"""

from __future__ import annotations

import ast
import functools
import hashlib
import json
import os
from collections.abc import Iterable, Iterator
from pathlib import Path
from typing import Any

from robotfix.fs import UnreadableError, read_regular
from robotfix.lazyre import lazy
from robotfix.stubs import byname

# the data a stub gives, re-exported: what the analysis asks a `StubSet` for
from robotfix.stubs.model import Attribute as Attribute
from robotfix.stubs.model import Class as Class
from robotfix.stubs.model import Function as Function
from robotfix.stubs.model import Module as Module
from robotfix.stubs.model import Param as Param
from robotfix.stubs.model import Problem as Problem
from robotfix.stubs.reader import BUILTINS, MAX_STUB_BYTES, read_module

DATA = Path(__file__).parent / "data"
MAX_USER_STUBS = 10_000  # files under the stub paths that a run looks at
MAX_HOPS = 8  # re-exports followed for one name
MAX_STAR_DEPTH = 8  # `from m import *` followed through at most so many modules
_UNSEEN = object()  # `StubSet.lookup`: a name not looked up yet
# `def name(` in a stub's text (a name runs to the first space or parenthesis: each
# `def name(` the text holds is one match)
_DEF = lazy(r"def ([^\s(]+)\(")


@functools.cache
def _shipped_files() -> frozenset[str]:
    """The shipped stubs' files, relative to `DATA` (`rclpy/node.pyi`): listed once
    a process, not probed for each module a run asks about (843 names on corpus25,
    two `lexists` each: 0.6% of its CPU)."""
    return frozenset(
        path.relative_to(DATA).as_posix()
        for path in DATA.rglob("*.pyi")
        if not path.is_dir()
    )


class StubSet:
    """The stubs of one run: the user's `stub-paths` (first) and the shipped ones."""

    def __init__(self, paths: tuple[Path, ...] = ()) -> None:
        self.paths = paths
        self._modules: dict[str, Module | None] = {}
        self._methods: dict[str, tuple[Function, ...]] = {}
        self._files: dict[str, tuple[Path, str, bool] | None] = {}
        self._found: dict[str, Function | Class | None] = {}  # `lookup`'s answers
        # (id(class), name) -> `member`'s answer (a class lives as long as its set)
        self._members: dict[tuple[int, str], Function | None] = {}
        self._defining: dict[str, list[str]] | None = None  # `_definitions`

    # -- modules -------------------------------------------------------------
    def module(self, name: str) -> Module | None:
        if name not in self._modules:
            self._modules[name] = self._load(name)
        return self._modules[name]

    def _load(self, name: str) -> Module | None:
        found = self._file_of(name)
        return read_module(name, *found) if found is not None else None

    def _file_of(self, name: str) -> tuple[Path, str, bool] | None:
        """The stub file of a module: (path, as messages show it, shipped)."""
        if name not in self._files:
            self._files[name] = self._find_file(name)
        return self._files[name]

    def _find_file(self, name: str) -> tuple[Path, str, bool] | None:
        if not name or not all(part.isidentifier() for part in name.split(".")):
            return None
        relative = name.replace(".", "/")
        candidates = (f"{relative}.pyi", f"{relative}/__init__.pyi")
        for root in self.paths:
            for candidate in candidates:
                path = root / candidate
                # a FIFO, a device or a dangling link too: reading it refuses it
                # (RF512), never blocks
                if os.path.lexists(path) and not path.is_dir():
                    return path, str(path), False
        shipped = _shipped_files()
        for candidate in candidates:
            if candidate in shipped:
                return DATA / candidate, candidate, True
        return None

    # -- names ---------------------------------------------------------------
    def lookup(self, qualified: str) -> Function | Class | None:
        """The stub function or class a qualified name stands for: the longest
        stubbed module prefix, then classes and their members (`rospy.Duration.
        from_sec`); re-exports (`from .rostime import Duration as Duration`) are
        followed. Once per name: the modules it reads are kept as well."""
        found = self._found.get(qualified, _UNSEEN)
        if found is _UNSEEN:
            found = self._found[qualified] = self._lookup(qualified, 0)
        return found  # type: ignore[return-value]

    def _lookup(self, qualified: str, hops: int) -> Function | Class | None:
        parts = qualified.split(".")
        for cut in range(len(parts) - 1, 0, -1):
            module = self.module(".".join(parts[:cut]))
            if module is None:
                continue
            head, rest = parts[cut], parts[cut + 1 :]
            found: Function | Class | None = module.function(head)
            if found is None:
                found = module.classes.get(head)
            if found is None and hops < MAX_HOPS:
                via = module.exports.get(head) or self._starred(module, head)
                if via is not None:
                    return self._lookup(".".join([via, *rest]), hops + 1)
            for attr in rest:
                found = self.member(found, attr) if isinstance(found, Class) else None
            return found
        return None

    def _star_levels(self, module: Module) -> Iterator[list[Module]]:
        """The modules `module` star-imports, level by level (those it names, the
        ones they name, ...), each module once; stub modules only."""
        seen = {module.name}
        level = [module]
        while level:
            following = []
            for here in level:
                for name, _, _ in here.stars:
                    found = self.module(name) if name not in seen else None
                    seen.add(name)
                    if found is not None:
                        following.append(found)
            level = following
            if level:
                yield level

    def _starred(self, module: Module, head: str) -> str | None:
        """The qualified name `head` has through the module's star imports, at
        most MAX_STAR_DEPTH modules away (a `_name` is not star-imported)."""
        if head.startswith("_"):
            return None
        for depth, level in enumerate(self._star_levels(module), 1):
            for here in level:
                if here.has(head):
                    return f"{here.name}.{head}"
            if depth == MAX_STAR_DEPTH:
                break
        return None

    def _too_deep(self, names: list[str]) -> list[Problem]:
        """RF512 at the first star import of a module from which star imports
        lead further than MAX_STAR_DEPTH modules (what lies beyond is not read for
        its names): once per chain, at its head, a module no other star-imports
        (when every one is star-imported, as in a cycle: the first by name)."""
        modules = [m for m in map(self.module, names) if m is not None and m.stars]
        imported = {name for m in modules for name, _, _ in m.stars}
        heads = [m for m in modules if m.name not in imported] or modules[:1]
        found = []
        for module in heads:
            levels = self._star_levels(module)
            beyond = next(
                (lv for d, lv in enumerate(levels, 1) if d > MAX_STAR_DEPTH), None
            )
            if beyond is None:
                continue
            _, line, col = module.stars[0]
            message = (
                f"star imports lead further than {MAX_STAR_DEPTH} modules from "
                f"`{module.name}`: the names of `{beyond[0].name}` and the modules "
                "it star-imports are not found through it"
            )
            shown = self._file_of(module.name)
            found.append(
                Problem(shown[1] if shown else module.name, line, col, message)
            )
        return found

    def member(self, cls: Class, attr: str) -> Function | None:
        """A method or property of a stub class, also an inherited one (once per
        class and name: asked at every `self.x` read of a `Node`'s subclass)."""
        key = (id(cls), attr)
        found = self._members.get(key, _UNSEEN)
        if found is _UNSEEN:
            found = self._members[key] = self._member(cls, attr)
        return found  # type: ignore[return-value]

    def _member(self, cls: Class, attr: str) -> Function | None:
        for here in self._lineage(cls):
            found = here.method(attr)
            if found is not None:
                return found
        return None

    def attribute(self, cls: Class, attr: str) -> Attribute | None:
        for here in self._lineage(cls):
            if attr in here.attributes:
                return here.attributes[attr]
        return None

    def _lineage(self, cls: Class) -> Iterator[Class]:
        """The class, then its stub bases breadth first, each once."""
        seen: set[str] = set()
        todo = [cls]
        while todo:
            here = todo.pop(0)
            if here.qualname in seen:
                continue
            seen.add(here.qualname)
            yield here
            todo += [b for b in map(self.lookup, here.bases) if isinstance(b, Class)]

    def methods_named(self, name: str) -> list[Function]:
        """Every shipped or user stub method called `name`, for a call on a value
        of unknown type (`self.client.wait_for_service(timeout_sec=1.0)`)."""
        return [
            f
            for module in self._modules_defining(name)
            for cls in module.classes.values()
            for f in [cls.method(name)]
            if f is not None and f.kind == "method"
        ]

    def _modules_defining(self, name: str) -> list[Module]:
        """The stub modules whose text has `def name(`: only those are parsed."""
        if self._defining is None:
            self._defining = self._definitions()
        found = []
        for module_name in self._defining.get(name, ()):
            module = self.module(module_name)
            if module is not None:
                found.append(module)
        return found

    def _definitions(self) -> dict[str, list[str]]:
        """For each `def name(` in the stubs' texts, the modules whose text has it,
        in order: every text searched once, not once for each method name."""
        names: set[str] = set()
        for root in [*self.paths, DATA]:
            names |= set(_module_names(root))
        found: dict[str, list[str]] = {}
        for module_name in sorted(names):
            where = self._file_of(module_name)
            text = _text_of(where[0]) if where is not None else ""
            for defined in dict.fromkeys(_DEF.findall(text)):
                found.setdefault(defined, []).append(module_name)
        return found

    def problems(self) -> list[Problem]:
        """Every problem of the user's stubs (read all at once, for a run)."""
        found: list[Problem] = []
        names = []
        for root in self.paths:
            for name in sorted(_module_names(root)):
                module = self.module(name)
                if module is not None:
                    module.force()
                    found += module.problems
                    names.append(name)
        return found + self._too_deep(names)

    def fingerprint(self) -> str:
        """What the user's stubs hold: a run's results depend on it."""
        digest = hashlib.sha256()
        for root in self.paths:
            for path in sorted(_stub_files(root)):
                digest.update(str(path).encode())
                try:
                    digest.update(read_regular(path, MAX_STUB_BYTES))
                except UnreadableError as err:
                    digest.update(err.reason.encode())
        return digest.hexdigest()


def stub_set(paths: tuple[Path, ...] = ()) -> StubSet:
    """One StubSet per process and stub paths: a module is read once. `stub_set()`
    is `stub_set(())` (`lru_cache` alone keys the two calls apart: the summaries
    and the checks each read and parsed every stub they asked for)."""
    return _stub_set(tuple(paths))


@functools.lru_cache(maxsize=8)
def _stub_set(paths: tuple[Path, ...]) -> StubSet:
    return StubSet(paths)


def forget() -> None:
    """A stub file changed under a process that lives on (the editor's server):
    every stub set, text and listing is read again when next asked for."""
    _stub_set.cache_clear()
    _text_of.cache_clear()
    _module_names.cache_clear()
    _shipped.cache_clear()


def methods_named(stubs: StubSet, name: str) -> tuple[Function, ...]:
    """`StubSet.methods_named`, once per name and process."""
    found = stubs._methods.get(name)
    if found is None:
        found = stubs._methods[name] = tuple(stubs.methods_named(name))
    return found


def _stub_files(root: Path) -> Iterable[Path]:
    if not root.is_dir():
        return []
    found = []
    for path in root.rglob("*.pyi"):
        found.append(path)
        if len(found) >= MAX_USER_STUBS:
            break
    return found


@functools.lru_cache(maxsize=256)
def _text_of(path: Path) -> str:
    try:
        return read_regular(path, MAX_STUB_BYTES).decode("utf-8", "replace")
    except UnreadableError:
        return ""


@functools.lru_cache(maxsize=16)
def _module_names(root: Path) -> tuple[str, ...]:
    names = []
    for path in _stub_files(root):
        parts = list(path.relative_to(root).with_suffix("").parts)
        if parts and parts[-1] == "__init__":
            parts.pop()
        if parts and all(p.isidentifier() for p in parts):
            names.append(".".join(parts))
    return tuple(names)


def defined_names(stubs: StubSet) -> frozenset[str]:
    """The identifiers through which a stub can give a checked file a unit or a
    refinement (`analysis/relevance.py`): every function and method whose stub has
    a decorator (`@unit_rule`, `@property`), returns a class (of a stub, or a
    message) or an `Annotated`, or has a parameter refined beyond a unit (a
    unitless value meets a unit, and a value with a unit came from a source the
    file names already); every attribute with an `Annotated`; every class with such
    an attribute, such an `__init__` or an operator. Module names are not among
    them: a call or read through a module names the member too."""
    names: set[str] = set()
    for root in stubs.paths:
        names |= root_names(root)
    return frozenset(names | _shipped_names())


# `root_names` of the shipped stubs, written by tools/build_package_data.py: each
# run would parse them all (50 M instructions of every start) to find the same
SHIPPED_NAMES = Path(__file__).parent / "shipped_names.json"


def shipped_key() -> str:
    """The shipped stubs' text, as a hash: what `SHIPPED_NAMES` must be made from."""
    digest = hashlib.sha256()
    for path in sorted(_stub_files(DATA)):
        digest.update(f"{path.relative_to(DATA).as_posix()}\0".encode())
        digest.update(_text_of(path).encode("utf-8", "surrogatepass"))
    return digest.hexdigest()


@functools.cache
def _shipped() -> dict[str, Any]:
    """`SHIPPED_NAMES`' data, when made from the shipped stubs as they are (else
    nothing: each fact is then found from the stubs themselves)."""
    try:
        raw = json.loads(SHIPPED_NAMES.read_text(encoding="utf-8"))
        if isinstance(raw, dict) and raw.get("key") == shipped_key():
            return raw
    except (OSError, ValueError):
        pass
    return {}


def _shipped_names() -> set[str]:
    names = _shipped().get("names")
    if isinstance(names, list) and all(isinstance(n, str) for n in names):
        return set(names)
    return root_names(DATA)  # edited stubs: read them


def by_name_checks(stubs: StubSet) -> dict[str, tuple[list[int], list[str]]]:
    """`byname.checked` for each method name on whose stub methods disagree (what
    tools/build_package_data.py writes into `SHIPPED_NAMES` for the shipped set)."""
    if stubs._defining is None:
        stubs._defining = stubs._definitions()
    found = {}
    for name in sorted(stubs._defining):
        candidates = methods_named(stubs, name)
        if candidates and not byname.agree(candidates):
            found[name] = byname.checked(candidates)
    return found


def unchecked_call(
    stubs: StubSet, name: str, positional: int, keys: Iterable[str | None]
) -> bool:
    """Whether a call of a method `name` of a value of unknown type, with so many
    positional arguments and these keywords, is known from `SHIPPED_NAMES` alone
    to have no argument the stubs' disagreeing candidates let the analysis check
    (`super().__init__("talker")`). False when unsure: the candidates decide."""
    if stubs.paths:
        return False  # a user's stub may add a candidate
    found = _shipped().get("by_name", {}).get(name)
    if not isinstance(found, list) or len(found) != 2:
        return False
    positions, keywords = found
    return all(i >= positional for i in positions) and not any(
        k in keywords for k in keys
    )


def root_names(root: Path) -> set[str]:
    """`defined_names` of the stubs under one folder."""
    names: set[str] = set()
    renamed: set[tuple[str, str]] = set()  # `from m import f as g`: g is f too
    for path in _stub_files(root):
        try:
            tree = ast.parse(_text_of(path))
        except (SyntaxError, ValueError, RecursionError):
            continue
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom):
                renamed.update((a.name, a.asname) for a in node.names if a.asname)
            elif isinstance(node, ast.ClassDef) and _class_gives(node):
                names.add(node.name)
            elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                if node.name != "__init__" and _function_gives(node):
                    names.add(node.name)
            elif isinstance(node, (ast.AnnAssign, ast.Assign)) and (
                "Annotated" in ast.unparse(node)
            ):
                names.update(
                    t.id
                    for t in ast.walk(node)
                    if isinstance(t, ast.Name) and isinstance(t.ctx, ast.Store)
                )
    while fresh := {new for old, new in renamed if old in names} - names:
        names |= fresh  # a re-export of a re-export, under a third name
    return names


def _function_gives(node: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    returns = ast.unparse(node.returns) if node.returns else "None"
    return (
        bool(node.decorator_list)
        or returns not in BUILTINS  # a stub class, a message class, an Annotated
        or any(map(_refines, _annotations(node.args)))
    )


def _class_gives(node: ast.ClassDef) -> bool:
    for item in node.body:
        if isinstance(item, ast.AnnAssign) and "Annotated" in ast.unparse(item):
            return True
        if isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)):
            if item.name == "__init__" and (
                item.decorator_list or any(map(_refines, _annotations(item.args)))
            ):
                return True
            if item.name.startswith("__") and item.name != "__init__":
                return True  # an operator
    return False


_ONLY_A_UNIT = lazy(r"""Annotated\[\w+, ['"]Unit\('[^'"()]*'\)['"]\]""")


def _annotations(args: ast.arguments) -> list[ast.expr]:
    every = [*args.posonlyargs, *args.args, *args.kwonlyargs, args.vararg, args.kwarg]
    return [a.annotation for a in every if a is not None and a.annotation is not None]


def _refines(annotation: ast.expr) -> bool:
    """Does a parameter's stub annotation say more than its unit?"""
    text = ast.unparse(annotation)
    return "Annotated" in text and _ONLY_A_UNIT.fullmatch(text) is None
