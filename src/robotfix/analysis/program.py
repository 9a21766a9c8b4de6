"""What a file defines, found before any code is interpreted: functions and methods
(with their signatures), classes and their refined attributes, and which functions
are ROS callbacks of which interface.

A syntactic pre-pass, so that a call or a callback registration resolves whatever
order the definitions come in.
"""

from __future__ import annotations

import ast
from collections.abc import Callable
from dataclasses import dataclass, field

from robotfix.analysis.context import FileContext, Scope, build_scope
from robotfix.analysis.types import TypeModel
from robotfix.analysis.values import Value
from robotfix.annotations.extract import Refinement
from robotfix.ros.api_model import REGISTRATIONS

FunctionNode = ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda


@dataclass
class Function:
    """A function or method of the file, with its scope and refined result."""

    key: str  # "name", "Class.method", or "<lambda@line:col>"
    node: FunctionNode
    parent: Scope
    class_name: str | None = None
    scope: Scope | None = None
    returns: Refinement | None = None
    decorators: frozenset[str] = frozenset()

    @property
    def first_parameter(self) -> str | None:
        """The name of its first positional parameter (`self`, `cls`), if any."""
        args = self.node.args
        every = [*args.posonlyargs, *args.args]
        return every[0].arg if every else None

    @property
    def is_method(self) -> bool:
        return self.class_name is not None and "staticmethod" not in self.decorators

    @property
    def name(self) -> str:
        return getattr(self.node, "name", "<lambda>")


@dataclass(frozen=True)
class Callback:
    """How a ROS callback is registered: its kind, interface type, bound arguments."""

    kind: str  # subscription, service, service1, action, action1, timer
    interface: str | None  # pkg/Name of the message, service or action
    bound: int = 0  # leading positional arguments bound by functools.partial


@dataclass
class Program:
    """A file's functions, classes, refined attributes and callbacks (the pre-pass)."""

    module: Scope
    functions: dict[str, Function] = field(default_factory=dict)
    classes: dict[str, Scope] = field(default_factory=dict)
    attributes: dict[str, dict[str, Refinement]] = field(default_factory=dict)
    callbacks: dict[str, Callback] = field(default_factory=dict)
    by_node: dict[int, Function] = field(default_factory=dict)  # id(node) ->
    # what expressions are (`self.left`, a helper's result), asked when needed
    types: TypeModel = field(init=False)
    bases: dict[str, list[str]] = field(default_factory=dict)  # classes of this file
    # module names that functions declare `global` (callbacks may set them)
    shared_globals: set[str] = field(default_factory=set)
    ends: dict[int, bool] = field(default_factory=dict)  # id(def node) -> never returns
    # id(`x += d` node) -> `x + d`, made once and kept with the file's tree: findings
    # are reported once per node `id`, and a node freed after one statement could
    # lend its address to the next one's, silencing its finding
    augmented: dict[int, ast.BinOp | None] = field(default_factory=dict)
    # (id(call), id(argument), depth) -> the call only reads that argument
    # (`CallFacts.only_reads`), kept with the tree for the same reason
    reading_calls: dict[tuple[int, int, int], bool] = field(default_factory=dict)
    # `pkg.name` -> what a module's attribute read stands for (`Lookups.
    # module_attribute`: the same in every function of the file)
    module_attributes: dict[str, Value] = field(default_factory=dict)

    def add(self, function: Function) -> Function:
        self.functions[function.key] = function
        self.by_node[id(function.node)] = function
        return function

    def signature(self, ctx: FileContext, function: Function) -> Scope:
        """The function's scope: parameters, their refinements, its locals."""
        if function.scope is None:
            function.scope = build_scope(
                ctx, "function", function.name, function.node, function.parent
            )
            returns = getattr(function.node, "returns", None)
            if returns is not None:
                function.returns = ctx.refinement(returns, function.name)
        return function.scope


def never_returns(node: ast.AST, ends: Callable[[ast.stmt], bool]) -> bool:
    """A function whose body can only end by raising (`def fail(msg): raise
    X(msg)`, or a last statement for which `ends` holds, `sys.exit(1)`), or one
    annotated `NoReturn`/`Never`."""
    if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
        return False
    returns = node.returns
    if getattr(returns, "id", getattr(returns, "attr", "")) in ("NoReturn", "Never"):
        return True
    if not node.body or not ends(node.body[-1]):
        return False
    todo: list[ast.AST] = list(node.body)
    while todo:
        child = todo.pop()
        if isinstance(child, (ast.Return, ast.Yield, ast.YieldFrom)):
            return False
        if not isinstance(
            child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)
        ):
            todo.extend(ast.iter_child_nodes(child))
    return True


def attribute_key(node: ast.Attribute) -> str | None:
    """`self.x` for `self.x`, `self.x.y` or `self.x.y.z`: the cached attribute a
    store to (or a call on) that target may change."""
    while isinstance(node.value, ast.Attribute):
        node = node.value
    return f"{node.value.id}.{node.attr}" if isinstance(node.value, ast.Name) else None


def collect(ctx: FileContext, tree: ast.Module, module: Scope) -> Program:
    program = Program(module)
    program.types = TypeModel(ctx, program)
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            _add_function(program, node, module, None)
        elif isinstance(node, ast.ClassDef):
            scope = build_scope(ctx, "class", node.name, node, module)
            program.classes[node.name] = scope
            program.attributes[node.name] = dict(scope.decls)
            program.bases[node.name] = [
                b.id for b in node.bases if isinstance(b, ast.Name)
            ]
            for item in node.body:
                if isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)):
                    _add_function(program, item, scope, node.name)
    for class_name, attribute, annotation in sorted(
        ctx.index.attributes, key=lambda a: (a[2].lineno, a[2].col_offset)
    ):
        table = program.attributes.setdefault(class_name, {})
        if attribute not in table:
            found = ctx.refinement(annotation, attribute)
            if found is not None:
                table[attribute] = found
    _collect_callbacks(ctx, program)
    for scope_id, names in ctx.index.scopes.items():
        if scope_id != id(tree):
            program.shared_globals |= names.global_names
    return program


def _add_function(
    program: Program,
    node: ast.FunctionDef | ast.AsyncFunctionDef,
    parent: Scope,
    class_name: str | None,
) -> None:
    key = f"{class_name}.{node.name}" if class_name else node.name
    decorators = frozenset(
        d.id if isinstance(d, ast.Name) else getattr(d, "attr", "")
        for d in node.decorator_list
    )
    program.add(Function(key, node, parent, class_name, decorators=decorators))


def _collect_callbacks(ctx: FileContext, program: Program) -> None:
    for class_name, call in ctx.index.calls:  # every call of the file: one test each
        func = call.func
        kind = func.__class__
        if kind is ast.Attribute:
            registration = REGISTRATIONS.get(func.attr)  # type: ignore[attr-defined]
        elif kind is ast.Name:
            registration = REGISTRATIONS.get(func.id)  # type: ignore[attr-defined]
        else:
            continue
        if registration is None:
            continue
        callback = call_argument(call, *registration.callback_arg)
        interface = None
        if registration.type_arg is not None:
            type_node = call_argument(call, *registration.type_arg)
            interface = ctx.interface_of(type_node) if type_node is not None else None
        resolved = _callback_key(program, callback, class_name)
        if resolved is not None:
            key, bound = resolved
            program.callbacks[key] = Callback(registration.kind, interface, bound)


def call_argument(call: ast.Call, position: int, keyword: str) -> ast.expr | None:
    """The argument given by `keyword`, or at `position` when no `*args` comes
    before it; None when it is not given."""
    for kw in call.keywords:
        if kw.arg == keyword:
            return kw.value
    if position < len(call.args) and not any(
        isinstance(a, ast.Starred) for a in call.args[: position + 1]
    ):
        return call.args[position]
    return None


def _callback_key(
    program: Program, node: ast.expr | None, class_name: str | None
) -> tuple[str, int] | None:
    if node is None:
        return None
    if isinstance(node, ast.Call) and node.args:  # functools.partial(f, a, ...)
        func = node.func
        name = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
        if name == "partial":
            inner = _callback_key(program, node.args[0], class_name)
            return None if inner is None else (inner[0], inner[1] + len(node.args) - 1)
        return None
    if (
        isinstance(node, ast.Attribute)
        and isinstance(node.value, ast.Name)
        and class_name
    ):
        key = f"{class_name}.{node.attr}"
        return (key, 0) if key in program.functions else None
    if isinstance(node, ast.Name) and node.id in program.functions:
        return node.id, 0
    if isinstance(node, ast.Lambda):
        key = f"<lambda@{node.lineno}:{node.col_offset}>"
        parent = program.classes.get(class_name or "", program.module)
        program.add(Function(key, node, parent.module() if class_name else parent))
        return key, 0
    return None
