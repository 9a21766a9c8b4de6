"""The statement walker's third layer: compound statements.

`CompoundWalker` runs `if` (a test decided on each side), `while` and `for` (the
loop head havocked once, the body run from it; a first iteration run again,
muted, where a `break` may leave a name unbound; a retry loop whose attempts all
failed), `with`, `try` (a handler entered from the state before the body or from
the havocked body) and `break`/`continue`. It asks the layer above for
`exec_block` (declared by `calls.CallEvaluator`) and uses `PathWalker` below.
"""

from __future__ import annotations

import ast
from fractions import Fraction

from robotfix.analysis.constants import bound_names
from robotfix.analysis.paths import PathWalker
from robotfix.analysis.state import MAYBE, MaybeUnbound, State
from robotfix.analysis.stmtsyntax import (
    PLAIN,
    accumulated,
    bound_before_raising,
    cannot_raise,
    catches_name_error,
    has_break,
    head_of,
    is_case,
    iteration_of,
    literal_test,
    surely_nonempty,
    truth_value,
)
from robotfix.analysis.values import MUTABLE, SEQUENCES, Value
from robotfix.annotations import ast as A
from robotfix.astwalk import walk


class CompoundWalker(PathWalker):
    def visit_Break(self, node: ast.stmt, state: State) -> State:
        kept = self._breaking[-1] if self._breaking else None
        if kept is not None:
            kept.append(state.fork())
        state.reachable = False
        return state

    def visit_Continue(self, node: ast.stmt, state: State) -> State:
        state.reachable = False
        return state

    # -- compound statements -------------------------------------------------
    def visit_If(self, node: ast.If, state: State) -> State:
        cond = self.condition(node.test, state)
        since = state.exits
        # the `else` path goes on in the state itself: nothing reads it after this
        then_state, else_state = state.fork(), state
        then_state.assume(cond)
        else_state.assume(A.Unary("not", cond))
        if (
            truth_value(cond) is None
        ):  # `if self.verbose:` right after setting it: no choice
            self._decided(node.test, then_state, else_state)
        elif literal_test(node.test):  # `if True:`, `if False: ... else:`, `if 0:`
            (else_state if truth_value(cond) else then_state).reachable = False
        if len(node.orelse) == 1 and type(node.orelse[0]) is ast.If:
            self.elifs.add(id(node.orelse[0]))
        elif not node.orelse and id(node) in self.elifs and is_case(node.test):
            # past `if m == A: ... elif m == B: ...` its author may know no case
            # is left (an enum, a closed set of strings)
            else_state.exits += 1
        then_state = self.exec_block(node.body, then_state)
        else_state = self.exec_block(node.orelse, else_state)
        return self._join(then_state, else_state, since)

    # -- loops ---------------------------------------------------------------
    def visit_While(self, node: ast.While, state: State) -> State:
        entry = state
        loop = entry.fork()
        iteration = iteration_of(node)
        stored, summed = self.havoc_sums(loop, [iteration], loop=True)
        body_state = loop.fork()
        body_state.assume(self.condition(node.test, body_state))
        self._decided(node.test, body_state, loop)
        end = self._iterate(node.body, body_state)
        self._loop_units(loop, end, self._summed(node, iteration, summed))
        breaks = has_break(node.body)
        first: list[State] = []
        if self._first_may_break(node.body, breaks, stored, entry):
            start = entry.fork()
            cond = self.condition(node.test, start)
            start.assume(cond)
            if truth_value(cond) is not False:
                first = self._first_breaks(node.body, start)
        # Normal exits: the condition is false, after some iterations or none.
        # (With a break, `normal` stands for the exits by break too.)
        normal = loop.fork() if breaks and node.orelse else loop
        if isinstance(node.test, ast.Constant):
            if not breaks or node.orelse:  # else `normal` holds the exits by break
                normal.reachable = not node.test.value and normal.reachable
        elif not breaks:
            cond = self.condition(node.test, normal)
            if truth_value(cond) is True:
                normal.reachable = False
            normal.assume(A.Unary("not", cond))
        if self._binds_new_names(stored, entry):
            zero = entry.fork()
            cond = self.condition(node.test, zero)
            zero.reachable = (
                truth_value(cond) is not True
            )  # `done = False; while not done`
            zero.assume(A.Unary("not", cond))
            normal = self._join(zero, normal)
        failed = self._all_attempts_failed(node, entry, loop)
        if failed is not None:
            normal = self._join(failed, normal)
        return self._after_loop(node, normal, loop, breaks, first)

    def visit_For(self, node: ast.For | ast.AsyncFor, state: State) -> State:
        empty, nonempty, iterable = self._empty_when(node.iter, state)
        entry = state
        loop = entry.fork()
        iteration = iteration_of(node)
        stored, summed = self.havoc_sums(loop, [iteration], loop=True)
        body_state = loop.fork()
        body_state.assume(nonempty)  # an iteration: the iterable had an element
        if empty is None:
            # `if ... in kwargs.values(): hints = ...`, then a loop over the
            # `...` of kwargs: that it runs may imply the earlier test, for all
            # the analysis can tell
            for name, bound in list(body_state.env.items()):
                if isinstance(bound, MaybeUnbound) and bound.when is not None:
                    body_state.env[name] = MAYBE
        self._bind_element(node, iterable, body_state)
        end = self._iterate(node.body, body_state)
        self._loop_units(loop, end, self._summed(node, iteration, summed))
        breaks = has_break(node.body)
        first: list[State] = []
        if self._first_may_break(node.body, breaks, stored, entry):
            start = entry.fork()
            start.assume(nonempty)
            self._bind_element(node, iterable, start)
            first = self._first_breaks(node.body, start)
        normal = loop.fork() if breaks and node.orelse else loop
        if empty is not None and empty != A.Bool(False):  # a path with no iteration
            targets = {t.id for t in walk(node.target) if isinstance(t, ast.Name)}
            if self._binds_new_names(stored - targets, entry):
                zero = entry.fork()
                zero.assume(empty)
                for target in targets:
                    if target not in zero.env:
                        zero.env[target] = MAYBE  # a loop variable: never an error
                normal = self._join(zero, normal)
        failed = self._all_attempts_failed(node, entry, loop)
        if failed is not None:
            normal = self._join(failed, normal)
        return self._after_loop(node, normal, loop, breaks, first)

    def _summed(
        self, node: ast.stmt, iteration: ast.stmt, summed: set[str]
    ) -> set[str]:
        """`accumulated([node])`: `summed`, what havoc found of the loop without
        its `else`, unless it has one."""
        return summed if iteration is node else accumulated([node])

    def _bind_element(
        self, node: ast.For | ast.AsyncFor, iterable: Value | None, state: State
    ) -> None:
        element = (
            self.lookups.element(iterable, node.target, state)
            if iterable is not None
            and iterable.kind in SEQUENCES
            and isinstance(node, ast.For)
            else self.unknown(node.target)
        )
        self.bind(node.target, element, state)

    def _iterate(self, body: list[ast.stmt], state: State) -> State:
        """A loop's body, run once from the loop head: its `break`s are exits the
        loop head's state already stands for."""
        self._breaking.append(None)
        try:
            return self.exec_block(body, state)
        finally:
            self._breaking.pop()

    def _first_may_break(
        self, body: list[ast.stmt], breaks: bool, stored: set[str], entry: State
    ) -> bool:
        """Whether a `break` of the first iteration may leave a name the loop binds
        unbound: the loop has a `break`, binds a name unbound on entry that no
        plain assignment before the first statement holding a `break` binds, and
        is not inside a first iteration run again (which would double the work at
        every level of nesting)."""
        if not breaks or any(kept is not None for kept in self._breaking):
            return False
        local = self.scope.local_names
        new = {
            n for n in stored if n in local and not isinstance(entry.env.get(n), Value)
        }
        for stmt in body:
            if not new or has_break([stmt]):
                break
            if isinstance(stmt, ast.Assign | ast.AnnAssign) and stmt.value is not None:
                new -= bound_names([stmt])
        return bool(new)

    def _first_breaks(self, body: list[ast.stmt], start: State) -> list[State]:
        """The states at the `break`s of the loop's first iteration, run again from
        the state before the loop (`start`, its test assumed): a name the iteration
        binds after a `break` is unbound there (`if not line: break` before
        `value = parse(line)`), and a guard flag still holds its value from before
        the loop. Run muted: the body's reports were made by the run from the loop
        head."""
        kept: list[State] = []
        self._breaking.append(kept)
        try:
            with self.ctx.quiet():
                self.exec_block(body, start)
        finally:
            self._breaking.pop()
        return kept

    def _all_attempts_failed(
        self, node: ast.For | ast.AsyncFor | ast.While, entry: State, loop: State
    ) -> State | None:
        """The exit of a retry loop after every attempt raised and was handled: a
        name that only its `try` body binds (`conn = connect()`) is unbound there.
        Only where each iteration surely can take that path: plain statements
        before the `try`, something that may raise before the binding, a handler of
        plain statements that goes on, nothing after it that may leave the
        function. What the `try` body binds from the binding on keeps its value
        from before the loop (a guard flag `ok = True` is still False)."""
        body = node.body
        for index, stmt in enumerate(body):
            if not isinstance(stmt, ast.Try) or stmt.finalbody:
                continue
            prefix, suffix = body[:index], body[index + 1 :]
            if not all(self._plain(s) for s in prefix):
                continue
            at = next(
                (i for i, one in enumerate(stmt.body) if self._new_names([one], entry)),
                None,
            )
            if at is None:
                continue
            first, new = stmt.body[at], self._new_names([stmt.body[at]], entry)
            binding = [*stmt.body[at:]]
            elsewhere = bound_names(
                [*prefix, *suffix, *stmt.body[:at], *stmt.handlers, *stmt.orelse]
            ) | bound_names([node.test if isinstance(node, ast.While) else node.target])
            new -= elsewhere
            if not new or not any(
                isinstance(n, ast.Call) for n in walk([*stmt.body[:at], head_of(first)])
            ):
                continue
            for handler in stmt.handlers:
                goes_on = isinstance(handler.body[-1], ast.Continue)
                plain = handler.body[:-1] if goes_on else handler.body
                if not all(self._plain(s) for s in plain) or (
                    not goes_on and not self._may_follow(suffix)
                ):
                    continue
                failed = loop.fork()
                for name in bound_names(binding) - elsewhere:
                    before = entry.env.get(name)
                    if isinstance(before, Value):
                        failed.env[name] = before
                    else:
                        failed.env.pop(name, None)
                if isinstance(node, ast.While):
                    cond = self.condition(node.test, failed)
                    if truth_value(cond) is True:
                        return None
                    failed.assume(A.Unary("not", cond))
                return failed
        return None

    def _new_names(self, nodes: list[ast.stmt], entry: State) -> set[str]:
        """The locals `nodes` bind that are unbound on entry."""
        return {
            n
            for n in bound_names(nodes)
            if n in self.scope.local_names and not isinstance(entry.env.get(n), Value)
        }

    def _plain(self, stmt: ast.stmt) -> bool:
        """A statement that runs through on some run: a simple one, whose calls
        return as far as the analysis knows."""
        if not isinstance(stmt, PLAIN):
            return False
        return not isinstance(stmt, ast.Expr) or not (
            isinstance(stmt.value, ast.Call) and self.facts.may_stop(stmt.value.func)
        )

    def _may_follow(self, suffix: list[ast.stmt]) -> bool:
        """Whether these statements, after a handler, may go on to the next
        iteration or leave the loop by a `break`: no `return`, `raise` or call that
        may not return."""
        for node in walk(suffix):
            if isinstance(node, (ast.Return, ast.Raise)) or (
                isinstance(node, ast.Expr)
                and isinstance(node.value, ast.Call)
                and self.facts.may_stop(node.value.func)
            ):
                return False
        return True

    def _empty_when(
        self, iterable: ast.expr, state: State
    ) -> tuple[A.Expr | None, A.Expr | None, Value | None]:
        """Evaluate a `for` loop's iterable: when is it empty (a path with no
        iteration), what holds in an iteration, and its value (None for `range`)?
        The first is known for `range()` of numbers and for literals only: that a
        list that arrived may be empty is not taken for a path."""
        call = iterable
        if (
            isinstance(call, ast.Call)
            and isinstance(call.func, ast.Name)
            and 1 <= len(call.args) <= 2
            and not call.keywords
            and not any(isinstance(a, ast.Starred) for a in call.args)
            and self.eval(call.func, state) == Value("builtin", name="range")
        ):
            bounds = [self.eval(a, state) for a in call.args]
            if len(bounds) == 1:
                bounds.insert(0, Value("int", A.Num(Fraction(0), True)))
            low, high = bounds
            if {low.kind, high.kind} <= {"int", "unknown"} and low.term and high.term:
                empty = A.Binary("<=", high.term, low.term)
                return empty, A.Unary("not", empty), None
            return None, None, None
        value = self.eval(iterable, state)
        if isinstance(iterable, (ast.List, ast.Tuple, ast.Set, ast.Dict)):
            nonempty = surely_nonempty(iterable)
            return A.Bool(not nonempty), A.Bool(nonempty), value
        if isinstance(value.term, A.Sym) and value.kind in MUTABLE:
            # `if items: first = ...` then `for x in items: use(first)`
            return None, self.truthy(value, iterable, state), value
        return None, None, value

    visit_AsyncFor = visit_For

    def _after_loop(
        self,
        node: ast.For | ast.AsyncFor | ast.While,
        normal: State,
        loop: State,
        breaks: bool,
        first: list[State],
    ) -> State:
        """`else` runs on normal exits; a `break` leaves with what the body may have
        changed (the havocked loop state), or, in the first iteration, with what
        it changed so far (`first`)."""
        if node.orelse:
            result = self.exec_block(node.orelse, normal)
            normal = self._join(result, loop) if breaks else result
        # (without an `else`, `normal` already stands for the later exits by break)
        for exit in first:
            normal = self._join(normal, exit)
        return normal

    def _binds_new_names(self, stored: set[str], entry: State) -> bool:
        """Is one of these names a local unbound on entry? Only then can skipping
        the statements that bind them (no iteration, an early exception) leave a
        name unbound."""
        return any(
            name in self.scope.local_names
            and not isinstance(entry.env.get(name), Value)
            for name in stored
        )

    def visit_With(self, node: ast.With | ast.AsyncWith, state: State) -> State:
        for item in node.items:
            self.eval(item.context_expr, state)
            if item.optional_vars is not None:
                self.bind(item.optional_vars, self.unknown(item.optional_vars), state)
        return self.exec_block(node.body, state)

    visit_AsyncWith = visit_With

    def visit_Try(self, node: ast.Try, state: State) -> State:
        body = node.body
        safe = 0  # `try: final = None` binds before anything can raise
        while safe < len(body) and cannot_raise(body[safe]):
            safe += 1
        if safe and node.handlers:
            state = self.exec_block(body[:safe], state)
            body = body[safe:]
        raised = state.fork()  # an exception somewhere in the body
        stored = self.havoc(raised, body)
        inside = raised
        binds = bool(node.handlers) and self._binds_new_names(stored, state)
        entry = state.fork() if binds else state  # (read only where it `binds`)
        if binds:
            raised = self._join(entry.fork(), inside.fork())  # ... or before binding
        guards = any(catches_name_error(h.type) for h in node.handlers)
        self.guarded += guards
        state = self.exec_block(body, state)
        self.guarded -= guards
        result = self.exec_block(node.orelse, state)
        last = node.handlers[-1] if node.handlers and not node.finalbody else None
        for handler in node.handlers:
            first = bound_before_raising(body, handler) if binds else set()
            if first & self.scope.local_names:
                before = entry.fork()  # it raised after these were bound
                for name in sorted(first & self.scope.local_names):
                    before.env[name] = self.unknown(node)
                handler_state = self._join(before, inside.fork())
            else:  # (the last handler, with no `finally`, is the last to read it)
                handler_state = raised if handler is last else raised.fork()
            since = handler_state.exits
            if handler.type is not None:  # evaluated only if no earlier one matched
                self.guarded += 1
                self.eval(handler.type, handler_state)
                self.guarded -= 1
            if handler.name:
                handler_state.env[handler.name] = self.unknown(handler)
            handled = self.exec_block(handler.body, handler_state)
            result = self._join(result, handled, since)
        if node.finalbody:
            if not result.reachable:
                self.havoc(raised, node.handlers)  # type: ignore[arg-type]
                self.exec_block(node.finalbody, raised)
                return result
            result = self.exec_block(node.finalbody, result)
        return result

    visit_TryStar = visit_Try
