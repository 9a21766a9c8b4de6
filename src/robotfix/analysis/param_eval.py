"""Parameter calls -> abstract values (the analysis side of `analysis/parameters.py`).

`declare_parameter` and `get_parameter` give a Parameter handle; its `.value` (or
`.get_parameter_value().double_value`, ...) is an unknown of the declared type that
lies in the declared range and satisfies the refinements attached where it was
declared. A default outside the declared range is RF101 at the default (rclpy
refuses it). `rospy.get_param(name, default)` is an unknown; assigned to a refined
target right away, its default is checked against the refinement and the
refinement is assumed (`paramchecks.attach`).
"""

from __future__ import annotations

import ast
from dataclasses import replace
from fractions import Fraction

from robotfix import messages
from robotfix.analysis.context import FileContext
from robotfix.analysis.parameters import Handle, ParamContext, ParamRead, summarize
from robotfix.analysis.paramsummary import MODULE, ParamDecl
from robotfix.analysis.paramwalk import called_name, owner_of
from robotfix.analysis.program import Function, call_argument
from robotfix.analysis.state import State
from robotfix.analysis.values import Value
from robotfix.annotations import ast as A
from robotfix.annotations.units import Unit, resolve
from robotfix.messages import Declared
from robotfix.ros.api_model import (
    PARAMETER_FIELD_DEFAULTS,
    PARAMETER_KINDS,
    PARAMETER_VALUE_FIELDS,
)
from robotfix.ros.catalog import suffix_unit

HANDLE_KINDS = frozenset({"parameter", "parameter_value"})


class ParameterCalls:
    """Parameter API calls and reads of the handles they return; the evaluator
    holds one (`self.params`). It reads the file's context alone: the summary of
    the file's parameters (`ctx.parameters`, made at the first call)."""

    def __init__(self, ctx: FileContext) -> None:
        self.ctx = ctx

    def parameters(self) -> ParamContext:
        found = self.ctx.parameters
        if not isinstance(found, ParamContext):
            found = ParamContext(
                summarize(
                    self.ctx.source, self.ctx.index, self.ctx.resolver, self.ctx.stubs
                )
            )
            self.ctx.parameters = found
        return found

    def parameter_call(
        self,
        name: str,
        callee: Value,
        node: ast.Call,
        args: list[Value],
        kwargs: dict[str | None, Value],
        state: State,
        function: Function | None,
    ) -> Value | None:
        """The value of a parameter API call made in `function` (None: at module
        level), or None when it is not one (or not one this checker can follow)."""
        if name == "get_param":
            if callee.kind == "module" and callee.name == "rospy.get_param":
                return self._ros1_read(node, args, kwargs)
            return None
        if not isinstance(node.func, ast.Attribute):
            return None
        owner = _owner(node.func.value, function)
        summary = self.parameters().summary
        if name == "declare_parameters":
            for item in ast.walk(node):
                decl = summary.by_node.get(id(item))
                if (
                    decl is not None
                    and isinstance(item, ast.Tuple)
                    and len(item.elts) > 1
                ):
                    self._check_range(decl, item.elts[1])
            return None
        if owner is None:
            return None
        if name == "declare_parameter":
            decl = summary.by_node.get(id(node))
            if decl is None:
                return None
            default_node = call_argument(node, 1, "value")
            default = _given(args, kwargs, 1, "value")
            if default_node is not None:
                self._check_range(decl, default_node)
            with_default = decl.default_at is not None
            return self._handle(
                Handle(
                    owner,
                    decl.name,
                    decl,
                    with_default,
                    default if with_default else None,
                    default_node if with_default else None,
                    node,
                )
            )
        if name == "get_parameter":
            pname = self._name(node, args, kwargs, "name")
            if pname is None:
                return None
            decl = summary.declaration(owner, pname)
            if decl is None or not _literal_name(node):
                return self._handle(Handle(owner, pname, decl, False, call=node))
            # declared by its class: a refined target's refinement is the
            # parameter's, as for `declare_parameter(...).value` (the syntactic
            # pass attaches it too, `Summary.attached`)
            default_node = self._declared_default(decl)
            default = (
                _constant(decl.default)
                if default_node is not None
                and isinstance(decl.default, (bool, int, float, str))
                else None
            )
            return self._handle(
                Handle(
                    owner,
                    pname,
                    decl,
                    True,
                    default,
                    default_node if default is not None else None,
                    node,
                    later=True,
                )
            )
        return None

    def _declared_default(self, decl: ParamDecl) -> ast.expr | None:
        """The default's expression of a declaration, found by its node's id in
        the file's calls (`declare_parameter(name, default)`, or a tuple of
        `declare_parameters`); the calls are read once a file, at the first ask."""
        params = self.parameters()
        nodes = params.declarations
        if nodes is None:
            nodes = params.declarations = _declarations(self.ctx.index.calls)
        node = nodes.get(decl.node_id)
        if isinstance(node, ast.Tuple):
            return node.elts[1] if len(node.elts) > 1 else None
        return None if node is None else call_argument(node, 1, "value")

    def _name(
        self,
        node: ast.Call,
        args: list[Value],
        kwargs: dict[str | None, Value],
        keyword: str,
    ) -> str | None:
        """A parameter's name: a string the analysis knows, or a module constant."""
        given = _given(args, kwargs, 0, keyword)
        if given is not None and isinstance(given.term, A.Str):
            return given.term.value
        found = self.parameters().summary.constant(call_argument(node, 0, keyword))
        return found if isinstance(found, str) else None

    def _handle(self, handle: Handle) -> Value:
        params = self.parameters()
        key = str(len(params.handles) + 1)
        params.handles[key] = handle
        return Value("parameter", name=key)

    def _check_range(self, decl: ParamDecl, default_node: ast.expr) -> None:
        """rclpy refuses a default outside the declared range (when no override
        replaces it): RF101 at the default."""
        default = decl.default
        rng = decl.range
        if (
            rng is None
            or isinstance(default, bool)
            or not isinstance(default, (int, float))
            or rng.accepts(default)
        ):
            return
        path = self.ctx.source.path
        text = self.ctx.source.segment(default_node) or repr(default)
        self.ctx.report(
            messages.parameter_value_violated(
                path,
                self.ctx.source.span(default_node),
                f"the default `{text}` of parameter `{decl.name}`",
                f"its declared range {rng.text()}",
                Declared(f"range of parameter `{decl.name}`", path, rng.line),
                "rclpy refuses it (InvalidParameterValueException) when no parameter "
                "file or launch argument sets the parameter",
            ),
            once=("parameter-range", id(default_node)),
        )

    # -- reads ------------------------------------------------------------------
    def parameter_attribute(
        self, base: Value, node: ast.Attribute, state: State
    ) -> Value:
        handle = self.parameters().handles.get(base.name)
        if handle is None:
            return self.ctx.fresh("unknown", node)
        decl = handle.decl
        declared = decl.type if decl is not None and not decl.dynamic else None
        if base.kind == "parameter":
            if node.attr == "value":
                return self._read(handle, node, state, declared)
            if node.attr == "get_parameter_value":
                return Value("parameter_method", name=base.name)
            return self.ctx.fresh("unknown", node)
        field_type = PARAMETER_VALUE_FIELDS.get(node.attr)
        if field_type is None:
            return self.ctx.fresh("unknown", node)
        if declared is not None and field_type == declared:
            return self._read(handle, node, state, declared)
        if declared is not None and field_type in PARAMETER_FIELD_DEFAULTS:
            return _constant(PARAMETER_FIELD_DEFAULTS[field_type])
        return self.ctx.fresh("unknown", node)

    def _read(
        self, handle: Handle, node: ast.Attribute, state: State, type_: str | None
    ) -> Value:
        kind = PARAMETER_KINDS.get(type_ or "", "unknown")
        decl = handle.decl
        fixed = self.parameters().fixed
        key = (handle.owner, handle.name)
        if decl is not None and decl.read_only and handle.value is None:
            handle.value = fixed.get(key)  # every read sees the declared value
        value = handle.value
        if value is None or value.kind != kind:
            unit = name_unit(handle.name) if self.ctx.catalog.unit_suffixes else None
            value = self.ctx.fresh(kind, f"parameter `{handle.name}`", unit)
            if kind == "str" and decl is not None and isinstance(decl.default, str):
                value = replace(value, frame=decl.default)  # analysis/frames.py
            handle.value = value
        if decl is not None and decl.read_only:
            fixed[key] = value
        term = value.known_term
        if decl is not None and decl.range is not None and kind in ("int", "float"):
            integer = kind == "int"
            state.assume(A.Binary("<=", A.Num(decl.range.low, integer), term))
            state.assume(A.Binary("<=", term, A.Num(decl.range.high, integer)))
        if not handle.declaration or handle.later:
            summary = self.parameters().summary
            for attached in summary.refinements(handle.owner, handle.name, True):
                predicate = attached.refinement.predicate
                if all(n.name == "_" for n in A.names(predicate)):
                    state.assume(A.substitute(predicate, {"_": term}))
        assert isinstance(term, A.Sym)
        self.parameters().reads[term.ident] = ParamRead(
            handle.name,
            2,
            node,
            handle.declaration,
            handle.default,
            handle.default_node,
            handle.later,
        )
        return value

    def _ros1_read(
        self, node: ast.Call, args: list[Value], kwargs: dict[str | None, Value]
    ) -> Value | None:
        name = self._name(node, args, kwargs, "param_name")
        if name is None:
            return None
        value = self.ctx.fresh("unknown", f"parameter `{name}`")
        default = _given(args, kwargs, 1, "default")
        if default is not None and isinstance(default.term, A.Str):
            value = replace(value, frame=default.term.value)  # analysis/frames.py
        assert isinstance(value.term, A.Sym)
        self.parameters().reads[value.term.ident] = ParamRead(
            name,
            1,
            node,
            True,
            _given(args, kwargs, 1, "default"),
            call_argument(node, 1, "default"),
        )
        return value


def _literal_name(call: ast.Call) -> bool:
    """Whether a parameter call names its parameter with a literal string."""
    name = call_argument(call, 0, "name")
    return isinstance(name, ast.Constant) and isinstance(name.value, str)


def _given(
    args: list[Value], kwargs: dict[str | None, Value], position: int, keyword: str
) -> Value | None:
    if keyword in kwargs:
        return kwargs[keyword]
    return args[position] if position < len(args) else None


def _constant(value: object) -> Value:
    if isinstance(value, bool):
        return Value("bool", A.Bool(value))
    if isinstance(value, int):
        return Value("int", A.Num(Fraction(value), True), literal=True)
    if isinstance(value, float):
        return Value("float", A.Num(Fraction(value), False), literal=True)
    return Value("str", A.Str(str(value)))


def name_unit(name: str) -> Unit | None:
    """The unit a parameter's name gives its value under the opt-in `unit-suffixes`
    setting (`_deg`, `_ms`, `speed_kmph`: Autoware's naming guidelines), as for
    interface fields. (A value in a parameter file has no unit to compare, so
    `paramcheck` needs nothing.)"""
    text = suffix_unit(name)
    return resolve(text) if text is not None else None


def _owner(receiver: ast.expr, function: Function | None) -> str | None:
    if function is None:
        return owner_of(receiver, MODULE, None, None)
    args = getattr(function.node, "args", None)
    params = [*args.posonlyargs, *args.args] if args is not None else []
    is_method = function.is_method and params
    return owner_of(
        receiver,
        function.key,
        function.class_name if is_method else None,
        params[0].arg if is_method else None,
    )


def _declarations(
    calls: list[tuple[str | None, ast.Call]],
) -> dict[int, ast.Call | ast.Tuple]:
    """id(node) -> the node, for every call and every tuple under a
    `declare_parameters` call (the first such call that holds it)."""
    found: dict[int, ast.Call | ast.Tuple] = {}
    for _, call in calls:
        found.setdefault(id(call), call)
        if called_name(call) == "declare_parameters":
            for item in ast.walk(call):
                if isinstance(item, ast.Tuple):
                    found.setdefault(id(item), item)
    return found
