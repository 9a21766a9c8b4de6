"""One walk over a module's AST that records what every scope binds and declares,
the imports, the calls (with the class they sit in) and `self.x: Annotated[...]`
declarations. Everything else reads this index instead of walking the tree again.
"""

from __future__ import annotations

import ast
import weakref
from collections import Counter
from dataclasses import dataclass, field
from typing import Any

from robotfix.astwalk import FIELDS, children, fields, walk

FUNCTIONS = (ast.FunctionDef, ast.AsyncFunctionDef)
COMPREHENSIONS = (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)


@dataclass
class ScopeNames:
    """One scope's names: bound here, declared global, and annotated targets."""

    local_names: set[str] = field(default_factory=set)
    global_names: set[str] = field(default_factory=set)
    annotated: list[tuple[ast.expr, str]] = field(
        default_factory=list
    )  # (annotation, target)


@dataclass
class FileIndex:
    """What one walk of a file finds: scopes, imports, calls, annotated attributes."""

    scopes: dict[int, ScopeNames] = field(default_factory=dict)  # id(scope node) ->
    imports: dict[str, str] = field(default_factory=dict)  # local name -> qualified
    # local name -> (level, module, name) of `from ..module import name`
    relative: dict[str, tuple[int, str | None, str]] = field(default_factory=dict)
    star_import: bool = False
    calls: list[tuple[str | None, ast.Call]] = field(
        default_factory=list
    )  # (class, call)
    # the calls of a function named `setattr` (any attribute they name may change)
    setattrs: list[ast.Call] = field(default_factory=list)
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
    # of those, the assignments of `None` to an attribute (`self.a = None`)
    assigned_none: Counter[str] = field(default_factory=Counter)
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


# what a walk is in: the owning scope node's id, the enclosing top-level class and
# the method's `self` name; on the walk's stack it marks where a nested scope ends
Where = tuple[int, str | None, str | None]
Todo = list[ast.AST | Where]


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
    _drain(index, list(tree.body), (id(tree), None, None), id(tree))
    index.aliases = _aliases(tree)
    return index


ALIAS_FORMS = (ast.Subscript, ast.BinOp, ast.Name, ast.Attribute, ast.Constant)


def _aliases(tree: ast.Module) -> dict[str, ast.expr]:
    """Top-level `Name = <type form or string>`, kept only when the name is bound by
    no other top-level statement (a rebound name is no alias). The other
    statements' names are looked for only when there is an alias to lose."""
    found: dict[str, ast.expr] = {}
    seen: set[str] = set()
    others: list[ast.stmt] = []  # statements that bind otherwise
    for statement in tree.body:
        target: ast.expr | None = None
        value: ast.expr | None = None
        kind = type(statement)
        if kind is ast.Assign and len(statement.targets) == 1:  # type: ignore[attr-defined]
            target, value = statement.targets[0], statement.value  # type: ignore[attr-defined]
        elif kind is ast.AnnAssign:
            target, value = statement.target, statement.value  # type: ignore[attr-defined]
        elif kind.__name__ == "TypeAlias":  # 3.12 `type X = ...` (named: not in 3.11)
            target = getattr(statement, "name", None)
            value = getattr(statement, "value", None)
        else:
            others.append(statement)
            continue
        if type(target) is not ast.Name:
            continue
        name = target.id
        if name in seen:
            found.pop(name, None)
        elif isinstance(value, ALIAS_FORMS) and _type_like(value):
            found[name] = value
        seen.add(name)
    for statement in others if found else ():
        for name in _bound(statement):
            found.pop(name, None)
    return found


def _bound(statement: ast.stmt) -> set[str]:
    """Module names another top-level statement binds."""
    if isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
        return {statement.name}
    if isinstance(statement, (ast.Import, ast.ImportFrom)):
        return {(a.asname or a.name).split(".")[0] for a in statement.names}
    return {
        child.id
        for child in walk(statement)
        if type(child) is ast.Name and type(child.ctx) is not ast.Load
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
    _drain(scratch, [node], (outside, None, None), outside)
    del scratch.scopes[outside]
    found = scratch.scopes.get(id(node), ScopeNames())
    index.extra[id(node)] = (node, found)
    return found


def _drain(index: FileIndex, todo: Todo, where: Where, root: int) -> None:
    """Walk `todo` (nodes of the scope `where`, last first). A nested scope's nodes
    go on the same stack above a marker, the `Where` to go back to, so that the
    nodes are met in one stack walk's order (that of the calls, returns and
    imports recorded); `Name`s and `Constant`s are read as they are met under
    their parent, never put on the stack."""
    scopes, pop, append, extend = index.scopes, todo.pop, todo.append, todo.extend
    stores, calls, assigned = index.stores, index.calls, index.assigned
    attribute_stores, attribute_class = index.attribute_stores, ast.Attribute
    known = FIELDS  # node class -> fields that may hold nodes
    node_class, name_class, constant_class = ast.AST, ast.Name, ast.Constant
    load, special_of = ast.Load, _SPECIAL.get
    owner, cls, self_name = where
    local_names = scopes[owner].local_names
    node: Any  # a node, or the marker at the end of a nested scope
    v: Any
    while todo:
        node = pop()
        kind = type(node)
        special = special_of(kind)
        if special is not None:  # (the tests in the order of their frequency)
            if special is _CALL:
                calls.append((cls, node))
                func = node.func
                if type(func) is name_class and func.id == "setattr":
                    index.setattrs.append(node)
                names = _CALLED  # a keyword's value is stacked in its place below
                keywords = node.keywords
            elif special is _ASSIGN:
                targets = node.targets
                for part in targets:  # most are a name or `self.x`
                    while type(part) is attribute_class:
                        assigned[part.attr] += 1
                        part = part.value
                    if type(part) is not name_class:
                        _count_assigned(index, part)
                v = node.value
                if type(v) is constant_class and v.value is None:
                    _count_none(index, targets)
            elif special is _EXPRESSION:  # its one child in its place
                append(node.value)
                continue
            elif special is _SCOPE:
                where = _enter(index, node, owner, cls, self_name, root, todo)
                owner, cls, self_name = where
                local_names = scopes[owner].local_names
                continue
            elif special is _MARK:  # the end of a nested scope: back to its parent
                owner, cls, self_name = node
                local_names = scopes[owner].local_names
                continue
            elif special is _NAME:  # one a scope's own statement holds directly
                if type(node.ctx) is not load:
                    local_names.add(node.id)
                    stores[node.id] += 1
                continue
            elif special is _CONSTANT:
                continue
            elif special is _ATTRIBUTE:  # one a scope's own statement holds
                if type(node.ctx) is not load:
                    attribute_stores.add(node.attr)
            elif special is _RETURN:
                index.returns.setdefault(owner, []).append(node)
            elif special is _YIELD:
                index.generators.add(owner)
            elif special is _IMPORT:  # its aliases hold nothing more
                index.import_statements.append(node)
                _record_import(index, scopes[owner], node)
                continue
            else:
                _record(index, scopes[owner], node, kind, cls, self_name)
        if special is not _CALL:
            names = known.get(kind) or fields(kind)
        for name in names:  # not contexts, operators and strings
            value = getattr(node, name, None)
            for v in value if type(value) is list else (value,):
                child = type(v)
                while child is attribute_class:  # `a.b.c`: read here, not stacked
                    if type(v.ctx) is not load:
                        attribute_stores.add(v.attr)
                    v = v.value
                    child = type(v)
                if child is name_class:
                    if type(v.ctx) is not load:
                        local_names.add(v.id)
                        stores[v.id] += 1
                elif child is not constant_class and isinstance(v, node_class):
                    append(v)
        if special is _CALL and keywords:
            extend([keyword.value for keyword in keywords])


# the statements and nodes `_record` reads (besides walking under them)
_RECORDED = frozenset(
    {ast.AugAssign, ast.AnnAssign, ast.Global, ast.Nonlocal, ast.ExceptHandler}
)
_CALLED: tuple[str, ...] = ("func", "args")  # a call's fields but its keywords


# how `_drain` treats a node class it does not just walk under
_MARK, _NAME, _CONSTANT, _SCOPE, _CALL, _ATTRIBUTE, _RETURN, _YIELD = range(8)
_RECORD, _IMPORT, _ASSIGN, _EXPRESSION = 8, 9, 10, 11
_SPECIAL: dict[type, int] = {
    tuple: _MARK,
    ast.Name: _NAME,
    ast.Constant: _CONSTANT,
    **dict.fromkeys([*FUNCTIONS, ast.Lambda, ast.ClassDef, *COMPREHENSIONS], _SCOPE),
    ast.Call: _CALL,
    ast.Attribute: _ATTRIBUTE,
    ast.Return: _RETURN,
    ast.Yield: _YIELD,
    ast.YieldFrom: _YIELD,
    **dict.fromkeys(_RECORDED, _RECORD),
    ast.Import: _IMPORT,
    ast.ImportFrom: _IMPORT,
    ast.Assign: _ASSIGN,
    ast.Expr: _EXPRESSION,
}


def _record(
    index: FileIndex,
    names: ScopeNames,
    node: ast.AST,
    kind: type,
    cls: str | None,
    self_name: str | None,
) -> None:
    if kind is ast.AugAssign or kind is ast.AnnAssign:
        _count_assigned(index, node.target)  # type: ignore[attr-defined]
        value = node.value  # type: ignore[attr-defined]
        if (
            kind is ast.AnnAssign
            and type(value) is ast.Constant
            and value.value is None
        ):
            _count_none(index, [node.target])  # type: ignore[attr-defined]
    if kind is ast.Global or kind is ast.Nonlocal:
        names.global_names.update(node.names)  # type: ignore[attr-defined]
    elif kind is ast.ExceptHandler and node.name:  # type: ignore[attr-defined]
        names.local_names.add(node.name)  # type: ignore[attr-defined]
    elif kind is ast.AnnAssign:
        _record_annotation(index, names, node, cls, self_name)  # type: ignore[arg-type]


def _count_none(index: FileIndex, targets: list[ast.expr]) -> None:
    """`x.a = None`: an attribute that may hold a value or None (`frames.remember`)."""
    for target in targets:
        if type(target) is ast.Attribute:
            index.assigned_none[target.attr] += 1


def _count_assigned(index: FileIndex, target: ast.AST) -> None:
    """Each attribute of an assignment's target, as a walk of it meets them."""
    todo: list[Any] = [target]
    while todo:  # most targets are one `Name`
        part = todo.pop()
        if type(part) is ast.Name:
            continue
        if type(part) is ast.Attribute:
            index.assigned[part.attr] += 1
        todo += children(part)


def _enter(
    index: FileIndex,
    node: ast.AST,
    owner: int,
    cls: str | None,
    self_name: str | None,
    root: int,
    todo: Todo,
) -> Where:
    """Open the scope of a function, lambda, class or comprehension: push what the
    enclosing scope evaluates (defaults, decorators, bases, a comprehension's first
    iterable), the marker back to it, then the scope's own nodes; its `Where`."""
    outer = (owner, cls, self_name)
    inner = index.scopes[id(node)] = ScopeNames()
    kind = type(node)
    if kind is ast.ClassDef:
        index.scopes[owner].local_names.add(node.name)  # type: ignore[attr-defined]
        index.class_scopes.add(id(node))
        todo += [*node.decorator_list, *node.bases, *node.keywords, outer, *node.body]  # type: ignore[attr-defined]
        return id(node), node.name if owner == root else cls, None  # type: ignore[attr-defined]
    if kind in _COMPREHENSION_KINDS:  # its first iterable is the enclosing one's
        first = node.generators[0]  # type: ignore[attr-defined]
        todo += [first.iter, outer, first.target, *first.ifs, *node.generators[1:]]  # type: ignore[attr-defined]
        todo += [c for c in children(node) if not isinstance(c, ast.comprehension)]
        return id(node), cls, self_name
    assert kind in _FUNCTION_KINDS
    args = node.args  # type: ignore[attr-defined]
    todo += args.defaults
    every = args.args  # most functions have only these
    if args.posonlyargs or args.kwonlyargs or args.vararg or args.kwarg:
        todo += [d for d in args.kw_defaults if d is not None]
        every = [*args.posonlyargs, *args.args, *args.kwonlyargs]
        every += [a for a in (args.vararg, args.kwarg) if a is not None]
    names = inner.local_names
    for arg in every:
        names.add(arg.arg)
        if arg.annotation is not None:
            inner.annotated.append((arg.annotation, arg.arg))
            _count_stores(index, arg.annotation)
    if kind is ast.Lambda:
        todo += [outer, node.body]  # type: ignore[attr-defined]
        return id(node), cls, None
    if node.returns is not None:  # type: ignore[attr-defined]
        _count_stores(index, node.returns)  # type: ignore[attr-defined]
    index.scopes[owner].local_names.add(node.name)  # type: ignore[attr-defined]
    is_method = owner in index.class_scopes
    todo += [*node.decorator_list, outer, *node.body]  # type: ignore[attr-defined]
    return id(node), cls, args.args[0].arg if is_method and args.args else None


_COMPREHENSION_KINDS = frozenset(COMPREHENSIONS)
_FUNCTION_KINDS = frozenset({*FUNCTIONS, ast.Lambda})


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
