"""Constants: module and class names bound once, to a constant, and never rebound.

Such a name is that value in every function and method and in every refinement
(`MAX_SPEED = 0.22`, `TWO_PI = 2 * math.pi`, `LIMITS = (0.22, 2.84)`, a teleop node's
`moveBindings = {'i': (1, 0, 0, 0), ...}`). Two halves:

- `scan` decides from the syntax, before any code is interpreted, which names are
  bound exactly once and changed nowhere else: no second binding in their scope, no
  `global` declaration in a function, for a class attribute no `obj.name = ...` and no
  other class body binding it (a subclass could override it; `Final` forbids that),
  and, for a dict or list, no use that is not a read (`d[k]`, `k in d`, `d.get(k)`,
  `len(d)`, `for x in d`): `d[k] = v`, `d.update(...)` or passing `d` to a function
  rules it out.
- the interpreter records the value such a name is bound to; `is_constant` says whether
  it is built from literals only, which makes it a constant.

Anything else about module names (a `rospy.get_param` result, say) stays unknown, and
so does a constant's value in a file that another module might rebind: that is out of
sight of a per-file analysis.
"""

from __future__ import annotations

import ast
import weakref
from collections import Counter
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field

from robotfix.analysis.index import FileIndex
from robotfix.analysis.values import CONTAINERS, Value
from robotfix.annotations import ast as A
from robotfix.astwalk import Mentions, children, names_under

FINAL = frozenset({"typing.Final", "typing_extensions.Final"})
# Methods and builtins that only read a dict or list they are given.
READING_METHODS = frozenset(
    {"get", "keys", "values", "items", "copy", "index", "count"}
)
READING_CALLS = frozenset(
    {"len", "min", "max", "sorted", "list", "tuple", "set", "frozenset", "dict"}
    | {"sum", "enumerate", "reversed", "iter", "any", "all", "zip", "print", "str"}
)
SCALARS = frozenset({"int", "float", "bool", "str"})
# Statements with statement bodies (`try` also has handlers).
_BLOCK_NAMES = "If For AsyncFor While With AsyncWith Try TryStar"  # TryStar: 3.11
BLOCKS = frozenset(
    getattr(ast, name) for name in _BLOCK_NAMES.split() if hasattr(ast, name)
)


@dataclass
class ConstantNames:
    """Which names may hold constants (`scan`), and their values once bound."""

    module: set[str] = field(default_factory=set)  # bound once at module level
    changed_globals: set[str] = field(default_factory=set)  # `global x` somewhere
    read_only: set[str] = field(default_factory=set)  # dict/list names only read
    classes: dict[str, set[str]] = field(default_factory=dict)  # class -> attributes
    values: dict[str, Value] = field(default_factory=dict)  # module name -> value
    class_values: dict[str, dict[str, Value]] = field(default_factory=dict)
    class_attrs: set[str] = field(default_factory=set)  # names in class_values

    def record(self, scope_kind: str, scope_name: str, name: str, value: Value) -> None:
        """The interpreter binds `name` in a module or top-level class body."""
        if scope_kind == "module" and name in self.module:
            self.values.setdefault(name, value)
        elif scope_kind == "class" and name in self.classes.get(scope_name, ()):
            self.class_values.setdefault(scope_name, {}).setdefault(name, value)
            self.class_attrs.add(name)

    def module_constants(self) -> dict[str, Value]:
        return {
            name: value
            for name, value in self.values.items()
            if is_constant(value)
            and (value.kind not in ("list", "dict") or name in self.read_only)
        }

    def class_constant(self, class_name: str, attr: str) -> Value | None:
        """A scalar or tuple (a class's dicts and lists may be changed through
        `self.table[k] = v`, which `scan` does not follow)."""
        found = self.class_values.get(class_name, {}).get(attr)
        if found is None or found.kind in ("list", "dict"):
            return None
        return found if is_constant(found) else None


def is_constant(value: Value) -> bool:
    """Built from literals only: a number, bool or str without unknowns, or a tuple
    (or read-only list or dict) of such."""
    if value.uninit is not None:
        return False
    if value.kind in SCALARS:
        return value.term is not None and not A.syms(value.term)
    if value.kind in CONTAINERS and value.elements is not None:
        parts = [*value.elements, *(value.keys or ())]
        return all(is_constant(p) for p in parts)
    return False


def scan(
    tree: ast.Module,
    index: FileIndex,
    qualname: Callable[[ast.expr], str | None],
    walrus: bool = True,
    lines: list[str] | None = None,
    keep: bool = False,
) -> ConstantNames:
    """`walrus`: whether the source may contain `:=` (False makes the scan cheaper);
    `lines`: the tree's source lines, if known (the uses of a table are looked for
    only in the statements whose lines name it).

    `keep` (a module summarised for its importers, whose tree its own check may
    take): the scan is kept for the next scan of the same tree, which takes it
    (222 of 1,257 scans on corpus25 were of a tree scanned before). It is taken
    only for the same index and `walrus`, and if `qualname` still names every
    annotation it asked about as it did; it holds no values (the interpreter
    records into the scan it is given)."""
    kept = _KEPT.pop(tree, None) if _KEPT else None
    if (
        kept is not None
        and kept[0] is index
        and kept[1] == walrus
        and all(qualname(node) == name for node, name in kept[2])
    ):
        return kept[3]
    if not keep:
        return _scan(tree, index, qualname, walrus, lines)
    asked: list[tuple[ast.expr, str | None]] = []

    def recording(node: ast.expr) -> str | None:
        name = qualname(node)
        asked.append((node, name))
        return name

    found = _scan(tree, index, recording, walrus, lines)
    _KEPT[tree] = (index, walrus, asked, _copy(found))
    return found


# tree -> (its index, `walrus`, what `qualname` answered, a scan without values)
_KEPT: weakref.WeakKeyDictionary[
    ast.Module,
    tuple[FileIndex, bool, list[tuple[ast.expr, str | None]], ConstantNames],
] = weakref.WeakKeyDictionary()


def _copy(found: ConstantNames) -> ConstantNames:
    """The syntax's half of a scan, in sets of its own."""
    return ConstantNames(
        module=set(found.module),
        changed_globals=set(found.changed_globals),
        read_only=set(found.read_only),
        classes={k: set(v) for k, v in found.classes.items()},
    )


def _scan(
    tree: ast.Module,
    index: FileIndex,
    qualname: Callable[[ast.expr], str | None],
    walrus: bool,
    lines: list[str] | None,
) -> ConstantNames:
    found = ConstantNames()
    for scope_id, names in index.scopes.items():
        if scope_id != id(tree):
            found.changed_globals |= names.global_names
    counts = _bindings(tree.body, walrus)
    found.module = {n for n, c in counts.items() if c == 1} - found.changed_globals
    tables = {
        target.id
        for target, value in _simple_assignments(tree.body)
        if isinstance(value, (ast.Dict, ast.List))
        and target.id in found.module
        and _literal_display(value)
    }
    if tables:
        found.read_only = _only_read(tree, tables, lines)
    classes = [n for n in tree.body if isinstance(n, ast.ClassDef)]
    if classes:
        _scan_classes(found, classes, index, qualname, walrus)
    return found


def _scan_classes(
    found: ConstantNames,
    classes: list[ast.ClassDef],
    index: FileIndex,
    qualname: Callable[[ast.expr], str | None],
    walrus: bool,
) -> None:
    per_class = {id(c): _bindings(c.body, walrus) for c in classes}
    everywhere: Counter[str] = Counter()
    for counts in per_class.values():
        everywhere.update(counts.keys())
    set_by_name = _setattr_names(index)
    if set_by_name is None:  # setattr(obj, name, ...): any attribute may change
        return
    changed = index.attribute_stores | set_by_name
    for cls in classes:
        final = {
            target
            for annotation, target in index.scopes[id(cls)].annotated
            if _is_final(annotation, qualname)
        }
        found.classes[cls.name] = {
            name
            for name, count in per_class[id(cls)].items()
            if count == 1
            and (everywhere[name] == 1 or name in final)
            and name not in changed
        }


def _is_final(annotation: ast.expr, qualname: Callable[[ast.expr], str | None]) -> bool:
    node = annotation.value if isinstance(annotation, ast.Subscript) else annotation
    return qualname(node) in FINAL


def _setattr_names(index: FileIndex) -> set[str] | None:
    """Attribute names `setattr` is called with; None if one is not a literal."""
    names: set[str] = set()
    for call in index.setattrs:
        if len(call.args) < 2:
            return None
        name = call.args[1]
        if not (isinstance(name, ast.Constant) and isinstance(name.value, str)):
            return None
        names.add(name.value)
    return names


def _bindings(body: list[ast.stmt], walrus: bool) -> Counter[str]:
    """How often each name is bound in a module or class body (not counting what
    functions and classes inside it bind in their own bodies). Only statements bind,
    but for `:=`, which only a walk of every expression finds."""
    if walrus:
        return _bindings_everywhere(body)
    counts: Counter[str] = Counter()
    todo: list[ast.stmt] = list(body)
    while todo:
        node = todo.pop()
        kind = type(node)
        if kind is ast.Expr or kind is ast.Pass or kind is ast.Return:
            continue
        if kind is ast.Assign:
            for target in node.targets:  # type: ignore[attr-defined]
                _count_targets(target, counts)
        elif kind is ast.AnnAssign:
            if node.value is not None:  # type: ignore[attr-defined]
                _count_targets(node.target, counts)  # type: ignore[attr-defined]
        elif kind is ast.AugAssign or kind is ast.For or kind is ast.AsyncFor:
            _count_targets(node.target, counts)  # type: ignore[attr-defined]
        elif kind is ast.Delete:
            for target in node.targets:  # type: ignore[attr-defined]
                _count_targets(target, counts)
        elif kind is ast.With or kind is ast.AsyncWith:
            for item in node.items:  # type: ignore[attr-defined]
                if item.optional_vars is not None:
                    _count_targets(item.optional_vars, counts)
        elif kind in (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef):
            counts[node.name] += 1  # type: ignore[attr-defined]
            continue
        elif kind is ast.Import or kind is ast.ImportFrom:
            for alias in node.names:  # type: ignore[attr-defined]
                counts[alias.asname or alias.name.split(".")[0]] += 1
            continue
        elif kind is ast.Match:
            for case in node.cases:  # type: ignore[attr-defined]
                counts.update(_bindings_everywhere([case.pattern]))
                todo.extend(case.body)
            continue
        elif kind.__name__ == "TypeAlias":  # type X = ... (Python 3.12)
            counts[node.name.id] += 1  # type: ignore[attr-defined]
        if kind in BLOCKS:
            for block in ("body", "orelse", "finalbody"):
                todo.extend(getattr(node, block, ()))
            for handler in getattr(node, "handlers", ()):
                if handler.name:
                    counts[handler.name] += 1
                todo.extend(handler.body)
    return counts


def _count_targets(target: ast.expr, counts: Counter[str]) -> None:
    if isinstance(target, ast.Name):
        counts[target.id] += 1
    elif isinstance(target, (ast.Tuple, ast.List)):
        for element in target.elts:
            _count_targets(element, counts)
    elif isinstance(target, ast.Starred):
        _count_targets(target.value, counts)


def bound_names(nodes: Iterable[ast.AST]) -> set[str]:
    """The names `nodes` bind in their own scope (not in functions they define)."""
    return set(_bindings_everywhere(nodes))


def _bindings_everywhere(body: Iterable[ast.AST]) -> Counter[str]:
    counts: Counter[str] = Counter()
    todo = list(body)
    while todo:
        node = todo.pop()
        kind = type(node)
        if kind is ast.Name:
            if node.ctx.__class__ is not ast.Load:  # type: ignore[attr-defined]
                counts[node.id] += 1  # type: ignore[attr-defined]
            continue
        if kind in (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef):
            counts[node.name] += 1  # type: ignore[attr-defined]
            continue
        if kind is ast.Lambda:
            continue
        if kind is ast.Import or kind is ast.ImportFrom:
            for alias in node.names:  # type: ignore[attr-defined]
                counts[alias.asname or alias.name.split(".")[0]] += 1
            continue
        bound = getattr(node, "name", None) or getattr(node, "rest", None)
        if isinstance(bound, str):  # except ... as name, match captures
            counts[bound] += 1
        todo.extend(children(node))
    return counts


def _simple_assignments(
    body: Iterable[ast.stmt],
) -> Iterable[tuple[ast.Name, ast.expr]]:
    for statement in body:
        if isinstance(statement, ast.Assign) and len(statement.targets) == 1:
            target, value = statement.targets[0], statement.value
        elif isinstance(statement, ast.AnnAssign) and statement.value is not None:
            target, value = statement.target, statement.value
        else:
            continue
        if isinstance(target, ast.Name):
            yield target, value


def _literal_display(node: ast.expr) -> bool:
    """Whether a display may be a constant: made of literals, names, arithmetic and
    nested displays (no calls, lambdas or comprehensions), so that no walk of the
    file is spent on a table of callbacks."""
    todo: list[ast.AST] = [node]
    while todo:
        current = todo.pop()
        kind = type(current)
        if kind is ast.Constant or kind is ast.Name:
            continue
        if kind is ast.Dict:
            todo.extend(k for k in current.keys if k is not None)  # type: ignore[attr-defined]
            todo.extend(current.values)  # type: ignore[attr-defined]
        elif kind in (ast.Tuple, ast.List):
            todo.extend(current.elts)  # type: ignore[attr-defined]
        elif kind is ast.UnaryOp:
            todo.append(current.operand)  # type: ignore[attr-defined]
        elif kind is ast.BinOp:
            todo += [current.left, current.right]  # type: ignore[attr-defined]
        elif kind is ast.Attribute:
            todo.append(current.value)  # type: ignore[attr-defined]
        else:
            return False
    return True


def _only_read(
    tree: ast.Module, names: set[str], lines: list[str] | None = None
) -> set[str]:
    """Those of `names` whose every use reads the dict or list and nothing else
    (given the source `lines`, only statements that name one are walked)."""
    keep = Mentions(lines, names) if lines is not None else None
    changed = {
        name.id
        for parent, name in names_under(tree, keep)
        if name.id in names and not _reads(parent, name)
    }
    return names - changed


def _reads(parent: ast.AST, name: ast.Name) -> bool:
    if isinstance(name.ctx, ast.Store):
        return True  # the one binding (`scan` counted it)
    if isinstance(name.ctx, ast.Del):
        return False
    if isinstance(parent, ast.Subscript):
        return parent.value is name and isinstance(parent.ctx, ast.Load)
    if isinstance(parent, ast.Attribute):
        return parent.attr in READING_METHODS
    if isinstance(parent, ast.Compare):
        return True
    if isinstance(parent, ast.Call):
        func = parent.func
        return isinstance(func, ast.Name) and func.id in READING_CALLS
    if isinstance(parent, (ast.For, ast.AsyncFor, ast.comprehension)):
        return parent.iter is name
    return False


def plain_kind(node: ast.expr, constants: dict[str, Value]) -> str:
    """The kind (`int`, `float`) of the number with no unit that `node` surely gives,
    as a literal does (it takes the unit of its context): a number literal, or a
    scalar of a constant table of literals (`moveBindings[key][1]`); `?` otherwise."""
    depth = 0
    while isinstance(node, ast.Subscript) and not isinstance(node.slice, ast.Slice):
        node, depth = node.value, depth + 1
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub | ast.UAdd):
        return plain_kind(node.operand, constants) if depth == 0 else "?"
    if isinstance(node, ast.Constant):
        kind = type(node.value).__name__
        return kind if depth == 0 and kind in ("int", "float") else "?"
    if isinstance(node, ast.Name) and node.id in constants:
        return _leaf_kind(constants[node.id], depth)
    return "?"


def _leaf_kind(value: Value, depth: int) -> str:
    """The kind of every scalar `depth` subscripts into `value`, if each is a
    number literal with no unit; `?` otherwise."""
    if depth == 0:
        plain = value.kind in ("int", "float") and value.literal and value.unit is None
        return value.kind if plain else "?"
    if value.kind not in CONTAINERS or not value.elements:
        return "?"
    kinds = {_leaf_kind(element, depth - 1) for element in value.elements}
    return "?" if "?" in kinds else ("float" if "float" in kinds else "int")
