"""Issue 25 (tenth session): a checked file's graph reading (`run._graph_of`)
takes its imports and its number of classes from the check's index, so that
`bind_module` walks no statement when every class is at the top level, and it
reads nothing more of a file none of whose calls makes an endpoint. Both must
find what the whole walk finds, on every Python file of tests/cases."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from robotfix.analysis.index import index_of
from robotfix.ros.graph import python as G
from robotfix.ros.graph import python_names as N
from robotfix.ros.graph.model import FileGraph, dump

CASES = Path(__file__).parent / "cases"
FILES = sorted(CASES.rglob("*.py"))


def _tree(path: Path) -> ast.Module | None:
    try:
        return ast.parse(path.read_bytes())
    except (SyntaxError, ValueError):
        return None


def _bound(file: N.File) -> tuple[object, ...]:
    functions = {
        c: {n: id(f) for n, f in fs.items()} for c, fs in file.functions.items()
    }
    return (
        list(file.imports.items()),
        file.rospy,
        list(file.bases.items()),
        list(file.scope_class.items()),
        [(c, list(fs.items())) for c, fs in functions.items()],
    )


def _read(tree: ast.Module, **known: object) -> FileGraph:
    index = index_of(tree)
    return G.read_python(
        tree,
        index.calls,
        index.import_statements,
        len(index.class_scopes),
        **known,  # type: ignore[arg-type]
    )


@pytest.mark.parametrize("path", FILES, ids=lambda p: str(p.relative_to(CASES)))
def test_the_index_binds_the_module_as_its_statements_do(path: Path) -> None:
    """Imports (in the walk's order: the last binding of a name wins), rospy,
    class bases and methods, module functions: the same from the index's
    import statements as from a walk of every statement."""
    tree = _tree(path)
    if tree is None:
        return
    index = index_of(tree)
    walked, given = N.File(tree), N.File(tree)
    N.bind_module(walked)
    N.bind_module(given, index.import_statements, len(index.class_scopes))
    assert _bound(given) == _bound(walked)


@pytest.mark.parametrize("path", FILES, ids=lambda p: str(p.relative_to(CASES)))
def test_the_graph_read_with_the_index_is_the_whole_walks(path: Path) -> None:
    tree = _tree(path)
    if tree is None:
        return
    whole = dump(G.read_python(tree))
    assert dump(_read(tree)) == whole
    only = _read(tree, endpoints_only=True)
    assert dump(only) == (whole if only.endpoints else dump(FileGraph()))
    assert bool(only.endpoints) == bool(G.read_python(tree).endpoints)


def test_no_statement_walked_when_every_class_is_at_the_top(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """With the index's import statements, a module whose classes are all at its
    top level is not walked for them; one with a class in a function is."""
    walked: list[int] = []
    real = N._walk_statements
    monkeypatch.setattr(
        N, "_walk_statements", lambda file: walked.append(1) or real(file)
    )
    text = (
        "import rclpy\nfrom std_msgs.msg import String\n"
        "def main():\n    import rospy as r\n    if True:\n        pass\n"
        "class A(rclpy.node.Node):\n    def __init__(self):\n"
        "        super().__init__('a')\n"
        "        self.create_publisher(String, 't', 10)\n"
    )
    found = _read(ast.parse(text))
    assert not walked
    assert found.nodes == {"A": ["a"]} and found.ros == 1
    _read(ast.parse(text + "def f():\n    class B:\n        pass\n"))
    assert walked == [1]


def test_a_file_without_an_endpoint_call_is_not_read(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Only the endpoints wanted (`run._graph_of`): a file that names a node but
    makes no endpoint is not walked; a call of an imported endpoint class is one."""
    visited: list[int] = []
    real = G._visit
    monkeypatch.setattr(G, "_visit", lambda *a: visited.append(1) or real(*a))
    text = "import rclpy\nnode = rclpy.create_node('n')\nprint(node)\n"
    assert dump(_read(ast.parse(text), endpoints_only=True)) == dump(FileGraph())
    assert not visited
    assert _read(ast.parse(text)).nodes == {"node": ["n"]}
    ros1 = "from rospy import Publisher as P\nP('t', int)\n"
    assert [e.name for e in _read(ast.parse(ros1), endpoints_only=True).endpoints] == [
        "t"
    ]
