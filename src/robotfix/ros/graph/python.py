"""The graph endpoints of one Python file, read from its AST (never run).

rclpy's `create_publisher(Type, 'topic', qos)`, `create_subscription`,
`create_service`, `create_client` (any receiver, as `ros.api_model` lists them),
`rclpy.action.ActionServer`/`ActionClient`; rospy's `Publisher('t', Type)`,
`Subscriber`, `Service`, `ServiceProxy`; actionlib's servers and clients.

Interface types are named through the file's imports (`from geometry_msgs.msg
import Twist`, `import std_msgs.msg as m` ... `m.String`): a class name, or a name
or `self.x` every assignment of which is one (then each is a possible type: a
parameter choosing `Twist` or `TwistStamped`); anything else is unknown. Topic
names are string constants, or names bound to one only. QoS: a depth, rclpy's
preset profiles, `QoSProfile(reliability=..., durability=...)` with constant
policies, through a name bound once and never changed.

Which node makes an endpoint: the class of the method it is in (its name from
`super().__init__('name')`, or from a class of the file it derives from), or the
variable a node is in (`node = rclpy.create_node('name')`); rospy's
`init_node('name')` names the file's one node.
"""

from __future__ import annotations

import ast
import re
import sys
from bisect import bisect_left
from collections import Counter
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import replace

from robotfix.astwalk import children, dotted
from robotfix.astwalk import walk as walk_all
from robotfix.ros.api_model import (
    ENDPOINT_CLASSES,
    ENDPOINT_METHODS,
    NODE_CONSTRUCTORS,
    EndpointCall,
)
from robotfix.ros.graph.model import Endpoint, FileGraph, Qos
from robotfix.ros.graph.python_names import BLOCKS, File, Scope, bind_module


def _argument(call: ast.Call, where: tuple[int, str]) -> ast.expr | None:
    position, keyword = where
    for item in call.keywords:
        if item.arg == keyword:
            return item.value
    if any(isinstance(a, ast.Starred) for a in call.args[: position + 1]):
        return None
    return call.args[position] if position < len(call.args) else None


def read_python(
    tree: ast.Module,
    calls: Iterable[tuple[str | None, ast.Call]] | None = None,
    imports: Sequence[ast.Import | ast.ImportFrom] | None = None,
    classes: int | None = None,
    endpoints_only: bool = False,
) -> FileGraph:
    """The endpoints and node names of a module's code. `calls`: every call of
    the module with its top-level class (`analysis.index.FileIndex.calls`, which
    the file's check built): then only the statements that hold an endpoint or
    node call are walked, and only those `__init__` calls are looked at for the
    classes' node names; a call the walk does not meet where its position says
    (one in a decorator) makes the whole module walked, as without `calls`.
    `imports` and `classes`: its import statements and how many classes it
    defines, from the same index (`bind_module`). `endpoints_only` (with
    `calls`): a module none of whose calls makes an endpoint is not read (an
    empty graph: its node names are not wanted)."""
    if calls is not None:
        calls = list(calls)
        found = _read(tree, calls, imports, classes, endpoints_only)
        if found is not None:
            return found
    found = _read(tree, None)
    assert found is not None
    return found


def _read(
    tree: ast.Module,
    calls: list[tuple[str | None, ast.Call]] | None,
    imports: Sequence[ast.Import | ast.ImportFrom] | None = None,
    classes: int | None = None,
    endpoints_only: bool = False,
) -> FileGraph | None:
    found = File(tree)
    bind_module(found, imports if calls is not None else None, classes)
    inits = None
    if calls is not None:
        wanted, inits, endpoints = _wanted(found, calls)
        if endpoints_only and not endpoints:
            return FileGraph()
        found.wanted = {id(c) for c in wanted}
        found.starts = sorted((c.lineno, c.col_offset) for c in wanted)
    _visit(found, tree.body, tree, None)
    if calls is not None and found.met != len(found.wanted):
        return None
    if any(e.kind == "client" and e.holder for e in found.found.endpoints):
        _responses(found)
    super_names(tree, found.found, inits)
    found.found.ros = 1 if found.rospy else 2
    return found.found


# the last names of what `_call` makes something of but a method's: a call of
# `x.y.z` is looked up (`qualified`) only when `z` is one of them
_TAILS = frozenset(
    {name.rsplit(".", 1)[-1] for name in ENDPOINT_CLASSES}
    | NODE_CONSTRUCTORS
    | {"init_node"}
)


def _wanted(
    file: File, calls: list[tuple[str | None, ast.Call]]
) -> tuple[list[ast.Call], dict[str | None, list[ast.Call]], bool]:
    """The calls `_call` makes anything of (an endpoint, a node's name), in the
    order of `calls`; the `__init__` calls by top-level class (`super_names`);
    and whether one of the calls makes an endpoint. One pass over the calls."""
    wanted: list[ast.Call] = []
    inits: dict[str | None, list[ast.Call]] = {}
    endpoints = False
    attribute, name, methods, tails = ast.Attribute, ast.Name, ENDPOINT_METHODS, _TAILS
    imports = file.imports
    for owner, call in calls:
        func = call.func
        kind = func.__class__
        if kind is attribute:
            attr = func.attr  # type: ignore[attr-defined]
            if attr in methods:
                wanted.append(call)
                endpoints = True
                continue
            if attr == "__init__":
                inits.setdefault(owner, []).append(call)
            if attr not in tails:  # what it names ends so: none of them
                continue
        elif kind is not name:
            continue  # no chain of names: `qualified` finds nothing
        elif func.id not in imports:  # type: ignore[attr-defined]
            continue  # (`print(...)`: nor then)
        called = file.qualified(func)
        if called is None:
            continue
        if called in ENDPOINT_CLASSES:
            wanted.append(call)
            endpoints = True
        elif _names_node(called):
            wanted.append(call)
    return wanted, inits, endpoints


def _names_node(called: str) -> bool:
    """Whether a call of `called` may name a node (`_node_call`)."""
    return called == "rospy.init_node" or (
        called.startswith("rclpy.") and called.rsplit(".", 1)[-1] in NODE_CONSTRUCTORS
    )


def _holds(file: File, statement: ast.stmt) -> bool:
    """Whether an endpoint or node call starts within `statement` (always, when
    the file's calls are not known)."""
    starts = file.starts
    if starts is None:
        return True
    end = getattr(statement, "end_lineno", None)
    if end is None:
        return True
    at = bisect_left(starts, (statement.lineno, statement.col_offset))
    return at < len(starts) and starts[at] <= (end, statement.end_col_offset or 0)


def _visit(file: File, body: list[ast.stmt], scope: Scope, cls: str | None) -> None:
    """The endpoint and node calls of `body`, each with the scope its names are
    looked up in: a nested function or lambda is a scope of its own. With the
    file's calls known, a statement (nested ones too) where none starts is not
    walked: every node but a decorator lies within its statement's lines."""
    for statement in body:
        if not _holds(file, statement):
            continue
        if isinstance(statement, ast.ClassDef):
            _visit(file, statement.body, scope, statement.name)
            continue
        if isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef)):
            _visit(file, statement.body, statement, cls)
            continue
        # (node, its scope, the innermost statement holding it: a call's own
        # `x = Node(...)` inside a `with`, `try` or `if`, not the block's)
        todo: list[tuple[ast.AST, Scope, ast.stmt]] = [(statement, scope, statement)]
        while todo:
            node, where, inner = todo.pop()
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                _visit(file, node.body, node, cls)
                continue
            if isinstance(node, ast.ClassDef):
                _visit(file, node.body, where, node.name)
                continue
            if isinstance(node, ast.Lambda):
                args = node.args
                file.params[id(node)] = {
                    a.arg for a in [*args.posonlyargs, *args.args, *args.kwonlyargs]
                }
                file.bound.add(id(node))  # its names: its parameters only
                todo.append((node.body, node, inner))
                continue
            if isinstance(node, ast.Call):
                if id(node) in file.wanted:
                    file.met += 1
                    _call(file, node, where, cls, inner)
                elif file.starts is None:  # the file's calls not known
                    _call(file, node, where, cls, inner)
            elif isinstance(node, ast.stmt):
                if not _holds(file, node):
                    continue  # (an `if`'s branch, a loop's body: no call starts there)
                inner = node
            for child in children(node):
                if child.__class__ not in _LEAVES:
                    todo.append((child, where, inner))


# nodes without children, neither calls nor scopes: not put on a walk's stack
_LEAVES = frozenset({ast.Name, ast.Constant})


def _call(
    file: File, call: ast.Call, scope: Scope, cls: str | None, statement: ast.stmt
) -> None:
    func = call.func
    spec: EndpointCall | None = None
    owner = cls or ""
    if isinstance(func, ast.Attribute) and func.attr in ENDPOINT_METHODS:
        spec = ENDPOINT_METHODS[func.attr]
        receiver = func.value
        if not (isinstance(receiver, ast.Name) and receiver.id == "self"):
            text = dotted(receiver)
            owner = text or ""
    else:
        called = file.qualified(func)
        if called in ENDPOINT_CLASSES:
            spec = ENDPOINT_CLASSES[called]
            if spec.ros == 2:  # ActionServer(node, ...): the node is the first
                node = _argument(call, (0, "node"))
                text = dotted(node) if node is not None else None
                if text and text != "self":
                    owner = text
        elif called is not None:
            _node_call(file, call, called, scope, cls, statement)
            return
    if spec is None:
        return
    if spec.ros == 1:
        owner = ""
    given = file.start()
    type_node = _argument(call, spec.type_arg)
    name_node = _argument(call, spec.name_arg)
    types = (
        file.types(type_node, scope, cls, spec.kind) if type_node is not None else None
    )
    name = file.string(name_node, scope, cls) if name_node is not None else None
    profile = None
    if spec.qos_arg is not None:
        qos_node = _argument(call, spec.qos_arg)
        if qos_node is not None:
            profile = file.profile(qos_node, scope, cls)
            if profile is not None and any(
                k.arg == "qos_overriding_options" for k in call.keywords
            ):
                profile = Qos(
                    profile.reliability, profile.durability, profile.depth, False
                )
    file.spent(given)
    contract = None
    returns = ""
    if spec.taken_arg is not None:
        callback = _argument(call, spec.taken_arg)
        contract = _contract(file, callback, cls) if callback is not None else None
        if spec.kind == "service" and callback is not None:
            returns = _callback_key(file, callback, cls)
    file.found.endpoints.append(
        Endpoint(
            spec.kind,
            name,
            tuple(sorted(types or ())),
            call.lineno,
            call.col_offset,
            owner,
            profile,
            spec.ros,
            contract=contract,
            holder=_holder(file, statement, call, scope, cls),
            returns=returns,
        )
    )


def _callback_key(file: File, callback: ast.expr, cls: str | None) -> str:
    """A service's callback as the analysis keys it (`analysis.program`): `handle`
    of a module function, `Server.handle` of `self.handle` defined in the class
    itself; "" otherwise (inherited, a lambda, a `partial`)."""
    if isinstance(callback, ast.Name) and callback.id in file.functions.get("", {}):
        return callback.id
    if (
        isinstance(callback, ast.Attribute)
        and isinstance(callback.value, ast.Name)
        and callback.value.id == "self"
        and cls is not None
        and callback.attr in file.functions.get(cls, {})
    ):
        return f"{cls}.{callback.attr}"
    return ""


def _responses(file: File) -> None:
    """What each client kept in a holder (`_holder`) assumes of the responses it
    receives: the refinement of the name a synchronous call binds (`resp:
    Annotated[SetSpeed.Response, "actual <= 2"] = self.cli.call(req)`; rospy's
    `proxy(req)`, `proxy.call(req)`), as the client's `contract`; every such
    assumption of one client joined; none for a place two clients are kept in.
    A future's refined `result()` is read as the call's (`_future_client`)."""
    # the last name of each place a client is kept (`cli` of `C:self.cli`,
    # `:main/cli`): other calls are not looked at further
    tails = {
        re.split(r"[:/.]", e.holder)[-1]
        for e in file.found.endpoints
        if e.kind == "client" and e.holder
    }
    found: dict[tuple[str, bool], list[tuple[int, int, str]]] = {}
    todo: list[tuple[ast.AST, Scope, str | None]] = [(file.tree, file.tree, None)]
    while todo:  # statements only: an annotated assignment is one
        node, scope, cls = todo.pop()
        for child in _statements(node):
            if isinstance(child, ast.ClassDef):
                todo.append((child, scope, child.name))
                continue
            if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)):
                todo.append((child, child, cls))
                continue
            if isinstance(child, ast.AnnAssign) and isinstance(child.value, ast.Call):
                func = child.value.func
                key = _future_client(file, child.value, scope, cls)
                if key:  # `response: Annotated[...] = future.result()`
                    text = _annotated_text(file, child.annotation)
                    if text is not None:
                        where = (child.lineno, child.col_offset, text)
                        found.setdefault((key, False), []).append(where)
                    todo.append((child, scope, cls))
                    continue
                receivers = [(func, True)]
                if isinstance(func, ast.Attribute) and func.attr == "call":
                    receivers.append((func.value, False))
                receivers = [r for r in receivers if _tail(r[0]) in tails]
                text = _annotated_text(file, child.annotation) if receivers else None
                if text is not None:
                    where = (child.lineno, child.col_offset, text)
                    for receiver, direct in receivers:
                        key = _receiver_key(file, receiver, scope, cls)
                        found.setdefault((key, direct), []).append(where)
            todo.append((child, scope, cls))
    endpoints = file.found.endpoints
    held = Counter(e.holder for e in endpoints if e.kind == "client")
    for i, end in enumerate(endpoints):
        if end.kind != "client" or not end.holder or held[end.holder] != 1:
            continue  # two clients kept in one place: which one answers is not known
        sites = found.get((end.holder, False), []) + (
            found.get((end.holder, True), []) if end.ros == 1 else []
        )
        texts = list(dict.fromkeys(text for _, _, text in sorted(sites)))
        if texts:
            joined = " and ".join(f"({t})" if len(texts) > 1 else t for t in texts)
            endpoints[i] = replace(end, contract=joined)


def _future_client(file: File, call: ast.Call, scope: Scope, cls: str | None) -> str:
    """Where the client is kept (`_holder`) whose future `call` reads the result
    of: `future.result()` of a local `future` every binding of which in its
    function (or module) is `<client>.call_async(...)` of one client, or of a
    `self.future` every assignment of which in its class is (the client kept in
    `self.x`, and no base of the file's binds it), or `None`; "" otherwise (a
    parameter, a name bound otherwise, declared `global` or `nonlocal`, a class
    another of the file derives from)."""
    func = call.func
    if not (
        isinstance(func, ast.Attribute)
        and func.attr == "result"
        and not call.args
        and not call.keywords
    ):
        return ""
    future = func.value
    if isinstance(future, ast.Name) and not isinstance(scope, ast.Lambda):
        file.bind(scope)
        if future.id in file.params.get(id(scope), set()) or (
            (id(scope), future.id) in file.mutated
        ):
            return ""
        bound = file.bindings.get(id(scope), {}).get(future.id)
        if any(
            isinstance(n, (ast.Global, ast.Nonlocal)) and future.id in n.names
            for n in walk_all(scope)
        ):
            return ""  # another function may bind it
    elif (
        isinstance(future, ast.Attribute)
        and isinstance(future.value, ast.Name)
        and future.value.id == "self"
        and cls is not None
        and not any(cls in bases for bases in file.bases.values())
    ):
        file.attribute(cls, future.attr, 0)  # binds every method of the class
        bound = file.attributes.get(cls, {}).get(future.attr)
        if any(file.attribute(b, future.attr, 0) for b in file.bases.get(cls, [])):
            return ""  # a base of the file binds it too
    else:
        return ""
    keys = set()
    for value in bound or [None]:
        if isinstance(value, ast.Constant) and value.value is None:
            continue  # `self.future = None` until a call: no client's future
        if not (
            isinstance(value, ast.Call)
            and isinstance(value.func, ast.Attribute)
            and value.func.attr == "call_async"
        ):
            return ""
        receiver = value.func.value
        if isinstance(future, ast.Attribute) and not (
            (dotted(receiver) or "").startswith("self.")
        ):
            return ""  # a local client of another method: its scope is not known
        keys.add(_receiver_key(file, receiver, scope, cls))
    return keys.pop() if len(keys) == 1 else ""


def _tail(node: ast.expr) -> str:
    """The last name of `x` or `self.x`."""
    if isinstance(node, ast.Name):
        return node.id
    return node.attr if isinstance(node, ast.Attribute) else ""


def _statements(node: ast.AST) -> Iterator[ast.AST]:
    """What `node`'s blocks hold (`BLOCKS`): statements, handlers, cases."""
    for name in BLOCKS:
        block = getattr(node, name, None)
        if block.__class__ is list:
            yield from block


def _receiver_key(file: File, receiver: ast.expr, scope: Scope, cls: str | None) -> str:
    """`receiver` as `_holder` names where an endpoint is kept."""
    if isinstance(receiver, ast.Name):
        if isinstance(scope, (ast.Module, ast.Lambda)):
            return f":{receiver.id}"
        file.bind(scope)
        local = receiver.id in file.params.get(id(scope), set()) or (
            receiver.id in file.bindings.get(id(scope), {})
        )
        return f"{cls or ''}:{scope.name}/{receiver.id}" if local else f":{receiver.id}"
    text = dotted(receiver) or ""
    return f"{cls}:{text}" if text.startswith("self.") and cls is not None else ""


def _holder(
    file: File, statement: ast.stmt, call: ast.Call, scope: Scope, cls: str | None
) -> str:
    """Where the endpoint is kept, as the analysis names it at a `publish` or
    `call_async` (`analysis.calls`): `Planner:self.pub` of `self.pub =
    self.create_publisher(...)` in a method of class `Planner`; `:main/cli` of
    `cli = node.create_client(...)` in a function `main` (`Planner:__init__/pub` in
    a method), `:pub` of a module's `pub = rospy.Publisher(...)`, each only for a
    name bound once in its scope; "" otherwise."""
    if isinstance(statement, ast.Assign) and len(statement.targets) == 1:
        target: ast.expr = statement.targets[0]
    elif isinstance(statement, ast.AnnAssign):
        target = statement.target
    else:
        return ""
    if statement.value is not call:
        return ""
    if isinstance(target, ast.Name) and not isinstance(scope, ast.Lambda):
        if file.values(target, scope, cls) != [call]:
            return ""  # bound again, or declared global: not followed
        if isinstance(scope, ast.Module):
            return f":{target.id}"
        return f"{cls or ''}:{scope.name}/{target.id}"
    text = dotted(target) or ""
    return f"{cls}:{text}" if text.startswith("self.") and cls is not None else ""


def _contract(file: File, callback: ast.expr, cls: str | None) -> str | None:
    """The refinement a subscription's callback declares on the message it takes
    (`def on_cmd(self, msg: Annotated[Twist, "abs(linear.x) <= 0.5"])`), or a
    service's on the request (`def handle(self, request: Annotated[...],
    response)`), an action server's on the goal (rclpy's `goal_callback`,
    actionlib's `execute_cb`), as written; None without one (or when the
    callback is not a function of the file)."""
    function = None
    if isinstance(callback, ast.Name):
        function = file.functions.get("", {}).get(callback.id)
        first = 0
    elif (
        isinstance(callback, ast.Attribute)
        and isinstance(callback.value, ast.Name)
        and callback.value.id == "self"
        and cls is not None
    ):
        seen: set[str] = set()
        todo = [cls]
        while todo and function is None:
            owner = todo.pop(0)
            if owner in seen:
                continue
            seen.add(owner)
            function = file.functions.get(owner, {}).get(callback.attr)
            todo += file.bases.get(owner, [])
        first = 1
    if function is None:
        return None
    params = [*function.args.posonlyargs, *function.args.args]
    if len(params) <= first:
        return None
    return _annotated_text(file, params[first].annotation)


def _annotated_text(file: File, written: ast.expr | None) -> str | None:
    """The refinement texts of an `Annotated[T, "..."]` (or of an alias of one),
    joined; None without one."""
    annotation = _aliased(file, written)
    if not (
        isinstance(annotation, ast.Subscript)
        and (dotted(annotation.value) or "").rsplit(".", 1)[-1] == "Annotated"
        and isinstance(annotation.slice, ast.Tuple)
    ):
        return None
    texts = [
        e.value
        for e in annotation.slice.elts[1:]
        if isinstance(e, ast.Constant) and isinstance(e.value, str)
    ]
    return " and ".join(f"({t})" if len(texts) > 1 else t for t in texts) or None


def _aliased(file: File, annotation: ast.expr | None) -> ast.expr | None:
    """An annotation that names a module-level alias bound once and never changed
    (`SafeTwist = Annotated[Twist, "..."]`, `SafeTwist: TypeAlias = ...`, then
    `msg: SafeTwist`) stands for the alias's value; any other annotation for
    itself. (An alias imported from another module is not followed here.)"""
    if not isinstance(annotation, ast.Name):
        return annotation
    bound = file.values(annotation, file.tree, None)
    if bound is not None and len(bound) == 1 and bound[0] is not None:
        return bound[0]
    return annotation


def _node_call(
    file: File,
    call: ast.Call,
    called: str,
    scope: Scope,
    cls: str | None,
    statement: ast.stmt,
) -> None:
    """A node's name: `super().__init__('name')` in a class, `x = Node('name')`,
    `rospy.init_node('name')`."""
    if called == "rospy.init_node":
        name = _node_name(file, call, scope, cls)
        anonymous = any(
            k.arg == "anonymous"
            and not (isinstance(k.value, ast.Constant) and not k.value.value)
            for k in call.keywords
        )
        if name is not None and not anonymous:
            file.found.nodes.setdefault("", []).append(name)
        return
    if (
        _names_node(called)
        and isinstance(statement, ast.Assign)
        and statement.value is call
    ):
        for target in statement.targets:
            text = dotted(target)
            owner = text[5:] if text and text.startswith("self.") else text
            name = _node_name(file, call, scope, cls)
            if owner and name is not None:
                file.found.nodes.setdefault(owner, []).append(name)


def _node_name(file: File, call: ast.Call, scope: Scope, cls: str | None) -> str | None:
    node = _argument(call, (0, "node_name"))
    if node is None:
        node = _argument(call, (0, "name"))
    given = file.start()
    found = file.string(node, scope, cls) if node is not None else None
    file.spent(given)
    return found


def super_names(
    tree: ast.Module,
    file: FileGraph,
    inits: dict[str | None, list[ast.Call]] | None = None,
) -> None:
    """Each class's node name from `super().__init__('name')` (or
    `Base.__init__(self, 'name')`), and what a class of the file derives from one.
    `inits`: every `__init__` call of the module by its top-level class
    (`_wanted`): a class's are taken from them (none in its decorators or
    annotations: they name no node), its code walked only when it makes more
    than one (their order is the walk's); None: every class is walked."""
    classes: dict[str, ast.ClassDef] = {
        n.name: n for n in tree.body if isinstance(n, ast.ClassDef)
    }
    for name, cls in classes.items():
        start = (cls.lineno, cls.col_offset)
        end = (cls.end_lineno or sys.maxsize, cls.end_col_offset or 0)
        mine = [  # not another class of that name (`if ...: class A`)
            c
            for c in (inits or {}).get(name, ())
            if start <= (c.lineno, c.col_offset) <= end
        ]
        for node in walk_all(cls) if inits is None or len(mine) > 1 else mine:
            if not (
                isinstance(node, ast.Call)
                and isinstance(node.func, ast.Attribute)
                and node.func.attr == "__init__"
            ):
                continue
            receiver = node.func.value
            args = list(node.args)
            if isinstance(receiver, ast.Call) and dotted(receiver.func) == "super":
                pass
            elif (
                isinstance(receiver, ast.Name)
                and args
                and isinstance(args[0], ast.Name)
                and args[0].id == "self"
            ):
                args = args[1:]
            else:
                continue
            value = None
            for keyword in node.keywords:
                if keyword.arg == "node_name":
                    value = keyword.value
            if value is None and args:
                value = args[0]
            if isinstance(value, ast.Constant) and isinstance(value.value, str):
                file.nodes.setdefault(name, []).append(value.value)
    for name, cls in classes.items():
        seen = {name}
        todo = [b.id for b in cls.bases if isinstance(b, ast.Name)]
        while todo and name not in file.nodes:
            base = todo.pop()
            if base in seen:
                continue
            seen.add(base)
            if base in file.nodes:
                file.nodes[name] = list(file.nodes[base])
            elif base in classes:
                todo += [b.id for b in classes[base].bases if isinstance(b, ast.Name)]
