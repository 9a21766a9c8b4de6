"""What the names of one Python file are bound to, for its graph's reading
(`python.read_python`): its imports, class bases and methods, module
functions (`bind_module`, the statements only), each scope's bindings and a
class's `self.x` attributes (made when a call's argument first needs them), and
the interface types, strings and QoS profiles a name stands for through them,
each within a budget of steps (`CALL_STEPS`, `FILE_STEPS`).
"""

from __future__ import annotations

import ast
from collections.abc import Sequence

from robotfix.astwalk import STATEMENT_BLOCKS, children, dotted
from robotfix.astwalk import walk as walk_all
from robotfix.ros.graph import qos as Q
from robotfix.ros.graph.model import MIDDLE, FileGraph, Qos

MAX_DEPTH = 8  # names followed through names
CALL_STEPS = 5_000  # values looked at for one call (a name bound 3,000 times to a
# name bound 3,000 times is 9 million otherwise): past it, unknown
FILE_STEPS = 200_000  # and for all the calls of a file
MIDDLES = frozenset({"msg", "srv", "action"})
Scope = ast.FunctionDef | ast.AsyncFunctionDef | ast.Module | ast.Lambda


class File:
    def __init__(self, tree: ast.Module) -> None:
        self.tree = tree
        self.imports: dict[str, str] = {}
        # scope -> name -> the values it is bound to (None: bound otherwise)
        self.bindings: dict[int, dict[str, list[ast.expr | None]]] = {}
        # class -> attribute -> values assigned to `self.attr`
        self.attributes: dict[str, dict[str, list[ast.expr | None]]] = {}
        self.mutated: set[tuple[int, str]] = set()  # (scope, name) of `x.a = ...`
        self.params: dict[int, set[str]] = {}
        self.found = FileGraph()
        self.bases: dict[str, list[str]] = {}
        self.rospy = False
        self.bound: set[int] = set()  # scopes bound (`bind`)
        self.scope_class: dict[int, str] = {}  # a method's scope -> its class
        self.steps = 0  # values the call being read may still look at
        self.left = FILE_STEPS  # what the file's other calls may
        # functions by name: the module's ("") and each class's methods
        self.functions: dict[
            str, dict[str, ast.FunctionDef | ast.AsyncFunctionDef]
        ] = {}
        # with the file's calls given (`read_python`): where the endpoint and node
        # calls start (the statements around none are not walked), and how many
        # of them the walk met
        self.starts: list[tuple[int, int]] | None = None
        self.wanted: set[int] = set()
        self.met = 0

    def start(self) -> int:
        """Work for one call's arguments: what is left of the file's, at most
        `CALL_STEPS` (`spent` takes what it used from the file's)."""
        self.steps = min(CALL_STEPS, self.left)
        return self.steps

    def spent(self, given: int) -> None:
        self.left -= given - max(self.steps, 0)

    # -- names -----------------------------------------------------------------
    def qualified(self, node: ast.expr) -> str | None:
        text = dotted(node)
        if text is None:
            return None
        head, _, rest = text.partition(".")
        if head in self.imports:
            return self.imports[head] + ("." + rest if rest else "")
        return None

    def values(
        self, node: ast.expr, scope: Scope, cls: str | None
    ) -> list[ast.expr | None] | None:
        """What a name or `self.x` is bound to; None if it is no such name."""
        if isinstance(node, ast.Name):
            for where in (scope, self.tree):
                self.bind(where)
                if node.id in self.params.get(id(where), set()):
                    return [None]
                bound = self.bindings.get(id(where), {}).get(node.id)
                if bound is not None:
                    if (id(where), node.id) in self.mutated:
                        return [None]
                    return bound
            return None
        if (
            isinstance(node, ast.Attribute)
            and isinstance(node.value, ast.Name)
            and node.value.id == "self"
            and cls is not None
        ):
            return self.attribute(cls, node.attr, 0)
        return None

    def bind(self, scope: Scope) -> None:
        """The scope's bindings (and, for a method, its class's `self.x`), made
        when a call's argument first needs them: most files never do."""
        if id(scope) not in self.bound:
            self.bound.add(id(scope))
            _bind_scope(self, scope, self.scope_class.get(id(scope)))

    def attribute(
        self, cls: str, attr: str, depth: int
    ) -> list[ast.expr | None] | None:
        for method in self.functions.get(cls, {}).values():
            self.bind(method)
        found = self.attributes.get(cls, {}).get(attr)
        if found is not None:
            return found
        if depth > MAX_DEPTH:
            return [None]
        for base in self.bases.get(cls, []):
            found = self.attribute(base, attr, depth + 1)
            if found is not None:
                return found
        return None

    # -- types, strings, profiles -------------------------------------------------
    def types(
        self, node: ast.expr, scope: Scope, cls: str | None, kind: str, depth: int = 0
    ) -> set[str] | None:
        self.steps -= 1
        if depth > MAX_DEPTH or self.steps < 0:
            return None
        if isinstance(node, ast.IfExp):
            a = self.types(node.body, scope, cls, kind, depth + 1)
            b = self.types(node.orelse, scope, cls, kind, depth + 1)
            return a | b if a is not None and b is not None else None
        bound = self.values(node, scope, cls)
        if bound is not None:
            out: set[str] = set()
            for value in bound:
                one = (
                    None
                    if value is None
                    else self.types(value, scope, cls, kind, depth + 1)
                )
                if one is None:
                    return None
                out |= one
            return out
        name = self.qualified(node)
        if name is None:
            return None
        parts = name.split(".")
        if len(parts) == 3 and parts[1] in MIDDLES:
            return {f"{parts[0]}/{MIDDLE[kind] or parts[1]}/{parts[2]}"}
        if len(parts) == 4 and parts[1] in MIDDLES and parts[2].startswith("_"):
            return {f"{parts[0]}/{MIDDLE[kind] or parts[1]}/{parts[3]}"}
        return None

    def string(
        self, node: ast.expr, scope: Scope, cls: str | None, depth: int = 0
    ) -> str | None:
        if isinstance(node, ast.Constant):
            return node.value if isinstance(node.value, str) else None
        self.steps -= 1
        if depth > MAX_DEPTH or self.steps < 0:
            return None
        bound = self.values(node, scope, cls)
        if not bound:
            return None
        found = {
            None if v is None else self.string(v, scope, cls, depth + 1) for v in bound
        }
        return found.pop() if len(found) == 1 else None

    def profile(
        self, node: ast.expr, scope: Scope, cls: str | None, depth: int = 0
    ) -> Qos | None:
        self.steps -= 1
        if depth > MAX_DEPTH or self.steps < 0:
            return None
        if isinstance(node, ast.Constant):
            if type(node.value) is int:
                return Q.depth_only(node.value)
            return None
        if isinstance(node, ast.IfExp):
            a = self.profile(node.body, scope, cls, depth + 1)
            b = self.profile(node.orelse, scope, cls, depth + 1)
            return a if a == b else None
        bound = self.values(node, scope, cls)
        if bound is not None:
            found = {
                None if v is None else self.profile(v, scope, cls, depth + 1)
                for v in bound
            }
            return found.pop() if len(found) == 1 else None
        if isinstance(node, ast.Attribute) and node.attr == "value":
            node = node.value  # QoSPresetProfiles.SENSOR_DATA.value
        name = self.qualified(node)
        if name is not None and name.startswith("rclpy.qos."):
            return Q.PY_PROFILES.get(name.rsplit(".", 1)[-1])
        if isinstance(node, ast.Call):
            called = self.qualified(node.func)
            if called == "rclpy.qos.QoSProfile":
                return self._qos_profile(node)
        return None

    def _qos_profile(self, call: ast.Call) -> Qos | None:
        fields: dict[str, str | None] = {
            "reliability": Q.RELIABLE,
            "durability": Q.VOLATILE,
        }
        depth = None
        for keyword in call.keywords:
            if keyword.arg is None:
                return None  # **kwargs
            if keyword.arg == "depth":
                value = keyword.value
                depth = (
                    value.value
                    if isinstance(value, ast.Constant) and type(value.value) is int
                    else None
                )
            elif keyword.arg in ("reliability", "durability"):
                text = dotted(keyword.value)
                policy = Q.POLICIES.get(text.rsplit(".", 1)[-1]) if text else None
                if policy is None or policy[0] not in ("", keyword.arg):
                    fields[keyword.arg] = None
                else:
                    fields[keyword.arg] = policy[1]
        return Qos(fields["reliability"], fields["durability"], depth)


# the fields of a statement that hold statements, in `_fields` order
BLOCKS = STATEMENT_BLOCKS  # (`python.py` reads them by this name)


def bind_module(
    file: File,
    imports: Sequence[ast.Import | ast.ImportFrom] | None = None,
    classes: int | None = None,
) -> None:
    """Imports, class bases and methods, module functions: the statements only
    (in the order a walk of the whole tree meets them), not the expressions.
    `imports`: every import statement of the module in that order, and
    `classes`: how many classes it defines (`analysis.index.FileIndex`'s
    `import_statements` and `class_scopes`): when they are all at its top level,
    its other statements are not walked."""
    body = file.tree.body
    if imports is not None and classes == sum(
        1 for n in body if n.__class__ is ast.ClassDef
    ):
        for statement in imports:
            _import(file, statement)
        for node in reversed(body):  # the walk's order: the last one first
            if isinstance(node, ast.ClassDef):
                _class(file, node)
    else:
        _walk_statements(file)
    for item in body:
        if isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)):
            file.functions.setdefault("", {})[item.name] = item


def _walk_statements(file: File) -> None:
    """`bind_module`'s imports and classes, from a walk of every statement."""
    todo: list[ast.AST] = [file.tree]
    blocks = _BLOCK_FIELDS
    while todo:  # a class before its methods
        node = todo.pop()
        kind = node.__class__
        names = blocks.get(kind)
        if names is None:
            names = blocks[kind] = tuple(n for n in BLOCKS if n in kind._fields)
        if not names:  # an expression statement, an assignment ...: no block
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                _import(file, node)
            continue
        if isinstance(node, ast.ClassDef):
            _class(file, node)
        for name in names:
            block = getattr(node, name, None)
            if block.__class__ is list:
                todo.extend(block)


def _class(file: File, node: ast.ClassDef) -> None:
    """A class's bases (by name) and methods."""
    file.bases[node.name] = [b.id for b in node.bases if isinstance(b, ast.Name)]
    for item in node.body:
        if isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)):
            file.scope_class[id(item)] = node.name
            file.functions.setdefault(node.name, {})[item.name] = item


# each statement class's fields of `BLOCKS` (none: it holds no statement)
_BLOCK_FIELDS: dict[type, tuple[str, ...]] = {}


def _import(file: File, node: ast.Import | ast.ImportFrom) -> None:
    """The names an import statement binds, and whether it imports rospy."""
    if isinstance(node, ast.Import):
        for alias in node.names:
            if alias.asname:
                file.imports[alias.asname] = alias.name
            else:
                head = alias.name.split(".")[0]
                file.imports[head] = head
        if any(a.name == "rospy" for a in node.names):
            file.rospy = True
    elif node.module and not node.level:
        for alias in node.names:
            file.imports[alias.asname or alias.name] = f"{node.module}.{alias.name}"
        if node.module == "rospy" or node.module.startswith("rospy."):
            file.rospy = True


def _bind_scope(file: File, scope: Scope, cls: str | None) -> None:
    if isinstance(scope, ast.Lambda):
        return  # its names are its parameters (`_visit`)
    names: dict[str, list[ast.expr | None]] = {}
    if not isinstance(scope, ast.Module):
        args = scope.args
        file.params[id(scope)] = {
            a.arg for a in [*args.posonlyargs, *args.args, *args.kwonlyargs]
        } | {a.arg for a in (args.vararg, args.kwarg) if a is not None}
    todo: list[ast.AST] = list(scope.body)
    while todo:  # each node's class tested once: most are names and constants
        node = todo.pop()
        kind = node.__class__
        if kind is ast.Name:
            if node.ctx.__class__ is not ast.Load:  # type: ignore[attr-defined]
                # for, with, walrus, del
                names.setdefault(node.id, []).append(None)  # type: ignore[attr-defined]
            continue
        if kind is ast.Assign or kind is ast.AnnAssign:
            _bind_assignment(file, scope, cls, node, names)  # type: ignore[arg-type]
            if node.value is not None:  # type: ignore[attr-defined]
                todo.append(node.value)  # type: ignore[attr-defined]
            continue
        if kind in _SCOPES:  # their own scopes; a name here, and what they
            # may store in `self.x`
            if kind is not ast.Lambda:
                names.setdefault(node.name, []).append(None)  # type: ignore[attr-defined]
            if cls is not None:
                for inner in walk_all(node):
                    if (
                        isinstance(inner, ast.Attribute)
                        and isinstance(inner.ctx, ast.Store)
                        and isinstance(inner.value, ast.Name)
                        and inner.value.id == "self"
                    ):
                        attributes = file.attributes.setdefault(cls, {})
                        attributes.setdefault(inner.attr, []).append(None)
            continue
        if kind is ast.AugAssign:
            target = node.target  # type: ignore[attr-defined]
            if isinstance(target, ast.Name):
                names.setdefault(target.id, []).append(None)
            todo.append(node.value)  # type: ignore[attr-defined]
            continue
        if (
            kind is ast.Attribute
            and node.ctx.__class__ is ast.Store  # type: ignore[attr-defined]
            and isinstance(node.value, ast.Name)  # type: ignore[attr-defined]
        ):
            assert isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name)
            if node.value.id == "self" and cls is not None:
                file.attributes.setdefault(cls, {}).setdefault(node.attr, []).append(
                    None
                )
            else:
                file.mutated.add((id(scope), node.value.id))
        for child in children(node):  # not contexts and operators: none binds
            if child.__class__ is not ast.Constant:
                todo.append(child)
    file.bindings[id(scope)] = names


_SCOPES = frozenset({ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda})


def _bind_assignment(
    file: File,
    scope: Scope,
    cls: str | None,
    node: ast.Assign | ast.AnnAssign,
    names: dict[str, list[ast.expr | None]],
) -> None:
    """What an assignment's targets bind: a name or `self.x` its value, another
    object's attribute marks the object changed, anything else binds otherwise."""
    targets = node.targets if isinstance(node, ast.Assign) else [node.target]
    value = node.value
    for target in targets:
        if isinstance(target, ast.Name):
            names.setdefault(target.id, []).append(value)
        elif isinstance(target, ast.Attribute) and isinstance(target.value, ast.Name):
            if target.value.id == "self" and cls is not None:
                file.attributes.setdefault(cls, {}).setdefault(target.attr, []).append(
                    value
                )
            else:
                file.mutated.add((id(scope), target.value.id))
        else:  # a, b = ...: each bound otherwise
            for inner in walk_all(target):
                if isinstance(inner, ast.Name):
                    names.setdefault(inner.id, []).append(None)
                elif (
                    isinstance(inner, ast.Attribute)
                    and isinstance(inner.value, ast.Name)
                    and inner.value.id == "self"
                    and cls is not None
                ):
                    file.attributes.setdefault(cls, {}).setdefault(
                        inner.attr, []
                    ).append(None)
