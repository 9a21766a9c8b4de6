"""What the walker asks of a call by its syntax and the program: whether it
ends the path (`never_returns`: `sys.exit()`, a function of this file that can
only raise), may end it (`may_stop`: a call whose result is dropped and that may
not return, for all the analysis can tell), or only reads a message it is given
(`only_reads`: a reading builtin, `math`, logging, publishing, tf2, or a function
of this file that only reads that parameter).

`CallFacts` is a collaborator of the walker (`Binder.facts`), made per body with
the file's context and program, the body's scope and function, and the walker's
`nested` functions (shared, filled as the walk meets their definitions). Its
answers are kept in the program (`Program.ends`, `Program.reading_calls`).
"""

from __future__ import annotations

import ast
from functools import partial

from robotfix.analysis import frames, writes
from robotfix.analysis.calls import LEAVING
from robotfix.analysis.context import FileContext, Scope
from robotfix.analysis.program import Function, Program
from robotfix.analysis.program import never_returns as program_never_returns
from robotfix.analysis.stmtsyntax import (
    BUILTINS,
    LOGGING,
    NO_RETURN_NAMES,
    READING_BUILTINS,
    RETURNS,
    ROS_LOGGING,
    may_raise,
    no_return,
)


class CallFacts:
    def __init__(
        self,
        ctx: FileContext,
        program: Program,
        scope: Scope,
        function: Function | None,
        nested: dict[str, ast.AST],
    ) -> None:
        self.ctx = ctx
        self.program = program
        self.scope = scope  # the walker's (a comprehension's while one is run)
        self.function = function
        self.nested = nested

    def only_reads(self, call: ast.Call, arg: ast.expr, depth: int = 0) -> bool:
        """Whether `call` only reads the argument `arg` (a message): a builtin that
        reads, `math`, logging, publishing, a tf2 transform, or a function of this
        file that only reads that parameter. Syntactic, so kept per call and
        argument (asked again on every pass of a loop)."""
        key = (id(call), id(arg), depth)
        found = self.program.reading_calls.get(key)
        if found is None:
            found = self.program.reading_calls[key] = self._only_reads(call, arg, depth)
        return found

    def _only_reads(self, call: ast.Call, arg: ast.expr, depth: int) -> bool:
        func = call.func
        user = self._user_function(func)
        if user is not None:
            return depth < 2 and self._reads_parameter(user, call, arg, depth + 1)
        if isinstance(func, ast.Name):
            return (
                func.id in READING_BUILTINS
                and func.id not in self.scope.module().local_names
            )
        if not isinstance(func, ast.Attribute):
            return False
        name = func.attr
        if name in LEAVING or name in ROS_LOGGING:
            return True
        if frames.is_tf2(name):  # unless this file defines a method of that name
            return not any(k.rpartition(".")[2] == name for k in self.program.functions)
        receiver = func.value
        if isinstance(receiver, ast.Name) and receiver.id == "math":
            return True
        return self.logs(func)

    def _user_function(self, func: ast.expr) -> Function | None:
        """The function of this file a call's `func` names, syntactically."""
        if isinstance(func, ast.Name):
            return self.program.functions.get(func.id)
        if (
            isinstance(func, ast.Attribute)
            and isinstance(func.value, ast.Name)
            and self.function is not None
            and self.function.class_name is not None
            and func.value.id == self.function.first_parameter
        ):
            return self.program.functions.get(f"{self.function.class_name}.{func.attr}")
        return None

    def _reads_parameter(
        self, function: Function, call: ast.Call, arg: ast.expr, depth: int
    ) -> bool:
        node = function.node
        if isinstance(node, ast.Lambda):
            return False
        params = [a.arg for a in [*node.args.posonlyargs, *node.args.args]]
        if function.is_method and isinstance(call.func, ast.Attribute):
            params = params[1:]
        name = next((k.arg for k in call.keywords if k.value is arg), None)
        if name is None and arg in call.args:
            index = call.args.index(arg)
            starred = any(isinstance(a, ast.Starred) for a in call.args[: index + 1])
            name = params[index] if index < len(params) and not starred else None
        if name is None:
            return False
        found = writes.uses(
            node.body,
            {name},
            lambda root, path: False,
            partial(self.only_reads, depth=depth),
        )
        return not found[name]

    def logs(self, func: ast.Attribute) -> bool:
        """`self.get_logger().error(...)`, `logger.error(...)`; not `parser.error`:
        a logging method called on something its code calls a logger."""
        receiver = self.ctx.source.segment(func.value) or ""
        return func.attr in LOGGING and "log" in receiver.lower()

    def may_stop(self, func: ast.expr) -> bool:
        """A call whose result is dropped, which may never return for all the
        analysis can tell: a function of this file that can raise, or one it
        cannot see (`self.fail(msg)`, `parser.exit(1)`), unless its name says it
        returns (`print`, `logger.error`, `pub.publish`)."""
        name = func.id if isinstance(func, ast.Name) else getattr(func, "attr", "")
        if name in RETURNS:
            return False
        if name in LOGGING and isinstance(func, ast.Attribute):
            return not self.logs(func)
        known: Function | None = None
        if isinstance(func, ast.Name):
            if func.id in self.nested:
                return self._function_may_raise(self.nested[func.id])
            if func.id in BUILTINS and func.id not in self.scope.module().local_names:
                return False
            known = self.program.functions.get(func.id)
        elif (
            isinstance(func, ast.Attribute)
            and self.function is not None
            and self.function.class_name is not None
            and isinstance(func.value, ast.Name)
        ):
            method = f"{self.function.class_name}.{func.attr}"
            known = self.program.functions.get(method)
        if known is not None:
            return self._function_may_raise(known.node)
        return True

    def _function_may_raise(self, node: ast.AST) -> bool:
        key = -id(node)  # `ends` holds never-returns by id(node); this by -id(node)
        found = self.program.ends.get(key)
        if found is None:
            found = self.program.ends[key] = may_raise(node)
        return found

    def _may_not_return(self, func: ast.expr) -> bool:
        """A cheap first look: a name that could be one of the calls below."""
        if isinstance(func, ast.Name):
            name = func.id
            return (
                name in NO_RETURN_NAMES
                or name in self.ctx.imports
                or name in self.program.functions
                or name in self.nested
            )
        name = getattr(func, "attr", "")
        if name in NO_RETURN_NAMES:
            return True
        return (
            self.function is not None
            and self.function.class_name is not None
            and isinstance(getattr(func, "value", None), ast.Name)
            and f"{self.function.class_name}.{name}" in self.program.functions
        )

    def never_returns(self, func: ast.expr) -> bool:
        """`sys.exit()`, `pytest.fail()`, or a function of this file that can only
        raise: the path ends there."""
        if not self._may_not_return(func):
            return False
        module = self.scope.module()
        known: Function | None = None
        if isinstance(func, ast.Name):
            if func.id in self.nested:  # a helper defined in this function
                return self._function_never_returns(self.nested[func.id])
            if func.id in self.scope.local_names:  # `from pytest import fail` here
                return no_return(self.ctx.qualname(func))
            if func.id in ("exit", "quit") and func.id not in module.local_names:
                return True
            known = self.program.functions.get(func.id)
        elif (
            isinstance(func, ast.Attribute)
            and isinstance(func.value, ast.Name)
            and self.function is not None
            and self.function.is_method
            and func.value.id == self.function.first_parameter
        ):
            method = f"{self.function.class_name}.{func.attr}"
            known = self.program.functions.get(method)
        if known is not None:
            return self._function_never_returns(known.node)
        return no_return(self.ctx.qualname(func))

    def _function_never_returns(self, node: ast.AST) -> bool:
        known = self.program.ends.get(id(node))
        if known is None:
            known = self.program.ends[id(node)] = program_never_returns(
                node, self._ends_path
            )
        return known

    def _ends_path(self, stmt: ast.stmt) -> bool:
        """A last statement after which a function cannot go on."""
        if isinstance(stmt, ast.Raise):
            return True
        if not isinstance(stmt, ast.Expr) or not isinstance(stmt.value, ast.Call):
            return False
        func = stmt.value.func
        name = func.id if isinstance(func, ast.Name) else getattr(func, "attr", "")
        if name in ("exit", "quit") and isinstance(func, ast.Name):
            return True
        if name not in NO_RETURN_NAMES and name not in self.ctx.imports:
            return False
        return no_return(self.ctx.qualname(func))
