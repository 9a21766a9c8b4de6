"""Names imported from other modules of the checked tree, as the per-file analysis
sees them (cf. mypy's module interfaces).

The analysis never reads another file. `api.py` hands the file's context a
`Resolver` (built by `robotfix.project`) that answers one question: the summary of
a module, by its absolute dotted name, or None when it is not in the tree. What a
summary holds is data computed from the AST of that module alone: refined functions
(parameters checked at the call, return assumed), constants, type aliases, classes
(refined attributes, methods, constants) and the names it imports (re-exports).

`resolve` is the one place where an imported dotted name becomes what it stands
for; a name it cannot resolve stays unknown, as before.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Protocol

from robotfix.analysis.values import Value
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Alias, Refinement
from robotfix.stubs import load as stubs

if TYPE_CHECKING:
    from robotfix.analysis.index import FileIndex
    from robotfix.analysis.state import State
    from robotfix.analysis.typeterms import Type
    from robotfix.annotations.units import Unit

MAX_HOPS = 20  # re-exports followed for one name (`a` re-exports `b` re-exports...)


@dataclass(frozen=True)
class FunctionSummary:
    """A function's or method's signature: what a caller checks and assumes."""

    name: str  # as the caller's messages show it: `normalize`, `Robot.drive`
    params: tuple[str, ...]  # positional parameters in order (`self` included)
    keywords: tuple[str, ...]  # keyword-only parameters
    decls: tuple[tuple[str, Refinement], ...]  # refined parameters
    returns: Refinement | None
    method: bool  # its first parameter is bound by an instance
    # a classmethod: its first parameter is bound through the class too (`Path.make`)
    class_bound: bool = False
    result: Type | None = None  # what it returns (`analysis/types.py`), if known


@dataclass(frozen=True)
class ClassSummary:
    """What importers see of a class: refined attributes, methods, constants and
    attribute types."""

    name: str
    attributes: tuple[tuple[str, Refinement], ...]  # refined attributes
    methods: tuple[tuple[str, FunctionSummary], ...]
    constants: tuple[tuple[str, Value], ...]  # class constants (`MAX = 0.22`)
    types: tuple[tuple[str, Type], ...] = ()  # attributes' types (`self.left`)


@dataclass
class ModuleSummary:
    """What an importer may see of one module; `fingerprint` hashes its name and
    file, `members` each member's part (`project/summary.py`: what a check read is
    what re-checks it)."""

    name: str  # absolute dotted name
    path: str
    functions: dict[str, FunctionSummary] = field(default_factory=dict)
    classes: dict[str, ClassSummary] = field(default_factory=dict)
    constants: dict[str, Value] = field(default_factory=dict)
    aliases: dict[str, Alias] = field(default_factory=dict)
    reexports: dict[str, str] = field(default_factory=dict)  # name -> qualified
    fingerprint: str = ""
    members: dict[str, str] = field(default_factory=dict)  # name -> fingerprint


Imported = FunctionSummary | ClassSummary | ModuleSummary | Value | Alias


class Resolver(Protocol):
    """How one checked file sees the modules of its tree."""

    @property
    def package(self) -> str | None:
        """The dotted package the file is in (for relative imports)."""

    def module(self, name: str) -> ModuleSummary | None:
        """The summary of the module `name` (absolute), if it is in the tree."""

    def member(self, module: str, summary: ModuleSummary, name: str) -> None:
        """Note that the member `name` of `summary` (asked for as `module`) was
        looked up: what was read of it decides the result."""

    @property
    def resolved(self) -> dict[str, Imported | None]:
        """What each dotted name stands for, kept by `resolve` (the analysis asks
        most names again: 7 of 10 on real code, each failing prefix a lookup)."""


def absolute(package: str | None, level: int, module: str | None) -> str | None:
    """`from ..limits import X` in package `a.b.c` -> `a.b.limits`; None when the
    file is in no package or the dots go above its top."""
    if package is None:
        return None
    parts = package.split(".") if package else []
    if level - 1 >= len(parts):
        return None  # above the top package: Python refuses it too
    base = parts[: len(parts) - (level - 1)]
    if module:
        base.append(module)
    return ".".join(base) or None


def absolute_imports(index: FileIndex, package: str | None) -> dict[str, str]:
    """A file's imports by local name, its relative ones (`from .limits import X`)
    made absolute in `package` (dropped outside a package): what its names mean in
    the tree."""
    if not index.relative:
        return index.imports
    found = dict(index.imports)
    for local, (level, module, name) in index.relative.items():
        base = absolute(package, level, module)
        if base is not None:
            found[local] = f"{base}.{name}"
    return found


def dotted_name(node: ast.expr, imports: dict[str, str]) -> str | None:
    """`t.Annotated` -> `typing.Annotated`, `limits.Speed` -> `my_pkg.limits.Speed`,
    when the first name comes from `imports`."""
    if isinstance(node, ast.Name):
        return imports.get(node.id)
    if isinstance(node, ast.Attribute):
        base = dotted_name(node.value, imports)
        return f"{base}.{node.attr}" if base else None
    return None


def resolve(resolver: Resolver | None, qualified: str) -> Imported | None:
    """What `qualified` (`my_pkg.util.normalize`) stands for: the longest prefix that
    is a module of the tree, then its members; None when nothing is known of it.
    (Stubs of libraries outside the tree would be asked here, after the tree.)"""
    if resolver is None or not qualified:
        return None
    memo = resolver.resolved
    if qualified not in memo:
        memo[qualified] = _resolve(resolver, qualified, 0)
    return memo[qualified]


def resolve_library(ctx: object, qualified: str) -> stubs.Function | stubs.Class | None:
    """What an imported name stands for outside the checked code: today its stub
    (the user's `stub-paths`, then the shipped ones), else None (unknown). The one
    place to join with the modules of the checked tree (searched before stubs)."""
    return stub_set_of(ctx).lookup(qualified)


def stub_set_of(ctx: object) -> stubs.StubSet:
    """The stubs a file's context reads (its `stub-paths`, then the shipped ones)."""
    found: stubs.StubSet = getattr(ctx, "stubs", None) or stubs.stub_set()
    return found


def _resolve(resolver: Resolver, qualified: str, hops: int) -> Imported | None:
    parts = qualified.split(".")
    for cut in range(len(parts), 0, -1):
        module = ".".join(parts[:cut])
        summary = resolver.module(module)
        if summary is not None:
            return _member(resolver, module, summary, parts[cut:], hops)
    return None


def _member(
    resolver: Resolver,
    module: str,
    summary: ModuleSummary,
    rest: list[str],
    hops: int,
) -> Imported | None:
    if not rest:
        return summary
    name, more = rest[0], rest[1:]
    resolver.member(module, summary, name)  # all that is read below is of `name`
    if name in summary.functions:
        return summary.functions[name] if not more else None
    if name in summary.classes:
        cls = summary.classes[name]
        if not more:
            return cls
        if len(more) == 1:
            return dict(cls.constants).get(more[0]) or dict(cls.methods).get(more[0])
        return None
    if name in summary.constants:
        return summary.constants[name] if not more else None
    if name in summary.aliases:
        return summary.aliases[name] if not more else None
    target = summary.reexports.get(name)
    if target is not None and hops < MAX_HOPS:
        return _resolve(resolver, ".".join([target, *more]), hops + 1)
    return None


def alias(resolver: Resolver | None, qualified: str | None) -> Alias | None:
    """An imported type alias or metadata string (`from .units import Meters`)."""
    found = resolve(resolver, qualified) if qualified else None
    return found if isinstance(found, Alias) else None


def constant(resolver: Resolver | None, qualified: str) -> Value | None:
    """An imported constant (`from .limits import MAX_SPEED`), with its unit."""
    found = resolve(resolver, qualified)
    return found if isinstance(found, Value) else None


def method_name(class_name: str, attr: str) -> str:
    return f"{class_name}.{attr}"


def call_arguments(
    function: FunctionSummary,
    args: list[Value],
    kwargs: dict[str | None, Value],
    bound: bool,
) -> dict[str, Value]:
    """Which parameter each argument gives (starred arguments are not followed)."""
    params = list(function.params)
    if bound and function.method and params:
        params = params[1:]
    given: dict[str, Value] = dict(zip(params, args, strict=False))
    known = set(function.params) | set(function.keywords)
    given.update({k: v for k, v in kwargs.items() if k is not None and k in known})
    return given


def starred(node: ast.Call, kwargs: dict[str | None, Value]) -> bool:
    """`f(*xs)` or `f(**kw)`: which parameter gets which argument is unknown."""
    if None in kwargs:
        return True
    for arg in node.args:  # noqa: SIM110 (no generator per call: 51,588 on corpus25)
        if isinstance(arg, ast.Starred):
            return True
    return False


class Symbols(Protocol):
    """What `call` needs of the file's context: a fresh unknown value."""

    def fresh(
        self, kind: str, description: str | ast.AST, unit: object = None
    ) -> Value: ...


class RefinedChecks(Protocol):
    """What `call` needs of the refinement checks (`analysis/refined.py`): an
    argument checked against a parameter's refinement, a result assumed to meet
    its own."""

    def assign_refined(
        self,
        state: State,
        name: str,
        decl: Refinement,
        value: Value,
        site: ast.AST,
        lookup: dict[str, A.Expr],
        leaving: bool = False,
    ) -> Value: ...

    def assumed(
        self, state: State, name: str, decl: Refinement, lookup: dict[str, A.Expr]
    ) -> Value: ...


class Typed(Protocol):
    """What `call` needs of the evaluator's lookups (`analysis/lookups.py`): a
    value of the type a summary gives a function's result."""

    def typed(
        self,
        found: Type | None,
        node: ast.AST,
        state: State,
        label: str | None = None,
    ) -> Value: ...


class Site(Protocol):
    """What a call into code RobotFix does not walk (an imported function, a
    library's stub: `library.Libraries`) needs of the walker that meets it."""

    site: ast.AST  # the statement being interpreted

    def note_sink(
        self,
        expr: ast.expr,
        unit: Unit | None,
        value: Value | None,
        integer: bool = False,
    ) -> None: ...


class Caller(Site, Protocol):
    """What `call` needs of the evaluator making the call (`analysis/calls.py`)."""

    @property
    def ctx(self) -> Symbols: ...

    @property
    def refined(self) -> RefinedChecks: ...

    @property
    def lookups(self) -> Typed: ...


def call(
    ev: Caller,
    function: FunctionSummary,
    args: list[Value],
    kwargs: dict[str | None, Value],
    node: ast.Call,
    state: State,
    bound: bool,
) -> Value:
    """A call of an imported function: each refined parameter is checked at the
    call, the refined return assumed (as for a function of the same file)."""
    if not function.decls and function.returns is None:  # nothing refined (most
        return ev.lookups.typed(function.result, node, state)  # unannotated code)
    given = call_arguments(function, args, kwargs, bound)
    terms = {k: v.term for k, v in given.items() if v.term is not None}
    decls = dict(function.decls)
    params = list(function.params)[1 if bound and function.method else 0 :]
    exprs = dict(zip(params, node.args, strict=False))
    exprs.update({k.arg: k.value for k in node.keywords if k.arg is not None})
    for name, value in given.items():
        decl = decls.get(name)
        if decl is not None:
            lookup = {**_unknowns(ev, decl), **terms}
            ev.refined.assign_refined(state, name, decl, value, ev.site, lookup)
            if name in exprs:  # for `robotfix suggest`: the argument met a unit
                ev.note_sink(exprs[name], decl.unit, value, decl.base == "int")
    if function.returns is None:
        return ev.lookups.typed(function.result, node, state)
    lookup = {**_unknowns(ev, function.returns), **terms}
    return ev.refined.assumed(state, f"{function.name}()", function.returns, lookup)


def _unknowns(ev: Caller, decl: Refinement) -> dict[str, A.Expr]:
    """Names a callee's refinement mentions besides its parameters (the summary
    already put in its module's constants): unknown values here."""
    found: dict[str, A.Expr] = {}
    for ref in [n for p in decl.predicates() for n in A.names(p)]:
        if ref.name != "_" and ref.name not in found:
            found[ref.name] = ev.ctx.fresh("unknown", f"`{ref.name}`").known_term
    return found
