"""Calls -> abstract values: user functions (refined parameters are checked at the call,
refined returns assumed), message constructors, messages that leave the node, ROS API
parameters with units, math, and builtins. Unknown callees give unknown values and
forget what they may change in the messages and instances they are handed.
"""

from __future__ import annotations

import ast
from functools import partial
from typing import TYPE_CHECKING

from robotfix.analysis import containers, frames, heap, imported, inline
from robotfix.analysis.builtincalls import BuiltinEvaluator
from robotfix.analysis.collaborators import Collaborators
from robotfix.analysis.context import FileContext, Scope
from robotfix.analysis.program import Function, Program, attribute_key
from robotfix.analysis.state import State
from robotfix.analysis.values import (
    MESSAGE_LIKE,
    MUTABLE,
    NONE,
    SEQUENCES,
    Value,
)
from robotfix.annotations import ast as A
from robotfix.annotations.extract import Refinement
from robotfix.astwalk import dotted
from robotfix.ros.api_model import PARAMETER_CALLS
from robotfix.ros.frames_model import TF2_CALLS
from robotfix.stubs import load as stubs

if TYPE_CHECKING:  # only `robotfix suggest` keeps flows: a check never loads them
    from robotfix.analysis.flows import FlowLog

# Methods whose first argument leaves the node: it must satisfy its refinements.
LEAVING = frozenset(
    {
        "publish",
        "publish_feedback",
        "set_succeeded",
        "set_aborted",
        "set_preempted",
        "call",
        "call_async",
        "send_goal",
        "send_goal_async",
    }
)
# What sends a message a publisher's subscribers (a client's server, an action
# client's server) assume of.
CONTRACTED = frozenset(
    {"publish", "call", "call_async", "send_goal", "send_goal_async"}
)
# Objects that send the message they are called with (`proxy(request)`).
SENDING = frozenset({"rospy.ServiceProxy"})
# Methods after which a container holds an element.
FILLING = frozenset({"append", "appendleft", "insert", "add"})
# Methods that change a container (not only code the analysis cannot see).
MUTATORS = FILLING | {
    "extend",
    "update",
    "remove",
    "discard",
    "clear",
    "pop",
    "popitem",
    "popleft",
    "setdefault",
    "sort",
    "reverse",
}
# Methods of lists that RobotFix follows (others give unknown values).
SEQUENCE_METHODS = containers.MUTATORS | containers.READERS
# Callees that change nothing they are handed (math functions too).
_CHANGE_NOTHING = frozenset({"msgclass", "builtin", "parameter_method"})
# Callees `_dispatch` has a way of its own for; others go to the libraries.
_DISPATCHED = frozenset(
    {"msgclass", "parameter_method", "function", "method", "class", "builtin", "module"}
)
# The statement whose value nobody reads (a test swaps it to compare the paths),
# and the value a call evaluated there gives: no symbol, never bound nor read.
_DROPPING: type = ast.Expr
_DROPPED = Value("unknown")


class CallEvaluator(BuiltinEvaluator):
    inlined: tuple[str, ...] = ()  # helpers being evaluated at a call

    def __init__(
        self, ctx: FileContext, program: Program, parts: Collaborators | None = None
    ) -> None:
        # (the base named, not `super()`: an object per call, 9.5k bodies on corpus25;
        # no class between them has an `__init__`)
        BuiltinEvaluator.__init__(self, ctx, program, parts)
        self.libraries = self.parts.libraries

    # -- what the stubs add to names and operators -----------------------------
    def member(self, base: Value, attr: str, state: State) -> Value | None:
        if base.kind == "object":
            return self.libraries.object_member(base.name, attr, state)
        # (the base class's, named: `super()` makes an object per read, 37k on
        # corpus25; no class between them in the walker's order has a `member`)
        return BuiltinEvaluator.member(self, base, attr, state)

    def inherited_method(self, class_name: str, attr: str) -> Value | None:
        return self.libraries.inherited_method(class_name, attr)

    def object_operation(
        self, node: ast.BinOp, left: Value, right: Value, state: State
    ) -> Value | None:
        return self.libraries.object_operation(self, node, left, right, state)

    # -- calls -----------------------------------------------------------------

    def eval_Call(self, node: ast.Call, state: State) -> Value:
        # (an AST node's attribute costs about 280 instructions a read, a slot's
        # 25: the callee's node and method name are read here once, and handed on)
        func = node.func
        method = func.attr if type(func) is ast.Attribute else None
        given = node.args
        if method in LEAVING and given:
            self.eval(func.value, state)  # type: ignore[attr-defined]
            values = []  # (loops: a comprehension makes cells at every call)
            for argument in given:
                values.append(self.eval(argument, state))
            self._leaving(values, state)
            if method in CONTRACTED and self.ctx.obligations:
                holder = self._holder(func.value)  # type: ignore[attr-defined]
                self._contracts(values, state, holder)
            return self._call_value(node)
        # a list's method: its receiver, then the arguments; else the callee first
        sequence = method in SEQUENCE_METHODS
        receiver = self.receiver(func.value, state) if sequence else None  # type: ignore[attr-defined]
        callee = NONE if sequence else self.eval(func, state)
        # (loops, not comprehensions: a call is met about once, and each
        # comprehension costs a frame and makes cells)
        args = []
        for argument in given:
            args.append(self.eval(argument, state))
        kwargs = {}
        for keyword in node.keywords:
            kwargs[keyword.arg] = self.eval(keyword.value, state)
        if receiver is not None:
            assert isinstance(func, ast.Attribute)
            if receiver.kind in SEQUENCES and not any(
                isinstance(a, ast.Starred) for a in given
            ):
                return self.sequence_method(func, receiver, args, node, state)
            callee = self.eval_Attribute(func, state, receiver)
        elif callee.kind == "object" and callee.name in SENDING:
            self._leaving(args, state)
            if self.ctx.obligations and not imported.starred(node, kwargs):
                self._contracts(args, state, self._holder(func), kwargs)
        result = self._dispatch(callee, node, args, kwargs, state, method)
        self._forget_after_call(node, func, given, args, kwargs, state, callee, method)
        return result

    def _leaving(self, values: list[Value], state: State) -> None:
        """The message a call sends (its first argument) leaves the node."""
        for value in values[:1]:
            if value.kind == "msg" and value.ref is not None:
                self.fields.check_whole(state, value.ref, self.site, publishing=True)
                frames.check_leaving(self.ctx, state, value.ref, self.site)

    def _contracts(
        self,
        values: list[Value],
        state: State,
        holder: str,
        fields: dict[str | None, Value] | None = None,
    ) -> None:
        """What the subscribers of the publisher in `holder` (`Class:self.pub`)
        assume of the message, or a service of a client's request
        (`FileContext.obligations`), checked as a refined argument is. `fields`:
        a rospy proxy's call, whose arguments are the request's fields unless
        it is one message: genpy builds it of every field by position, or of
        some by keyword (others, or mixing the two, raise: not checked)."""
        for label, refinement in self.ctx.obligations.get(holder, []):
            value = values[0] if values else None
            whole = len(values) == 1 and not fields and values[0].kind in MESSAGE_LIKE
            if fields is not None and not whole:
                kind = refinement.msg_type or ""
                spec = self.ctx.catalog.lookup(kind)
                built = spec is not None and (
                    not values or (not fields and len(values) == len(spec.fields))
                )
                value = self.construct(kind, values, fields, state) if built else None
            if value is not None and value.kind in MESSAGE_LIKE:
                self.refined.assign_refined(
                    state, label, refinement, value, self.site, {}, leaving=True
                )

    def _dispatch(
        self,
        callee: Value,
        node: ast.Call,
        args: list[Value],
        kwargs: dict[str | None, Value],
        state: State,
        method: str | None,
    ) -> Value:
        """The call's value; `method`: the callee's attribute (`x.m(...)`), if it
        is one."""
        kind = callee.kind
        if kind in _DISPATCHED:  # (the others go on to the libraries: most calls)
            if kind == "msgclass":
                message = self.construct(callee.name, args, kwargs, state)
                if self.ctx.unit_flows is not None:
                    self._constructor_flows(message, node, args, kwargs, state)
                return message
            if kind == "parameter_method":  # p.get_parameter_value()
                return Value("parameter_value", name=callee.name)
            if (
                kind in ("function", "method")
                and callee.name in self.program.functions
                and not imported.starred(node, kwargs)
            ):
                return self.call_known(
                    self.program.functions[callee.name],
                    args,
                    kwargs,
                    node,
                    state,
                    bound=kind == "method",
                )
            if kind == "class" and callee.name in self.program.classes:
                init = self.program.functions.get(f"{callee.name}.__init__")
                if init is not None and not any(
                    isinstance(a, ast.Starred) for a in node.args
                ):
                    self.call_known(init, args, kwargs, node, state, bound=True)
                return Value("instance", name=callee.name)
            if kind == "builtin":
                found = self.builtin(callee.name, args, node, state, kwargs)
                if found is not None:
                    return found
            if kind in ("module", "method"):
                found = self.imported_call(callee, node, args, kwargs, state)
                if found is not None:
                    return found
        name = callee.name.rsplit(".", 1)[-1] if kind == "module" else method or ""
        if name in PARAMETER_CALLS:
            found = self.params.parameter_call(
                name, callee, node, args, kwargs, state, getattr(self, "function", None)
            )
            if found is not None:
                return found
        found = self.libraries.library_call(
            self, callee, node, args, kwargs, state, method
        )
        if name in TF2_CALLS:  # the stub checked the arguments; frames follow
            moved = frames.tf2_call(self.ctx, name, node, args, kwargs, state)
            if moved is not None:
                return moved
        if found is not None:
            return found
        if kind == "module" and _literal_arguments(node):
            # `platform.system()` twice: the same answer, for all the analysis knows
            value = self.unknown(node)
            self.ctx.first_read(("call", self.ctx.source.segment(node)), value.term)  # type: ignore[arg-type]
            return value
        return self._call_value(node)

    def _call_value(self, node: ast.Call) -> Value:
        """A fresh unknown for the value of a call no one knows; none for a call
        statement's (`self.get_logger().info(...)`, a quarter of the calls), whose
        value nobody reads: its symbol's number is taken all the same, so every
        later symbol keeps its number."""
        site = self.site
        if type(site) is _DROPPING and site.value is node:  # type: ignore[attr-defined]
            self.ctx.fresh_id()
            return _DROPPED
        return self.ctx.fresh("unknown", node)

    def imported_call(
        self,
        callee: Value,
        node: ast.Call,
        args: list[Value],
        kwargs: dict[str | None, Value],
        state: State,
    ) -> Value | None:
        """A function, class or method of another module of the tree (`callee` a
        module's name or a method)."""
        if self.ctx.resolver is None:
            return None
        found = imported.resolve(self.ctx.resolver, callee.name)
        if imported.starred(node, kwargs):
            found = None if isinstance(found, imported.FunctionSummary) else found
        if isinstance(found, imported.FunctionSummary):
            bound = callee.kind == "method" or found.class_bound
            return imported.call(self, found, args, kwargs, node, state, bound)
        if isinstance(found, imported.ClassSummary):
            methods = dict(found.methods)
            init = methods.get("__init__")
            if init is not None and not imported.starred(node, kwargs):
                imported.call(self, init, args, kwargs, node, state, True)
            self.program.attributes.setdefault(callee.name, dict(found.attributes))
            return Value("instance", name=callee.name)
        return None

    def _forget_after_call(
        self,
        node: ast.Call,
        func: ast.expr,
        given: list[ast.expr],
        args: list[Value],
        kwargs: dict[str | None, Value],
        state: State,
        callee: Value,
        method: str | None,
    ) -> None:
        """Unknown code may change the messages and instances it is handed. (Most
        calls change nothing: a value the walk never read a version of, which
        `State.changed` leaves alone, is passed over without the call. A call is
        met about once: loops here, not comprehensions or helpers, each of which
        costs a frame. `func` and `given`: `node.func` and `node.args`, as read.)"""
        env = state.env
        names: list[ast.Name] = []
        for argument in given:  # (the call's argument nodes, `node.args`)
            if type(argument) is ast.Name:
                names.append(argument)
        if names:
            for lent_node in containers.lends(func, names):  # it may keep, change it
                lent_name = lent_node.id
                lent = env.get(lent_name)
                if isinstance(lent, Value) and lent.kind == "list":
                    env[lent_name] = containers.stripped(lent)
        kind = callee.kind
        if kind in _CHANGE_NOTHING or (
            kind == "module" and callee.name.startswith("math.")
        ):
            return
        attr = method or ""
        if attr in PARAMETER_CALLS:
            return  # rclpy and rospy change no attribute of the node's class
        if self.ctx.frame_facts is not None and frames.followed(self.ctx, node):
            return  # tf2 reads the stamped values and transforms it is given
        watched = state.shared.watched  # (`State.changed` changes only these)
        values = [*args, *kwargs.values()] if kwargs else args
        for index, value in enumerate(values):
            term = value.term
            if value.kind == "msg" and value.ref is not None:
                if not self.only_reads(node, _argument(node, kwargs, index)):
                    heap.havoc(state, value.ref)
            elif (
                value.kind in MUTABLE and type(term) is A.Sym and term.ident in watched
            ):
                state.changed(value)
        if method is not None:
            owner = func.value  # type: ignore[attr-defined]
            if type(owner) is ast.Name:
                # a method of this file's class may change `self.x`; rclpy's and
                # rospy's own (`self.get_clock()`) do not touch its attributes
                receiver = env.get(owner.id)
                if (
                    kind == "method"
                    or not isinstance(receiver, Value)
                    or receiver.kind != "instance"
                ):
                    names.append(owner)
            elif type(owner) is ast.Attribute:  # self.x.reset()
                env.pop(attribute_key(owner) or "", None)
        for name in names:
            bound = env.get(name.id)
            if not isinstance(bound, Value):
                continue
            if bound.kind in MUTABLE:
                state.changed(bound, attr in MUTATORS)
                if isinstance(bound.term, A.Sym) and attr in FILLING:
                    # `xs.append(v)`: xs is not empty now
                    state.assume(self.truthy(bound, node, state))
            elif bound.kind == "instance":
                prefix = name.id + "."
                for key in list(env):  # (no comprehension: its cell at every call)
                    if key.startswith(prefix):
                        del env[key]

    def only_reads(self, call: ast.Call, arg: ast.expr) -> bool:
        """Whether `call` only reads the argument `arg` (the interpreter knows)."""
        return False

    # -- user functions ------------------------------------------------------
    def call_known(
        self,
        function: Function,
        args: list[Value],
        kwargs: dict[str | None, Value],
        node: ast.Call,
        state: State,
        bound: bool,
    ) -> Value:
        scope = self.program.signature(self.ctx, function)
        log = self.flow_log()
        terms: dict[str, A.Expr] = {}
        if scope.decls or log is not None or function.returns is not None:
            # (else nothing reads the arguments here: unannotated code, a check)
            terms = self._given(function, scope, args, kwargs, node, state, bound, log)
        if function.returns is None:  # `return <expr>` alone: the expression here
            inlined = self.inline_call(function, args, kwargs, bound, state)
            if inlined is not None:
                return inlined  # else what its `return`s give, if they agree
            return self.lookups.typed(
                self.program.types.returns(function.key), node, state
            )
        lookup = {**self._callee_names(function.returns, function, state), **terms}
        return self.refined.assumed(
            state, f"{function.name}()", function.returns, lookup
        )

    def _given(
        self,
        function: Function,
        scope: Scope,
        args: list[Value],
        kwargs: dict[str | None, Value],
        node: ast.Call,
        state: State,
        bound: bool,
        log: FlowLog | None,
    ) -> dict[str, A.Expr]:
        """The arguments of a call of `function`, each checked against its
        parameter's refinement (and logged for `robotfix suggest`); the terms
        they give the parameters."""
        fn = function.node
        params = [a.arg for a in [*fn.args.posonlyargs, *fn.args.args]]
        if bound and function.is_method and params:
            params = params[1:]
        given: dict[str, Value] = dict(zip(params, args, strict=False))
        given.update({k: v for k, v in kwargs.items() if k is not None})
        terms = {k: v.term for k, v in given.items() if v.term is not None}
        exprs = dict(zip(params, node.args, strict=False))
        exprs.update({k.arg: k.value for k in node.keywords if k.arg is not None})
        where = self.flow_where() if log is not None else None
        for name, value in given.items():
            decl = scope.decls.get(name)
            if decl is not None:
                lookup = {**self._callee_names(decl, function, state), **terms}
                self.refined.assign_refined(
                    state, name, decl, value, self.site, lookup, leaving=True
                )
            if log is not None and where is not None and name in exprs:
                if decl is not None:
                    integer = decl.base == "int"
                    log.sink(where, exprs[name], decl.unit, value, integer=integer)
                else:
                    log.call(where, function.key, name, exprs[name])
        return terms

    def helper_evaluator(self, function: Function) -> CallEvaluator | None:
        """An evaluator for `function`'s expression at a call (the statement
        interpreter provides one, with the helper's scope)."""
        return None

    def exec_block(
        self, body: list[ast.stmt], state: State, flush: bool = True
    ) -> State:
        """Run statements (the statement interpreter's, for a helper's body)."""
        raise NotImplementedError

    def inline_call(
        self,
        function: Function,
        args: list[Value],
        kwargs: dict[str | None, Value],
        bound: bool,
        state: State,
    ) -> Value | None:
        """The result of a one-expression helper, or of one that builds a message,
        evaluated with its parameters bound to the arguments (`analysis/inline.py`);
        None when it is not one, or when evaluating it reported something (a bug
        inside it: unknown, as before)."""
        if self.ctx.unit_flows is not None:
            # `suggest`: a helper's result stays unknown there, so that what it
            # proposes is reached in one round (a unit a helper gives a name would
            # hold back the sink's unit until the arguments are annotated)
            return None
        found = self._inlinable(function, self.inlined)
        fn = function.node
        if found is None or not isinstance(fn, ast.FunctionDef):
            return None
        stmts, expr, read = found
        given = inline.bind(fn, bound and function.is_method, args, kwargs)  # type: ignore[arg-type]
        scope = self.program.signature(self.ctx, function)
        params = {n for n, _ in inline.parameters(fn, False)}
        if (
            given is None
            or any(scope.decls.get(n) is not None for n in params)
            or not (read & params) <= set(given)
        ):
            return None
        sub = self.helper_evaluator(function)
        if sub is None:
            return None
        ctx, env, dropped = self.ctx, state.env, self.ctx.dropped
        state.env = {}
        try:
            with ctx.quiet():  # the helper's text shows its own hovers and flows
                bindings = {
                    name: value if isinstance(value, Value) else sub.eval(value, state)  # type: ignore[arg-type]
                    for name, value in given.items()
                }
                state.env = dict(bindings)
                body: list[ast.stmt] = [*stmts]
                if body and sub.exec_block(body, state, flush=False) is not state:
                    return None  # straight-line stores change the state in place
                value = sub.eval(expr, state)
        finally:
            state.env = env
        return value if ctx.dropped == dropped else None

    def _inlinable(
        self, function: Function, within: tuple[str, ...]
    ) -> tuple[list[ast.Assign], ast.expr, set[str]] | None:
        """What a module-level helper's call may be evaluated through, not inside
        itself and at most `inline.MAX_DEPTH` deep: the statements that build its
        message (`inline.built`; none for a one-expression helper,
        `inline.returned`), the expression it returns, and the names they read;
        every expression `inline.pure`."""
        module = function.parent
        if function.key in within or len(within) >= inline.MAX_DEPTH:
            return None
        if module.parent is not None or function.returns is not None:
            return None
        params = {n for n, _ in inline.parameters(function.node, False)}  # type: ignore[arg-type]
        known = params | module.local_names | inline.PURE_BUILTINS
        expr = inline.returned(function.node)
        stmts: list[ast.Assign] = []
        exprs: list[ast.expr] = [] if expr is None else [expr]
        built = None if expr is not None else inline.built(function.node)
        if built is not None:
            stmts, name = built
            maker = stmts[0].value
            assert isinstance(maker, ast.Call) and isinstance(maker.func, ast.Name)
            made = self.static_value(maker.func.id)
            if name in params or made is None or made.kind != "msgclass":
                return None
            known = known | {name}
            expr = ast.Name(name, ast.Load())
            exprs = [*maker.args, *(k.value for k in maker.keywords)]
            exprs += [s.value for s in stmts[1:]]
            if any(k.arg is None for k in maker.keywords):
                return None
        if expr is None:
            return None
        read = set().union(*(inline.names(e) for e in exprs)) if exprs else set()
        if not read <= known:
            return None  # a name that is not bound where the helper is
        defaults = [d for _, d in inline.parameters(function.node, False) if d]  # type: ignore[arg-type]
        if any(inline.names(d) & params for d in defaults):
            return None  # a default reads a module name the parameter hides
        ok = partial(self._pure_callee, params, module, (*within, function.key))
        if all(inline.pure(e, ok) for e in [*exprs, *defaults]):
            return stmts, expr, read
        return None

    def _pure_callee(
        self, params: set[str], module: Scope, within: tuple[str, ...], call: ast.Call
    ) -> bool:
        """A pure builtin, a stubbed `math`/`numpy` function, or a helper that may
        itself be evaluated at the call."""
        func = call.func
        if isinstance(func, ast.Name) and func.id not in params:
            if func.id in inline.PURE_BUILTINS and func.id not in module.local_names:
                return True
            helper = self.program.functions.get(func.id)
            return helper is not None and self._inlinable(helper, within) is not None
        name = dotted(func)
        head, _, rest = (name or "").partition(".")
        found = self.static_value(head) if head not in params else None
        if not rest or found is None or found.kind != "module" or not found.name:
            return False
        qualified = f"{found.name}.{rest}"
        return (
            qualified.split(".")[0] in inline.PURE_LIBRARIES
            and qualified.rsplit(".", 1)[-1] not in inline.MUTATING
            and isinstance(
                imported.resolve_library(self.ctx, qualified), stubs.Function
            )
        )

    def _callee_names(
        self, decl: object, function: Function, state: State
    ) -> dict[str, A.Expr]:
        """Terms for the names a callee's refinement mentions: constants and module
        names (which hold one value during the call), else fresh unknowns (the
        callee's own parameters are filled in by the caller)."""
        predicates = decl.predicates() if isinstance(decl, Refinement) else []
        own = function.scope.local_names if function.scope is not None else set()
        found: dict[str, A.Expr] = {}
        for ref in [n for p in predicates for n in A.names(p)]:
            name = ref.name
            if name == "_" or name in found:
                continue
            term: A.Expr | None = None
            if name.split(".")[0] not in own:
                constant = self.scoped_constant(name, state, function.class_name)
                term = constant.term if constant is not None else None
                if term is None and "." not in name:
                    term = self.global_term(name, state)
            if term is None:
                term = self.ctx.fresh("unknown", f"`{name}`").known_term
            found[name] = term
        return found

    # -- messages ------------------------------------------------------------
    def construct(
        self,
        msg_type: str,
        args: list[Value],
        kwargs: dict[str | None, Value],
        state: State,
    ) -> Value:
        message = heap.new_message(self.ctx, state, msg_type, "constructed")
        spec = self.ctx.catalog.lookup(msg_type)
        assert message.ref is not None and spec is not None
        short = msg_type.split("/")[-1]
        given = list(zip(spec.fields, args, strict=False))
        given += [(k, v) for k, v in kwargs.items() if k]
        for name, value in given:
            self.fields.write_field(
                state, message.ref, name, value, self.site, f"{short}.{name}"
            )
        return message

    def _constructor_flows(
        self,
        message: Value,
        node: ast.Call,
        args: list[Value],
        kwargs: dict[str | None, Value],
        state: State,
    ) -> None:
        """For `robotfix suggest`: `Twist(linear=...)`, `Vector3(x=speed)`,
        `Twist(Vector3(speed, 0.0, 0.0))` (analysis/flows.py)."""
        spec = self.ctx.catalog.lookup(message.name or "")
        log, where = self.flow_log(), self.flow_where()
        if message.ref is None or message.ref not in state.heap or spec is None:
            return
        if log is None or where is None:
            return
        starred = [i for i, a in enumerate(node.args) if isinstance(a, ast.Starred)]
        positional = node.args[: starred[0]] if starred else node.args
        given = list(zip(spec.fields, positional, args, strict=False))
        given += [
            (k.arg, k.value, kwargs[k.arg])
            for k in node.keywords
            if k.arg is not None and k.arg in kwargs
        ]
        log.constructor(self.ctx, state, where, message.ref, node, given)

    def _class_name(self) -> str | None:
        """The class whose code is interpreted (the statement interpreter's)."""
        raise NotImplementedError

    def _local_scope(self, name: str) -> Scope | None:
        """The function that binds `name` here; None for a module name (the
        statement interpreter's)."""
        raise NotImplementedError

    def _holder(self, receiver: ast.expr) -> str:
        """The key of the endpoint a call's receiver holds, as the graph names it
        (`ros.graph.python._holder`): `Planner:self.pub`, `:main/cli` (a local of
        function `main`), `:pub` (a module name)."""
        if isinstance(receiver, ast.Name):
            scope = self._local_scope(receiver.id)
            if scope is None:
                return f":{receiver.id}"
            return f"{self._class_name() or ''}:{scope.name}/{receiver.id}"
        return f"{self._class_name()}:{dotted(receiver)}"


def _argument(node: ast.Call, kwargs: dict[str | None, Value], index: int) -> ast.expr:
    """The expression of a call's `index`-th argument value: its positional
    arguments, then its keyword arguments in the order of `kwargs`."""
    if index < len(node.args):
        return node.args[index]
    key = list(kwargs)[index - len(node.args)]
    return {k.arg: k.value for k in node.keywords}[key]


def _literal_arguments(node: ast.Call) -> bool:
    """Whether every argument of the call is a literal (loops: no generators)."""
    for given in node.args:
        if type(given) is not ast.Constant:
            return False
    for keyword in node.keywords:  # noqa: SIM110 (no generator per call)
        if type(keyword.value) is not ast.Constant:
            return False
    return True
