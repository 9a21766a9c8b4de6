"""One walk over a module's AST that records what every scope binds and declares,
the imports, the calls (with the class they sit in) and `self.x: Annotated[...]`
declarations. Everything else reads this index instead of walking the tree again.
"""

from __future__ import annotations

import ast
import weakref
from collections import Counter
from dataclasses import dataclass, field

from robotfix.astwalk import FIELDS, children, fields, walk

FUNCTIONS = (ast.FunctionDef, ast.AsyncFunctionDef)
COMPREHENSIONS = (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)


@dataclass
class ScopeNames:
    local_names: set[str] = field(default_factory=set)
    global_names: set[str] = field(default_factory=set)
    annotated: list[tuple[ast.expr, str]] = field(
        default_factory=list
    )  # (annotation, target)


@dataclass
class FileIndex:
    scopes: dict[int, ScopeNames] = field(default_factory=dict)  # id(scope node) ->
    imports: dict[str, str] = field(default_factory=dict)  # local name -> qualified
    # local name -> (level, module, name) of `from ..module import name`
    relative: dict[str, tuple[int, str | None, str]] = field(default_factory=dict)
    star_import: bool = False
    calls: list[tuple[str | None, ast.Call]] = field(
        default_factory=list
    )  # (class, call)
    # (class name, attribute, annotation) for `self.x: Annotated[...]` in methods
    attributes: list[tuple[str, str, ast.expr]] = field(default_factory=list)
    class_scopes: set[int] = field(default_factory=set)
    # names `x` of attributes stored or deleted anywhere (`obj.x = ...`, `del obj.x`)
    attribute_stores: set[str] = field(default_factory=set)
    # module names bound once, at top level, to a type form or a string: type aliases
    # (`Speed = Annotated[...]`, `Speed: TypeAlias = ...`, `type Speed = ...`) and
    # metadata strings (`SPEC = "Unit('m')"`)
    aliases: dict[str, ast.expr] = field(default_factory=dict)
    # how often each attribute name is a part of an assignment's target (`x.a = `,
    # `x.a += `, `x[o.i] = `), as `frames.facts` counts them
    assigned: Counter[str] = field(default_factory=Counter)
    # scopes `index_scope` indexed on demand, kept apart from `scopes` so that the
    # index stays as `index_module` built it: id(node) -> (node, its names)
    extra: dict[int, tuple[ast.AST, ScopeNames]] = field(default_factory=dict)
    # how often each name is stored or deleted anywhere in the tree (`x = `, `for x`,
    # `del x`, `(x := ...)`, annotations included): `Name` nodes only, as a walk of
    # the whole tree counts them (`parameters._module_constants`)
    stores: Counter[str] = field(default_factory=Counter)
    # id(function or lambda) -> its own `return` statements, in the order a
    # stack walk of it meets them; the functions that `yield` (generators)
    returns: dict[int, list[ast.Return]] = field(default_factory=dict)
    generators: set[int] = field(default_factory=set)
    # every import statement, nested ones too
    import_statements: list[ast.Import | ast.ImportFrom] = field(default_factory=list)


Todo = list[tuple[ast.AST, int, str | None, str | None]]


# each tree's index, built once and shared by everything that reads it in a run
# (the module's summary, its parameter summary and its check)
_INDEXES: weakref.WeakKeyDictionary[ast.Module, FileIndex] = weakref.WeakKeyDictionary()


def built(tree: ast.Module) -> FileIndex | None:
    """The index of `tree` if one was built (none is built here)."""
    return _INDEXES.get(tree)


def index_of(tree: ast.Module) -> FileIndex:
    """The index of `tree`, built on the first request. Readers must not change it
    (`index_scope` keeps what it adds apart)."""
    index = _INDEXES.get(tree)
    if index is None:
        index = _INDEXES[tree] = index_module(tree)
    return index


def index_module(tree: ast.Module) -> FileIndex:
    index = FileIndex()
    index.scopes[id(tree)] = ScopeNames()
    # (node, owning scope node id, enclosing top-level class, method's self name)
    _drain(index, [(node, id(tree), None, None) for node in tree.body], id(tree))
    index.aliases = _aliases(tree)
    return index


ALIAS_FORMS = (ast.Subscript, ast.BinOp, ast.Name, ast.Attribute, ast.Constant)


def _aliases(tree: ast.Module) -> dict[str, ast.expr]:
    """Top-level `Name = <type form or string>`, kept only when the name is bound by
    no other top-level statement (a rebound name is no alias)."""
    found: dict[str, ast.expr] = {}
    seen: set[str] = set()
    for statement in tree.body:
        target: ast.expr | None = None
        value: ast.expr | None = None
        if isinstance(statement, ast.Assign) and len(statement.targets) == 1:
            target, value = statement.targets[0], statement.value
        elif isinstance(statement, ast.AnnAssign):
            target, value = statement.target, statement.value
        elif type(statement).__name__ == "TypeAlias":  # 3.12 `type X = ...`
            target = getattr(statement, "name", None)
            value = getattr(statement, "value", None)
        else:
            for name in _bound(statement):
                seen.add(name)
                found.pop(name, None)
            continue
        if not isinstance(target, ast.Name):
            continue
        name = target.id
        if name in seen:
            found.pop(name, None)
        elif isinstance(value, ALIAS_FORMS) and _type_like(value):
            found[name] = value
        seen.add(name)
    return found


def _bound(statement: ast.stmt) -> set[str]:
    """Module names another top-level statement binds."""
    if isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
        return {statement.name}
    if isinstance(statement, (ast.Import, ast.ImportFrom)):
        return {(a.asname or a.name).split(".")[0] for a in statement.names}
    return {
        child.id
        for child in ast.walk(statement)
        if isinstance(child, ast.Name) and not isinstance(child.ctx, ast.Load)
    }


def _type_like(node: ast.expr) -> bool:
    if isinstance(node, ast.Constant):
        return isinstance(node.value, str)
    if isinstance(node, ast.BinOp):
        return isinstance(node.op, ast.BitOr)
    return True


def index_scope(index: FileIndex, node: ast.AST) -> ScopeNames:
    """Index a scope the module walk did not reach (a node of another tree). The
    walk goes into a throwaway index; only the scopes it finds are kept, in
    `index.extra`, so the shared index's calls, stores and scopes stay as built."""
    known = index.extra.get(id(node))
    if known is not None:
        return known[1]
    scratch = FileIndex()
    outside = -id(node)  # a throwaway owner for the node itself
    scratch.scopes[outside] = ScopeNames()
    _drain(scratch, [(node, outside, None, None)], outside)
    del scratch.scopes[outside]
    found = scratch.scopes.get(id(node), ScopeNames())
    index.extra[id(node)] = (node, found)
    return found


def _drain(index: FileIndex, todo: Todo, root: int) -> None:
    scopes, pop, append = index.scopes, todo.pop, todo.append
    stores = index.stores
    known = FIELDS  # node class -> fields that may hold nodes
    node_class = ast.AST
    while todo:
        node, owner, cls, self_name = pop()
        kind = type(node)
        if kind is ast.Name:
            if node.ctx.__class__ is not ast.Load:  # type: ignore[attr-defined]
                scopes[owner].local_names.add(node.id)  # type: ignore[attr-defined]
                stores[node.id] += 1  # type: ignore[attr-defined]
            continue
        if kind in FUNCTIONS or kind is ast.Lambda:
            _enter_function(index, node, owner, cls, self_name, todo)  # type: ignore[arg-type]
            continue
        if kind is ast.ClassDef:
            assert isinstance(node, ast.ClassDef)
            scopes[owner].local_names.add(node.name)
            scopes[id(node)] = ScopeNames()
            index.class_scopes.add(id(node))
            top = node.name if owner == root else cls
            todo.extend(
                (d, owner, cls, self_name) for d in [*node.decorator_list, *node.bases]
            )
            todo.extend((d, owner, cls, self_name) for d in node.keywords)
            todo.extend((s, id(node), top, None) for s in node.body)
            continue
        if kind in COMPREHENSIONS:  # a scope of its own; its first iterable is not
            inner = id(node)
            scopes[inner] = ScopeNames()
            first = node.generators[0]  # type: ignore[attr-defined]
            append((first.iter, owner, cls, self_name))
            rest = [first.target, *first.ifs, *node.generators[1:]]  # type: ignore[attr-defined]
            rest += [c for c in children(node) if not isinstance(c, ast.comprehension)]
            todo.extend((child, inner, cls, self_name) for child in rest)
            continue
        if kind is ast.Call:
            index.calls.append((cls, node))  # type: ignore[arg-type]
        elif kind is ast.Attribute:
            if node.ctx.__class__ is not ast.Load:  # type: ignore[attr-defined]
                index.attribute_stores.add(node.attr)  # type: ignore[attr-defined]
        elif kind is ast.Constant:
            continue  # no node under it
        elif kind is ast.Return:
            index.returns.setdefault(owner, []).append(node)  # type: ignore[arg-type]
        elif kind is ast.Yield or kind is ast.YieldFrom:
            index.generators.add(owner)
        elif kind in _RECORDED:
            _record(index, scopes[owner], node, kind, cls, self_name)
        names = known.get(kind)
        if names is None:
            names = fields(kind)
        for name in names:  # not contexts, operators and strings
            value = getattr(node, name, None)
            if value.__class__ is list:
                for v in value:
                    if isinstance(v, node_class):
                        append((v, owner, cls, self_name))
            elif isinstance(value, node_class):
                append((value, owner, cls, self_name))


# the statements and nodes `_record` reads (besides walking under them)
_RECORDED = frozenset(
    {ast.Assign, ast.AugAssign, ast.AnnAssign, ast.Import, ast.ImportFrom}
    | {ast.Global, ast.Nonlocal, ast.ExceptHandler}
)


def _record(
    index: FileIndex,
    names: ScopeNames,
    node: ast.AST,
    kind: type,
    cls: str | None,
    self_name: str | None,
) -> None:
    if kind is ast.Assign or kind is ast.AugAssign or kind is ast.AnnAssign:
        targets = getattr(node, "targets", None) or [node.target]  # type: ignore[attr-defined]
        for part in walk(targets):
            if type(part) is ast.Attribute:
                index.assigned[part.attr] += 1
    if kind is ast.Import or kind is ast.ImportFrom:
        index.import_statements.append(node)  # type: ignore[arg-type]
        _record_import(index, names, node)  # type: ignore[arg-type]
    elif kind is ast.Global or kind is ast.Nonlocal:
        names.global_names.update(node.names)  # type: ignore[attr-defined]
    elif kind is ast.ExceptHandler and node.name:  # type: ignore[attr-defined]
        names.local_names.add(node.name)  # type: ignore[attr-defined]
    elif kind is ast.AnnAssign:
        _record_annotation(index, names, node, cls, self_name)  # type: ignore[arg-type]


def _enter_function(
    index: FileIndex,
    node: ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda,
    owner: int,
    cls: str | None,
    self_name: str | None,
    todo: list[tuple[ast.AST, int, str | None, str | None]],
) -> None:
    outer = index.scopes[owner]
    inner = index.scopes[id(node)] = ScopeNames()
    args = node.args
    every = [*args.posonlyargs, *args.args, *args.kwonlyargs]
    every += [a for a in (args.vararg, args.kwarg) if a is not None]
    defaults = [*args.defaults, *[d for d in args.kw_defaults if d is not None]]
    todo.extend((d, owner, cls, self_name) for d in defaults)
    for arg in every:
        inner.local_names.add(arg.arg)
        if arg.annotation is not None:
            inner.annotated.append((arg.annotation, arg.arg))
            _count_stores(index, arg.annotation)
    returns = getattr(node, "returns", None)
    if returns is not None:
        _count_stores(index, returns)
    if isinstance(node, ast.Lambda):
        todo.append((node.body, id(node), cls, None))
        return
    outer.local_names.add(node.name)
    todo.extend((d, owner, cls, self_name) for d in node.decorator_list)
    is_method = owner in index.class_scopes
    method_self = args.args[0].arg if is_method and args.args else None
    todo.extend((s, id(node), cls, method_self) for s in node.body)


def _count_stores(index: FileIndex, annotation: ast.expr) -> None:
    """The names stored in an annotation the walk does not enter (`:=`, or a
    comprehension's target, in a parameter's or a return's annotation)."""
    if type(annotation) is ast.Name or type(annotation) is ast.Constant:
        return
    for node in walk(annotation):
        if type(node) is ast.Name and not isinstance(node.ctx, ast.Load):
            index.stores[node.id] += 1


def _record_import(
    index: FileIndex, names: ScopeNames, node: ast.Import | ast.ImportFrom
) -> None:
    for alias in node.names:
        if alias.name == "*":
            index.star_import = True
            continue
        local = alias.asname or alias.name.split(".")[0]
        names.local_names.add(local)
        if isinstance(node, ast.Import):
            index.imports[local] = alias.name if alias.asname else local
        elif node.module and not node.level:
            index.imports[local] = f"{node.module}.{alias.name}"
        elif node.level:
            index.relative[local] = (node.level, node.module, alias.name)


def _record_annotation(
    index: FileIndex,
    names: ScopeNames,
    node: ast.AnnAssign,
    cls: str | None,
    self_name: str | None,
) -> None:
    target = node.target
    if isinstance(target, ast.Name):
        names.annotated.append((node.annotation, target.id))
    elif (
        isinstance(target, ast.Attribute)
        and isinstance(target.value, ast.Name)
        and self_name is not None
        and target.value.id == self_name
        and cls is not None
    ):
        index.attributes.append((cls, target.attr, node.annotation))
