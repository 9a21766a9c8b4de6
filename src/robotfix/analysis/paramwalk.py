"""The syntactic walk that fills a file's parameter summary: declarations
(`declare_parameter`, `declare_parameters`, with the type rclpy infers and the
descriptor's ranges), ROS 1 reads, refinements attached where a read is assigned
to an `Annotated` target, node names and listeners, each with the owner the
calls are made on (`owner_of`). `parameters.summarize` runs it per function.
"""

from __future__ import annotations

import ast
import functools
import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from fractions import Fraction
from typing import TYPE_CHECKING

from robotfix.analysis import imported
from robotfix.analysis.constants import scan
from robotfix.analysis.index import FileIndex
from robotfix.analysis.paramsummary import (
    ROSPY,
    UNKNOWN,
    Attached,
    ParamDecl,
    Summary,
    constant_of,
    constants_of,
    exact,
)
from robotfix.analysis.paramunit import Placed, unit_nodes
from robotfix.analysis.program import call_argument
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Alias, Names, Refinement, extract
from robotfix.annotations.numbers import named_number
from robotfix.annotations.parser import parse_predicate
from robotfix.astwalk import walk
from robotfix.ros.api_model import (
    NODE_CONSTRUCTORS,
    PARAMETER_TYPES,
    PARAMETER_VALUE_FIELDS,
)
from robotfix.ros.rclpy_params import Range, python_type
from robotfix.source import SourceFile

if TYPE_CHECKING:
    from robotfix.stubs.load import Param as StubParam
    from robotfix.stubs.load import StubSet


def _python_constant(name: str, value: object) -> A.Expr | None:
    """A module constant (`_module_constants`) as a term labelled with its name; a
    float as the decimal Python shows (`0.3`, not its binary value), which orders
    as the floats do, as a parameter file's value is read (`paramcheck._term`)."""
    if isinstance(value, bool):
        return None  # a flag in a refinement: not worth a term
    if isinstance(value, int):
        return A.Num(Fraction(value), True, label=name)
    if isinstance(value, float) and math.isfinite(value):
        return A.Num(Fraction(repr(value)), False, label=name)
    if isinstance(value, str):
        return A.Str(value, label=name)
    return None


def owner_of(
    receiver: ast.expr, unit: str, class_name: str | None, self_name: str | None
) -> str | None:
    """Who a parameter call is made on (see the module docstring); None when the
    receiver is not a name or `self.attr`."""
    if isinstance(receiver, ast.Name):
        if class_name is not None and receiver.id == self_name:
            return class_name
        return f"{unit}#{receiver.id}"
    if (
        isinstance(receiver, ast.Attribute)
        and isinstance(receiver.value, ast.Name)
        and class_name is not None
        and receiver.value.id == self_name
    ):
        return f"{class_name}#{receiver.attr}"
    return None


def _no_message(node: ast.expr) -> str | None:
    return None  # parameters hold no messages


def _position(param: StubParam) -> int:
    """Where a call passes a stub's parameter by position (past any position a
    call has when it is keyword-only: `call_argument` then reads the keyword)."""
    if param.positional is None or param.variadic:
        return 1 << 30
    return param.positional


def _number_text(value: object) -> str | None:
    """A bound's constant as refinement text (`0.5`, `-1`); None if not a number."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    return repr(value) if math.isfinite(value) else None


def called_name(call: ast.Call) -> str:
    """The name a call calls: `declare_parameter` of `self.declare_parameter(...)`."""
    func = call.func
    return func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")


@dataclass
class _Local:
    """A local variable bound once, by a direct statement: the value it was bound
    to and the attribute stores on it (`d.read_only = True`) with their lines."""

    value: ast.expr
    stores: list[tuple[int, str, ast.expr]] = field(default_factory=list)


class Walker:
    def __init__(
        self,
        source: SourceFile,
        index: FileIndex,
        summary: Summary,
        constants: dict[str, object],
        resolver: imported.Resolver | None = None,
        stubs: StubSet | None = None,
    ) -> None:
        self.source = source
        self.index = index
        self.summary = summary
        self.constants = constants
        self.resolver = resolver
        self.stubs = stubs

    @functools.cached_property
    def _placed(self) -> Placed | None:
        """The index's calls by position (None: the index is not of this tree's,
        whose calls it would not hold)."""
        tree = self.source.tree
        if tree is None or id(tree) not in self.index.scopes:
            return None
        return Placed(self.index.calls)

    # -- names ------------------------------------------------------------------
    def qualname(self, node: ast.expr) -> str | None:
        return imported.dotted_name(node, self.index.imports)

    @functools.cached_property
    def _in_tree(self) -> dict[str, str]:
        """The imports, relative ones made absolute: what an alias or a constant a
        refinement names is in the tree (`imported.resolve`)."""
        package = self.resolver.package if self.resolver is not None else None
        return imported.absolute_imports(self.index, package)

    def const(self, node: ast.expr | None) -> object:
        if node is None:
            return UNKNOWN
        return constant_of(node, self.constants, self.index.imports)

    def text(self, node: ast.expr | None) -> str | None:
        found = self.const(node)
        return found if isinstance(found, str) else None

    # -- one function (or the module's statements) ------------------------------------
    def unit(
        self,
        key: str,
        cls: ast.ClassDef | None,
        function: ast.FunctionDef | ast.AsyncFunctionDef | None,
        body: list[ast.stmt],
    ) -> None:
        self.key = key
        self.cls = cls.name if cls is not None else None
        args = function.args.args if function is not None else []
        self.self_name = args[0].arg if cls is not None and args else None
        self.function = function
        self.body = body
        self._bound: dict[str, _Local] | None = None
        # a function's every node; the module's, but for its functions and classes
        for node in unit_nodes(body, function is not None, self._placed):
            if isinstance(node, ast.Call):
                self.call(node)
            else:
                self.assignment(node)  # type: ignore[arg-type]

    def _locals(self, body: list[ast.stmt]) -> dict[str, _Local]:
        """Names bound exactly once in the body, by a direct statement, whose
        attribute stores are direct statements too and that no call mutates."""
        stores: dict[str, int] = {}
        mutated: set[str] = set()
        for node in walk(body):
            if isinstance(node, ast.Name) and not isinstance(node.ctx, ast.Load):
                stores[node.id] = stores.get(node.id, 0) + 1
            elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
                root = node.func.value
                while isinstance(root, ast.Attribute):
                    root = root.value
                if isinstance(root, ast.Name) and node.func.value is not root:
                    mutated.add(root.id)
            elif (
                isinstance(node, ast.Attribute)
                and isinstance(node.ctx, ast.Store)
                and isinstance(node.value, ast.Name)
            ):
                stores.setdefault(f"{node.value.id}.", 0)
                stores[f"{node.value.id}."] += 1
        found: dict[str, _Local] = {}
        direct_attr: dict[str, int] = {}
        for statement in body:
            if (
                isinstance(statement, ast.Assign)
                and len(statement.targets) == 1
                and isinstance(statement.targets[0], ast.Name)
            ):
                found[statement.targets[0].id] = _Local(statement.value)
            elif (
                isinstance(statement, ast.Assign)
                and len(statement.targets) == 1
                and isinstance(statement.targets[0], ast.Attribute)
                and isinstance(statement.targets[0].value, ast.Name)
            ):
                target = statement.targets[0]
                assert isinstance(target.value, ast.Name)
                name = target.value.id
                direct_attr[name] = direct_attr.get(name, 0) + 1
                if name in found:
                    found[name].stores.append(
                        (statement.lineno, target.attr, statement.value)
                    )
        return {
            name: local
            for name, local in found.items()
            if stores.get(name) == 1
            and name not in mutated
            and stores.get(f"{name}.", 0) == direct_attr.get(name, 0)
        }

    # -- calls ------------------------------------------------------------------
    def call(self, call: ast.Call) -> None:
        name = called_name(call)
        func = call.func
        qualified = self.qualname(func) or ""
        if qualified in ("rospy.get_param",) or qualified.endswith(".rospy.get_param"):
            self.ros1_read(call)
        elif qualified == "rospy.init_node":
            self.node_name(ROSPY, call_argument(call, 0, "name"))
        elif isinstance(func, ast.Attribute) and name in (
            "declare_parameter",
            "declare_parameters",
        ):
            owner = owner_of(func.value, self.key, self.cls, self.self_name)
            if owner is not None:
                if name == "declare_parameter":
                    self.declare(owner, call, call, *self._declare_args(call))
                else:
                    self.declare_many(owner, call)
        elif name == "__init__" and self.cls is not None and self._on_self(call):
            self.init(call)
        elif name == "ParamListener" and isinstance(func, ast.Attribute):
            self.listener(call, func)
        elif self.stubs is not None and qualified:
            self.described(call, qualified)

    def described(self, call: ast.Call, qualified: str) -> None:
        """A call of a parameter API a stub describes (`@ros_parameter`): a read of
        the ROS 1 parameter it names, as `rospy.get_param`, its bounds a
        refinement of its value (`DTParam("~gain", min_value=0, max_value=1)`)."""
        from robotfix.stubs.load import Class

        assert self.stubs is not None
        found = self.stubs.lookup(qualified)
        if isinstance(found, Class):
            found = found.method("__init__")  # a class: its constructor
        if found is None or not found.parameter:
            return
        params = {p.name: p for p in found.params}
        given = {
            role: call_argument(call, _position(params[held]), held)
            for role, held in found.parameter
        }
        decl = self.ros1_read(call, given["name"], given.get("default"))
        bounds = [
            (op, text)
            for op, role in (("_ >= ", "low"), ("_ <= ", "high"))
            if (text := _number_text(self.const(given.get(role)))) is not None
        ]
        if decl is None or not bounds:
            return
        text = " and ".join(op + number for op, number in bounds)
        refinement = Refinement("other", None, parse_predicate(text), text, call.lineno)
        shown = f'{found.short}("{decl.name}")'  # the notes' "annotation of ..."
        self.summary.attached.append(
            Attached(ROSPY, decl.name, refinement, shown, decl.path, decl.line, True)
        )

    def _on_self(self, call: ast.Call) -> bool:
        """`super().__init__(...)` or `Base.__init__(self, ...)`."""
        func = call.func
        assert isinstance(func, ast.Attribute)
        if isinstance(func.value, ast.Call) and called_name(func.value) == "super":
            return True
        return bool(
            call.args
            and isinstance(call.args[0], ast.Name)
            and call.args[0].id == self.self_name
        )

    def init(self, call: ast.Call) -> None:
        assert self.cls is not None and isinstance(call.func, ast.Attribute)
        shift = 0 if isinstance(call.func.value, ast.Call) else 1
        self.node_name(self.cls, call_argument(call, shift, "node_name"))
        self._auto_declare(self.cls, call)

    def _auto_declare(self, owner: str, call: ast.Call) -> None:
        for kw in call.keywords:
            if kw.arg == "allow_undeclared_parameters" and (
                self.const(kw.value) is not False
            ):
                self.summary.open_owners.add(owner)
            if kw.arg == "automatically_declare_parameters_from_overrides" and (
                self.const(kw.value) is not False
            ):
                self.summary.auto_declare.add(owner)

    def node_name(self, owner: str, node: ast.expr | None) -> None:
        name = self.text(node)
        if name is None and isinstance(node, ast.Name) and self.function is not None:
            name = self._parameter_default(node.id)
        if name:
            names = self.summary.node_names.setdefault(owner, [])
            if name not in names:
                names.append(name)

    def _parameter_default(self, name: str) -> str | None:
        """`def __init__(self, node_name='talker')`: the default of a parameter."""
        assert self.function is not None
        args = self.function.args
        positional = [*args.posonlyargs, *args.args]
        defaults = dict(
            zip(
                [a.arg for a in positional[len(positional) - len(args.defaults) :]],
                args.defaults,
                strict=True,
            )
        )
        defaults.update(
            {
                a.arg: d
                for a, d in zip(args.kwonlyargs, args.kw_defaults, strict=True)
                if d is not None
            }
        )
        return self.text(defaults.get(name))

    def listener(self, call: ast.Call, func: ast.Attribute) -> None:
        """`admittance_controller.ParamListener(self)`: the node uses the
        generate_parameter_library definitions whose root key is
        `admittance_controller`."""
        namespace = func.value
        if not call.args:
            return
        if isinstance(namespace, ast.Attribute):
            key = namespace.attr
        elif isinstance(namespace, ast.Name):
            key = namespace.id
        else:
            return
        owner = owner_of(call.args[0], self.key, self.cls, self.self_name)
        if owner is not None:
            found = self.summary.listeners.setdefault(owner, [])
            if key not in found:
                found.append(key)

    def assignment(self, node: ast.Assign | ast.AnnAssign) -> None:
        value = node.value
        targets = node.targets if isinstance(node, ast.Assign) else [node.target]
        if value is None or len(targets) != 1:
            return
        target = targets[0]
        if isinstance(value, ast.Call) and called_name(value) in NODE_CONSTRUCTORS:
            owner = self._target_owner(target)
            if owner is not None:
                self.node_name(owner, call_argument(value, 0, "node_name"))
                self._auto_declare(owner, value)
            return
        read = read_call(value, self.qualname)
        if read is None:
            return
        call, declaration = read
        annotation = node.annotation if isinstance(node, ast.AnnAssign) else None
        refinement, label = self._refinement_of(target, annotation)
        if refinement is None:
            return
        owner, pname = self._read_owner(call)
        if owner is None or pname is None:
            return
        with_default = declaration and (
            call_argument(call, 1, "default" if owner == ROSPY else "value") is not None
        )
        self.summary.attached.append(
            Attached(
                owner,
                pname,
                refinement,
                label,
                self.source.path,
                node.lineno,
                with_default,
            )
        )

    def _target_owner(self, target: ast.expr) -> str | None:
        if isinstance(target, ast.Name):
            return f"{self.key}#{target.id}"
        return owner_of(target, self.key, self.cls, self.self_name)

    def _read_owner(self, call: ast.Call) -> tuple[str | None, str | None]:
        if isinstance(call.func, ast.Attribute) and called_name(call) in (
            "declare_parameter",
            "get_parameter",
        ):
            owner = owner_of(call.func.value, self.key, self.cls, self.self_name)
            return owner, self.text(call_argument(call, 0, "name"))
        return ROSPY, self.text(call_argument(call, 0, "param_name"))

    def _refinement_of(
        self, target: ast.expr, annotation: ast.expr | None
    ) -> tuple[Refinement | None, str]:
        if isinstance(target, ast.Name):
            label = target.id
            if annotation is None:
                scope = self.function if self.function is not None else self.module
                names = self.index.scopes.get(id(scope))
                found = [a for a, t in (names.annotated if names else []) if t == label]
                annotation = found[0] if found else None
        elif (
            isinstance(target, ast.Attribute)
            and isinstance(target.value, ast.Name)
            and self.cls is not None
            and target.value.id == self.self_name
        ):
            label = f"{target.value.id}.{target.attr}"
            if annotation is None:
                annotation = self._attribute_annotation(target.attr)
        else:
            return None, ""
        if annotation is None:
            return None, label
        short = label.rsplit(".", 1)[-1]
        found_refinement, _ = extract(
            annotation,
            short,
            self.qualname,
            _no_message,
            self.source.segment,
            self.source.char_col,
            alias=self.alias_of,
        )
        if found_refinement is None:
            return None, label
        # the constants put in, as the analysis reads them (`_ <= MAX`), each shown
        # by its name: a parameter file's value is a number to test
        terms = {
            n.name: term
            for n in A.names(found_refinement.predicate)
            if (term := self._constant_term(n.name))
        }
        predicate = A.substitute(found_refinement.predicate, terms)
        return replace(found_refinement, predicate=predicate), label

    def _constant_term(self, name: str) -> A.Expr | None:
        """A module constant, a named number (`math.pi`), a class constant
        (`Driver.MAX`, `self.MAX`, or `MAX` in the class), or a constant imported
        from the tree (`from .limits import MAX`), as a term labelled with its name:
        the names the analysis reads as constants in a refinement."""
        head, dot, rest = name.partition(".")
        in_class = self._class_constant(head, rest) if dot else None
        if not dot and self.cls is not None:
            in_class = self._class_constant(self.cls, name)
            module = self.constants.get(name, in_class)
            if in_class is not None and module != in_class:
                return None  # a class and a module constant of one name disagree
        if in_class is not None:
            return _python_constant(name, in_class)
        if name in self.constants:
            return _python_constant(name, self.constants[name])
        qualified = self.index.imports.get(head)
        number = named_number(f"{qualified}{dot}{rest}") if qualified else None
        if number is not None:  # infinity too: 10**400, above every double
            return A.Num(number, False, label=name)
        base = self._in_tree.get(head)
        found = imported.constant(self.resolver, f"{base}{dot}{rest}") if base else None
        return A.labelled(found.term, name) if found is not None else None

    def _class_constant(self, owner: str, attr: str) -> object | None:
        """`Driver.MAX` (or `self.MAX` in Driver's methods): a constant of a class
        of this module, by the analysis's rule (`constants.scan`)."""
        if owner == self.self_name and self.cls is not None:
            owner = self.cls
        return self._class_constants.get(owner, {}).get(attr)

    @functools.cached_property
    def _class_constants(self) -> dict[str, dict[str, object]]:
        tree = self.source.tree
        if tree is None:
            return {}
        source = self.source
        names = scan(tree, self.index, self.qualname, ":=" in source.text, source.lines)
        return {
            cls.name: constants_of(
                cls.body,
                names.classes.get(cls.name, set()).__contains__,
                self.constants,
                self.index.imports,
            )
            for cls in tree.body
            if isinstance(cls, ast.ClassDef) and names.classes.get(cls.name)
        }

    def alias_of(self, node: ast.expr) -> Alias | None:
        """A type alias or metadata string (`Rate = Annotated[...]`), of this module
        or imported from another module of the tree, as `FileContext.alias_of`
        reads it."""
        if not isinstance(node, ast.Name) or node.id not in self.index.aliases:
            qualified = imported.dotted_name(node, self._in_tree)
            return imported.alias(self.resolver, qualified) if qualified else None
        found = self.index.aliases.get(node.id)
        if found is None or node.id in self._rebound:
            return None
        names = Names(
            self.qualname,
            _no_message,
            self.source.segment,
            self.source.char_col,
            self.alias_of,
        )
        return Alias(found, names)

    @functools.cached_property
    def _rebound(self) -> set[str]:
        """Module names a function declares `global` (it may rebind them)."""
        return {n for scope in self.index.scopes.values() for n in scope.global_names}

    @property
    def module(self) -> ast.AST | None:
        return self.source.tree

    def _attribute_annotation(self, attr: str) -> ast.expr | None:
        for cls, name, annotation in self.index.attributes:
            if cls == self.cls and name == attr:
                return annotation
        tree = self.source.tree
        assert tree is not None
        for statement in tree.body:
            if isinstance(statement, ast.ClassDef) and statement.name == self.cls:
                for item in statement.body:
                    if (
                        isinstance(item, ast.AnnAssign)
                        and isinstance(item.target, ast.Name)
                        and item.target.id == attr
                    ):
                        return item.annotation
        return None

    # -- declarations -------------------------------------------------------------
    def _declare_args(
        self, call: ast.Call
    ) -> tuple[ast.expr | None, ast.expr | None, ast.expr | None, bool]:
        ignore = self.const(call_argument(call, 3, "ignore_override")) is True
        return (
            call_argument(call, 0, "name"),
            call_argument(call, 1, "value"),
            call_argument(call, 2, "descriptor"),
            ignore,
        )

    def declare_many(self, owner: str, call: ast.Call) -> None:
        namespace = self.text(call_argument(call, 0, "namespace"))
        listed = call_argument(call, 1, "parameters")
        if namespace is None or not isinstance(listed, (ast.List, ast.Tuple)):
            self.summary.open_owners.add(owner)
            return
        ignore = self.const(call_argument(call, 2, "ignore_override")) is True
        for item in listed.elts:
            if not isinstance(item, ast.Tuple) or not 1 <= len(item.elts) <= 3:
                self.summary.open_owners.add(owner)
                continue
            parts: list[ast.expr | None] = [*item.elts, None, None][:3]
            self.declare(
                owner, call, item, parts[0], parts[1], parts[2], ignore, namespace
            )

    def declare(
        self,
        owner: str,
        call: ast.Call,
        site: ast.AST,
        name_node: ast.expr | None,
        value_node: ast.expr | None,
        descriptor_node: ast.expr | None,
        ignore_override: bool,
        namespace: str = "",
    ) -> None:
        name = self.text(name_node)
        if name is None:
            self.summary.open_owners.add(owner)
            return
        if namespace:
            name = f"{namespace}.{name}"
        decl = ParamDecl(
            owner,
            name,
            2,
            self.source.path,
            site.lineno,  # type: ignore[attr-defined]
            self.source.char_col(site.lineno, site.col_offset),  # type: ignore[attr-defined]
            ignore_override=ignore_override,
            node_id=id(site),
        )
        described = self.descriptor(descriptor_node, call.lineno)
        typed = self._parameter_type(value_node)
        if typed is not None:
            decl.type = typed
        elif value_node is not None and not (
            isinstance(value_node, ast.Constant) and value_node.value is None
        ):
            default = self.const(value_node)
            decl.default = default
            decl.default_at = (
                value_node.lineno,
                self.source.char_col(value_node.lineno, value_node.col_offset),
            )
            decl.type = python_type(default) if default is not UNKNOWN else None
        decl.dynamic = decl.type is None or described.dynamic is not False
        decl.read_only = described.read_only
        rng = described.range
        if rng is not None and decl.type == ("integer" if rng.integer else "double"):
            decl.range = rng
        self.summary.decls.append(decl)

    def _parameter_type(self, node: ast.expr | None) -> str | None:
        """`Parameter.Type.DOUBLE` -> double."""
        if (
            isinstance(node, ast.Attribute)
            and isinstance(node.value, ast.Attribute)
            and node.value.attr == "Type"
        ):
            return PARAMETER_TYPES.get(node.attr)
        return None

    def ros1_read(
        self,
        call: ast.Call,
        name_node: ast.expr | None = None,
        default_node: ast.expr | None = None,
    ) -> ParamDecl | None:
        """`rospy.get_param(name, default)`, or another read of a ROS 1 parameter
        whose name and default are those arguments."""
        if name_node is None:
            name_node = call_argument(call, 0, "param_name")
            default_node = call_argument(call, 1, "default")
        name = self.text(name_node)
        if name is None:
            return None
        decl = ParamDecl(
            ROSPY,
            name,
            1,
            self.source.path,
            call.lineno,
            self.source.char_col(call.lineno, call.col_offset),
            node_id=id(call),
            dynamic=True,
        )
        if default_node is not None:
            decl.default = self.const(default_node)
            decl.default_at = (
                default_node.lineno,
                self.source.char_col(default_node.lineno, default_node.col_offset),
            )
        self.summary.decls.append(decl)
        return decl

    # -- descriptors ------------------------------------------------------------------
    def descriptor(self, node: ast.expr | None, before: int) -> _Described:
        """A ParameterDescriptor's range and dynamic_typing; what cannot be read
        is unknown (no range, typing not known to be static)."""
        if node is None:
            return _Described(None, False)
        call, stores = self._resolved(node, before)
        if (
            call is None
            or not called_name(call).endswith("ParameterDescriptor")
            or call.args
            or any(kw.arg is None for kw in call.keywords)
        ):
            return _Described(None, None)
        fields = {kw.arg: kw.value for kw in call.keywords if kw.arg is not None}
        fields.update(dict(stores))
        dynamic: bool | None = False
        if "dynamic_typing" in fields:
            flag = self.const(fields["dynamic_typing"])
            dynamic = flag if isinstance(flag, bool) else None
        found: Range | None = None
        for key, integer in (("floating_point_range", False), ("integer_range", True)):
            ranges = fields.get(key)
            if isinstance(ranges, (ast.List, ast.Tuple)) and ranges.elts:
                found = self._range(ranges.elts[0], integer, before) or found
        read_only = self.const(fields.get("read_only")) is True
        return _Described(found, dynamic, read_only)

    def _resolved(
        self, node: ast.expr, before: int
    ) -> tuple[ast.Call | None, list[tuple[str, ast.expr]]]:
        """A constructor call, inline or bound to a local, with the attribute stores
        made on the local before line `before`."""
        if isinstance(node, ast.Call):
            return node, []
        if self._bound is None:
            self._bound = self._locals(self.body)
        if isinstance(node, ast.Name) and node.id in self._bound:
            local = self._bound[node.id]
            if isinstance(local.value, ast.Call):
                stores = [(a, v) for line, a, v in local.stores if line < before]
                return local.value, stores
        return None, []

    def _range(self, node: ast.expr, integer: bool, before: int) -> Range | None:
        call, stores = self._resolved(node, before)
        expected = "IntegerRange" if integer else "FloatingPointRange"
        if call is None or not called_name(call).endswith(expected) or call.args:
            return None
        fields: dict[str | None, ast.expr] = {kw.arg: kw.value for kw in call.keywords}
        fields.update(dict(stores))
        numbers: list[int | float] = []
        for key in ("from_value", "to_value", "step"):
            number = self.const(fields[key]) if key in fields else 0
            if not isinstance(number, (int, float)) or isinstance(number, bool):
                return None
            if not math.isfinite(number):
                return None
            numbers.append(int(number) if integer else float(number))
        low, high = sorted(numbers[:2])
        return Range(
            integer,
            numbers[0],
            numbers[1],
            numbers[2],
            exact(low),
            exact(high),
            call.lineno,
        )


@dataclass(frozen=True)
class _Described:
    """What a ParameterDescriptor says: range, dynamic_typing, read_only."""

    range: Range | None
    dynamic: bool | None  # None: not known
    read_only: bool = False


def read_call(
    node: ast.expr, qualname: Callable[[ast.expr], str | None]
) -> tuple[ast.Call, bool] | None:
    """The parameter call whose value `node` reads, and whether it is a declaration
    (`declare_parameter(...)` or `rospy.get_param(...)`) rather than a
    `get_parameter(...)`: `X.value`, `X.get_parameter_value().double_value`, or a
    `rospy.get_param(...)` call."""
    if isinstance(node, ast.Call):
        if (
            called_name(node) == "get_param"
            and qualname(node.func) == "rospy.get_param"
        ):
            return node, True
        return None
    if not isinstance(node, ast.Attribute):
        return None
    inner = node.value
    if node.attr in PARAMETER_VALUE_FIELDS and isinstance(inner, ast.Call):
        if called_name(inner) == "get_parameter_value" and isinstance(
            inner.func, ast.Attribute
        ):
            inner = inner.func.value
        else:
            return None
    elif node.attr != "value":
        return None
    if isinstance(inner, ast.Call) and isinstance(inner.func, ast.Attribute):
        called = called_name(inner)
        if called in ("declare_parameter", "get_parameter"):
            return inner, called == "declare_parameter"
    return None
