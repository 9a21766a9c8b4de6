"""`.pyi` stub files -> what library functions and classes take and return.

A stub is parsed with `ast` (never imported or executed) and its annotations are
read by `annotations/extract.py`, as the checked code's are. The stubs RobotFix
ships live in `stubs/data/<module path>.pyi` (`rospy.pyi`, `rclpy/node.pyi`,
`rclpy/__init__.pyi`); a user's `stub-paths` folders use the same layout and win
over the shipped ones, module by module. A module is read the first time the
analysis asks for one of its names, once per process.

Conventions a stub may use beyond ordinary typing:
- `Annotated[float, "Unit('s') and _ >= 0"]` on a parameter: an argument must have
  that unit (and satisfy the predicate); on a return: the result has it.
- a return annotated with a class of a stub (`-> Time`, `-> rclpy.time.Time`): the
  result is an object of that class, whose annotated properties, attributes and
  methods are known in turn; with a message class (`-> TransformStamped` imported
  from `geometry_msgs.msg`): a message as received.
- `@unit_rule("...")` on a function whose result's unit depends on its argument's:
  `same` (the arguments' common unit: `hypot`, `clip`, `fabs`), `root` (`sqrt`),
  `scale` (the argument times the ratio of its parameter's unit to the result's:
  `radians`, `deg2rad`), `agree` (the arguments agree with each other, the result
  is as annotated: `atan2`).
- `__add__`, `__sub__`, `__mul__`, `__truediv__` (and `__radd__`...) of a class
  give what `a + b`, `a - b`, ... of its objects are; `@overload`s of one, each with
  its operand's class or builtin type, say which result goes with which operand
  (`Time - Time` is a Duration, `Time - Duration` a Time).
- `@ros_parameter(name="name", default="default", low="min_value",
  high="max_value")` on a function, or on a class's `__init__`: a call reads the
  ROS 1 parameter its argument `name` names (`DTParam("~stop_distance")`, rospy's
  meaning), with that default and those bounds (each keyword names one of the
  function's parameters; only `name` is needed), so parameter files are checked
  against it as against `rospy.get_param` (docs/parameters.md).
Malformed stubs (a syntax error, an annotation that does not read, an unknown
`unit_rule`) are RF512 problems at the stub's line and column; what they spoil is
treated as unannotated.
"""

from __future__ import annotations

import ast
import functools
import hashlib
import json
import os
import re
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path

from robotfix.annotations import ast as A
from robotfix.annotations.extract import ANNOTATED, BASE_TYPES, Refinement, extract
from robotfix.annotations.units import UnitError, resolve
from robotfix.astwalk import dotted
from robotfix.fs import UnreadableError, read_regular

DATA = Path(__file__).parent / "data"
_UNIT_ONLY = re.compile(r"Unit\('([A-Za-z0-9_/*^ .]+)'\)")
UNIT_RULES = frozenset({"same", "root", "scale", "agree"})
# The binary operators a stub class may define (`Time.__sub__`), read by operand type
# when overloaded (`_operator_key`), and the method of each Python operator.
OPERATORS = frozenset(
    {"__add__", "__sub__", "__mul__", "__truediv__"}
    | {"__radd__", "__rsub__", "__rmul__", "__rtruediv__"}
)
MAX_STUB_BYTES = 1024 * 1024
MAX_USER_STUBS = 10_000  # files under the stub paths that a run looks at
MAX_HOPS = 8  # re-exports followed for one name
ROS_PARAM = "ros_parameter"  # the decorator of a parameter API (`_parameter`)
PARAMETER_ROLES = ("name", "default", "low", "high")
MAX_STAR_DEPTH = 8  # `from m import *` followed through at most so many modules
_UNSEEN = object()  # `StubSet.lookup`: a name not looked up yet
# `def name(` in a stub's text (a name runs to the first space or parenthesis: each
# `def name(` the text holds is one match)
_DEF = re.compile(r"def ([^\s(]+)\(")


@dataclass(frozen=True)
class Param:
    name: str
    positional: int | None  # its position among the arguments a call passes
    keyword: bool  # may be passed by keyword
    decl: Refinement | None
    variadic: bool = False  # `*args`: this and every later position
    flag: bool = False  # annotated `bool`: a condition, not a quantity (`where`)


@dataclass(frozen=True)
class Function:
    qualname: str  # `rclpy.node.Node.create_timer`, `rospy.sleep`
    params: tuple[Param, ...]  # without `self`/`cls` of a method or class method
    returns: Refinement | None
    returns_type: str | None  # the qualified name of a returned class, if one
    returns_kind: str | None  # `int`, `float` when the return is a plain one
    rule: str | None  # a `unit_rule`
    kind: str  # function, method, staticmethod, classmethod, property
    origin: str  # where it is written: `rclpy/node.pyi:42` (shipped) or a user path
    path: str | None  # the user stub's path (None: shipped with RobotFix)
    line: int
    # `@ros_parameter`: (role, the parameter that holds it): name, default, low, high
    parameter: tuple[tuple[str, str], ...] = ()

    @property
    def short(self) -> str:
        """How messages name it: `rospy.sleep`, `Node.create_timer`, `Duration`."""
        parts = self.qualname.split(".")
        if self.kind == "function":
            return self.qualname
        if parts[-1] == "__init__":
            return parts[-2]
        return ".".join(parts[-2:])


@dataclass(frozen=True)
class Attribute:
    decl: Refinement | None
    type: str | None  # qualified class name


def _built(
    pending: dict[str, Callable[[], Function | None]],
    built: dict[str, Function],
    name: str,
) -> Function | None:
    """A stub function, its annotations read the first time it is asked for."""
    build = pending.pop(name, None)
    if build is not None:
        found = build()
        if found is not None:
            built[name] = found
    return built.get(name)


@dataclass
class Class:
    qualname: str
    bases: tuple[str, ...]
    members: dict[str, Function] = field(default_factory=dict)
    attributes: dict[str, Attribute] = field(default_factory=dict)
    # methods not read yet: a method's annotations are read when it is first asked for
    pending: dict[str, Callable[[], Function | None]] = field(default_factory=dict)

    def method(self, name: str) -> Function | None:
        return _built(self.pending, self.members, name)

    def force(self) -> None:
        for name in list(self.pending):
            self.method(name)


@dataclass(frozen=True)
class Problem:
    path: str
    line: int
    col: int
    message: str


@dataclass
class Module:
    name: str
    functions: dict[str, Function] = field(default_factory=dict)
    classes: dict[str, Class] = field(default_factory=dict)
    exports: dict[str, str] = field(default_factory=dict)  # name -> qualified
    problems: list[Problem] = field(default_factory=list)
    pending: dict[str, Callable[[], Function | None]] = field(default_factory=dict)
    # `from m import *`: (m, line, col), in the stub's order
    stars: list[tuple[str, int, int]] = field(default_factory=list)

    def function(self, name: str) -> Function | None:
        return _built(self.pending, self.functions, name)

    def has(self, name: str) -> bool:
        """Does the module itself define or re-export `name`?"""
        return (
            name in self.functions
            or name in self.pending
            or name in self.classes
            or name in self.exports
        )

    def force(self) -> None:
        """Read every function and method (for the problems of a user stub)."""
        for name in list(self.pending):
            self.function(name)
        for cls in self.classes.values():
            cls.force()


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


# -- reading one stub ---------------------------------------------------------
def read_module(name: str, path: Path, shown: str, shipped: bool) -> Module:
    module = Module(name)
    try:
        text = read_regular(path, MAX_STUB_BYTES).decode("utf-8")
    except (UnreadableError, UnicodeDecodeError) as err:
        reason = err.reason if isinstance(err, UnreadableError) else "not UTF-8"
        module.problems.append(Problem(shown, 1, 0, f"cannot read: {reason}"))
        return module
    try:
        tree = ast.parse(text, filename=shown, type_comments=False)
    except (SyntaxError, ValueError, RecursionError, MemoryError) as err:
        line = getattr(err, "lineno", None) or 1
        col = max(0, (getattr(err, "offset", None) or 1) - 1)
        detail = getattr(err, "msg", None) or str(err)
        module.problems.append(Problem(shown, line, col, f"syntax error: {detail}"))
        return module
    _Reader(module, text, shown, None if shipped else str(path)).read(tree)
    return module


class _Reader:
    def __init__(self, module: Module, text: str, shown: str, path: str | None):
        self.module = module
        self.lines = text.splitlines()
        self.text = text
        self.shown = shown
        self.path = path
        self.imports: dict[str, str] = {}
        package = module.name if shown.endswith("__init__.pyi") else ""
        self.package = package or module.name.rpartition(".")[0]

    def read(self, tree: ast.Module) -> None:
        # names first: a class may be named in annotations before its definition
        for node in tree.body:
            if isinstance(node, ast.Import):
                for alias in node.names:
                    local = alias.asname or alias.name.split(".")[0]
                    self.imports[local] = alias.name if alias.asname else local
            elif isinstance(node, ast.ImportFrom):
                base = self._from(node)
                for alias in node.names:
                    if alias.name == "*" and base is not None:
                        col = self.col_of(node.lineno, node.col_offset)
                        self.module.stars.append((base, node.lineno, col))
                    if alias.name == "*" or base is None:
                        continue
                    qualified = f"{base}.{alias.name}"
                    self.imports[alias.asname or alias.name] = qualified
                    if (
                        alias.asname == alias.name
                        or self.module.name.split(".")[0] == qualified.split(".")[0]
                    ):
                        self.module.exports[alias.asname or alias.name] = qualified
            elif isinstance(node, ast.ClassDef):
                self.imports[node.name] = f"{self.module.name}.{node.name}"
        for node in tree.body:
            if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
                self.module.pending[node.name] = self._later(
                    node, self.module.name, False
                )
            elif isinstance(node, ast.ClassDef):
                self.module.classes[node.name] = self.cls(node)

    def _from(self, node: ast.ImportFrom) -> str | None:
        if not node.level:
            return node.module
        parts = self.package.split(".") if self.package else []
        if node.level > 1:
            parts = parts[: len(parts) - (node.level - 1)]
        base = ".".join(parts)
        if node.module:
            base = f"{base}.{node.module}" if base else node.module
        return base or None

    def qualname(self, node: ast.expr) -> str | None:
        if isinstance(node, ast.Name):
            return self.imports.get(node.id, node.id if node.id in BUILTINS else None)
        if isinstance(node, ast.Attribute):
            base = self.qualname(node.value)
            return f"{base}.{node.attr}" if base else None
        return None

    def cls(self, node: ast.ClassDef) -> Class:
        qualname = f"{self.module.name}.{node.name}"
        bases = tuple(q for q in map(self.qualname, node.bases) if q is not None)
        found = Class(qualname, bases)
        for item in node.body:
            if isinstance(item, ast.FunctionDef | ast.AsyncFunctionDef):
                key = self._operator_key(item)
                found.pending[key or item.name] = self._later(item, qualname, True)
            elif isinstance(item, ast.AnnAssign) and isinstance(item.target, ast.Name):
                decl = self.annotation(item.annotation, item.target.id)
                found.attributes[item.target.id] = Attribute(
                    decl, self._type_of(item.annotation)
                )
        return found

    def _operator_key(self, node: ast.FunctionDef | ast.AsyncFunctionDef) -> str | None:
        """`__sub__:rclpy.time.Time` for an `@overload` of an operator, by the class
        (or builtin) its operand is annotated with: `Time - Time` is a Duration,
        `Time - Duration` a Time. None for any other method."""
        name = node.name
        overloaded = any(
            (dotted(d) or "").rsplit(".", 1)[-1] == "overload"
            for d in node.decorator_list
        )
        operands = [*node.args.posonlyargs, *node.args.args][1:]
        if not (overloaded and name in OPERATORS and len(operands) == 1):
            return None
        annotation = operands[0].annotation
        operand = self._type_of(annotation) or _plain(annotation)
        return f"{name}:{operand}" if operand else None

    def _later(
        self, node: ast.FunctionDef | ast.AsyncFunctionDef, owner: str, in_class: bool
    ) -> Callable[[], Function | None]:
        return lambda: self.function(node, owner, in_class)

    def function(
        self, node: ast.FunctionDef | ast.AsyncFunctionDef, owner: str, in_class: bool
    ) -> Function | None:
        kind = "method" if in_class else "function"
        rule = None
        described = None  # `@ros_parameter(...)`
        for decorator in node.decorator_list:
            name = (dotted(decorator) or "").rsplit(".", 1)[-1]
            if name in ("staticmethod", "classmethod", "property"):
                kind = name
            elif name == "overload" and not (in_class and node.name in OPERATORS):
                return None  # overloads: too many meanings for one name
            elif isinstance(decorator, ast.Call) and _called(decorator) == "unit_rule":
                rule = self._rule(decorator)
            elif isinstance(decorator, ast.Call) and _called(decorator) == ROS_PARAM:
                described = decorator
        args = node.args
        positional = [*args.posonlyargs, *args.args]
        if in_class and kind in ("method", "classmethod", "property") and positional:
            positional = positional[1:]
        params: list[Param] = []
        for index, arg in enumerate(positional):
            params.append(
                Param(
                    arg.arg,
                    index,
                    arg not in args.posonlyargs,
                    self.annotation(arg.annotation, arg.arg),
                    flag=_plain(arg.annotation) == "bool",
                )
            )
        if args.vararg is not None:
            params.append(
                Param(
                    args.vararg.arg,
                    len(positional),
                    False,
                    self.annotation(args.vararg.annotation, args.vararg.arg),
                    variadic=True,
                )
            )
        for arg in args.kwonlyargs:
            params.append(
                Param(arg.arg, None, True, self.annotation(arg.annotation, arg.arg))
            )
        returns = self.annotation(node.returns, "return")
        return Function(
            f"{owner}.{node.name}",
            tuple(params),
            returns,
            self._type_of(node.returns),
            _plain(node.returns),
            rule,
            kind,
            f"{self.shown}:{node.lineno}",
            self.path,
            node.lineno,
            self._parameter(described, params) if described is not None else (),
        )

    def _parameter(
        self, decorator: ast.Call, params: list[Param]
    ) -> tuple[tuple[str, str], ...]:
        """`@ros_parameter(name="name", ...)`: which parameter holds each role."""
        names = {p.name for p in params}
        roles: list[tuple[str, str]] = []
        for keyword in decorator.keywords:
            value = keyword.value
            held = value.value if isinstance(value, ast.Constant) else None
            if keyword.arg not in PARAMETER_ROLES or held not in names:
                self.problem(
                    keyword.value,
                    f"`{ROS_PARAM}` takes {', '.join(PARAMETER_ROLES)} as keywords, "
                    "each naming a parameter of the function",
                )
                return ()
            roles.append((keyword.arg, held))
        if decorator.args or "name" not in dict(roles):
            self.problem(decorator, f"`{ROS_PARAM}` needs `name=` and keywords only")
            return ()
        return tuple(roles)

    def _rule(self, decorator: ast.Call) -> str | None:
        first = decorator.args[0] if decorator.args else None
        if (
            isinstance(first, ast.Constant)
            and isinstance(first.value, str)
            and first.value in UNIT_RULES
        ):
            return first.value
        self.problem(
            decorator,
            f"`unit_rule` takes one of {', '.join(sorted(UNIT_RULES))}",
        )
        return None

    def _type_of(self, node: ast.expr | None) -> str | None:
        """The class a plain annotation names (`Time`, `'Time'`, `Optional[Time]`)."""
        if node is None:
            return None
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            try:
                node = ast.parse(node.value.strip(), mode="eval").body
            except (SyntaxError, ValueError, RecursionError, MemoryError):
                return None
        if isinstance(node, ast.Subscript) and self.qualname(node.value) in (
            "typing.Optional",
            "typing_extensions.Optional",
        ):
            return self._type_of(node.slice)
        found = self.qualname(node)
        return None if found is None or found in BUILTINS else found

    def annotation(self, node: ast.expr | None, name: str) -> Refinement | None:
        if node is None:
            return None
        if isinstance(node, ast.Name | ast.Attribute):
            return None  # `float`, `Node`, `rclpy.time.Time`: no refinement
        plain = self._unit_only(node)
        if plain is not None:
            return plain
        try:
            found, problems = extract(
                node,
                name,
                self.qualname,
                lambda _: None,
                self.segment,
                self.col_of,
            )
        except (RecursionError, MemoryError):
            self.problem(node, "annotation nested too deeply")
            return None
        for problem in problems:
            self.module.problems.append(
                Problem(self.shown, problem.line, problem.col, problem.message)
            )
        return None if problems else found

    def segment(self, node: ast.AST) -> str | None:
        """`ast.get_source_segment`, without splitting the whole text each time."""
        line, end = getattr(node, "lineno", None), getattr(node, "end_lineno", None)
        col, end_col = (
            getattr(node, "col_offset", None),
            getattr(node, "end_col_offset", None),
        )
        if line is None or end is None or col is None or end_col is None:
            return None
        if not 0 < line <= end <= len(self.lines):
            return None
        parts = [s.encode("utf-8") for s in self.lines[line - 1 : end]]
        if len(parts) == 1:
            return parts[0][col:end_col].decode("utf-8", "replace")
        parts[0], parts[-1] = parts[0][col:], parts[-1][:end_col]
        return b"\n".join(parts).decode("utf-8", "replace")

    def _unit_only(self, node: ast.expr) -> Refinement | None:
        """`Annotated[float, "Unit('s')"]`, most of a stub, read without the
        refinement parser (what `extract` gives for it; a test compares the two)."""
        if not (
            isinstance(node, ast.Subscript)
            and self.qualname(node.value) in ANNOTATED
            and isinstance(node.slice, ast.Tuple)
            and len(node.slice.elts) == 2
        ):
            return None
        base, meta = node.slice.elts
        if not (
            isinstance(base, ast.Name)
            and base.id in BASE_TYPES
            and isinstance(meta, ast.Constant)
            and isinstance(meta.value, str)
        ):
            return None
        match = _UNIT_ONLY.fullmatch(meta.value)
        if match is None:
            return None
        try:
            unit = resolve(match.group(1))
        except UnitError:
            return None  # `extract` reports it where it is
        if any(":" in dim for dim, _ in unit.dims):
            return None  # a tag or frame: let `extract` read it
        return Refinement(BASE_TYPES[base.id], unit, A.TRUE, meta.value, node.lineno)

    def problem(self, node: ast.AST, message: str) -> None:
        line = getattr(node, "lineno", 1)
        col = self.col_of(line, getattr(node, "col_offset", 0))
        self.module.problems.append(Problem(self.shown, line, col, message))

    def col_of(self, line: int, byte_col: int) -> int:
        if 0 < line <= len(self.lines):
            return len(
                self.lines[line - 1]
                .encode("utf-8")[:byte_col]
                .decode("utf-8", "replace")
            )
        return byte_col


BUILTINS = frozenset({"int", "float", "bool", "str", "bytes", "object", "None"})


def _plain(node: ast.expr | None) -> str | None:
    if isinstance(node, ast.Name) and node.id in ("int", "float", "bool"):
        return node.id
    return None


def _called(node: ast.Call) -> str:
    func = node.func
    if isinstance(func, ast.Attribute):
        return func.attr
    return func.id if isinstance(func, ast.Name) else ""


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


def _shipped_names() -> set[str]:
    try:
        raw = json.loads(SHIPPED_NAMES.read_text(encoding="utf-8"))
        if isinstance(raw, dict) and raw.get("key") == shipped_key():
            names = raw.get("names")
            if isinstance(names, list) and all(isinstance(n, str) for n in names):
                return set(names)
    except (OSError, ValueError):
        pass
    return root_names(DATA)  # edited stubs: read them


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


_ONLY_A_UNIT = re.compile(r"""Annotated\[\w+, ['"]Unit\('[^'"()]*'\)['"]\]""")


def _annotations(args: ast.arguments) -> list[ast.expr]:
    every = [*args.posonlyargs, *args.args, *args.kwonlyargs, args.vararg, args.kwarg]
    return [a.annotation for a in every if a is not None and a.annotation is not None]


def _refines(annotation: ast.expr) -> bool:
    """Does a parameter's stub annotation say more than its unit?"""
    text = ast.unparse(annotation)
    return "Annotated" in text and _ONLY_A_UNIT.fullmatch(text) is None
