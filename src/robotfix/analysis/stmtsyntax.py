"""What the statement walker knows of statements from their syntax alone: which
calls return, may raise or never return, which statements cannot raise, what a
handler catches, what a loop body binds, sums and breaks, which tests are
literal. Functions of the AST and constants only: no state, no context, no
evaluator (asked by `binder`, `paths`, `compound` and `interpreter`).
"""

from __future__ import annotations

import ast
import builtins
import copy

from robotfix.analysis import writes
from robotfix.analysis.constants import plain_kind
from robotfix.analysis.state import MAYBE, State
from robotfix.analysis.values import Value
from robotfix.annotations import ast as A
from robotfix.astwalk import TRIES, children, walk

NO_RETURN = frozenset(
    {
        "sys.exit",
        "os._exit",
        "os.abort",
        "pytest.fail",
        "pytest.skip",
        "pytest.exit",
        "pytest.xfail",
        "typing.assert_never",
        "typing_extensions.assert_never",
        "_pytest.outcomes.fail",
        "_pytest.outcomes.skip",
        "_pytest.outcomes.exit",
    }
)
# Python 2's builtins: `raw_input = raw_input` in a module's Python 2 branch.
PY2_BUILTINS = frozenset(
    {"raw_input", "unicode", "basestring", "long", "xrange", "unichr", "file"}
    | {"execfile", "reload", "cmp", "buffer", "apply", "intern", "coerce"}
)
BUILTINS = frozenset(dir(builtins)) | {"__file__", "__name__", "__doc__", "__spec__"}
# Calls whose result is dropped and which return: logging, output, containers,
# ROS publishing and sleeping (a call may still raise; these are not written to).
RETURNS = frozenset(
    {
        "print",
        "log",
        "loginfo",
        "logwarn",
        "logerr",
        "logdebug",
        "logfatal",
        "loginfo_throttle",
        "logwarn_throttle",
        "logerr_throttle",
        "write",
        "flush",
        "append",
        "extend",
        "insert",
        "add",
        "update",
        "remove",
        "discard",
        "clear",
        "pop",
        "sort",
        "reverse",
        "setdefault",
        "publish",
        "sleep",
        "spin_once",
        "spin_until_future_complete",
        "destroy_node",
        "shutdown",
        "close",
        "join",
        "start",
        "put",
        "send",
        "set",
        "wait",
        "acquire",
        "release",
    }
)


# rospy's logging functions, and builtins that only read what they are given
ROS_LOGGING = frozenset(n for n in RETURNS if n.startswith("log"))
READING_BUILTINS = frozenset(
    {"len", "print", "str", "repr", "isinstance", "type", "id", "hash", "bool"}
    | {"float", "int", "abs", "round", "format", "hasattr", "callable"}
)

# Logging methods: they return when called on a logger, not on any object
# (`parser.error(msg)` exits).
LOGGING = frozenset(
    {"debug", "info", "warn", "warning", "error", "exception", "critical", "fatal"}
)


def may_raise(node: ast.AST) -> bool:
    """A function with a `raise` or an `assert` in its own body. Both are
    statements, and no expression holds a statement: only the statement lists
    are walked (a lambda's body is an expression)."""
    if isinstance(node, ast.Lambda):
        return False
    todo: list[ast.stmt] = list(getattr(node, "body", []))
    while todo:
        child = todo.pop()
        kind = type(child)
        if kind is ast.Raise or kind is ast.Assert:
            return True
        if kind in _NESTED_SCOPES:
            continue
        for block in _STATEMENT_LISTS:
            todo.extend(getattr(child, block, ()))
        for part in getattr(child, "handlers", ()) or getattr(child, "cases", ()):
            todo.extend(part.body)
    return False


_NESTED_SCOPES = frozenset({ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef})
_STATEMENT_LISTS = ("body", "orelse", "finalbody")


def is_case(test: ast.expr) -> bool:
    """`m == A`, `m is A`, `m in (A, B)`, `isinstance(m, A)`, `is_array(m)`: one
    case of a case analysis, which may cover every value the subject can have."""
    if isinstance(test, ast.Compare):
        return len(test.ops) == 1 and isinstance(test.ops[0], (ast.Eq, ast.Is, ast.In))
    if isinstance(test, ast.BoolOp) and isinstance(test.op, ast.Or):
        return all(is_case(v) for v in test.values)
    # a predicate call: `isinstance(x, A)`, `is_array(v)`, `self.check_event(E)`
    return isinstance(test, ast.Call)


BROAD_ERRORS = frozenset({"Exception", "BaseException", "TypeError"})


def bound_before_raising(body: list[ast.stmt], handler: ast.ExceptHandler) -> set[str]:
    """Names surely bound before anything `handler` catches can be raised: with a
    `try` body that is one `for` loop (one `with` block), a handler of named
    exceptions (not a broad one, which may come from iterating something that is
    not iterable) catch what its body raised, after its target (the names after
    `as`) and the leading `x = y` of the body were bound."""
    block = body[-1] if body and without_calls(body[:-1], handler) else None
    if isinstance(block, ast.For) and isinstance(block.target, ast.Name):
        names = {block.target.id}  # a tuple: unpacking may raise first
        if block.orelse:
            return set()
    elif isinstance(block, ast.With) and all(
        isinstance(item.optional_vars, (ast.Name, type(None))) for item in block.items
    ):
        names = {
            item.optional_vars.id
            for item in block.items
            if isinstance(item.optional_vars, ast.Name)
        }
    else:
        return set()
    if handler.type is None or catches(handler.type, BROAD_ERRORS):
        return set()
    for stmt in block.body:
        if not isinstance(stmt, ast.Assign) or not (
            cannot_raise(stmt) or isinstance(stmt.value, ast.Name)
        ):
            break
        names |= {t.id for t in stmt.targets if isinstance(t, ast.Name)}
    return names


def without_calls(stmts: list[ast.stmt], handler: ast.ExceptHandler) -> bool:
    """Statements that cannot raise what `handler` catches: none, or (a handler of
    exceptions that are not builtin ones, which only a call or a `raise` raises,
    not `self.level += 1`) statements without a call, `raise`, `assert` or `yield`."""
    if not stmts:
        return True
    if catches(handler.type, BUILTIN_ERRORS):
        return False
    return not any(
        isinstance(
            n,
            (
                ast.Call,
                ast.Raise,
                ast.Assert,
                ast.Await,
                ast.Yield,
                ast.YieldFrom,
                ast.FunctionDef,
                ast.ClassDef,
                ast.Delete,
            ),
        )
        for n in walk(stmts)
    )


BUILTIN_ERRORS = frozenset(
    name
    for name in dir(builtins)
    if isinstance(getattr(builtins, name), type)
    and issubclass(getattr(builtins, name), BaseException)
)


def cannot_raise(stmt: ast.stmt) -> bool:
    """`x = None`, `n = 0`, `a = b = ""`, `pass`: a statement that never raises."""
    if isinstance(stmt, ast.Pass):
        return True
    if not isinstance(stmt, ast.Assign) or not all(
        isinstance(t, ast.Name) for t in stmt.targets
    ):
        return False
    value = stmt.value
    if isinstance(value, ast.UnaryOp) and isinstance(value.op, ast.USub):
        value = value.operand
    if isinstance(value, ast.Dict):
        return not value.keys
    if isinstance(value, (ast.List, ast.Tuple)):
        return not value.elts
    return isinstance(value, ast.Constant)


def excuse(side: State, other: State) -> None:
    """Names bound on `other` but not on `side`, which may have ended: unbound
    there only if it went on, which the analysis cannot tell."""
    get = side.env.get
    for name, bound in other.env.items():
        mine = get(name)
        if mine is bound and (not isinstance(mine, Value) or mine.uninit is None):
            continue  # (most names) the same binding: nothing to excuse
        if "." in name or not isinstance(bound, Value):
            continue
        if not isinstance(mine, Value) or mine.uninit is not None:
            side.env[name] = MAYBE


def accumulated(nodes: list[ast.stmt]) -> set[str]:
    """Names whose every store under `nodes` is `name += e` or `name -= e`."""
    summed: set[str] = set()
    targets: set[int] = set()
    stores: list[ast.Name] = []
    for child in walk(nodes):
        if isinstance(child, ast.AugAssign):
            note_sum(child, summed, targets)
        elif isinstance(child, ast.Name) and isinstance(child.ctx, ast.Store):
            stores.append(child)
    return sums(summed, targets, stores)


def note_sum(node: ast.AST, summed: set[str], targets: set[int]) -> None:
    """`name += e` or `name -= e`: `name` is summed, and its target no plain store."""
    if (
        isinstance(node, ast.AugAssign)
        and isinstance(node.target, ast.Name)
        and isinstance(node.op, (ast.Add, ast.Sub))
    ):
        summed.add(node.target.id)
        targets.add(id(node.target))


def sums(summed: set[str], targets: set[int], stores: list[ast.Name]) -> set[str]:
    """The summed names that no other store under the same nodes binds."""
    if not summed:
        return summed
    return summed - {n.id for n in stores if id(n) not in targets}


NAME_ERRORS = frozenset(
    {"NameError", "UnboundLocalError", "Exception", "BaseException"}
)


def catches_name_error(kind: ast.expr | None) -> bool:
    return catches(kind, NAME_ERRORS)


def catches(kind: ast.expr | None, errors: frozenset[str]) -> bool:
    """Whether a handler of `kind` catches one of `errors` (a bare one: all)."""
    if kind is None:
        return True
    if isinstance(kind, ast.Tuple):
        return any(catches(e, errors) for e in kind.elts)
    return isinstance(kind, ast.Name) and kind.id in errors


NO_RETURN_NAMES = frozenset(
    {q.rsplit(".", 1)[-1] for q in NO_RETURN} | {"exit", "quit", "assert_never"}
)


def no_return(qualified: str | None) -> bool:
    return qualified is not None and (
        qualified in NO_RETURN or qualified.endswith(".assert_never")
    )


LITERAL_TEST = (
    ast.Constant,
    ast.BoolOp,
    ast.UnaryOp,
    ast.Compare,
    ast.boolop,
    ast.unaryop,
    ast.cmpop,
)


def literal_test(test: ast.expr) -> bool:
    """A test written with literals only (`True`, `not 0`, `1 and False`): Python
    takes one branch only. A name's value (`TYPE_CHECKING`, a flag) is not folded."""
    return all(isinstance(n, LITERAL_TEST) for n in ast.walk(test))


def truth_value(cond: A.Expr) -> bool | None:
    """The value of a condition made of constants (`True`, `1 != 0`, `not False`),
    or None."""
    if isinstance(cond, A.Bool):
        return cond.value
    if isinstance(cond, A.Unary) and cond.op == "not":
        inner = truth_value(cond.operand)
        return None if inner is None else not inner
    if isinstance(cond, A.Binary):
        if cond.op in ("and", "or"):
            left, right = truth_value(cond.left), truth_value(cond.right)
            decisive = cond.op == "or"  # True decides an `or`, False an `and`
            if decisive in (left, right):
                return decisive
            return None if left is None or right is None else not decisive
        if isinstance(cond.left, A.Num) and isinstance(cond.right, A.Num):
            a, b = cond.left.value, cond.right.value
            return {
                "==": a == b,
                "!=": a != b,
                "<": a < b,
                "<=": a <= b,
                ">": a > b,
                ">=": a >= b,
            }.get(cond.op)
    return None


# Constant kinds a store may have and keep a variable's kind.
KEEPS = {
    "bool": {"bool"},
    "int": {"int"},
    "float": {"int", "float"},
    "str": {"str"},
}


def constant_stores(
    node: ast.Assign | ast.AugAssign,
    found: dict[str, set[str]],
    constants: dict[str, Value],
) -> None:
    """The kind of constant each plain name target gets (`?` when not a constant):
    a literal, or a number of a constant table of literals (`constants`)."""
    value = node.value
    kind = "?"
    if isinstance(value, ast.Constant) and not isinstance(value.value, complex):
        kind = {bool: "bool", int: "int", float: "float", str: "str"}.get(
            type(value.value), "?"
        )
    else:  # `-1.0`, `moveBindings[key][1]`
        kind = plain_kind(value, constants)
    if isinstance(node, ast.AugAssign) and kind == "str":
        kind = "?"
    for target in assign_targets(node):
        if isinstance(target, ast.Name):
            found.setdefault(target.id, set()).add(kind)
        else:
            for inner in walk(target):
                if isinstance(inner, ast.Name):
                    found.setdefault(inner.id, set()).add("?")


def assign_targets(node: ast.Assign | ast.AugAssign) -> list[ast.expr]:
    return node.targets if isinstance(node, ast.Assign) else [node.target]


BINDERS = (
    ast.Import,
    ast.ImportFrom,
    ast.FunctionDef,
    ast.AsyncFunctionDef,
    ast.ClassDef,
    ast.ExceptHandler,
    ast.MatchAs,
    ast.MatchStar,
    ast.MatchMapping,
)


BINDER_KINDS = frozenset(BINDERS)


def bound_by(node: ast.AST) -> list[str]:
    """Names a node binds other than by an `ast.Name` target: imports, definitions,
    exception and pattern names."""
    if not isinstance(node, BINDERS):
        return []
    if isinstance(node, (ast.Import, ast.ImportFrom)):
        return [a.asname or a.name.split(".")[0] for a in node.names if a.name != "*"]
    name = node.rest if isinstance(node, ast.MatchMapping) else node.name
    return [name] if name else []


WHOLE = frozenset({writes.CHANGE, writes.ESCAPE})
PLAIN = (ast.Assign, ast.AnnAssign, ast.AugAssign, ast.Expr, ast.Pass)


def head_of(stmt: ast.stmt) -> ast.AST:
    """What a statement surely evaluates before it binds: an assignment's value, a
    `with`'s context managers."""
    if isinstance(stmt, (ast.Assign, ast.AnnAssign, ast.AugAssign)):
        return stmt.value or stmt
    if isinstance(stmt, (ast.With, ast.AsyncWith)):
        return ast.Tuple([i.context_expr for i in stmt.items], ast.Load())
    return ast.Pass()  # a compound statement may bind before it calls


def iteration_of(node: ast.While | ast.For | ast.AsyncFor) -> ast.stmt:
    """The loop without its `else`: what its iterations may change. A `break`
    leaves with that state, so a name the `else` alone binds is unbound there."""
    if not node.orelse:
        return node
    plain = copy.copy(node)
    plain.orelse = []
    return plain


def has_break(body: list[ast.stmt]) -> bool:
    """Does a `break` in `body` leave this loop (not a nested one)?"""
    todo: list[ast.AST] = list(body)
    while todo:
        node = todo.pop()
        kind = type(node)
        if kind is ast.Break:
            return True
        if kind in LOOPS:
            todo.extend(node.orelse)  # type: ignore[attr-defined]
        elif kind in COMPOUND:
            todo.extend(children(node))
    return False


LOOPS = frozenset({ast.For, ast.AsyncFor, ast.While})
# Statements with statements inside (a `break` cannot hide in an expression).
COMPOUND = frozenset(
    {ast.If, ast.With, ast.AsyncWith, *TRIES, ast.Match, ast.match_case}
    | {ast.ExceptHandler}
)


def surely_nonempty(node: ast.expr) -> bool:
    """An iterable that has an element on every path: a non-empty literal, or
    `range`, `enumerate`, `reversed`... of one."""
    if isinstance(node, (ast.List, ast.Tuple, ast.Set)):
        return any(not isinstance(e, ast.Starred) for e in node.elts)
    if isinstance(node, ast.Dict):
        return any(k is not None for k in node.keys)
    if isinstance(node, ast.Constant):
        return isinstance(node.value, (str, bytes)) and len(node.value) > 0
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
        name, args = node.func.id, node.args
        if node.keywords or any(isinstance(a, ast.Starred) for a in args):
            return False
        if name == "range" and 1 <= len(args) <= 2:
            bounds = [int_constant(a) for a in args]
            if any(b is None for b in bounds):
                return False
            low, high = (0, bounds[0]) if len(bounds) == 1 else bounds
            return low is not None and high is not None and low < high
        if name in ("enumerate", "reversed", "sorted", "list", "tuple") and args:
            return surely_nonempty(args[0])
        if name == "zip" and args:
            return all(surely_nonempty(a) for a in args)
    return False


def int_constant(node: ast.expr) -> int | None:
    if isinstance(node, ast.Constant) and type(node.value) is int:
        return node.value
    if (
        isinstance(node, ast.UnaryOp)
        and isinstance(node.op, ast.USub)
        and isinstance(node.operand, ast.Constant)
        and type(node.operand.value) is int
    ):
        return -node.operand.value
    return None


def augmented_op(node: ast.AugAssign) -> ast.BinOp | None:
    """`x += d` as the expression `x + d`, at the statement (kept in
    `Program.augmented`)."""
    load: ast.expr
    if isinstance(node.target, ast.Name):
        load = ast.Name(node.target.id, ast.Load())
    elif isinstance(node.target, ast.Attribute):
        load = ast.Attribute(node.target.value, node.target.attr, ast.Load())
    elif isinstance(node.target, ast.Subscript):  # `ranges[i] += d`
        load = ast.Subscript(node.target.value, node.target.slice, ast.Load())
    else:
        return None
    combined = ast.BinOp(ast.copy_location(load, node.target), node.op, node.value)
    return ast.copy_location(combined, node)
