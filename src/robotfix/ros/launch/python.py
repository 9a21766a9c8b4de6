"""ROS 2 Python launch files, read with `ast`: never imported, never run.

`generate_launch_description()` (and the functions `OpaqueFunction(function=f)`
names) is evaluated abstractly: a name bound once to an expression stands for it
(module constants too), strings, numbers, lists, dicts, tuples and `+`/f-strings of
them are values, and so are the launch API's static pieces: `os.path.join`,
`get_package_share_directory`, `FindPackageShare`, `PathJoinSubstitution`,
`ThisLaunchFileDir`, `TextSubstitution`, `LaunchConfiguration` (the value the
including file passes, else its `DeclareLaunchArgument` default),
`ParameterFile`, nav2's `RewrittenYaml` (its source file). Every `Node(...)`,
`LifecycleNode(...)` and `ComposableNode(...)` call is an entry, whatever
condition guards it; `GroupAction([PushRosNamespace(ns), ...])` namespaces the
entries it holds, and `IncludeLaunchDescription` of a file in the tree adds that
file's entries. Anything else is unknown (`UNKNOWN`), never an error.
"""

from __future__ import annotations

import ast
import weakref
from collections import deque
from collections.abc import Iterator
from pathlib import Path

from robotfix.astwalk import children, dotted
from robotfix.ros import paramfile as P
from robotfix.ros import yamlfile as Y
from robotfix.ros.launch import substitution as S
from robotfix.ros.launch import values as V
from robotfix.ros.launch.model import (
    FileParam,
    Include,
    InlineParam,
    LaunchFile,
    NodeEntry,
    Place,
    Remap,
)

ENTRY = "generate_launch_description"
NODES = ("Node", "LifecycleNode", "ComposableNode")
MAX_EVAL_DEPTH = 60
# the launch API's calls this reader evaluates -> the method that does
API = {
    "LaunchConfiguration": "launch_configuration",
    "PathJoinSubstitution": "path_join_substitution",
    "ThisLaunchFileDir": "this_launch_file_dir",
    "TextSubstitution": "text_substitution",
    "ParameterFile": "parameter_file",
    "RewrittenYaml": "rewritten_yaml",
    "OpaqueFunction": "opaque_function",
    "IncludeLaunchDescription": "include_launch_description",
    "Node": "node",
    "LifecycleNode": "node",
    "ComposableNode": "node",
}


class _Unknown:
    def __repr__(self) -> str:
        return "UNKNOWN"


UNKNOWN = _Unknown()


class _Actions:
    """What a group, an include or a list of actions holds: its node entries."""

    def __init__(self, entries: list[NodeEntry]) -> None:
        self.entries = entries


class _Namespace:
    def __init__(self, namespace: str | None) -> None:
        self.namespace = namespace


class _ArgText(str):
    """A launch argument's value (the includer's, or the declared default): a
    path or a name may use it, a parameter's value is unknown (set at launch)."""


class _File:
    def __init__(self, path: str | None) -> None:
        self.path = path


def read_python(tree: ast.Module, text: str, ctx: S.Context) -> LaunchFile:
    out = LaunchFile(str(ctx.path), 2)
    functions = {
        s.name: s
        for s in tree.body
        if isinstance(s, (ast.FunctionDef, ast.AsyncFunctionDef))
    }
    if ENTRY not in functions:
        out.launch = False
        return out
    _Evaluator(tree, text, ctx, out, functions).run(functions[ENTRY])
    return out


_BINDINGS: weakref.WeakKeyDictionary[ast.AST, dict[str, ast.expr | None]] = (
    weakref.WeakKeyDictionary()
)
_NODES: weakref.WeakKeyDictionary[ast.AST, list[ast.AST]] = weakref.WeakKeyDictionary()


def _bindings_of(owner: ast.AST, body: list[ast.stmt]) -> dict[str, ast.expr | None]:
    """`_single_bindings` of a function or module, made once per tree."""
    found = _BINDINGS.get(owner)
    if found is None:
        found = _BINDINGS[owner] = _single_bindings(_nodes_of(owner, body))
    return dict(found)


def _nodes_of(owner: ast.AST, body: list[ast.stmt]) -> list[ast.AST]:
    """`_walk` of a function's or module's body, made once per tree (its bindings
    and its calls read the same nodes)."""
    found = _NODES.get(owner)
    if found is None:
        found = _NODES[owner] = list(_walk(body))
    return found


def _single_bindings(nodes: list[ast.AST]) -> dict[str, ast.expr | None]:
    """Names stored once, by `name = expr` (None: stored otherwise or again)."""
    counts: dict[str, int] = {}
    for node in nodes:
        if isinstance(node, ast.Name) and not isinstance(node.ctx, ast.Load):
            counts[node.id] = counts.get(node.id, 0) + 1
    found: dict[str, ast.expr | None] = dict.fromkeys(counts)
    for node in nodes:
        if isinstance(node, (ast.Assign, ast.AnnAssign)) and node.value is not None:
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            if len(targets) == 1 and isinstance(targets[0], ast.Name):
                name = targets[0].id
                if counts.get(name) == 1:
                    found[name] = node.value
    return found


_DEFAULTS: weakref.WeakKeyDictionary[ast.Module, dict[str, ast.expr | None]] = (
    weakref.WeakKeyDictionary()
)


def _defaults(tree: ast.Module) -> dict[str, ast.expr | None]:
    """Each `DeclareLaunchArgument(name, default_value=...)`'s default (the first
    one of a name), wherever it is in the file."""
    found = _DEFAULTS.get(tree)
    if found is None:
        found = {}
        for node in _breadth_first(tree):  # ast.walk's order: the first one wins
            if (
                isinstance(node, ast.Call)
                and _called(node.func) == "DeclareLaunchArgument"
            ):
                name = _Evaluator._arg(node, 0, "name")
                if isinstance(name, ast.Constant) and isinstance(name.value, str):
                    found.setdefault(
                        name.value, _Evaluator._arg(node, 1, "default_value")
                    )
        _DEFAULTS[tree] = found
    return found


def _walk(body: list[ast.stmt]) -> Iterator[ast.AST]:
    """The nodes of a function body, not those of functions defined in it (nor
    contexts and operators: `astwalk.children`)."""
    todo: list[ast.AST] = list(body)
    while todo:
        node = todo.pop()
        yield node
        for child in children(node):
            if not isinstance(
                child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)
            ):
                todo.append(child)


def _breadth_first(tree: ast.AST) -> Iterator[ast.AST]:
    """`ast.walk`'s order, without contexts and operators."""
    todo = deque([tree])
    while todo:
        node = todo.popleft()
        yield node
        todo.extend(children(node))


def _called(func: ast.expr) -> str:
    if isinstance(func, ast.Attribute):
        return func.attr
    return func.id if isinstance(func, ast.Name) else ""


class _Evaluator:
    def __init__(
        self,
        tree: ast.Module,
        text: str,
        ctx: S.Context,
        out: LaunchFile,
        functions: dict[str, ast.FunctionDef | ast.AsyncFunctionDef],
    ) -> None:
        self.ctx, self.out, self.functions = ctx, out, functions
        self.lines = text.splitlines()
        self.module = _bindings_of(
            tree,
            [
                s
                for s in tree.body
                if not isinstance(s, (ast.FunctionDef, ast.ClassDef))
            ],
        )
        self.scopes: list[dict[str, ast.expr | None]] = [self.module]
        self.memo: dict[int, object] = {}
        self.busy: set[int] = set()
        self.ran: set[str] = set()
        self.defaults = _defaults(tree)

    # -- places -------------------------------------------------------------------
    def place(self, node: ast.AST) -> Place:
        line = getattr(node, "lineno", 1)
        col = getattr(node, "col_offset", 0)
        text = self.lines[line - 1] if 0 < line <= len(self.lines) else ""
        char = len(text.encode("utf-8")[:col].decode("utf-8", "replace"))
        return Place(self.out.path, line, char)

    # -- functions --------------------------------------------------------------------
    def run(self, function: ast.FunctionDef | ast.AsyncFunctionDef) -> None:
        if function.name in self.ran:
            return
        self.ran.add(function.name)
        scope = _bindings_of(function, function.body)
        for arg in [*function.args.args, *function.args.kwonlyargs]:
            scope[arg.arg] = None
        self.scopes.append(scope)
        try:
            for node in _nodes_of(function, function.body):
                if isinstance(node, ast.Call) and _called(node.func) in (
                    *NODES,
                    "IncludeLaunchDescription",
                    "OpaqueFunction",
                ):
                    self.eval(node)
                elif isinstance(node, ast.Return) and node.value is not None:
                    self.eval(node.value)
        finally:
            self.scopes.pop()

    # -- expressions ------------------------------------------------------------------
    def eval(self, node: ast.expr | None) -> object:
        if node is None:
            return UNKNOWN
        key = id(node)
        if key in self.memo:
            return self.memo[key]
        if key in self.busy or len(self.busy) > MAX_EVAL_DEPTH:
            return UNKNOWN
        self.busy.add(key)
        try:
            value = self._eval(node)
        except RecursionError:
            value = UNKNOWN
        finally:
            self.busy.discard(key)
        self.memo[key] = value
        return value

    def _eval(self, node: ast.expr) -> object:
        if isinstance(node, ast.Constant):
            return node.value
        if isinstance(node, ast.Name):
            for scope in reversed(self.scopes):
                if node.id in scope:
                    return self.eval(scope[node.id])
            return UNKNOWN
        if isinstance(node, (ast.List, ast.Tuple)):
            return [self.eval(e) for e in node.elts]
        if isinstance(node, ast.Dict):
            return {
                self.eval(k) if k is not None else UNKNOWN: self.eval(v)
                for k, v in zip(node.keys, node.values, strict=True)
            }
        if isinstance(node, ast.JoinedStr):
            parts = [self.eval(v) for v in node.values]
            return "".join(parts) if all(isinstance(p, str) for p in parts) else UNKNOWN  # type: ignore[arg-type]
        if isinstance(node, ast.FormattedValue):
            inner = self.eval(node.value)
            plain = node.conversion == -1 and node.format_spec is None
            return inner if isinstance(inner, str) and plain else UNKNOWN
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
            left, right = self.eval(node.left), self.eval(node.right)
            if isinstance(left, str) and isinstance(right, str):
                return left + right
            if isinstance(left, list) and isinstance(right, list):
                return left + right
            return UNKNOWN
        if isinstance(node, ast.Call):
            return self.call(node)
        for child in children(node):  # an entry in a condition, a lambda
            if isinstance(child, ast.expr):
                self.eval(child)
        return UNKNOWN

    @staticmethod
    def _arg(call: ast.Call, index: int, keyword: str) -> ast.expr | None:
        for kw in call.keywords:
            if kw.arg == keyword:
                return kw.value
        if 0 <= index < len(call.args) and not any(
            isinstance(a, ast.Starred) for a in call.args[: index + 1]
        ):
            return call.args[index]
        return None

    def arg(self, call: ast.Call, index: int, *keywords: str) -> object:
        for keyword in keywords:
            found = self._arg(call, index if keyword == keywords[0] else -1, keyword)
            if found is not None:
                return self.eval(found)
        return UNKNOWN

    def text(self, call: ast.Call, index: int, *keywords: str) -> str | None:
        return _text(self.arg(call, index, *keywords))

    def call(self, call: ast.Call) -> object:
        name = _called(call.func)
        if name in API:
            return getattr(self, API[name])(call)
        if name == "join" and (dotted(call.func) or "") in (
            "os.path.join",
            "path.join",
            "join",
        ):
            return S.join([_text(self.eval(a)) for a in call.args]) or UNKNOWN
        if name in ("perform",) and isinstance(call.func, ast.Attribute):
            return self.eval(call.func.value)
        if name == "items" and isinstance(call.func, ast.Attribute):
            value = self.eval(call.func.value)
            return (
                [[k, v] for k, v in value.items()]
                if isinstance(value, dict)
                else UNKNOWN
            )
        if name in ("PushRosNamespace", "PushROSNamespace"):
            return _Namespace(self.text(call, 0, "namespace"))
        if name in ("GroupAction", "LaunchDescription"):
            return self.group(self.arg(call, 0, "actions", "initial_entities"))
        if name in ("get_package_share_directory", "FindPackageShare"):
            return (
                S.share(self.ctx, self.text(call, 0, "package", "package_name"))
                or UNKNOWN
            )
        for child in [*call.args, *(k.value for k in call.keywords)]:
            self.eval(child)  # entries in the arguments of anything else
        if isinstance(call.func, ast.Attribute):
            self.eval(call.func.value)  # `ld.add_action(node)`
        return UNKNOWN

    # -- the launch API ---------------------------------------------------------
    def launch_configuration(self, call: ast.Call) -> object:
        name = self.text(call, 0, "variable_name")
        if name is None:
            return UNKNOWN
        if name in self.ctx.args:
            found = self.ctx.args[name]
        elif name in self.defaults:
            found = _text(self.eval(self.defaults[name]))
        else:
            found = self.text(call, 1, "default")
        return _ArgText(found) if found is not None else UNKNOWN

    def path_join_substitution(self, call: ast.Call) -> object:
        parts = self.arg(call, 0, "substitutions")
        if not isinstance(parts, list):
            return UNKNOWN
        return S.join([_text(p) for p in parts]) or UNKNOWN

    def this_launch_file_dir(self, call: ast.Call) -> object:
        return S.here(self.ctx)

    def text_substitution(self, call: ast.Call) -> object:
        return self.text(call, 0, "text") or UNKNOWN

    def parameter_file(self, call: ast.Call) -> object:
        inner = self.arg(call, 0, "param_file")
        return inner if isinstance(inner, _File) else _File(_text(inner))

    def rewritten_yaml(self, call: ast.Call) -> object:
        return _File(self.text(call, 0, "source_file"))

    def opaque_function(self, call: ast.Call) -> object:
        target = self._arg(call, 0, "function")
        if isinstance(target, ast.Name) and target.id in self.functions:
            self.run(self.functions[target.id])
        return UNKNOWN

    def include_launch_description(self, call: ast.Call) -> object:
        source = self._arg(call, 0, "launch_description_source")
        shown = ast.unparse(source) if source is not None else ""
        path = None
        if isinstance(source, ast.Call):
            where = self.arg(source, 0, "launch_file_path")
            path = S.in_tree(self.ctx, _text(where))
        self.out.includes.append(Include(path, shown, self.place(call)))
        passed = self.arg(call, 1, "launch_arguments")
        args: dict[str, str | None] = {}
        if isinstance(passed, list):
            for pair in passed:
                if (
                    isinstance(pair, list)
                    and len(pair) == 2
                    and isinstance(pair[0], str)
                ):
                    args[pair[0]] = _text(pair[1])
        if path is None or self.ctx.follow is None:
            return _Actions([])
        included = self.ctx.follow(Path(path), args)
        if included is None:
            return _Actions([])
        self.out.entries.extend(included.entries)
        return _Actions(list(included.entries))

    def group(self, actions: object) -> object:
        if not isinstance(actions, list):
            return _Actions([])
        namespace: str | None = ""
        entries: list[NodeEntry] = []
        for action in actions:
            if isinstance(action, _Namespace):
                namespace = S.push_namespace(namespace, action.namespace)
                continue
            held = (
                [action]
                if isinstance(action, NodeEntry)
                else (action.entries if isinstance(action, _Actions) else [])
            )
            for entry in held:
                entry.namespace = S.push_namespace(namespace, entry.namespace)
                entries.append(entry)
        return _Actions(entries)

    def node(self, call: ast.Call) -> object:
        entry = NodeEntry(
            2,
            self.place(call),
            self.text(call, -1, "package"),
            self.text(call, -1, "executable", "node_executable"),
            self.text(call, -1, "name", "node_name"),
            self.text(call, -1, "namespace", "node_namespace")
            if any(k.arg in ("namespace", "node_namespace") for k in call.keywords)
            else "",
            plugin=self.text(call, -1, "plugin"),
        )
        entry.parameters = self.parameters(self._arg(call, -1, "parameters"))
        remaps = self._arg(call, -1, "remappings")
        for item in remaps.elts if isinstance(remaps, (ast.List, ast.Tuple)) else []:
            pair = self.eval(item)
            if isinstance(pair, list) and len(pair) == 2:
                entry.remappings.append(
                    Remap(_text(pair[0]), _text(pair[1]), self.place(item))
                )
        arguments = self.arg(call, -1, "arguments")
        if isinstance(arguments, list):
            entry.arguments = [_text(a) for a in arguments]
        for kw in call.keywords:  # entries in a condition, say
            if kw.arg not in ("parameters", "remappings"):
                self.eval(kw.value)
        self.out.entries.append(entry)
        return entry

    def parameters(self, node: ast.expr | None) -> list[InlineParam | FileParam]:
        found: list[InlineParam | FileParam] = []
        items = node.elts if isinstance(node, (ast.List, ast.Tuple)) else []
        for item in items:
            if isinstance(item, ast.Dict):
                self.inline(item, "", found)
                continue
            value = self.eval(item)
            if isinstance(value, dict):
                continue  # a dict built elsewhere: its places are not here
            path = value.path if isinstance(value, _File) else _text(value)
            found.append(
                FileParam(
                    S.in_tree(self.ctx, path), ast.unparse(item), self.place(item)
                )
            )
        return found

    def inline(
        self, node: ast.Dict, prefix: str, out: list[InlineParam | FileParam]
    ) -> None:
        for key_node, value_node in zip(node.keys, node.values, strict=True):
            key = _text(self.eval(key_node)) if key_node is not None else None
            if key is None:
                continue
            name = f"{prefix}.{key}" if prefix else key
            if isinstance(value_node, ast.Dict):
                self.inline(value_node, name, out)
                continue
            out.append(
                InlineParam(
                    name,
                    typed(self.eval(value_node)),
                    self.place(value_node),
                    self.place(key_node) if key_node is not None else None,
                )
            )


def _text(value: object) -> str | None:
    """A string, or a list of them (launch concatenates a list of substitutions)."""
    if isinstance(value, list) and value and all(isinstance(v, str) for v in value):
        return "".join(value)
    return value if isinstance(value, str) else None


def typed(value: object) -> P.Typed | P.Unread | None:
    """A Python value as launch_ros passes it: a string is read as YAML (launch
    makes it a substitution and `yaml.safe_load`s the result: `'10'` is an
    integer), numbers and bools keep their type, a list's strings stay strings;
    then as rcl reads the parameter file launch writes of it (`values`). A value
    from a launch argument is unknown."""
    if _argument(value):
        return None
    if isinstance(value, str):
        return V.from_yaml(Y.Scalar(value, True, None, 1, 0))
    return V.from_python(value)


def _argument(value: object) -> bool:
    if isinstance(value, list):
        return any(_argument(v) for v in value)
    return isinstance(value, _ArgText)
