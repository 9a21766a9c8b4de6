"""Which files cannot produce a finding: those are parsed (RF001/RF002, suppressions,
RF010) but not analysed (issue 13; mypy skips unannotated bodies for the same reason).

A finding needs something that carries a unit, a frame or a refinement, or a name
that can be unbound. `skippable` answers "nothing can" syntactically and
conservatively: every test below only ever sends a file to the analysis, so a file
it lets through is one the analysis would have reported nothing on. A unit, frame
or refinement enters a file only through

- an annotation of ours: the text has `Annotated`, `Unit(`, `Frame(` or `Tag(`
  (string annotations and comments included, so no alias spelling escapes it);
- a message, service or action class: an import with a part `msg`, `srv` or
  `action`, or a part the catalog knows as an interface package (the seed
  programs write `from std_msgs import Float64`);
- a library call or object the stubs describe: a name or attribute that is the
  name of a stub member able to give a unit or a refinement
  (`stubs.load.defined_names`), or that the API model keys on (registrations,
  time objects, node constructors, tf2 calls) - by name, since a method of an
  unknown receiver is looked up by its name alone; a name read only as the
  receiver of an attribute (`time` in `time.sleep`) counts through the attribute;
- a parameter: `_param` or `ParamListener` anywhere in the text (every
  declaration and read `analysis/parameters.py` follows). The calls are names of
  the vocabulary too, but the word is the cheaper exit: without it, 38 more of
  corpus25's 1,391 files were skipped and the run cost 0.6% more instructions;
- another module of the tree: a plain `import` of a module of the tree, or a name
  `from` one that is itself a module, a re-export, an alias, or a member whose
  summary carries something (`carries`: a refinement, a type, a unit, a frame, a
  message, an instance, a list); a module of the tree whose summary is unknown (a
  fault of ours) counts too. A plain member (a function with nothing refined or
  typed, a class with nothing of these, a plain constant) gives the analysis
  only what an unknown name would: its tests can prune paths, which only ever
  removes findings. This is asked after the cheaper tests: it may build
  summaries (which the file's analysis would build too);
- a declaration without a value (`x: float` in a body), whose read is RF301.

RF301 needs no annotation, so `_may_be_unbound` runs a plain definite-assignment
pass over every scope, more pessimistic than the analysis (every branch may run or
not, loops may run zero times, a `try` body may stop anywhere, `with` bodies as
written): a read of a local that is not assigned on every syntactic path, a name
that no enclosing scope, the module or the builtins bind, or a `del`eted name sends
the file to the analysis. The analysis can only prune paths (facts, dead code), so
it never finds an unbound read this pass misses.

RF902 (the work budget) is a warning about the analysis, not a finding; files
large enough to come near it (over a 16th of the budget in bytes, 125 kB) are
analysed as before. A smaller file can spend it too (one-line helpers inlined
into each other, 30 calls deep four times); skipped, it has nothing to find, so
only the warning is not given.

`tests/test_relevance.py` checks the claim on every case file and on generated
programs: a file this module skips gets no diagnostic from the full analysis.
"""

from __future__ import annotations

import ast
import builtins
import functools
import os
import re
import unicodedata
import weakref
from collections.abc import Iterable, Sequence
from typing import Any, cast

from robotfix import budget
from robotfix.analysis.constants import SCALARS
from robotfix.analysis.imported import (
    ClassSummary,
    FunctionSummary,
    Resolver,
    absolute,
)
from robotfix.analysis.values import Value
from robotfix.astwalk import FIELDS, TRIES, children, fields
from robotfix.ros import api_model, frames_model
from robotfix.ros.catalog import MsgCatalog
from robotfix.stubs.load import StubSet, defined_names

# declare_parameter(s), get_param(eter), has_parameter, ParamListener (g_p_l)...
PARAMETER_WORDS = ("_param", "paramlistener")
MARKERS = ("Annotated", "Unit(", "Frame(", "Tag(")
INTERFACE_PARTS = frozenset({"msg", "srv", "action"})
BYTES_PER_STEP_BUDGET = 16  # a file over FILE_STEPS / 16 bytes is analysed: RF902
# as the interpreter resolves names (`analysis/interpreter.py`)
BUILTINS = frozenset(dir(builtins)) | {"__file__", "__name__", "__doc__", "__spec__"}
FUNCTIONS = (ast.FunctionDef, ast.AsyncFunctionDef)
COMPREHENSIONS = (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)
DEFINITIONS = (*FUNCTIONS, ast.ClassDef)  # built once: tested at every node

ENABLED = os.environ.get("ROBOTFIX_NO_SKIP", "") == ""  # off: analyse every file


def skippable(
    tree: ast.Module,
    text: str,
    catalog: MsgCatalog,
    stubs: StubSet,
    resolver: Resolver | None,
) -> bool:
    """Can the analysis of this file report nothing? (True only when sure.)"""
    if not text.isascii():  # Python reads identifiers NFKC-normalised, so do we
        text = unicodedata.normalize("NFKC", text)
    if (
        not ENABLED
        or len(text) * BYTES_PER_STEP_BUDGET > budget.FILE_STEPS
        or any(marker in text for marker in MARKERS)
    ):
        return False
    lowered = text.lower()
    if any(word in lowered for word in PARAMETER_WORDS):
        return False
    # the exits in the order they fire on real code (corpus2): parameters, imports
    # of the tree, a stub name; every statement first (cheap), every name only
    # when the text has a stub word at all
    imported: list[tuple[int, str | None, tuple[str, ...]]] = []
    declared: set[str] = set()  # names some function declares `global`
    for node in _statements(tree.body):
        kind = type(node)
        if kind is ast.Import:
            for alias in node.names:  # type: ignore[attr-defined]
                if _interface(alias.name, catalog):
                    return False
                imported.append((0, alias.name, ()))
        elif kind is ast.ImportFrom:
            assert isinstance(node, ast.ImportFrom)
            if node.module and _interface(node.module, catalog):
                return False
            if node.level and resolver is not None:  # `from . import Cmd`
                base = absolute(resolver.package, node.level, node.module)
                if base and _interface(base, catalog):
                    return False
            names = tuple(a.name for a in node.names)
            if any(n in INTERFACE_PARTS for n in names):
                return False
            imported.append((node.level, node.module, names))
        elif kind is ast.AnnAssign and node.value is None:  # type: ignore[attr-defined]
            return False
        elif kind is ast.Global:
            declared.update(node.names)  # type: ignore[attr-defined]
    vocabulary = _vocabulary(stubs)
    # a stub member imported under another name (`from math import degrees as d`)
    if any(n in vocabulary for _, _, names in imported for n in names):
        return False
    # no stub word anywhere in the text: no name or attribute can be one
    if _pattern(vocabulary).search(text) is not None and _names_one(tree, vocabulary):
        return False
    # before the definite-assignment pass: what it builds, the file's analysis
    # would build too (the summaries of the modules it imports)
    if resolver is not None and _tree_relevant(resolver, imported):
        return False
    return not _may_be_unbound(tree, frozenset(declared), ":=" in text)


def _names_one(tree: ast.Module, vocabulary: frozenset[str]) -> bool:
    """Is a name or attribute of the tree a stub word? A name read only as the
    receiver of an attribute (`time` in `time.sleep`) counts through the
    attribute. Names, constants and attribute chains are read under their
    parent, never stacked."""
    todo: list[ast.AST] = [tree]
    pop, append = todo.pop, todo.append
    name_class, attribute_class, constant_class = ast.Name, ast.Attribute, ast.Constant
    node_class, known = ast.AST, FIELDS
    child: Any
    while todo:
        node = pop()
        kind = type(node)
        for name in known.get(kind) or fields(kind):
            value = getattr(node, name, None)
            for child in value if type(value) is list else (value,):
                part = type(child)
                if part is attribute_class:
                    while part is attribute_class:
                        if child.attr in vocabulary:
                            return True
                        child = child.value
                        part = type(child)
                    if part is name_class:
                        continue  # a receiver
                if part is name_class:
                    if child.id in vocabulary:
                        return True
                elif part is not constant_class and isinstance(child, node_class):
                    append(child)
    return False


@functools.lru_cache(maxsize=8)
def _pattern(vocabulary: frozenset[str]) -> re.Pattern[str]:
    """A stub word, whole: its alternatives a trie (`Time(?:Msg|r)?`), which `re`
    searches at about twice the speed of the 84 words side by side."""
    return re.compile(r"\b(?:" + _trie(sorted(vocabulary)) + r")\b")


def _trie(words: list[str]) -> str:
    """A pattern of exactly `words` (sorted), their common prefixes shared."""
    if len(words) == 1:
        return re.escape(words[0])
    rests: dict[str, list[str]] = {}
    for word in words:
        rests.setdefault(word[:1], []).append(word[1:])
    ends = "" in rests  # a word ends here, a longer one goes on
    branches = [re.escape(c) + _trie(after) for c, after in rests.items() if c]
    if not branches:
        return ""
    if len(branches) == 1 and not ends:
        return branches[0]
    return "(?:" + "|".join(branches) + (")?" if ends else ")")


def _statements(body: list[ast.stmt]) -> Iterable[ast.stmt]:
    """Every statement, nested ones too (those in `match` cases included)."""
    todo = list(reversed(body))
    while todo:
        stmt = todo.pop()
        yield stmt
        if type(stmt) not in _COMPOUND:  # most statements hold none
            continue
        for field in ("body", "orelse", "finalbody"):
            todo.extend(reversed(getattr(stmt, field, ())))
        for handler in getattr(stmt, "handlers", ()):
            todo.extend(reversed(handler.body))
        for case in getattr(stmt, "cases", ()):
            todo.extend(reversed(case.body))


# the statements that hold statements (`_statements`)
_COMPOUND = frozenset(
    {ast.If, ast.For, ast.AsyncFor, ast.While, ast.With, ast.AsyncWith, ast.Try}
    | {ast.Match, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, *TRIES}
)


def _interface(dotted: str, catalog: MsgCatalog) -> bool:
    """`x.msg`, `x.srv.y`, or a top-level package the catalog has interfaces of."""
    parts = dotted.split(".")
    return any(p in INTERFACE_PARTS for p in parts) or _has_package(catalog, parts[0])


_PACKAGES: weakref.WeakKeyDictionary[MsgCatalog, dict[str, bool]] = (
    weakref.WeakKeyDictionary()
)


def _has_package(catalog: MsgCatalog, part: str) -> bool:
    known = _PACKAGES.setdefault(catalog, {})
    if part not in known:
        known[part] = catalog.has_package(part)
    return known[part]


@functools.lru_cache(maxsize=8)
def _vocabulary(stubs: StubSet) -> frozenset[str]:
    return (
        defined_names(stubs)
        | set(api_model.REGISTRATIONS)
        | api_model.TIME_OBJECTS
        | api_model.NODE_CONSTRUCTORS
        | api_model.PARAMETER_CALLS
        | set(frames_model.TF2_CALLS)
    )


def _tree_relevant(
    resolver: Resolver, imported: list[tuple[int, str | None, tuple[str, ...]]]
) -> bool:
    """Does an import give the file something from a module of the tree? A module
    (all of it reachable through its name), or a member that `carries` something."""
    exists = getattr(resolver, "exists", None)
    for level, module, names in imported:
        base = module if level == 0 else absolute(resolver.package, level, module)
        if base is None:
            continue
        parts = base.split(".")
        prefixes = [".".join(parts[:i]) for i in range(1, len(parts) + 1)]
        if not names:  # `import a.b`: `a.c.f()` reaches any module under `a`
            if any(_in_tree(resolver, exists, p) for p in prefixes):
                return True
            continue
        if not _in_tree(resolver, exists, base):
            # `from a.b import x` where `a` is of the tree, `a.b` not: not followed
            if any(_in_tree(resolver, exists, p) for p in prefixes[:-1]):
                return True
            continue
        summary = resolver.module(base)
        if summary is None or "*" in names:
            return True
        for name in names:
            if _in_tree(resolver, exists, f"{base}.{name}"):
                return True  # a module: its submodules are reached through it
            resolver.member(base, summary, name)
            if name in summary.reexports or name in summary.aliases:
                return True
            member = (
                summary.functions.get(name)
                or summary.classes.get(name)
                or summary.constants.get(name)
            )
            if carries(member):
                return True
    return False


def _in_tree(resolver: Resolver, exists: object, name: str) -> bool:
    if callable(exists):
        return bool(exists(name))
    return resolver.module(name) is not None


PLAIN_KINDS = SCALARS | {"none", "unknown"}  # what a plain constant holds


def carries(member: object, depth: int = 0) -> bool:
    """Can what a summary says of an imported member give an importer something to
    find with: a refinement, a type, a unit, a frame, or a value that is not a
    plain number, string or flag (a member the summary does not know: nothing,
    the importer knows no more of it than of an unknown name)."""
    if member is None:
        return False
    if depth > 3:
        return True
    if isinstance(member, FunctionSummary):
        return (
            bool(member.decls)
            or member.returns is not None
            or member.result is not None
        )
    if isinstance(member, ClassSummary):
        return (
            bool(member.attributes or member.types)
            or any(carries(m, depth + 1) for _, m in member.methods)
            or any(carries(v, depth + 1) for _, v in member.constants)
        )
    if isinstance(member, Value):  # a number, string or flag, and nothing else
        plain = Value(member.kind, member.term, literal=member.literal)
        return not (
            member.kind in PLAIN_KINDS
            and member == plain
            and member.conversion is None
            and member.choices is None
        )
    return True  # anything newer


# -- RF301: a definite-assignment pass, more pessimistic than the analysis ------
Bound = frozenset[str] | None  # None: this point is not reached


class _RiskError(Exception):
    """A read the analysis might report as unbound."""


def _may_be_unbound(
    tree: ast.Module, declared: frozenset[str], walrus: bool = True
) -> bool:
    """`walrus`: whether the text may hold `:=` (without, an expression binds
    nothing of its scope, and only statements are searched for bindings)."""
    try:
        _Scope(tree, None, declared, walrus).run(tree.body, frozenset())
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
        self.is_class = isinstance(node, ast.ClassDef)
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
        if isinstance(self.node, COMPREHENSIONS) and name not in self.locals:
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
            bound = self.defaults(node.args, bound)
            inner = _Scope(node, self)
            inner.expr(node.body, _params(node.args))
            return bound
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

    def comprehension(self, node: ast.AST, bound: frozenset[str]) -> frozenset[str]:
        """Runs at once, in order: the first iterable here, the rest inside, where
        the names of the enclosing scope are read as they are bound here."""
        if any(isinstance(sub, ast.NamedExpr) for sub in ast.walk(node)):
            raise _RiskError  # `:=` in a comprehension binds outside it: not followed
        generators: list[ast.comprehension] = node.generators  # type: ignore[attr-defined]
        inner = _Scope(node, self)
        inside = self.expr(generators[0].iter, bound)
        for i, gen in enumerate(generators):
            if i:
                inside = inner.expr(gen.iter, inside)
            inside = inside | _stores(gen.target)
            for test in gen.ifs:
                inside = inner.expr(test, inside)
        for part in ("elt", "key", "value"):
            if hasattr(node, part):
                inner.expr(getattr(node, part), inside)
        return bound

    def defaults(self, args: ast.arguments, bound: frozenset[str]) -> frozenset[str]:
        for default in [*args.defaults, *args.kw_defaults]:
            bound = self.expr(default, bound)
        return bound

    # -- statements ----------------------------------------------------------
    def run(self, body: Sequence[ast.stmt], bound: Bound) -> Bound:
        for stmt in body:
            if bound is None:
                return None
            bound = self.stmt(stmt, bound)
        return bound

    def stmt(self, node: ast.stmt, bound: frozenset[str]) -> Bound:
        if isinstance(node, (ast.Return, ast.Raise)):
            for child in ast.iter_child_nodes(node):
                self.expr(child, bound)
            return None
        if isinstance(node, (ast.Break, ast.Continue)):
            return None
        if isinstance(node, (ast.Pass, ast.Global, ast.Nonlocal)):
            return bound
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            return bound | {
                a.asname or a.name.partition(".")[0]
                for a in node.names
                if a.name != "*"
            }
        if isinstance(node, DEFINITIONS):
            for decorator in node.decorator_list:
                bound = self.expr(decorator, bound)
            if isinstance(node, ast.ClassDef):
                for base in [*node.bases, *node.keywords]:
                    bound = self.expr(base, bound)
                _Scope(node, self).run(node.body, frozenset())
            else:
                bound = self.defaults(node.args, bound)
                _Scope(node, self).run(node.body, _params(node.args))
            return bound | {node.name}
        if isinstance(node, ast.Assign):
            bound = self.expr(node.value, bound)
            for target in node.targets:
                bound = self.target(target, bound)
            return bound
        if isinstance(node, ast.AnnAssign):
            if node.value is None:
                raise _RiskError
            bound = self.expr(node.value, bound)
            return self.target(node.target, bound)
        if isinstance(node, ast.AugAssign):
            bound = self.expr(node.value, bound)
            if isinstance(node.target, ast.Name):
                self.read(node.target.id, bound)
                return bound
            return self.target(node.target, bound)
        if isinstance(node, ast.Delete):
            for target in node.targets:
                if not isinstance(target, ast.Name):
                    bound = self.expr(target, bound)
                    continue
                self.read(target.id, bound)
                bound = bound - {target.id}
            return bound
        if isinstance(node, ast.Expr):
            return self.expr(node.value, bound)
        if isinstance(node, ast.If):
            bound = self.expr(node.test, bound)
            return _meet(self.run(node.body, bound), self.run(node.orelse, bound))
        if isinstance(node, (ast.For, ast.AsyncFor)):
            bound = self.expr(node.iter, bound)
            self.run(node.body, self.target(node.target, bound))
            self.run(node.orelse, bound)
            return bound  # zero iterations, or a `break` before the `else`
        if isinstance(node, ast.While):
            bound = self.expr(node.test, bound)
            self.run(node.body, bound)
            self.run(node.orelse, bound)
            return bound
        if isinstance(node, (ast.With, ast.AsyncWith)):
            for item in node.items:
                bound = self.expr(item.context_expr, bound)
                if item.optional_vars is not None:
                    bound = self.target(item.optional_vars, bound)
            return self.run(node.body, bound)
        if isinstance(node, TRIES):
            tried = cast(ast.Try, node)  # or an `ast.TryStar`: the same fields
            # a handler may start anywhere in the body: only what was sure before
            after = self.run(tried.orelse, self.run(tried.body, bound))
            for handler in tried.handlers:
                start = bound
                if handler.type is not None:
                    start = self.expr(handler.type, start)
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
        if isinstance(node, ast.Assert):
            bound = self.expr(node.test, bound)
            self.expr(node.msg, bound)
            return bound
        raise _RiskError  # match, and anything newer: not followed

    def target(self, node: ast.expr, bound: frozenset[str]) -> frozenset[str]:
        if isinstance(node, ast.Name):
            return bound | {node.id}
        if isinstance(node, (ast.Tuple, ast.List)):
            for element in node.elts:
                bound = self.target(element, bound)
            return bound
        if isinstance(node, ast.Starred):
            return self.target(node.value, bound)
        return self.expr(node, bound)  # obj.x, obj[i]: reads obj (and i)


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


_DEFINITION_KINDS = frozenset(DEFINITIONS)
_COMPREHENSION_KINDS = frozenset(COMPREHENSIONS)
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
    """What a scope's statements bind by name (definitions, imports, handlers'
    names) and declare; the targets they store to, for `_binders` to walk."""
    targets: list[ast.AST] = []
    todo: list[ast.AST] = list(body)
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
            bound.add(stmt.name)  # type: ignore[attr-defined]
            continue
        if kind is ast.Import or kind is ast.ImportFrom:
            for alias in stmt.names:  # type: ignore[attr-defined]
                if alias.name != "*":
                    bound.add(alias.asname or alias.name.partition(".")[0])
            continue
        if kind is ast.Global or kind is ast.Nonlocal:
            declared.update(stmt.names)  # type: ignore[attr-defined]
            continue
        if kind is ast.With or kind is ast.AsyncWith:
            for item in stmt.items:  # type: ignore[attr-defined]
                if item.optional_vars is not None:
                    targets.append(item.optional_vars)
        if kind not in _COMPOUND:
            continue
        todo.extend(getattr(stmt, "body", ()))
        todo.extend(getattr(stmt, "orelse", ()))
        todo.extend(getattr(stmt, "finalbody", ()))
        for handler in getattr(stmt, "handlers", ()):
            if handler.name:
                bound.add(handler.name)
            todo.extend(handler.body)
        for case in getattr(stmt, "cases", ()):
            todo.extend(case.body)
    return targets


def _stores(node: ast.AST) -> set[str]:
    return {
        n.id
        for n in ast.walk(node)
        if isinstance(n, ast.Name) and not isinstance(n.ctx, ast.Load)
    }
