"""RF301 for the skip rule (`relevance.skippable`): a definite-assignment pass,
more pessimistic than the analysis.

Every branch may run or not, loops may run zero times, a `try` body may stop
anywhere, `with` bodies run as written: a read of a local that is not assigned
on every syntactic path, a name that no enclosing scope, the module or the
builtins bind, or a `del`eted name makes `may_be_unbound` say yes. The analysis
can only prune paths (facts, dead code), so it never finds an unbound read this
pass misses.

Without `:=` in the text (`walrus` False) no expression binds a name, so an
expression's reads are checked in any order, by a stack walk (`_Scope.reads`);
with it, in evaluation order, recursively (`_Scope.expr`), which also serves an
expression of more than `FLAT_NODES` nodes: its recursion may overflow, which
sends the file to the analysis, as it always did.
"""

from __future__ import annotations

import ast
import builtins
from collections.abc import Callable, Sequence
from typing import Any, cast

from robotfix.astwalk import FIELDS, TRIES, children, fields

# as the interpreter resolves names (`analysis/interpreter.py`)
BUILTINS = frozenset(dir(builtins)) | {"__file__", "__name__", "__doc__", "__spec__"}
FUNCTIONS = (ast.FunctionDef, ast.AsyncFunctionDef)
COMPREHENSIONS = (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)
DEFINITIONS = (*FUNCTIONS, ast.ClassDef)  # built once: tested at every node
# an expression with more nodes than this is checked by the recursive `expr`
FLAT_NODES = 200

Bound = frozenset[str] | None  # None: this point is not reached


class _RiskError(Exception):
    """A read the analysis might report as unbound."""


def may_be_unbound(
    tree: ast.Module, declared: frozenset[str], walrus: bool = True
) -> bool:
    """`declared`: the names some function declares `global`. `walrus`: whether
    the text may hold `:=` (without, an expression binds nothing of its scope,
    and only statements are searched for bindings)."""
    try:
        scope = _Scope if walrus else _FlatScope
        scope(tree, None, declared, walrus).run(tree.body, frozenset())
    except (_RiskError, RecursionError):
        return True
    return False


def _meet(a: Bound, b: Bound) -> Bound:
    if a is None:
        return b
    if b is None:
        return a
    return a & b


class _Scope:
    """One module, class, function, lambda or comprehension."""

    def __init__(
        self,
        node: ast.AST,
        parent: _Scope | None,
        declared: frozenset[str] = frozenset(),
        walrus: bool = True,
    ) -> None:
        self.node = node
        self.parent = parent
        self.is_class = type(node) is ast.ClassDef
        self.is_comprehension = type(node) in _COMPREHENSION_KINDS
        self.walrus: bool = parent.walrus if parent is not None else walrus
        self.locals, self.declared = _binders(node, self.walrus)
        # the module scope (None: this one); not `self`, which would make a
        # reference cycle that keeps the file's tree alive until a collection
        self._module = parent.module if parent is not None else None
        if parent is None:
            self.globals = self.locals | declared  # bound by `global x; x = ...`

    @property
    def module(self) -> _Scope:
        return self._module or self

    # -- names ---------------------------------------------------------------
    def read(self, name: str, bound: frozenset[str]) -> None:
        if self.is_comprehension and name not in self.locals:
            assert self.parent is not None
            self.parent.read(name, bound)  # `bound` holds the enclosing sure names
            return
        if name in self.locals:
            if name not in bound:
                raise _RiskError
            return
        outer = self.parent
        while outer is not None:
            if outer.parent is None:
                break
            if not outer.is_class and name in outer.locals:
                return
            outer = outer.parent
        if name in self.module.globals or name in BUILTINS:
            return
        raise _RiskError

    # -- expressions ---------------------------------------------------------
    def reads(self, node: ast.AST | None, bound: frozenset[str]) -> frozenset[str]:
        """Check the reads of an expression that binds nothing (no `:=` in the
        text), in any order: names and attribute chains are read under their
        parent, never stacked; a lambda's and a comprehension's scopes as `expr`
        checks them."""
        kind = type(node)
        if kind is ast.Name:
            if type(node.ctx) is ast.Load:  # type: ignore[union-attr]
                self.read(node.id, bound)  # type: ignore[union-attr]
            return bound
        if node is None or kind is ast.Constant:
            return bound
        todo: list[Any] = [node]
        pop, append, read, local = todo.pop, todo.append, self.read, self.locals
        name_class, attribute_class, constant_class = (
            ast.Name,
            ast.Attribute,
            ast.Constant,
        )
        load, node_class, known, scopes = ast.Load, ast.AST, FIELDS, _SCOPE_KINDS
        seen = 0
        child: Any
        while todo:
            item = pop()
            seen += 1
            kind = type(item)
            if kind in scopes:
                if kind is ast.Lambda:
                    self.lambda_reads(item, bound)
                else:
                    self.comprehension(item, bound)
                continue
            for name in known.get(kind) or fields(kind):
                value = getattr(item, name, None)
                for child in value if type(value) is list else (value,):
                    part = type(child)
                    while part is attribute_class:
                        seen += 1
                        child = child.value
                        part = type(child)
                    if part is name_class:
                        # a local bound here: `read` would say so
                        if type(child.ctx) is load and not (
                            child.id in bound and child.id in local
                        ):
                            read(child.id, bound)
                    elif part is not constant_class and isinstance(child, node_class):
                        append(child)
        if seen > FLAT_NODES:  # as deep as the recursion may overflow at
            return self.expr(node, bound)
        return bound

    def expr(self, node: ast.AST | None, bound: frozenset[str]) -> frozenset[str]:
        """Check the reads of an expression in order; the names it binds (`:=`)."""
        if node is None:
            return bound
        kind = type(node)
        if kind is ast.Name:
            if type(node.ctx) is ast.Load:  # type: ignore[attr-defined]
                self.read(node.id, bound)  # type: ignore[attr-defined]
            return bound
        if kind is ast.Constant:
            return bound
        if kind is ast.Attribute:  # its one child
            return self.expr(node.value, bound)  # type: ignore[attr-defined]
        if kind is ast.Call:  # its children in order, a keyword's value for it
            bound = self.expr(node.func, bound)  # type: ignore[attr-defined]
            for argument in node.args:  # type: ignore[attr-defined]
                bound = self.expr(argument, bound)
            for keyword in node.keywords:  # type: ignore[attr-defined]
                bound = self.expr(keyword.value, bound)
            return bound
        if isinstance(node, ast.NamedExpr):
            bound = self.expr(node.value, bound)
            return bound | {node.target.id}
        if isinstance(node, ast.Lambda):
            return self.lambda_reads(node, bound)
        if isinstance(node, COMPREHENSIONS):
            return self.comprehension(node, bound)
        if isinstance(node, (ast.BoolOp, ast.IfExp)):
            # operands after the first may not run: names they bind are not sure
            first, *rest = (
                node.values
                if isinstance(node, ast.BoolOp)
                else [node.test, node.body, node.orelse]
            )
            after = self.expr(first, bound)
            for other in rest:
                self.expr(other, after)
            return after
        for child in children(node):
            bound = self.expr(child, bound)
        return bound

    # how this scope checks an expression's reads (a method of the class: one
    # kept on the instance would make a cycle that holds the tree)
    evaluate = expr

    def lambda_reads(self, node: ast.Lambda, bound: frozenset[str]) -> frozenset[str]:
        bound = self.defaults(node.args, bound)
        inner = type(self)(node, self)
        inner.evaluate(node.body, _params(node.args))
        return bound

    def comprehension(self, node: ast.AST, bound: frozenset[str]) -> frozenset[str]:
        """Runs at once, in order: the first iterable here, the rest inside, where
        the names of the enclosing scope are read as they are bound here."""
        if self.walrus and any(
            isinstance(sub, ast.NamedExpr) for sub in ast.walk(node)
        ):
            raise _RiskError  # `:=` in a comprehension binds outside it: not followed
        generators: list[ast.comprehension] = node.generators  # type: ignore[attr-defined]
        inner = type(self)(node, self)
        evaluate = inner.evaluate
        inside = self.evaluate(generators[0].iter, bound)
        for i, gen in enumerate(generators):
            if i:
                inside = evaluate(gen.iter, inside)
            inside = inside | _stores(gen.target)
            for test in gen.ifs:
                inside = evaluate(test, inside)
        for part in ("elt", "key", "value"):
            if hasattr(node, part):
                evaluate(getattr(node, part), inside)
        return bound

    def defaults(self, args: ast.arguments, bound: frozenset[str]) -> frozenset[str]:
        evaluate = self.evaluate
        for default in args.defaults:
            bound = evaluate(default, bound)
        for maybe in args.kw_defaults:  # None for a keyword without a default
            bound = evaluate(maybe, bound)
        return bound

    # -- statements ----------------------------------------------------------
    def run(self, body: Sequence[ast.stmt], bound: Bound) -> Bound:
        handlers = _STATEMENTS
        for stmt in body:
            if bound is None:
                return None
            handler = handlers.get(type(stmt))
            if handler is None:
                raise _RiskError  # match, and anything newer: not followed
            bound = handler(self, stmt, bound)
        return bound

    def leave(self, node: ast.Return | ast.Raise, bound: frozenset[str]) -> Bound:
        for child in (
            (node.value,) if type(node) is ast.Return else (node.exc, node.cause)  # type: ignore[union-attr]
        ):
            self.evaluate(child, bound)
        return None

    def jump(self, node: ast.stmt, bound: frozenset[str]) -> Bound:
        return None

    def nothing(self, node: ast.stmt, bound: frozenset[str]) -> Bound:
        return bound

    def imports(
        self, node: ast.Import | ast.ImportFrom, bound: frozenset[str]
    ) -> Bound:
        return bound | {
            a.asname or a.name.partition(".")[0] for a in node.names if a.name != "*"
        }

    def definition(self, node: ast.AST, bound: frozenset[str]) -> Bound:
        evaluate = self.evaluate
        for decorator in node.decorator_list:  # type: ignore[attr-defined]
            bound = evaluate(decorator, bound)
        if type(node) is ast.ClassDef:
            for base in node.bases:
                bound = evaluate(base, bound)
            for keyword in node.keywords:
                bound = evaluate(keyword, bound)
            type(self)(node, self).run(node.body, frozenset())
        else:
            args = node.args  # type: ignore[attr-defined]
            bound = self.defaults(args, bound)
            type(self)(node, self).run(node.body, _params(args))  # type: ignore[attr-defined]
        name = node.name  # type: ignore[attr-defined]
        return bound if name in bound else bound | {name}

    def assign(self, node: ast.Assign, bound: frozenset[str]) -> Bound:
        bound = self.evaluate(node.value, bound)
        for target in node.targets:
            bound = self.target(target, bound)
        return bound

    def annotated(self, node: ast.AnnAssign, bound: frozenset[str]) -> Bound:
        if node.value is None:
            raise _RiskError
        bound = self.evaluate(node.value, bound)
        return self.target(node.target, bound)

    def augmented(self, node: ast.AugAssign, bound: frozenset[str]) -> Bound:
        bound = self.evaluate(node.value, bound)
        if type(node.target) is ast.Name:
            self.read(node.target.id, bound)
            return bound
        return self.target(node.target, bound)

    def delete(self, node: ast.Delete, bound: frozenset[str]) -> Bound:
        for target in node.targets:
            if type(target) is not ast.Name:
                bound = self.evaluate(target, bound)
                continue
            self.read(target.id, bound)
            bound = bound - {target.id}
        return bound

    def expression(self, node: ast.Expr, bound: frozenset[str]) -> Bound:
        return self.evaluate(node.value, bound)

    def branch(self, node: ast.If, bound: frozenset[str]) -> Bound:
        bound = self.evaluate(node.test, bound)
        return _meet(self.run(node.body, bound), self.run(node.orelse, bound))

    def loop(self, node: ast.For | ast.AsyncFor, bound: frozenset[str]) -> Bound:
        bound = self.evaluate(node.iter, bound)
        self.run(node.body, self.target(node.target, bound))
        self.run(node.orelse, bound)
        return bound  # zero iterations, or a `break` before the `else`

    def repeat(self, node: ast.While, bound: frozenset[str]) -> Bound:
        bound = self.evaluate(node.test, bound)
        self.run(node.body, bound)
        self.run(node.orelse, bound)
        return bound

    def within(self, node: ast.With | ast.AsyncWith, bound: frozenset[str]) -> Bound:
        for item in node.items:
            bound = self.evaluate(item.context_expr, bound)
            if item.optional_vars is not None:
                bound = self.target(item.optional_vars, bound)
        return self.run(node.body, bound)

    def tried(self, node: ast.stmt, bound: frozenset[str]) -> Bound:
        tried = cast(ast.Try, node)  # or an `ast.TryStar`: the same fields
        # a handler may start anywhere in the body: only what was sure before
        after = self.run(tried.orelse, self.run(tried.body, bound))
        for handler in tried.handlers:
            start = bound
            if handler.type is not None:
                start = self.evaluate(handler.type, start)
            if handler.name:
                start = start | {handler.name}
            end = self.run(handler.body, start)
            if end is not None and handler.name:
                end = end - {handler.name}  # Python deletes it
            after = _meet(after, end)
        final = self.run(tried.finalbody, bound)
        if after is None or final is None:
            return None
        return after | final

    def asserted(self, node: ast.Assert, bound: frozenset[str]) -> Bound:
        bound = self.evaluate(node.test, bound)
        self.evaluate(node.msg, bound)
        return bound

    def target(self, node: ast.expr, bound: frozenset[str]) -> frozenset[str]:
        kind = type(node)
        if kind is ast.Name:
            name = node.id  # type: ignore[attr-defined]
            return bound if name in bound else bound | {name}
        if kind is ast.Tuple or kind is ast.List:
            for element in node.elts:  # type: ignore[attr-defined]
                bound = self.target(element, bound)
            return bound
        if kind is ast.Starred:
            return self.target(node.value, bound)  # type: ignore[attr-defined]
        return self.evaluate(node, bound)  # obj.x, obj[i]: reads obj (and i)


class _FlatScope(_Scope):
    """A scope of a text without `:=`: its expressions bind nothing."""

    evaluate = _Scope.reads


# statement class -> how `_Scope.run` checks it (a class not here: not followed)
_STATEMENTS: dict[type, Callable[[_Scope, Any, frozenset[str]], Bound]] = {
    ast.Return: _Scope.leave,
    ast.Raise: _Scope.leave,
    ast.Break: _Scope.jump,
    ast.Continue: _Scope.jump,
    ast.Pass: _Scope.nothing,
    ast.Global: _Scope.nothing,
    ast.Nonlocal: _Scope.nothing,
    ast.Import: _Scope.imports,
    ast.ImportFrom: _Scope.imports,
    **dict.fromkeys(DEFINITIONS, _Scope.definition),
    ast.Assign: _Scope.assign,
    ast.AnnAssign: _Scope.annotated,
    ast.AugAssign: _Scope.augmented,
    ast.Delete: _Scope.delete,
    ast.Expr: _Scope.expression,
    ast.If: _Scope.branch,
    ast.For: _Scope.loop,
    ast.AsyncFor: _Scope.loop,
    ast.While: _Scope.repeat,
    ast.With: _Scope.within,
    ast.AsyncWith: _Scope.within,
    **dict.fromkeys(TRIES, _Scope.tried),
    ast.Assert: _Scope.asserted,
}


def _params(args: ast.arguments) -> frozenset[str]:
    every = [*args.posonlyargs, *args.args, *args.kwonlyargs]
    every += [a for a in (args.vararg, args.kwarg) if a is not None]
    return frozenset(a.arg for a in every)


def _binders(
    node: ast.AST, walrus: bool = True
) -> tuple[frozenset[str], frozenset[str]]:
    """The names a scope binds (its locals, as Python decides them), and those it
    declares `global` or `nonlocal`: a walk of the nodes of its body, not of the
    scopes nested in it (their names, decorators and defaults are the outer
    scope's; the first iterable of a comprehension too). Without `walrus` (no
    `:=` in the text) only the statements and their targets are walked: no other
    expression stores a name of this scope (a comprehension's target is its
    own)."""
    bound: set[str] = set()
    declared: set[str] = set()
    if isinstance(node, (*FUNCTIONS, ast.Lambda)):
        bound |= _params(node.args)
    if isinstance(node, COMPREHENSIONS):
        for gen in node.generators:
            bound |= _stores(gen.target)
        return frozenset(bound), frozenset()
    if isinstance(node, ast.Lambda):
        todo: list[ast.AST] = [node.body] if walrus else []
    elif walrus:
        todo = list(getattr(node, "body", []))
    else:
        todo = _statement_binders(node.body, bound, declared)  # type: ignore[attr-defined]
    pop, extend = todo.pop, todo.extend
    while todo:
        child = pop()
        kind = type(child)
        if kind is ast.Name:
            if type(child.ctx) is not ast.Load:  # type: ignore[attr-defined]
                bound.add(child.id)  # type: ignore[attr-defined]
            continue
        if kind is ast.Constant:
            continue
        if kind in _DEFINITION_KINDS:
            bound.add(child.name)  # type: ignore[attr-defined]
            extend(child.decorator_list)  # type: ignore[attr-defined]
            if kind is ast.ClassDef:
                extend(child.bases)  # type: ignore[attr-defined]
                extend(child.keywords)  # type: ignore[attr-defined]
            else:
                extend(child.args.defaults)  # type: ignore[attr-defined]
                extend(d for d in child.args.kw_defaults if d is not None)  # type: ignore[attr-defined]
            continue
        if kind is ast.Lambda:
            args = child.args  # type: ignore[attr-defined]
            extend(d for d in [*args.defaults, *args.kw_defaults] if d)
            continue
        if kind in _COMPREHENSION_KINDS:
            # `:=` inside binds here, but comprehensions with one are not followed
            todo.append(child.generators[0].iter)  # type: ignore[attr-defined]
            continue
        if kind is ast.alias:
            if child.name != "*":  # type: ignore[attr-defined]
                bound.add(child.asname or child.name.partition(".")[0])  # type: ignore[attr-defined]
            continue
        if kind is ast.Global or kind is ast.Nonlocal:
            declared.update(child.names)  # type: ignore[attr-defined]
            continue
        if kind is ast.ExceptHandler:
            if child.name:  # type: ignore[attr-defined]
                bound.add(child.name)  # type: ignore[attr-defined]
        elif kind is ast.NamedExpr:
            bound.add(child.target.id)  # type: ignore[attr-defined]
        extend(children(child))
    return frozenset(bound - declared), frozenset(declared)


# the statements that hold statements
COMPOUND = frozenset(
    {ast.If, ast.For, ast.AsyncFor, ast.While, ast.With, ast.AsyncWith, ast.Try}
    | {ast.Match, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, *TRIES}
)
_DEFINITION_KINDS = frozenset(DEFINITIONS)
_COMPREHENSION_KINDS = frozenset(COMPREHENSIONS)
_SCOPE_KINDS = frozenset({*COMPREHENSIONS, ast.Lambda})
_TARGETS = {  # statement class -> its fields that hold targets
    ast.Assign: "targets",
    ast.AugAssign: "target",
    ast.AnnAssign: "target",
    ast.For: "target",
    ast.AsyncFor: "target",
    ast.Delete: "targets",
}


def _statement_binders(
    body: list[ast.stmt], bound: set[str], declared: set[str]
) -> list[ast.AST]:
    """What a scope's statements bind (definitions, imports, handlers' names, the
    names their targets store to) and declare, in a text without `:=`: a target
    stores a name as itself, in a tuple or list, or starred (`obj.x`, `obj[i]`
    store none: only `:=` could, or a comprehension, for itself). Nothing is
    left for `_binders` to walk."""
    targets: list[Any] = []
    todo: list[Any] = list(body)
    while todo:
        stmt = todo.pop()
        kind = type(stmt)
        field = _TARGETS.get(kind)
        if field is not None:
            found = getattr(stmt, field)
            if type(found) is list:
                targets.extend(found)
            else:
                targets.append(found)
        if kind in _DEFINITION_KINDS:
            bound.add(stmt.name)
            continue
        if kind is ast.Import or kind is ast.ImportFrom:
            for alias in stmt.names:
                if alias.name != "*":
                    bound.add(alias.asname or alias.name.partition(".")[0])
            continue
        if kind is ast.Global or kind is ast.Nonlocal:
            declared.update(stmt.names)
            continue
        if kind not in COMPOUND:
            continue
        if kind is ast.With or kind is ast.AsyncWith:
            for item in stmt.items:
                if item.optional_vars is not None:
                    targets.append(item.optional_vars)
        todo.extend(getattr(stmt, "body", ()))
        todo.extend(getattr(stmt, "orelse", ()))
        todo.extend(getattr(stmt, "finalbody", ()))
        for handler in getattr(stmt, "handlers", ()):
            if handler.name:
                bound.add(handler.name)
            todo.extend(handler.body)
        for case in getattr(stmt, "cases", ()):
            todo.extend(case.body)
    while targets:
        target = targets.pop()
        part = type(target)
        if part is ast.Name:
            bound.add(target.id)
        elif part is ast.Tuple or part is ast.List:
            targets.extend(target.elts)
        elif part is ast.Starred:
            targets.append(target.value)
    return targets


def _stores(node: ast.AST) -> set[str]:
    if type(node) is ast.Name:  # most targets (a stored name: not `Load`)
        return {node.id}
    return {
        n.id
        for n in ast.walk(node)
        if isinstance(n, ast.Name) and not isinstance(n.ctx, ast.Load)
    }
