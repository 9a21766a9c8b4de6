"""One `.pyi` stub file -> a `Module` (`model.py`).

A stub is parsed with `ast` (never imported or executed) and its annotations are
read by `annotations/extract.py`, as the checked code's are (a plain
`Annotated[float, "Unit('s')"]` without the refinement parser).

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
from collections.abc import Callable
from pathlib import Path

from robotfix.annotations import ast as A
from robotfix.annotations.extract import ANNOTATED, BASE_TYPES, Refinement, extract
from robotfix.annotations.units import UnitError, resolve
from robotfix.astwalk import dotted
from robotfix.fs import UnreadableError, read_regular
from robotfix.lazyre import lazy
from robotfix.stubs.model import Attribute, Class, Function, Module, Param, Problem

_UNIT_ONLY = lazy(r"Unit\('([A-Za-z0-9_/*^ .]+)'\)")
UNIT_RULES = frozenset({"same", "root", "scale", "agree"})
# The binary operators a stub class may define (`Time.__sub__`), read by operand type
# when overloaded (`_operator_key`), and the method of each Python operator.
OPERATORS = frozenset(
    {"__add__", "__sub__", "__mul__", "__truediv__"}
    | {"__radd__", "__rsub__", "__rmul__", "__rtruediv__"}
)
MAX_STUB_BYTES = 1024 * 1024
ROS_PARAM = "ros_parameter"  # the decorator of a parameter API (`_parameter`)
PARAMETER_ROLES = ("name", "default", "low", "high")


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
