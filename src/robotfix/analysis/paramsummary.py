"""A file's parameters as data: what it declares (`ParamDecl`), which refinements
are attached to them (`Attached`), node names and owners (`Summary`), and the
constants names and numbers are matched with (`constant_of`). `parameters.py`
makes a summary (`summarize`) with the walk of `paramwalk.py`; a run checks
parameter files and launch files against the summaries (`robotfix.paramcheck`).
"""

from __future__ import annotations

import ast
from collections.abc import Callable
from dataclasses import dataclass, field
from fractions import Fraction

from robotfix.annotations.extract import Refinement
from robotfix.annotations.numbers import INFINITY, named_number
from robotfix.ros.rclpy_params import Range

MODULE = "<module>"


ROSPY = "rospy"


class _Unknown:
    def __repr__(self) -> str:
        return "<unknown>"

    def __reduce__(self) -> str:  # one instance, in a worker's summary too (`-j N`)
        return "UNKNOWN"


UNKNOWN = _Unknown()  # a default that is there but not a constant


@dataclass
class ParamDecl:
    """A parameter declared (ROS 2) or read with a default (ROS 1)."""

    owner: str
    name: str
    ros: int  # 1 or 2
    path: str
    line: int
    col: int
    default: object = None  # a constant, None (no default) or UNKNOWN
    default_at: tuple[int, int] | None = None  # (line, col) of the default
    type: str | None = None  # ROS 2 type name; None: unknown or dynamic
    dynamic: bool = False  # dynamic_typing, or not known not to be
    range: Range | None = None
    ignore_override: bool = False
    read_only: bool = False  # never changes after its declaration
    node_id: int = 0  # id() of the call or tuple, for the analysis

    def meaning(self) -> tuple[object, ...]:
        """What a read of it may assume: two declarations with the same meaning
        (on two paths) are as good as one."""
        rng = self.range
        bounds = (rng.integer, rng.from_value, rng.to_value, rng.step) if rng else None
        return (self.type, bounds, self.dynamic, self.ignore_override, self.read_only)


@dataclass(frozen=True)
class Attached:
    """A refinement written where a parameter's value is assigned."""

    owner: str
    name: str
    refinement: Refinement
    target: str
    path: str
    line: int
    declaration: bool  # at the declaration (ROS 2) or at a get_param with default


@dataclass
class Summary:
    """What a file declares and reads of ROS parameters, by owner (for `paramcheck`)."""

    path: str
    decls: list[ParamDecl] = field(default_factory=list)
    attached: list[Attached] = field(default_factory=list)
    node_names: dict[str, list[str]] = field(default_factory=dict)  # owner ->
    auto_declare: set[str] = field(default_factory=set)  # owners: overrides declare
    # owners whose parameters are not all known by name here: a declaration with a
    # computed name, `allow_undeclared_parameters`, a class handing `self` to
    # code of the tree (which may declare more), a base class of another module
    open_owners: set[str] = field(default_factory=set)
    bases: dict[str, list[str]] = field(default_factory=dict)  # class -> bases here
    listeners: dict[str, list[str]] = field(default_factory=dict)  # owner -> gpl ns
    by_node: dict[int, ParamDecl] = field(default_factory=dict)
    constants: dict[str, object] = field(default_factory=dict)  # module constants
    imports: dict[str, str] = field(default_factory=dict)

    def constant(self, node: ast.expr | None) -> object:
        """A constant argument as this pass reads it (UNKNOWN if it is not one)."""
        if node is None:
            return UNKNOWN
        return constant_of(node, self.constants, self.imports)

    def lineage(self, owner: str) -> list[str]:
        """`owner` and the classes of this file it inherits from, nearest first."""
        found: list[str] = []
        todo = [owner]
        while todo and len(found) < 50:
            current = todo.pop(0)
            if current not in found:
                found.append(current)
                todo.extend(self.bases.get(current, []))
        return found

    def declaration(self, owner: str, name: str) -> ParamDecl | None:
        """The declaration of `name` nearest in `owner`'s lineage; None when there
        is none, or several that disagree (declared on different paths)."""
        for current in self.lineage(owner):
            found = [
                d
                for d in self.decls
                if d.owner == current and d.name == name and d.ros == 2
            ]
            if found:
                same = len({d.meaning() for d in found}) == 1
                return found[0] if same else None
        return None

    def refinements(
        self, owner: str, name: str, declaration_only: bool
    ) -> list[Attached]:
        lineage = self.lineage(owner)
        return [
            a
            for a in self.attached
            if a.owner in lineage
            and a.name == name
            and (a.declaration or not declaration_only)
        ]

    def names_of(self, owner: str) -> list[str]:
        for current in self.lineage(owner):
            if self.node_names.get(current):
                return self.node_names[current]
        return []


def constant_of(
    node: ast.expr, names: dict[str, object], imports: dict[str, str]
) -> object:
    """A constant expression's value (numbers, strings, bools, None, lists of
    them, `-x`, `+ - * /` of numbers, `math.pi`, module constants), else UNKNOWN."""
    if isinstance(node, ast.Constant):
        if isinstance(node.value, (int, float, str, bool, bytes)) or node.value is None:
            return node.value
        return UNKNOWN
    if isinstance(node, ast.Name):
        return names.get(node.id, UNKNOWN)
    if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
        qualified = f"{imports.get(node.value.id, node.value.id)}.{node.attr}"
        number = _named_number(qualified)
        return UNKNOWN if number is None else number
    if isinstance(node, (ast.List, ast.Tuple)):
        items = [constant_of(e, names, imports) for e in node.elts]
        return UNKNOWN if any(i is UNKNOWN for i in items) else items
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        inner = constant_of(node.operand, names, imports)
        if isinstance(inner, (int, float)) and not isinstance(inner, bool):
            return -inner if isinstance(node.op, ast.USub) else inner
        return UNKNOWN
    if isinstance(node, ast.BinOp) and isinstance(
        node.op, (ast.Add, ast.Sub, ast.Mult, ast.Div)
    ):
        left = constant_of(node.left, names, imports)
        right = constant_of(node.right, names, imports)
        if not all(
            isinstance(v, (int, float)) and not isinstance(v, bool)
            for v in (left, right)
        ):
            return UNKNOWN
        a, b = left, right
        assert isinstance(a, (int, float)) and isinstance(b, (int, float))
        if abs(a) > 1e300 or abs(b) > 1e300:
            return UNKNOWN
        if isinstance(node.op, ast.Add):
            return a + b
        if isinstance(node.op, ast.Sub):
            return a - b
        if isinstance(node.op, ast.Mult):
            return a * b
        return UNKNOWN if b == 0 else a / b
    return UNKNOWN


def _named_number(qualified: str) -> float | None:
    """`math.pi`, `np.tau`: the double Python holds (infinity is not a constant)."""
    number = named_number(qualified)
    return None if number is None or number == INFINITY else float(number)


def constants_of(
    body: list[ast.stmt],
    bound_once: Callable[[str], bool],
    names: dict[str, object],
    imports: dict[str, str],
) -> dict[str, object]:
    """The names of a module or class body bound once to a constant (`MAX = 0.5`),
    in order; a value may use `names` and the constants before it."""
    found: dict[str, object] = {}
    for statement in body:
        target, value = None, None
        if isinstance(statement, ast.Assign) and len(statement.targets) == 1:
            target, value = statement.targets[0], statement.value
        elif isinstance(statement, ast.AnnAssign) and statement.value is not None:
            target, value = statement.target, statement.value
        if isinstance(target, ast.Name) and bound_once(target.id) and value:
            constant = constant_of(value, {**names, **found}, imports)
            if constant is not UNKNOWN:
                found[target.id] = constant
    return found


def exact(value: int | float) -> Fraction:
    """The decimal a float was most likely written as (`0.1` is 1/10)."""
    return Fraction(value) if isinstance(value, int) else Fraction(repr(float(value)))
