"""Issue 25 target 1: havoc's walk pushes the children of its commonest node
classes itself. The walk must meet the same nodes in the same order as before
(`bound_at` keeps the first binder: the order numbers the symbols) and do the same
to the path: each loop's and `try`'s havoc of every case file with a loop or a
`try`, and of a text with each kind of node havoc acts on, leaves the same state
and the same diagnostics as the walk written before (`_havoc_sums_before`, the
code of 27bf02b)."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

from robotfix.analysis import containers
from robotfix.analysis.calls import MUTATORS
from robotfix.analysis.paths import PathWalker
from robotfix.analysis.program import attribute_key
from robotfix.analysis.state import State
from robotfix.analysis.stmtsyntax import (
    BINDER_KINDS,
    KEEPS,
    assign_targets,
    bound_by,
    constant_stores,
    note_sum,
    sums,
)
from robotfix.analysis.values import Value, replace
from robotfix.api import check_source
from robotfix.astwalk import FIELDS, SHAPES, children, fields, walk

CASES = Path(__file__).parent / "cases"

EVERY_KIND = """\
import rospy
from geometry_msgs.msg import Twist

received = False


class Node:
    def __init__(self):
        self.pub = rospy.Publisher("cmd", Twist, queue_size=1)
        self.xs = []
        self.scan = None
        self.speed = 0.5

    def spin(self, n, ranges):
        global received
        total = 0.0
        best = None
        hits = []
        table = {}
        cmd = Twist()
        flag = False
        i = 0
        while self.scan is None and not received:
            rospy.sleep(0.1)
        for k, r in enumerate(ranges):
            total += r
            i -= 1
            hits.append(r)
            table[k] = r
            self.xs.append(r)
            self.speed = r * 2
            cmd.linear.x = min(r, self.speed)
            a, b = r, k
            first = (second := r * 2)  # bound in this order: second, first
            print(r, end=(last := str(r)))  # a name a keyword binds
            self.pub.publish(Twist(linear=cmd.linear))
            flag = True
            if r < 0.5:
                best = r
                break
            import math
            def helper(v):
                return math.sqrt(v)
            class Local:
                pass
            for j in range(n):
                total -= j
                hits[j] = helper(j)
        else:
            best = 0.0
        try:
            value = float(ranges[0])
            self.pub.publish(cmd)
        except (ValueError, IndexError) as err:
            rospy.logwarn(str(err), throttle=1)
            value = None
        while n > 0:
            n -= 1
            if hits:
                del hits[0]
        return total, best, value, flag, a, b, i, table, first, second, last
"""


def _havoc_sums_before(
    self: PathWalker, state: State, nodes: list[ast.stmt], loop: bool = False
) -> tuple[set[str], set[str]]:
    """Forget what `nodes` may write: bound names and mentioned messages. A
    name only ever set to constants of the kind it has keeps that kind (a flag
    stays a bool), so that tests of it agree with what was set. A loop that
    calls anything (`rospy.sleep`, `spin_once`) lets callbacks run: the node's
    attributes and the globals that functions set may change there too.
    What lists they change (`xs.append(v)`, `xs[i] = v`) hold is forgotten.
    Returns the names they may bind, and `accumulated(nodes)` (read by the
    same walk)."""
    calls = False
    lists: set[str] = set()  # names of lists that `nodes` mention
    # what `accumulated(nodes)` reads, gathered by the walk below
    summed: set[str] = set()
    sum_targets: set[int] = set()
    stores: list[ast.Name] = []
    watched = state.shared.watched  # only their changes need a new version
    bound_at: dict[str, ast.AST] = {}
    # the assignments, whose constants (`constant_stores`) are read only if a
    # name they bind held a number, a bool or a string
    assigns: list[ast.Assign | ast.AugAssign] = []
    constant: dict[str, set[str]] | None = None
    other_binders: set[str] = set()  # bound otherwise than by `=` or `op=`
    assigned: set[int] = set()  # the name nodes `=` and `op=` bind
    objects: dict[str, int] = {}  # names of messages that `nodes` mention
    looked: set[str] = set()  # the names whose binding was looked at
    get = state.env.get
    todo: list[ast.AST] = [*reversed(nodes)]  # `walk` of each node in turn
    push = todo.append
    while todo:
        child = todo.pop()
        kind = type(child)
        if kind is ast.Name:  # (a name and a constant have no children)
            name: str = child.id  # type: ignore[attr-defined]
            if name not in looked:  # (the walk pops dotted keys only)
                looked.add(name)
                bound = get(name)
                if isinstance(bound, Value) and bound.ref is not None:
                    objects[name] = bound.ref
                elif isinstance(bound, Value) and bound.kind == "list":
                    lists.add(name)
            if type(child.ctx) is not ast.Load:  # type: ignore[attr-defined]
                bound_at.setdefault(name, child)
                if id(child) not in assigned:
                    other_binders.add(name)
                if type(child.ctx) is ast.Store:  # type: ignore[attr-defined]
                    stores.append(child)  # type: ignore[arg-type]
            continue
        if kind is ast.Constant:
            continue
        for field in FIELDS.get(kind) or fields(kind):  # `children`, inline
            value = getattr(child, field, None)
            if value.__class__ is list:
                for one in value:
                    if isinstance(one, ast.AST):
                        push(one)
            elif isinstance(value, ast.AST):
                push(value)
        if kind is ast.Attribute:
            if type(child.ctx) is ast.Store:  # type: ignore[attr-defined]
                key = attribute_key(child)  # type: ignore[arg-type]
                state.env.pop(key or "", None)
                if watched:
                    self._changed_root(child, state, firm=True)
            elif self.lists_seen:  # `self.xs.append(v)`: forget what it held
                key = attribute_key(child) or ""  # type: ignore[arg-type]
                kept = state.env.get(key)
                if isinstance(kept, Value) and kept.kind == "list":
                    state.env.pop(key, None)
        elif kind is ast.Subscript:
            if watched and type(child.ctx) is not ast.Load:  # type: ignore[attr-defined]
                self._changed_root(child, state, firm=True)
        elif kind is ast.Call:
            calls = True
            if watched:
                call: ast.Call = child  # type: ignore[assignment]
                method = getattr(call.func, "attr", "")
                self._changed_root(call.func, state, method in MUTATORS)
                for arg in call.args:
                    if type(arg) is not ast.Constant:  # (changes no object)
                        self._changed_root(arg, state)
                for keyword in call.keywords:
                    self._changed_root(keyword, state)
        elif kind is ast.Assign or kind is ast.AugAssign:
            assigns.append(child)  # type: ignore[arg-type]
            assigned.update(map(id, assign_targets(child)))  # type: ignore[arg-type]
            if kind is ast.AugAssign:
                note_sum(child, summed, sum_targets)
        elif kind in BINDER_KINDS:
            for name in bound_by(child):
                bound_at.setdefault(name, child)
                other_binders.add(name)
    self._changed_objects(state, nodes, objects)
    keeps_unit = sums(summed, sum_targets, stores)
    if lists:  # those `nodes` may change (`xs.append(v)`, `xs[i] = v`, `b = xs`)
        if self.follows_lists():
            lists &= containers.shared_names(nodes, changes=True)
        for name in lists:
            bound = state.env.get(name)
            if isinstance(bound, Value):
                state.env[name] = containers.forgetting(bound)
    if loop and calls:
        for key in [k for k in state.env if "." in k]:
            del state.env[key]  # `while self.scan is None: rospy.sleep(0.1)`
        for name in sorted(self.program.shared_globals):
            bound_at.setdefault(name, nodes[0])  # `while not received: ...`
    for name, child in bound_at.items():
        if name not in self.scope.local_names:
            continue
        decl = self.decl_for(name)
        before = state.env.get(name)
        keeps = KEEPS.get(before.kind) if isinstance(before, Value) else None
        if keeps and decl is None and constant is None:  # once, when first asked
            constant = {}
            for assign in assigns:
                constant_stores(assign, constant, self.statics)
        if decl is not None:
            lookup = self.refinement_lookup(decl, state)
            state.env[name] = self.refined.assumed(state, name, decl, lookup)
        elif (
            isinstance(before, Value)
            and keeps
            and constant is not None
            and constant.get(name, {"?"}) <= keeps
        ):
            kept = self.unknown(child, before.kind, before.unit)
            # a literal set to literals only (`z = 0.0`, then `z = table[k][1]`)
            # stays a number that takes the unit of its context
            plain = before.literal and name not in other_binders
            state.env[name] = replace(kept, literal=True) if plain else kept
        else:
            state.env[name] = self._forgotten(name, child, before, keeps_unit, None)
    return set(bound_at), keeps_unit


def _texts() -> list[tuple[str, str]]:
    found = [("every_kind.py", EVERY_KIND)]
    for path in sorted(CASES.rglob("*.py")):
        text = path.read_text(encoding="utf-8", errors="replace")
        if re.search(r"^\s*(for|while|try)\b", text, re.MULTILINE):
            found.append((str(path), text))
    return found


def _plain(text: str) -> str:
    # (nodes of two parses, and the ids of branch tests in decisions)
    return re.sub(r" at 0x[0-9a-f]+|\b[0-9]{10,}\b", "#", text)


def _run(
    monkeypatch: pytest.MonkeyPatch, havoc_sums: object, texts: list[tuple[str, str]]
) -> list[object]:
    """What each havoc returned and left in its state, and each file's
    diagnostics."""
    log: list[object] = []

    def logged(
        self: PathWalker, state: State, nodes: list[ast.stmt], loop: bool = False
    ) -> tuple[set[str], set[str]]:
        stored, summed = havoc_sums(self, state, nodes, loop)  # type: ignore[operator]
        after = (
            state.env,
            state.heap,
            state.versions,
            sorted(map(repr, state.shared.firm)),
        )
        log.append((sorted(stored), sorted(summed), _plain(repr(after))))
        return stored, summed

    with monkeypatch.context() as patch:
        patch.setattr(PathWalker, "havoc_sums", logged)
        for path, text in texts:
            log.append(_plain(repr(check_source(text, path))))
    return log


def test_havoc_walks_and_forgets_as_the_walk_before_it(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    texts = _texts()
    assert len(texts) > 20
    now = _run(monkeypatch, PathWalker.havoc_sums, texts)
    before = _run(monkeypatch, _havoc_sums_before, texts)
    assert sum(1 for one in now if isinstance(one, tuple)) > 100  # havocs met
    assert len(now) == len(before)
    for mine, theirs in zip(now, before, strict=True):
        assert mine == theirs


def test_the_shapes_are_the_fields_and_hold_nodes_only() -> None:
    """`SHAPES` lists each class's `fields` in their order, and in every case file
    (and the text above) each single field holds a node, each list nodes only: the
    children `children` finds, in its order."""
    for kind, (singles, lists) in SHAPES.items():
        assert (*singles, *lists) == fields(kind), kind.__name__
    met = 0
    for _, text in _texts():
        try:
            tree = ast.parse(text)
        except SyntaxError:
            continue
        for node in walk(tree):
            shape = SHAPES.get(type(node))
            if shape is None:
                continue
            found = [getattr(node, f) for f in shape[0]]
            for field in shape[1]:
                found.extend(getattr(node, field))
            assert all(isinstance(one, ast.AST) for one in found)
            assert found == children(node)
            met += 1
    assert met > 1000
