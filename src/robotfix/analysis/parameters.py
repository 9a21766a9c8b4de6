"""Parameters in Python: what a file declares and reads, found syntactically.

One pass over a module's AST (`summarize`) finds, per *owner* (the node object the
calls are made on: a Node subclass `C` for `self.declare_parameter`, `C#attr` for
`self.attr.declare_parameter`, `f#node` for a local `node` in function `f`, `rospy`
for ROS 1):

- ROS 2 declarations: `declare_parameter(name, default, descriptor)` and each tuple
  of `declare_parameters(namespace, [...])`, with the type rclpy infers from the
  default (or `Parameter.Type.X`), and the ParameterDescriptor's
  `floating_point_range`/`integer_range` and `dynamic_typing`, written inline or
  built in a local variable of the same function;
- ROS 1 reads `rospy.get_param(name, default)`;
- refinements attached where a read is assigned to an `Annotated` variable or
  attribute (`self.v: Annotated[float, "0 < _ <= 1"] = self.declare_parameter(
  'v', 0.5).value`);
- node names (`super().__init__('name')`, `Node('name')`, `rclpy.create_node`,
  `rospy.init_node`) and generate_parameter_library listeners
  (`ns.ParamListener(self)`).

Names and numbers are matched as constants: literals, `math.pi`, and module-level
constants; anything else is unknown and stays silent. The analysis uses the summary
for the reads it interprets (`ParamContext`), and a run uses the summaries of all
checked files to check parameter files (`robotfix.paramcheck`).
"""

from __future__ import annotations

import ast
import weakref
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from robotfix.analysis import imported
from robotfix.analysis.index import FileIndex, index_of
from robotfix.analysis.paramsummary import MODULE, ParamDecl, Summary, constants_of
from robotfix.analysis.paramwalk import Walker
from robotfix.analysis.values import Value
from robotfix.astwalk import walk
from robotfix.source import SourceFile

if TYPE_CHECKING:
    from robotfix.stubs.load import StubSet


# each tree's summary, made once a run: for the run's parameter files and for the
# file's own check (`ParamContext`), with the resolver it was made with (the check's
# own: they see the same modules); a summary is not changed once made
_SUMMARIES: weakref.WeakKeyDictionary[
    ast.Module, tuple[tuple[imported.Resolver | None, StubSet | None], Summary]
] = weakref.WeakKeyDictionary()


def summarize(
    source: SourceFile,
    index: FileIndex | None = None,
    resolver: imported.Resolver | None = None,
    stubs: StubSet | None = None,
) -> Summary:
    """What `source` declares and reads; an empty summary for a file with no tree.
    `resolver`: how the file sees the other modules of its tree (an alias or a
    constant a refinement imports from them); None, it sees none. `stubs`: where
    a parameter API of another framework may be described (`@ros_parameter`)."""
    tree = source.tree
    if tree is None:
        return Summary(source.path)
    shared = index_of(tree)
    if index is not None and index is not shared:
        return _summarize(source, tree, index, resolver, stubs)
    made, found = _SUMMARIES.get(tree, ((None, None), None))
    if (
        found is None
        or found.path != source.path
        or made[0] is not resolver
        or made[1] is not stubs
    ):
        found = _summarize(source, tree, shared, resolver, stubs)
        _SUMMARIES[tree] = ((resolver, stubs), found)
    return found


def _summarize(
    source: SourceFile,
    tree: ast.Module,
    index: FileIndex,
    resolver: imported.Resolver | None,
    stubs: StubSet | None = None,
) -> Summary:
    summary = Summary(source.path)
    summary.constants = _module_constants(tree, index)
    summary.imports = index.imports
    walker = Walker(source, index, summary, summary.constants, resolver, stubs)
    module_body: list[ast.stmt] = []
    passing: list[dict[str, set[str]] | None] = []  # `_passed_names`, made once
    for statement in tree.body:
        if isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef)):
            if _mentions(source, statement):
                walker.unit(statement.name, None, statement, statement.body)
        elif isinstance(statement, ast.ClassDef):
            summary.bases[statement.name] = [
                b.id for b in statement.bases if isinstance(b, ast.Name)
            ]
            if not passing:
                passing.append(_passed_names(tree, index))
            names = passing[0].get(statement.name, set()) if passing[0] else None
            if _hands_out_self(statement, index, names) or any(
                _base_name(b, index) not in (*NODE_BASES, *summary.bases)
                for b in statement.bases
            ):
                summary.open_owners.add(statement.name)
            for item in statement.body:
                if isinstance(
                    item, (ast.FunctionDef, ast.AsyncFunctionDef)
                ) and _mentions(source, item):
                    walker.unit(
                        f"{statement.name}.{item.name}", statement, item, item.body
                    )
        else:
            module_body.append(statement)
    walker.unit(MODULE, None, None, module_body)
    summary.by_node = {d.node_id: d for d in summary.decls}
    return summary


def _module_constants(tree: ast.Module, index: FileIndex) -> dict[str, object]:
    """Module-level names bound once, to a constant (`MAX_SPEED = 0.5`)."""
    counts = index_of(tree).stores  # what a walk of every node would count
    return constants_of(tree.body, lambda n: counts.get(n) == 1, {}, index.imports)


# what a node class may inherit from without inheriting parameter declarations
NODE_BASES = (
    "rclpy.node.Node",
    "rclpy.lifecycle.LifecycleNode",
    "rclpy.lifecycle.Node",
)


# libraries a node hands `self` to (a tf2 listener, a timer) that declare nothing
SELF_TAKERS = ("rclpy", "tf2_ros", "message_filters", "image_transport", "cv_bridge")


def _base_name(node: ast.expr, index: FileIndex) -> str:
    """A base class as written or as imported (`Node` -> `rclpy.node.Node`)."""
    return imported.dotted_name(node, index.imports) or ""


def _hands_out_self(
    cls: ast.ClassDef, index: FileIndex, names: set[str] | None = None
) -> bool:
    """Whether a method passes its `self` to a callee outside `SELF_TAKERS` (which
    may declare parameters on it where this file cannot see). `names`: every
    name any call of the class passes (`_passed_names`): a method whose `self` is
    none of them is not walked."""
    for item in cls.body:
        if not isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)):
            continue
        if not item.args.args:
            continue
        me = item.args.args[0].arg
        if names is not None and me not in names:
            continue
        for node in walk(item.body):
            if not isinstance(node, ast.Call):
                continue
            passed = [*node.args, *(k.value for k in node.keywords)]
            if not any(isinstance(a, ast.Name) and a.id == me for a in passed):
                continue
            callee = imported.dotted_name(node.func, index.imports) or ""
            if callee.split(".")[0] not in SELF_TAKERS and not (
                callee.endswith(".__init__") and callee.rsplit(".", 1)[0] in NODE_BASES
            ):
                return True
    return False


def _passed_names(tree: ast.Module, index: FileIndex) -> dict[str, set[str]] | None:
    """Top-level class -> the names its calls pass as arguments, from the index's
    calls (None: `index` is not this tree's, whose calls it would not hold)."""
    if id(tree) not in index.scopes:
        return None
    found: dict[str, set[str]] = {}
    name = ast.Name
    for cls, call in index.calls:
        if cls is not None:
            names = found.get(cls)
            if names is None:
                names = found[cls] = set()
            for arg in call.args:
                if type(arg) is name:
                    names.add(arg.id)
            for keyword in call.keywords:
                if type(keyword.value) is name:
                    names.add(keyword.value.id)
    return found


# A function whose text has none of these declares, reads and names nothing.
WORDS = ("_param", "ParamListener", "init_node", "__init__", "Node", "node")


def _mentions(source: SourceFile, node: ast.stmt) -> bool:
    end = getattr(node, "end_lineno", None) or node.lineno
    text = "\n".join(source.lines[node.lineno - 1 : end])
    return any(word in text for word in WORDS)


@dataclass
class Handle:
    """A Parameter object in the analysed code (what declare/get_parameter return)."""

    owner: str
    name: str
    decl: ParamDecl | None
    # its `.value` may attach: returned by declare_parameter, or by get_parameter
    # of a name its class declares (the default is the declaration's)
    declaration: bool
    default: Value | None = None
    default_node: ast.expr | None = None
    call: ast.Call | None = None
    value: Value | None = None  # the value read, once read
    later: bool = False  # a get_parameter of a name its class declares


@dataclass(frozen=True)
class ParamRead:
    """A value read from a parameter: where (the expression) and what attaches."""

    name: str
    ros: int
    node: ast.expr  # the expression that read it
    attach: bool  # assigned to a refined target right there: the refinement holds
    default: Value | None
    default_node: ast.expr | None
    later: bool = False  # a get_parameter of a name its class declares


@dataclass
class ParamContext:
    """A file's parameter summary in the making, with the handles and reads met."""

    summary: Summary
    handles: dict[str, Handle] = field(default_factory=dict)
    reads: dict[int, ParamRead] = field(default_factory=dict)  # Sym ident ->
    fixed: dict[tuple[str, str], Value] = field(default_factory=dict)  # read_only
    # id(node) -> every call of the file and every tuple under a `declare_parameters`
    # call: where a declaration's default is read (`param_eval`, made at the first ask)
    declarations: dict[int, ast.Call | ast.Tuple] | None = None
