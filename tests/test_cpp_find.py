"""The C++ reading's nodes, found from the words of a file (`cpp_find`), give
the reading a tree-sitter query of every node of their kinds gave before."""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from robotfix.ros.executables import CPP_SOURCE_SUFFIXES
from robotfix.ros.graph import cpp, cpp_find
from robotfix.ros.graph.cpp_scan import makers_in

CASES = Path(__file__).parent / "cases"
# the query the reading used before cpp_find (every node of the kinds it reads)
_PATTERNS = """
(call_expression) @call
(function_definition) @fn
(alias_declaration) @alias
(using_declaration) @using
(field_initializer) @init
((declaration) @decl (#match? @decl "NodeHandle|make_shared"))
((field_declaration) @decl (#match? @decl "NodeHandle"))
(class_specifier) @cls
(struct_specifier) @cls
"""
_CURSOR: Any = None
_KIND = {"function_definition": "fn", "field_initializer": "init"}


def _captures(root: Any) -> dict[str, list[Any]]:
    global _CURSOR
    if _CURSOR is None:
        import tree_sitter
        import tree_sitter_cpp

        language = tree_sitter.Language(tree_sitter_cpp.language())
        _CURSOR = tree_sitter.QueryCursor(tree_sitter.Query(language, _PATTERNS))
    return {
        name: sorted(found, key=lambda n: (n.start_byte, n.end_byte))
        for name, found in _CURSOR.captures(root).items()
    }


@contextlib.contextmanager
def queried(monkeypatch: pytest.MonkeyPatch) -> Iterator[None]:
    """The reading with the query's nodes (all of each kind, in source order)."""
    with monkeypatch.context() as m:
        m.setattr(cpp, "nodes", lambda root, data, makers: _captures(root))
        m.setattr(
            cpp,
            "named",
            lambda root, data, name, kind: _captures(root).get(_KIND[kind], []),
        )
        yield


def _read(data: bytes, names: bool) -> tuple[Any, ...]:
    found = cpp.read_cpp(data, names)
    return found.ros, list(found.nodes.items()), found.endpoints


def cpp_files(folder: Path) -> list[Path]:
    return sorted(
        p for p in folder.rglob("*") if p.suffix in CPP_SOURCE_SUFFIXES and p.is_file()
    )


# what the words find only by their edges: comments and line breaks before a
# string argument, a base class named across blanks, calls on a call's result,
# a callback defined twice, aliases, handles, a node made with make_shared
SNIPPETS = [
    b'class T : public rclcpp::Node { T() : Node( /* n */ "talker"), pnh_(\n"~") {} };',
    b'class T : public rclcpp :: Node { T() : Node(// c\n"a") { '
    b'create_publisher<std_msgs::msg::String>("x", 10); } };',
    b'struct S : nav2_util::LifecycleNode { S() : LifecycleNode(u8"s") {} };',
    b"void cb(const std_msgs::String::ConstPtr& m);\n"
    b"void cb(const geometry_msgs::Twist::ConstPtr& m) {}\n"
    b'void f() { ros::NodeHandle nh, pnh("~"); ros::init(argc, argv, "n");\n'
    b'  auto s = nh.subscribe("t", 10, cb); nh.advertise<std_msgs::Int32>("o", 1); }',
    b"using Twist = geometry_msgs::msg::Twist; using geometry_msgs::msg::Pose;\n"
    b'void f() { auto node = rclcpp::Node::make_shared("n");\n'
    b'  node->create_publisher<Twist>("a", rclcpp::QoS(10).best_effort());\n'
    b'  node->create_subscription<Pose>("b", 1, cb).get(); }',
    b'class A : public rclcpp::Node { A() : Node("a") {\n'
    b'  declare_parameter<double>("x", 0.5); declare_parameter("y", false);\n'
    b"  auto p = std::make_unique<nav2_util::TwistPublisher>(\n"
    b'    shared_from_this(), "c", 1);\n'
    b'  rclcpp_action::create_server<nav2_msgs::action::Spin>(this, "spin"); } };',
    b'void f() { ros::NodeHandle nh; nh.param("p", v, 0.5);'
    b' nh.subscribe("t", 1, &Foo::cb, this); }\n'
    b"void Foo::cb(const a::B::ConstPtr& m) {}",
    b'class B : public rclcpp::\xc2\xa0Node { B() : Node(\xc2\xa0"b") {} };',
    b'class L { L() : nh_("~"), gh_ {"/g"} {\n'
    b'  p_ = nh_.advertise<std_msgs::String>("c", 1);\n'
    b'  q_ = gh_.advertise<std_msgs::String>("d", 1); }\n'
    b"  ros::NodeHandle nh_, gh_; };",
]


def _all_inputs() -> list[tuple[str, bytes]]:
    files = [(str(p), p.read_bytes()) for p in cpp_files(CASES)]
    return files + [(f"snippet {i}", s) for i, s in enumerate(SNIPPETS)]


def test_reading_is_the_querys_on_every_case(monkeypatch: pytest.MonkeyPatch) -> None:
    inputs = _all_inputs()
    assert len(inputs) > len(SNIPPETS)  # (the cases hold C++ files)
    new = [_read(data, names) for _, data in inputs for names in (True, False)]
    with queried(monkeypatch):
        old = [_read(data, names) for _, data in inputs for names in (True, False)]
    assert [o for o in old if o[2]]  # (endpoints found)
    wheres = [where for where, _ in inputs for _ in (True, False)]
    for where, before, now in zip(wheres, old, new, strict=True):
        assert before == now, where


def test_no_query_is_compiled(monkeypatch: pytest.MonkeyPatch) -> None:
    """Compiling a query reads the grammar's whole parse table (63 M
    instructions) in every run that parses C++: the reading compiles none."""
    import tree_sitter

    def refused(*args: object) -> None:
        raise AssertionError("a query was compiled")

    monkeypatch.setattr(tree_sitter, "Query", refused)
    found = cpp.read_cpp(SNIPPETS[5])
    assert found.nodes == {"A": ["a"]}
    assert [e.name for e in found.endpoints] == ["x", "y", "c", "spin"]


def test_few_nodes_are_visited() -> None:
    """The descents visit the nodes around the words, not the tree."""
    data = b"int a;\n" * 2000 + SNIPPETS[5]
    root = cpp._parser().parse(data).root_node
    seen = cpp_find._around(root, cpp_find._places(data, makers_in(data)))
    assert len(seen) < 100 < root.descendant_count


def test_places() -> None:
    """The words a node the reading takes something from holds, and no more."""

    def words(data: bytes) -> list[bytes]:
        return [data[s:e] for s, e in sorted(cpp_find._places(data, makers_in(data)))]

    assert words(
        b'n.param("a", x); get_parameter("b"); initialize(); ros::init(a);'
    ) == [
        b"param",
        b"init",
    ]
    assert words(b"rclcpp::Node::SharedPtr n; NodeOptions o; rclcpp::Node") == [
        b"Node",
        b"Node",
    ]
    assert words(b"struct A : Life cycle\xc2\xa0No de {};") == [b"No de"]
    assert words(b"auto h = x.make_shared_handle(); NodeHandle_t t; using X = Y;") == [
        b"make_shared",
        b"NodeHandle",
        b"using",
    ]


def test_handles_are_read_when_a_call_asks() -> None:
    """An initializer's namespace for a handle (`nh_("~")`) is looked for when
    a roscpp call on the handle asks, and the last one given counts."""
    data = (
        b'class L { L() : nh_("/a") {} L(int) : nh_("~") {}\n'
        b'  void f() { p_ = nh_.advertise<std_msgs::String>("c", 1); } };'
    )
    found = cpp.read_cpp(data)
    assert [(e.name, e.handle) for e in found.endpoints] == [("c", "~")]
    assert cpp.read_cpp(data.replace(b"nh_.", b"gh_.")).endpoints[0].handle == ""


def test_a_declaration_not_in_utf8_is_read() -> None:
    """A Latin-1 comment in a declaration: the query's `#match?` decoded every
    declaration's text and raised UnicodeDecodeError (an internal error of the
    check; with other bytes, a crash of the process)."""
    data = (
        b'class T : public rclcpp::Node {\n  T() : Node("t") {\n'
        b"    int /* Gr\xfc\xdfe */ x = 1;\n"
        b'    pub_ = create_publisher<std_msgs::msg::String>("chatter", 10); } };'
    )
    found = cpp.read_cpp(data)
    assert found.nodes == {"T": ["t"]}
    assert [e.name for e in found.endpoints] == ["chatter"]
