"""What an expression is, found syntactically from a module's AST (cf. mypy's
semantic analysis and its inference of attribute types): the type model.

The interpreter asks it when it meets a value it did not build: a parameter, an
attribute read in a method that did not set it (`self.left`, set in `__init__`),
what a helper returns, an element of a container. The answers are types, never
values; the interpreter makes the value (a received message, an instance, a list
whose elements are of a type).

Where the types come from:
- declared annotations: parameters, `self.x: T`, class-level `x: T`, a function's
  `-> T`; `Optional[T]` and `T | None` are T that may be None, `Annotated`,
  `Final`, `ClassVar` are looked through; `list[T]`, `tuple[...]`, `dict[K, V]`
  and their `typing` spellings give element types;
- assignments: an attribute assigned in any method of its class (or of a class of
  the file above or below it) has a type only when every assignment of it agrees
  (a `None` aside); a function without an annotation returns the type all its
  `return` statements agree on;
- expressions: a constructor call, a message's field (its type in the catalog), a
  local bound once, a parameter, an element of a typed container, a call of a typed
  function, a display or comprehension whose elements agree;
- stubs (`robotfix/stubs/`): a class a stub describes is a type too (`last: Time`,
  `dict[int, rospy.Duration]`), and so is what a stub's function, method, property
  or operator returns (`self.get_clock().now()` through the node's stub base,
  `now - self.last` by `Time.__sub__`'s overload for a Time).

Anything else is unknown (None), and the interpreter then reports nothing new. The
model is computed on demand, once per module and question, and another module's
types come through its summary (`imported.ClassSummary.types`,
`imported.FunctionSummary.result`).
"""

from __future__ import annotations

import ast
import weakref
from collections.abc import Mapping
from typing import TYPE_CHECKING, Protocol

from robotfix.analysis import imported
from robotfix.analysis.imported import resolve_library
from robotfix.analysis.typesyntax import (
    Binding,
    BoundAnnotation,
    BoundElement,
    bind_types,
    is_ellipsis,
    is_none,
    last_name,
    local_bindings,
    self_stores,
)
from robotfix.analysis.typeterms import (
    Lib,
    Map,
    Maybe,
    Msg,
    Obj,
    Seq,
    Tup,
    Type,
    element,
    plain,
)
from robotfix.stubs import load as stubs

if TYPE_CHECKING:
    from robotfix.analysis.context import FileContext, Scope


class FunctionView(Protocol):
    """What the model needs of a function of the file (`program.Function`)."""

    @property
    def node(self) -> ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda: ...

    @property
    def class_name(self) -> str | None: ...

    @property
    def decorators(self) -> frozenset[str]: ...

    @property
    def first_parameter(self) -> str | None: ...

    @property
    def is_method(self) -> bool: ...


class ProgramView(Protocol):
    """What the model needs of the file's definitions (`program.Program`)."""

    @property
    def functions(self) -> Mapping[str, FunctionView]: ...

    @property
    def classes(self) -> Mapping[str, Scope]: ...

    @property
    def bases(self) -> Mapping[str, list[str]]: ...


SEQUENCE_FORMS = frozenset(
    {"list", "set", "frozenset", "deque", "Sequence", "MutableSequence"}
    | {"List", "Set", "FrozenSet", "Deque", "Iterable", "Iterator", "Collection"}
    | {"AbstractSet", "MutableSet", "Generator"}
)
MAP_FORMS = frozenset(
    {"dict", "Dict", "Mapping", "MutableMapping", "OrderedDict", "DefaultDict"}
    | {"defaultdict"}
)
LOOKED_THROUGH = frozenset(
    {"Annotated", "Final", "ClassVar", "Required", "NotRequired"}
)
# the stubs' operator methods (`Time.__sub__`) by the AST's operator
OPERATOR_METHODS = {
    ast.Add: "__add__",
    ast.Sub: "__sub__",
    ast.Mult: "__mul__",
    ast.Div: "__truediv__",
}
MAX_DEPTH = 12  # inference follows at most this many names, calls and returns


def _agree(found: list[Type | None]) -> Type | None:
    """The one type every source gives; None-only sources (a `None`) make it
    Optional; any unknown or disagreeing source makes it unknown."""
    kinds = [f for f in found if f is not _NONE]
    if not kinds or any(k is None for k in kinds):
        return None
    first = plain(kinds[0])
    if any(plain(k) != first for k in kinds):
        return None
    optional = len(kinds) < len(found) or any(isinstance(k, Maybe) for k in kinds)
    return Maybe(first) if optional and first is not None else first


_NONE = Msg("\0none")  # `None` while types are joined; never handed out


class TypeModel:
    """A module's types, asked by the interpreter: `annotation`, `attribute`,
    `returns`, `parameter`, `local`; each answer computed once."""

    def __init__(self, ctx: FileContext, program: ProgramView) -> None:
        self.ctx = ctx
        # the program owns the model: a strong reference back would be a cycle
        # that keeps the file's tree alive until the cycle collector runs
        self._program = weakref.ref(program)
        self._attributes: dict[tuple[str, str], Type | None] = {}
        self._returns: dict[str, Type | None] = {}
        self._assigned: dict[str, dict[str, list[tuple[ast.expr, FunctionView]]]] | None
        self._assigned = None
        self._locals: dict[int, dict[str, list[Binding]]] = {}
        self._declared: dict[str, dict[str, ast.expr]] | None = None
        self._busy: set[object] = set()  # questions being answered (recursion)
        self._families: dict[str, list[str]] = {}
        self._library_bases: dict[str, list[stubs.Class]] = {}
        self._walrus: bool | None = None  # the file's text holds `:=` (asked once)

    @property
    def program(self) -> ProgramView:
        program = self._program()
        assert program is not None, "asked after its program was freed"
        return program

    # -- annotations -----------------------------------------------------------
    def annotation(self, node: ast.expr | None) -> Type | None:
        """The type a type form names (`Twist`, `list[Range]`, `Optional[Driver]`,
        `"Driver"`), or None."""
        if node is None:
            return None
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            if len(node.value) > 200:
                return None
            try:  # read, never evaluated
                parsed = ast.parse(node.value.strip(), mode="eval").body
            except (SyntaxError, ValueError, RecursionError):
                return None
            return self.annotation(parsed)
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.BitOr):
            return self._union([node.left, node.right])
        if isinstance(node, ast.Subscript):
            return self._generic(node)
        if isinstance(node, (ast.Name, ast.Attribute)):
            return self._named(node)
        return None

    def _generic(self, node: ast.Subscript) -> Type | None:
        head = last_name(node.value)
        args = (
            list(node.slice.elts) if isinstance(node.slice, ast.Tuple) else [node.slice]
        )
        if head in LOOKED_THROUGH:
            return self.annotation(args[0])
        if head == "Optional":
            inner = self.annotation(args[0])
            return Maybe(inner) if inner is not None else None
        if head == "Union":
            return self._union(args)
        if head in SEQUENCE_FORMS:
            item = self.annotation(args[0])
            return Seq(item) if item is not None else None
        if head in MAP_FORMS and len(args) == 2:
            value = self.annotation(args[1])
            return Map(value) if value is not None else None
        if head in ("tuple", "Tuple"):
            if len(args) == 2 and is_ellipsis(args[1]):
                item = self.annotation(args[0])
                return Seq(item) if item is not None else None
            return Tup(tuple(self.annotation(a) for a in args))
        return None

    def _union(self, parts: list[ast.expr]) -> Type | None:
        found = [
            _NONE if is_none(p) else self.annotation(p) for p in parts
        ]  # `T | None`
        return _agree(found)

    def _named(self, node: ast.Name | ast.Attribute) -> Type | None:
        msg_type = self.ctx.msg_type_of(node)
        if msg_type is not None:
            return Msg(msg_type)
        if isinstance(node, ast.Name) and node.id in self.program.classes:
            return Obj(node.id)
        dotted = self.ctx.qualname(node)
        if dotted is not None and "." in dotted:
            found = imported.resolve(self.ctx.resolver, dotted)
            if isinstance(found, imported.ClassSummary):
                return Obj(dotted)
            if found is None:  # `last: Time`, `dict[int, rospy.Duration]`
                return self.library(dotted)
        return None

    def library(self, qualified: str | None) -> Type | None:
        """What a stub's class name stands for (an annotation, a stub's return):
        a message of the catalog, an object of a stub class, else None."""
        if not qualified:
            return None
        msg_type = self.ctx.msg_type_named(qualified)
        if msg_type is not None:
            return Msg(msg_type)
        found = resolve_library(self.ctx, qualified)
        return Lib(found.qualname) if isinstance(found, stubs.Class) else None

    def library_bases(self, class_name: str) -> list[stubs.Class]:
        """The stub classes a class of this file derives from (`Node`), nearest
        first, through the file's classes it derives from (asked at every
        `self.x` read of such a class: kept)."""
        kept = self._library_bases.get(class_name)
        if kept is not None:
            return kept
        found: list[stubs.Class] = self._library_bases.setdefault(class_name, [])
        for name in self._up(class_name):
            node = self.program.classes[name].node
            for base in node.bases if isinstance(node, ast.ClassDef) else ():
                if isinstance(base, ast.Name) and base.id in self.program.classes:
                    continue
                qualified = self.ctx.qualname(base)
                cls = resolve_library(self.ctx, qualified) if qualified else None
                if isinstance(cls, stubs.Class):
                    found.append(cls)
        return found

    def _stub_member(self, owner: Type | None, attr: str) -> stubs.Function | None:
        """The stub method or property `attr` of an object of a stub class."""
        cls = resolve_library(self.ctx, owner.name) if isinstance(owner, Lib) else None
        if not isinstance(cls, stubs.Class):
            return None
        return imported.stub_set_of(self.ctx).member(cls, attr)

    # -- what the interpreter asks --------------------------------------------
    def parameter(self, function: FunctionView, name: str) -> Type | None:
        """A parameter's declared type (the first one of a method: its class)."""
        node = function.node
        args = node.args
        ordered = [*args.posonlyargs, *args.args]
        if ordered and ordered[0].arg == name and function.is_method:
            return None  # `self` and `cls` are the interpreter's own
        defaults = dict(
            zip([a.arg for a in ordered][::-1], args.defaults[::-1], strict=False)
        )
        defaults.update(
            (a.arg, d)
            for a, d in zip(args.kwonlyargs, args.kw_defaults, strict=True)
            if d is not None
        )
        for arg in [*ordered, *args.kwonlyargs]:
            if arg.arg == name:
                found = self.annotation(arg.annotation)
                if found is not None and is_none(defaults.get(name)):
                    # `client: Client = None`: it may be None
                    return Maybe(plain(found))  # type: ignore[arg-type]
                return found
        if args.vararg is not None and args.vararg.arg == name:
            item = self.annotation(args.vararg.annotation)
            return Seq(item) if item is not None else None
        return None

    def attribute(self, class_name: str, attr: str) -> Type | None:
        """The type of `self.<attr>` in the methods of `class_name` (this file's, or
        another module's by its dotted name)."""
        key = (class_name, attr)
        if key in self._attributes:
            return self._attributes[key]
        if key in self._busy:
            return None
        self._busy.add(key)
        try:
            if class_name not in self.program.classes:
                found = self._imported_attribute(class_name, attr)
            else:
                found = self._own_attribute(class_name, attr)
        finally:
            self._busy.discard(key)
        self._attributes[key] = found
        return found

    def returns(self, key: str) -> Type | None:
        """What the function `key` of this file returns: its annotation, else what
        all its `return` statements agree on."""
        if key in self._returns:
            return self._returns[key]
        function = self.program.functions.get(key)
        if function is None or key in self._busy or len(self._busy) > MAX_DEPTH:
            return None
        self._busy.add(key)
        try:
            found = self._function_returns(function)
        finally:
            self._busy.discard(key)
        self._returns[key] = found
        return found

    def class_types(self, class_name: str) -> dict[str, Type]:
        """Every attribute of a class of this file with a known type (for its
        module summary)."""
        names = set(self._declarations().get(class_name, {}))
        names |= set(self._assignments().get(class_name, {}))
        found = {}
        for name in sorted(names):
            known = self.attribute(class_name, name)
            if known is not None:
                found[name] = known
        return found

    # -- attributes ----------------------------------------------------------
    def _imported_attribute(self, class_name: str, attr: str) -> Type | None:
        if "." not in class_name:
            return None
        found = imported.resolve(self.ctx.resolver, class_name)
        if isinstance(found, imported.ClassSummary):
            return dict(found.types).get(attr)
        return None

    def _up(self, class_name: str) -> list[str]:
        """The class and the classes of this file it derives from, nearest first."""
        found, todo = [], [class_name]
        while todo:
            name = todo.pop(0)
            if name not in found and name in self.program.classes:
                found.append(name)
                todo.extend(self.program.bases.get(name, []))
        return found

    def _family(self, class_name: str) -> list[str]:
        """The class, the file's classes it derives from, and those derived from it:
        an attribute of `self` may be assigned in any of them."""
        found = self._families.get(class_name)
        if found is None:
            up = self._up(class_name)
            found = self._families[class_name] = up + [
                name
                for name in self.program.classes
                if name not in up and self._derives(name, class_name)
            ]
        return found

    def _derives(self, name: str, ancestor: str) -> bool:
        seen, todo = set(), list(self.program.bases.get(name, []))
        while todo:
            base = todo.pop()
            if base == ancestor:
                return True
            if base not in seen:
                seen.add(base)
                todo.extend(self.program.bases.get(base, []))
        return False

    def _own_attribute(self, class_name: str, attr: str) -> Type | None:
        family = self._family(class_name)
        declarations = self._declarations()
        assignments = self._assignments()
        for name in family:
            declared = declarations.get(name, {}).get(attr)
            if declared is not None:
                found = self.annotation(declared)
                if found is not None and any(
                    is_none(value)
                    for other in family
                    for value, _ in assignments.get(other, {}).get(attr, [])
                ):  # `self.x: Driver = None`: it may be None
                    return Maybe(plain(found))  # type: ignore[arg-type]
                return found
        sources: list[Type | None] = []
        for name in family:
            for value, function in assignments.get(name, {}).get(attr, []):
                sources.append(_NONE if is_none(value) else self.infer(value, function))
                if sources[-1] is None:
                    return None
        return _agree(sources) if sources else None

    def _declarations(self) -> dict[str, dict[str, ast.expr]]:
        """class -> attribute -> its annotation (`x: T` in the class body,
        `self.x: T` in a method; the first one written)."""
        if self._declared is None:
            self._declared = {}
            for class_name, scope in self.program.classes.items():
                known = self.ctx.index.scopes.get(id(scope.node))
                table = self._declared.setdefault(class_name, {})
                for annotation, target in known.annotated if known else []:
                    table.setdefault(target, annotation)
            for class_name, attribute, annotation in sorted(
                self.ctx.index.attributes, key=lambda a: (a[2].lineno, a[2].col_offset)
            ):
                self._declared.setdefault(class_name, {}).setdefault(
                    attribute, annotation
                )
        return self._declared

    def _assignments(self) -> dict[str, dict[str, list[tuple[ast.expr, FunctionView]]]]:
        """class -> attribute -> the values assigned to `self.<attribute>` in its
        methods (and `x = ...` in its body); an assignment whose value cannot be
        told (`self.a, self.b = f()`, `self.n += 1`, `for self.x in ...`) is
        recorded as an unknown value (`ast.expr()`), which makes the type unknown."""
        if self._assigned is not None:
            return self._assigned
        found: dict[str, dict[str, list[tuple[ast.expr, FunctionView]]]] = {}
        for function in self.program.functions.values():
            name = function.class_name
            node = function.node
            if name is None or not function.is_method or isinstance(node, ast.Lambda):
                continue
            params = [*node.args.posonlyargs, *node.args.args]
            if not params:
                continue
            table = found.setdefault(name, {})
            for attr, value in self_stores(node, params[0].arg):
                table.setdefault(attr, []).append((value, function))
        self._assigned = found
        return found

    # -- returns -------------------------------------------------------------
    def _function_returns(self, function: FunctionView) -> Type | None:
        node = function.node
        if isinstance(node, ast.Lambda):
            return self.infer(node.body, function)
        if node.returns is not None:
            return self.annotation(node.returns)
        values = [r.value for r in self._returns_of(node)]
        if not values or any(v is None for v in values):
            return None
        return _agree(
            [_NONE if is_none(v) else self.infer(v, function) for v in values]  # type: ignore[arg-type]
        )

    def _returns_of(self, node: ast.AST) -> list[ast.Return]:
        """The function's own `return` statements (not those of nested functions),
        as the file's index found them; a generator's are not followed."""
        index = self.ctx.index
        if id(node) in index.generators:
            return [ast.Return(value=None)]
        return index.returns.get(id(node), [])

    # -- expressions ---------------------------------------------------------
    def infer(
        self,
        node: ast.expr,
        function: FunctionView | None,
        env: dict[str, Type | None] | None = None,
    ) -> Type | None:
        """The type of `node` in `function` (None: at module level), syntactically;
        `env`: names a comprehension binds."""
        if len(self._busy) > MAX_DEPTH:
            return None
        kind = type(node)
        if kind is ast.Call:
            return self._call(node, function, env)  # type: ignore[arg-type]
        if kind is ast.Name:
            return self._name(node.id, function, env)  # type: ignore[attr-defined]
        if kind is ast.Attribute:
            return self._attribute(node, function, env)  # type: ignore[arg-type]
        if kind is ast.Subscript:
            base = plain(self.infer(node.value, function, env))  # type: ignore[attr-defined]
            if isinstance(node.slice, ast.Slice):  # type: ignore[attr-defined]
                return base if isinstance(base, Seq) else None
            index = node.slice  # type: ignore[attr-defined]
            if isinstance(base, Tup) and isinstance(index, ast.Constant):
                at = index.value
                if isinstance(at, int) and -len(base.items) <= at < len(base.items):
                    return base.items[at]
                return None
            return element(base)
        if kind in (ast.List, ast.Set, ast.Tuple):
            items = [self.infer(e, function, env) for e in node.elts]  # type: ignore[attr-defined]
            if kind is ast.Tuple:
                return Tup(tuple(items))
            joined = _agree(items) if items else None
            return Seq(joined) if joined is not None else None
        if kind in (ast.ListComp, ast.SetComp, ast.GeneratorExp):
            item = self._comprehension(node, function, env)  # type: ignore[arg-type]
            return Seq(item) if item is not None else None
        if kind is ast.IfExp:
            return _agree(
                [
                    _NONE if is_none(n) else self.infer(n, function, env)
                    for n in (node.body, node.orelse)  # type: ignore[attr-defined]
                ]
            )
        if kind is ast.NamedExpr:
            return self.infer(node.value, function, env)  # type: ignore[attr-defined]
        if kind is ast.BinOp:
            return self._operation(node, function, env)  # type: ignore[arg-type]
        return None

    def _operation(
        self,
        node: ast.BinOp,
        function: FunctionView | None,
        env: dict[str, Type | None] | None,
    ) -> Type | None:
        """`now - self.last`: what the left operand's operator method returns (its
        `@overload` for the right operand's class), when the left operand is of a
        stub class (the reflected methods are the interpreter's: they need the
        other operand's kind, a value's)."""
        name = OPERATOR_METHODS.get(type(node.op))
        left = plain(self.infer(node.left, function, env))
        if name is None or not isinstance(left, Lib):
            return None
        right = plain(self.infer(node.right, function, env))
        keys = [f"{name}:{right.name}", name] if isinstance(right, Lib) else [name]
        for key in keys:
            method = self._stub_member(left, key)
            if method is not None:
                return self.library(method.returns_type)
        return None

    def _comprehension(
        self,
        node: ast.ListComp | ast.SetComp | ast.GeneratorExp,
        function: FunctionView | None,
        env: dict[str, Type | None] | None,
    ) -> Type | None:
        inner = dict(env or {})
        for generator in node.generators:
            item = element(self.infer(generator.iter, function, inner))
            bind_types(generator.target, item, inner)
        return self.infer(node.elt, function, inner)

    def _call(
        self,
        node: ast.Call,
        function: FunctionView | None,
        env: dict[str, Type | None] | None,
    ) -> Type | None:
        func = node.func
        if isinstance(func, ast.Name):
            if env is not None and func.id in env:
                return None
            if function is not None and func.id == function.first_parameter:
                # `cls(...)` in a classmethod
                if "classmethod" in function.decorators and function.class_name:
                    return Obj(function.class_name)
                return None
            if self._is_local(func.id, function):
                return None
            if func.id in self.program.classes:
                return Obj(func.id)
            if func.id in self.program.functions:
                return self.returns(func.id)
        elif isinstance(func, ast.Attribute):
            owner = func.value
            if (
                isinstance(owner, ast.Name)
                and owner.id in self.program.classes
                and not self._is_local(owner.id, function)
            ):  # Path.turn()
                return self._method_returns(owner.id, func.attr)
            receiver = plain(self._receiver(owner, function, env))
            if isinstance(receiver, Obj):  # self.make(), cls.make(), driver.read()
                return self._method_returns(receiver.name, func.attr)
            if isinstance(receiver, Lib):  # self.get_clock().now(), last.to_msg()
                method = self._stub_member(receiver, func.attr)
                return self.library(method.returns_type) if method else None
            interface = self.ctx.interface_of(owner)  # AddTwoInts.Request()
            if interface is not None:
                found = self.ctx.msg_type_named(
                    f"{interface.replace('/', '.msg.')}_{func.attr}"
                )
                return Msg(found) if found else None
        else:
            return None
        msg_type = self.ctx.msg_type_of(func)
        if msg_type is not None:
            return Msg(msg_type)
        dotted = self.ctx.qualname(func)
        if dotted is not None and "." in dotted:
            known = imported.resolve(self.ctx.resolver, dotted)
            if isinstance(known, imported.ClassSummary):
                return Obj(dotted)
            if isinstance(known, imported.FunctionSummary):
                return known.result
            if known is None:  # rospy.Time.now(), Time(), Duration.from_msg(m)
                stub = resolve_library(self.ctx, dotted)
                if isinstance(stub, stubs.Class):
                    return Lib(stub.qualname)
                if isinstance(stub, stubs.Function) and stub.kind != "property":
                    return self.library(stub.returns_type)
        return None

    def _receiver(
        self,
        owner: ast.expr,
        function: FunctionView | None,
        env: dict[str, Type | None] | None,
    ) -> Type | None:
        """What a method is called on: `self` (or `cls`) is an instance of its
        class, anything else is inferred."""
        if _is_self(owner, function, env):
            return Obj(function.class_name)  # type: ignore[union-attr,arg-type]
        return self.infer(owner, function, env)

    def _method_returns(self, class_name: str, method_name: str) -> Type | None:
        """What `method` of an instance of `class_name` returns (the first class up
        from it that defines the method)."""
        if class_name in self.program.classes:
            for name in self._up(class_name):
                key = f"{name}.{method_name}"
                if key in self.program.functions:
                    return self.returns(key)
            for cls in self.library_bases(class_name):  # `Node.get_clock()`
                method = imported.stub_set_of(self.ctx).member(cls, method_name)
                if method is not None and method.kind != "property":
                    return self.library(method.returns_type)
            return None
        found = imported.resolve(self.ctx.resolver, f"{class_name}.{method_name}")
        return found.result if isinstance(found, imported.FunctionSummary) else None

    def _attribute(
        self,
        node: ast.Attribute,
        function: FunctionView | None,
        env: dict[str, Type | None] | None,
    ) -> Type | None:
        owner = node.value
        if _is_self(owner, function, env):
            return self.attribute(function.class_name, node.attr)  # type: ignore[union-attr,arg-type]
        base = plain(self.infer(owner, function, env))
        if isinstance(base, Msg):
            return self.field(base.name, node.attr)
        if isinstance(base, Obj):
            return self.attribute(base.name, node.attr)
        if isinstance(base, Lib):  # a stub class's property or attribute
            member = self._stub_member(base, node.attr)
            if member is not None:
                return (
                    self.library(member.returns_type)
                    if member.kind == "property"
                    else None
                )
            cls = resolve_library(self.ctx, base.name)
            known = (
                imported.stub_set_of(self.ctx).attribute(cls, node.attr)
                if isinstance(cls, stubs.Class)
                else None
            )
            return self.library(known.type) if known is not None else None
        return None

    def field(self, msg_type: str, name: str) -> Type | None:
        """A message field's type: a sub-message or an array of them."""
        spec = self.ctx.catalog.lookup(msg_type)
        found = spec.fields.get(name) if spec is not None else None
        if found is None or found.kind != "msg" or found.msg_type is None:
            return None
        return Seq(Msg(found.msg_type)) if found.array else Msg(found.msg_type)

    def _name(
        self,
        name: str,
        function: FunctionView | None,
        env: dict[str, Type | None] | None,
    ) -> Type | None:
        if env is not None and name in env:
            return env[name]
        if function is None:
            return None
        node = function.node
        args = node.args
        if name in {a.arg for a in [*args.posonlyargs, *args.args, *args.kwonlyargs]}:
            return self.parameter(function, name)
        bound = self._bindings(function).get(name)
        if bound is None or len(bound) != 1 or bound[0] is None:
            return None
        key = (id(node), name)
        if key in self._busy:
            return None
        self._busy.add(key)
        try:
            value = bound[0]
            if isinstance(value, BoundAnnotation):
                return self.annotation(value.node)
            if isinstance(value, BoundElement):
                return element(self.infer(value.node, function))
            return self.infer(value, function)
        finally:
            self._busy.discard(key)

    def _is_local(self, name: str, function: FunctionView | None) -> bool:
        """Whether `name` is bound in `function` (a local shadows a class)."""
        if function is None:
            return False
        args = function.node.args
        params = {a.arg for a in [*args.posonlyargs, *args.args, *args.kwonlyargs]}
        return name in params or name in self._bindings(function)

    def _bindings(self, function: FunctionView) -> dict[str, list[Binding]]:
        found = self._locals.get(id(function.node))
        if found is None:
            if self._walrus is None:
                self._walrus = ":=" in self.ctx.source.text
            found = local_bindings(function.node, self._walrus)
            self._locals[id(function.node)] = found
        return found


def _is_self(
    owner: ast.expr, function: FunctionView | None, env: dict[str, Type | None] | None
) -> bool:
    """Whether `owner` is the first parameter of a method (`self`, `cls`), not
    rebound by a comprehension."""
    return (
        isinstance(owner, ast.Name)
        and function is not None
        and function.class_name is not None
        and function.is_method
        and owner.id == function.first_parameter
        and (env is None or owner.id not in env)
    )
