"""The graph endpoints of one C++ file, read with tree-sitter's C++ grammar (the
only import of tree-sitter; nothing is compiled or run).

rclcpp: `create_publisher<geometry_msgs::msg::Twist>("cmd_vel", qos)`,
`create_subscription<T>(...)`, `create_service<T>`, `create_client<T>`,
`rclcpp_action::create_server<T>(node, "name", ...)` and `create_client<T>`,
`declare_parameter<double>("max_speed", 0.5)` and `declare_parameter("x", 0.5)`.
roscpp: `nh.advertise<std_msgs::String>("chatter", 10)`, `subscribe("t", 10, cb)`
(the type from the callback's `const T::ConstPtr&` parameter, when `cb` is a
function of the file), `advertiseService`, `serviceClient<T>`, `nh.param("x", v,
0.5)`, and `ros::NodeHandle pnh("~")` making `pnh`'s names private.

Names and types only, where they are written as literals (a string literal; a
type spelled `pkg::msg::Name`, or an alias of one the file declares with `using`);
anything computed is unknown. QoS: a depth, `rclcpp::QoS(n)` with its setters
(`.best_effort()`, `.transient_local()`), `rclcpp::SensorDataQoS()` and the other
preset classes, in the call or through a local declared once and only read. A
parameter's type: its template argument, else its literal default's (`false`:
bool). Which node: the class a method belongs to (its name from the
`Node("name")` base initializer; `Node(node_name)`: unknown), else the node
variable (`node->create_...`).

Bad C++ never fails: tree-sitter recovers from errors; a file over
`MAX_CPP_BYTES` is not read, and one without any of `WORDS` (or where no name
that makes an endpoint stands as a word, or none is called and no node is
named: `cpp_scan`) not parsed. What the reading needs of the tree is found
from the words of the file's bytes (`cpp_find`): the nodes around them.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from typing import Any

from robotfix.ros.graph import qos as Q
from robotfix.ros.graph.cpp_find import named, nodes
from robotfix.ros.graph.cpp_scan import (
    ACTIONS,
    AUTO,
    CLASSES,
    METHODS,
    NODE_BASES,
    OPENING_WORDS,
    RCLCPP_BASES,
    WORDS,
    makers_in,
    may_make,
    opening,
)
from robotfix.ros.graph.model import (
    MIDDLE,
    OPENS,
    PARAMETER,
    SUBSCRIPTION,
    Endpoint,
    FileGraph,
    Qos,
)

MAX_CPP_BYTES = 2 * 1024 * 1024
# a call whose callee's text holds none of these makes nothing (`_File._call`)
_CALLED = re.compile(
    b"|".join(
        re.escape(w.encode())
        for w in sorted(
            {*METHODS, "make_unique", "make_shared", "rclcpp_action", "init"}
        )
    )
)
_PTR = re.compile(r"(::)?(ConstPtr|Ptr|SharedPtr|ConstSharedPtr|UniquePtr)$")

_PARSER: Any = None


def _parser() -> Any:
    global _PARSER
    if _PARSER is None:
        import tree_sitter
        import tree_sitter_cpp

        _PARSER = tree_sitter.Parser(tree_sitter.Language(tree_sitter_cpp.language()))
    return _PARSER


def read_cpp(data: bytes, names: bool = True) -> FileGraph:
    """The endpoints and node names of a C++ file's bytes. Without `names`, a
    file that can make no endpoint is not parsed for the node names and the ROS
    version it may hold: a graph without endpoints adds nothing to the run's
    (`graphcheck.read_cpp_files` keeps none)."""
    found = FileGraph()
    if len(data) > MAX_CPP_BYTES or not any(w in data for w in WORDS):
        return found
    if any(w in data for w in OPENING_WORDS):
        found.endpoints += opening(data)
    makers = makers_in(data)
    if not makers and not any(e.value == AUTO for e in found.endpoints):
        return found  # (given any override: parsed for the node it is given to)
    if not found.endpoints and not may_make(data, makers, names):
        return found  # a maker's name in comments only (`@param`): nothing found
    try:
        tree = _parser().parse(data)
    except (ValueError, RuntimeError):
        return found
    _File(found, data, tree.root_node).read(makers)
    found.endpoints.sort(key=lambda e: (e.line, e.col, e.kind))
    return found


def _text(node: Any) -> str:
    return node.text.decode("utf-8", "replace") if node is not None else ""


class _File:
    def __init__(self, found: FileGraph, data: bytes, root: Any) -> None:
        self.found = found
        self.data = data
        self.root = root
        self.aliases: dict[str, str] = {}  # `using Twist = geometry_msgs::msg::Twist`
        self._callbacks: dict[str, str | None] = {}  # (`callback`)
        self.handles: dict[str, str] = {}  # NodeHandle variable -> its namespace
        self._initialized: set[str] = set()  # (`_handle_of`)
        self.ros1 = False
        # a descriptor may make a declaration's type dynamic: then none is certain
        self.dynamic = b"dynamic_typing" in data

    def read(self, makers: list[tuple[int, int, bytes]]) -> None:
        # each kind in source order (which of two `chatterCallback`s a callback
        # is, the order of a class's node names)
        captures = nodes(self.root, self.data, makers)
        for node in captures.get("cls", []):
            name = node.child_by_field_name("name")
            if name is not None:
                self._bases(node, _text(name).split("::")[-1])
        for node in captures.get("alias", []):
            name = node.child_by_field_name("name")
            value = node.child_by_field_name("type")
            if name is not None and value is not None:
                self.aliases[_text(name)] = _text(value)
        for node in captures.get("using", []):
            text = _text(node)[len("using") :].strip().rstrip(";").strip()
            if "::" in text and not text.startswith("namespace"):
                self.aliases[text.rsplit("::", 1)[-1]] = text
        for node in captures.get("decl", []):  # (the enclosing class: when needed)
            self._handle(node)
        for node in captures.get("init", []):
            self._initializer(node)
        for node in captures.get("call", []):
            self._call(node)
        self.found.ros = 1 if self.ros1 else 2

    # -- declarations ----------------------------------------------------------
    def _bases(self, node: Any, cls: str) -> None:
        for child in node.children:
            if child.type == "base_class_clause":
                for base in child.children:
                    written = re.sub(r"\s+", "", _text(base).split("<")[0])
                    last = written.split("::")[-1]
                    if last in NODE_BASES:
                        self.found.nodes.setdefault(cls, [])
                    if last in NODE_BASES and written not in RCLCPP_BASES:
                        # another package's node class: it may declare parameters
                        point = base.start_point
                        self.found.endpoints.append(
                            Endpoint(
                                OPENS,
                                None,
                                (),
                                point[0] + 1,
                                point[1],
                                cls,
                                None,
                                2,
                                "",
                                written,
                            )
                        )

    def callback(self, name: str) -> str | None:
        """The first parameter's type of the function `name` (a roscpp
        callback's message type; of the last definition of that name), looked
        for when a subscription first asks: most files ask for none."""
        if name not in self._callbacks:
            found: dict[str, str] = {}
            for node in named(self.root, self.data, name, "function_definition"):
                self._function(node, found)
            self._callbacks[name] = found.get(name)
        return self._callbacks[name]

    def _function(self, node: Any, callbacks: dict[str, str]) -> None:
        """A function's first parameter's type, for a roscpp callback."""
        declarator = _declarator(node)
        if declarator is None:
            return
        text = _text(declarator.child_by_field_name("declarator"))
        params = declarator.child_by_field_name("parameters")
        first = (
            [c for c in params.children if c.type == "parameter_declaration"]
            if params
            else []
        )
        if first:
            kind = first[0].child_by_field_name("type")
            if kind is not None:
                callbacks[text.split("::")[-1]] = _text(kind)

    def _initializer(self, node: Any, handle: str | None = None) -> None:
        """`: Node("talker")` names the class's node; with `handle`, only
        `pnh_("~")` making `handle` a private handle (`_handle_of`)."""
        name = _text(node.children[0]) if node.children else ""
        args = [
            c
            for c in (node.children[-1].children if node.children else [])
            if c.type not in ("(", ")", ",")
        ]
        literal = _string(args[0]) if args else None
        last = name.split("::")[-1].split("<")[0]
        cls = _enclosing(node) if last in NODE_BASES and literal is not None else ""
        if cls and literal is not None:
            if handle is None:
                self.found.nodes.setdefault(cls, []).append(literal)
        elif (
            name == handle
            and literal is not None
            and (literal.startswith(("~", "/")) or name.endswith("_"))
        ):
            self.handles[name] = literal

    def _handle_of(self, receiver: str) -> str:
        """The namespace of the NodeHandle `receiver` ("?": unknown): of its
        declaration, or of the last initializer that gives it one, looked for
        when a roscpp call on it first asks (most files ask for none)."""
        if receiver not in self._initialized:
            self._initialized.add(receiver)
            for node in named(self.root, self.data, receiver, "field_initializer"):
                self._initializer(node, receiver)
        return self.handles.get(receiver, "?")

    def _handle(self, node: Any) -> None:
        """`ros::NodeHandle nh, pnh("~");`, `auto node =
        rclcpp::Node::make_shared("talker");`"""
        kind = node.child_by_field_name("type")
        if kind is None:
            return
        if not _text(kind).endswith("NodeHandle"):
            for child in node.children:
                value = (
                    child.child_by_field_name("value")
                    if child.type == "init_declarator"
                    else None
                )
                if value is None or value.type != "call_expression":
                    continue
                func = _text(value.child_by_field_name("function"))
                if "make_shared" in func and "Node" in func:
                    args = [
                        c
                        for c in value.child_by_field_name("arguments").children
                        if c.type not in ("(", ")", ",")
                    ]
                    literal = _string(args[0]) if args else None
                    var = _text(child.child_by_field_name("declarator"))
                    if literal is not None:
                        owner = _owner(_enclosing(node), var)
                        self.found.nodes.setdefault(owner, []).append(literal)
            return
        self.ros1 = True
        for child in node.children:
            if child.type == "init_declarator":
                name = child.child_by_field_name("declarator")
                value = child.child_by_field_name("value")
                if value is not None and value.type in (
                    "argument_list",
                    "initializer_list",
                ):
                    args = [
                        c
                        for c in value.children
                        if c.type not in ("(", ")", ",", "{", "}")
                    ]
                    literal = _string(args[0]) if args else None
                    self.handles[_text(name)] = literal if literal is not None else "?"
                else:
                    self.handles[_text(name)] = "?"
            elif child.type in ("identifier", "field_identifier"):
                self.handles[_text(child)] = ""

    # -- calls -------------------------------------------------------------------
    def _call(self, call: Any) -> None:
        func = call.child_by_field_name("function")
        if func is None or not _CALLED.search(
            self.data, func.start_byte, func.end_byte
        ):
            return  # (most calls: 85% of the issue-25 corpus's 12,487)
        args_node = call.child_by_field_name("arguments")
        if args_node is None:
            return
        receiver = None
        if func.type == "field_expression":
            receiver = func.child_by_field_name("argument")
            func = func.child_by_field_name("field")
            if func is None:
                return
        template = None
        if func.type in ("template_method", "template_function"):
            template = func.child_by_field_name("arguments")
            func = func.child_by_field_name("name")
        elif func.type == "qualified_identifier":
            scope = _text(func).split("::")[0]
            inner = func.child_by_field_name("name")
            if inner is not None and inner.type == "template_function":
                template = inner.child_by_field_name("arguments")
                func = inner.child_by_field_name("name")
            else:
                func = inner
            if (
                scope == "std"
                and func is not None
                and _text(func) in ("make_unique", "make_shared")
                and template is not None
            ):
                made = _text(template).strip("<> ")
                self._constructed(call, made, _arguments(args_node))
                return
            if scope == "rclcpp_action" and func is not None:
                self._action(call, _text(func), template, _arguments(args_node))
                return
            if scope == "ros" and func is not None and _text(func) == "init":
                self.ros1 = True
                args = _arguments(args_node)
                name = _string(args[2]) if len(args) > 2 else None
                if name is not None:
                    self.found.nodes.setdefault("", []).append(name)
                return
        method = _text(func)
        spec = METHODS.get(method)
        if spec is None:
            return
        kind, ros, name_at, qos_at, default_at = spec
        if ros == 1 and receiver is None:
            return  # advertise(...) alone is no roscpp call
        args = _arguments(args_node)
        handle = ""
        recv_text = _text(receiver) if receiver is not None else "this"
        if method == "declare_parameter_if_not_declared":
            recv_text = _helper_node(call, args[0] if args else None)
        owner = _owner(_enclosing(call), recv_text)
        if ros == 1:
            self.ros1 = True
            owner = ""
            handle = self._handle_of(recv_text)
        name = _string(args[name_at]) if len(args) > name_at else None
        types = self._types(template, kind)
        if kind == SUBSCRIPTION and ros == 1 and not types and len(args) > 2:
            types = self._callback_type(args[2], kind)
        profile = None
        if qos_at is not None and len(args) > qos_at:
            profile = _qos(args[qos_at])
        value = None
        if default_at is not None and len(args) > default_at:
            value = _text(args[default_at])[:80]
        if kind == PARAMETER and template is not None and not types:
            types = (_text(template)[1:-1].strip(),)  # `<std::vector<double>>`
        elif kind == PARAMETER and ros == 2 and default_at is not None:
            types = _literal_type(args[default_at] if len(args) > default_at else None)
        if kind == PARAMETER and ros == 2 and self.dynamic:
            types = ()
        if handle == "?":
            name = name if name is not None and name.startswith("/") else None
            handle = ""
        point = call.start_point
        self.found.endpoints.append(
            Endpoint(
                kind,
                name,
                types,
                point[0] + 1,
                _col(call, self.data),
                owner,
                profile,
                ros,
                handle,
                value,
            )
        )

    def _constructed(self, call: Any, made: str, args: list[Any]) -> None:
        """`std::make_unique<nav2_util::TwistPublisher>(node, "cmd_vel", 1)`."""
        spec = CLASSES.get(re.sub(r"\s+", "", made))
        if spec is None:
            return
        cls = _enclosing(call)
        kind, name_at, qos_at, types = spec
        receiver = _text(args[0]) if args else ""
        name = _string(args[name_at]) if len(args) > name_at else None
        profile = (
            _qos(args[qos_at]) if qos_at is not None and len(args) > qos_at else None
        )
        self.found.endpoints.append(
            Endpoint(
                kind,
                name,
                types,
                call.start_point[0] + 1,
                _col(call, self.data),
                _owner(cls, receiver),
                profile,
                2,
            )
        )

    def _action(self, call: Any, function: str, template: Any, args: list[Any]) -> None:
        kind = ACTIONS.get(function)
        if kind is None:
            return
        cls = _enclosing(call)
        receiver = _text(args[0]) if args else ""
        if receiver.startswith(("shared_from_this", "this->get_node", "this")):
            receiver = "this"
        owner = _owner(cls, receiver)
        name = _string(args[1]) if len(args) > 1 else None
        self.found.endpoints.append(
            Endpoint(
                kind,
                name,
                self._types(template, kind),
                call.start_point[0] + 1,
                _col(call, self.data),
                owner,
                None,
                2,
            )
        )

    def _types(self, template: Any, kind: str) -> tuple[str, ...]:
        if template is None:
            return ()
        parts = [c for c in template.children if c.type not in ("<", ">", ",")]
        if not parts or kind == PARAMETER:
            return ()
        return _interface(_text(parts[0]), self.aliases, kind)

    def _callback_type(self, node: Any, kind: str) -> tuple[str, ...]:
        text = _text(node).lstrip("&").strip()
        name = text.split("::")[-1]
        param = self.callback(name)
        if param is None:
            return ()
        param = param.replace("const", " ").replace("&", " ").strip()
        if param.startswith("boost::shared_ptr<"):
            param = param[len("boost::shared_ptr<") :].rstrip(">").strip()
        elif not _PTR.search(param):
            return ()  # a message taken by value: rare, and templates hide it
        param = _PTR.sub("", param).strip().rstrip(":")
        return _interface(param, self.aliases, kind)


MAX_DEPTH = 400  # ancestors looked at for the enclosing class


def _declarator(node: Any) -> Any:
    """A function definition's `function_declarator`, or None."""
    declarator = node.child_by_field_name("declarator")
    while declarator is not None and declarator.type in (
        "pointer_declarator",
        "reference_declarator",
    ):
        declarator = declarator.child_by_field_name("declarator")
    if declarator is None or declarator.type != "function_declarator":
        return None
    return declarator


def _enclosing(node: Any) -> str:
    """The class a node's code belongs to: of the class body it is in, or of the
    method defined out of its class (`Talker::Talker() : Node("talker")`)."""
    parent = node.parent
    for _ in range(MAX_DEPTH):
        if parent is None:
            return ""
        if parent.type in ("class_specifier", "struct_specifier"):
            name = parent.child_by_field_name("name")
            return _text(name).split("::")[-1] if name is not None else ""
        if parent.type == "function_definition":
            declarator = _declarator(parent)
            text = (
                _text(declarator.child_by_field_name("declarator"))
                if declarator
                else ""
            )
            if "::" in text:
                return text.split("::")[-2].split("<")[0]
        parent = parent.parent
    return ""


_SELF = re.compile(r"(?:this->)?shared_from_this\(\)|\*?this")


def _helper_node(call: Any, node: Any) -> str:
    """The node a helper is handed (`declare_parameter_if_not_declared(node,
    ...)`), as a receiver: "this" for `this`, `shared_from_this()`, or a local
    bound to it in the same function (`auto node = shared_from_this();`, as
    nav2's servers do); else as written."""
    text = re.sub(r"\s+", "", _text(node))
    if _SELF.fullmatch(text):
        return "this"
    body = _body(call)
    if body is not None and re.fullmatch(r"[A-Za-z_]\w*", text):
        bound = re.search(
            rf"\b{text}\s*=\s*(?:this\s*->\s*)?shared_from_this\s*\(\s*\)\s*;",
            _text(body),
        )
        if bound is not None:
            return "this"
    return text


def _arguments(node: Any) -> list[Any]:
    """A call's arguments (its `argument_list`'s children but punctuation)."""
    return [
        c for c in node.children if c.type not in ("(", ")", "{", "}", ",", "comment")
    ]


def _owner(cls: str, receiver: str) -> str:
    """Which node object a call is made on: the class for `this` (or no
    receiver), else the receiver as written (within its class)."""
    if receiver in ("this", "", "*this"):
        return cls
    return f"{cls}.{receiver}" if cls else receiver


def _interface(text: str, aliases: dict[str, str], kind: str) -> tuple[str, ...]:
    """`geometry_msgs::msg::Twist` (ROS 1: `geometry_msgs::Twist`) -> the type."""
    text = re.sub(r"\s+", "", text)
    for _ in range(4):
        if text in aliases:
            text = re.sub(r"\s+", "", aliases[text])
        else:
            break
    text = _PTR.sub("", text) if kind != PARAMETER else text
    parts = text.lstrip(":").split("::")
    if not all(re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", p) for p in parts):
        return ()
    if len(parts) == 3 and parts[1] in ("msg", "srv", "action"):
        return (f"{parts[0]}/{MIDDLE[kind] or parts[1]}/{parts[2]}",)
    if len(parts) == 2 and parts[0].islower() and parts[1][:1].isupper():
        return (f"{parts[0]}/{MIDDLE[kind]}/{parts[1]}",)
    return ()


# rclcpp::ParameterType given in place of a default: the type it declares
_PARAMETER_TYPES = {
    "PARAMETER_BOOL": "bool",
    "PARAMETER_INTEGER": "int64_t",
    "PARAMETER_DOUBLE": "double",
    "PARAMETER_STRING": "std::string",
    "PARAMETER_BYTE_ARRAY": "std::vector<uint8_t>",
    "PARAMETER_BOOL_ARRAY": "std::vector<bool>",
    "PARAMETER_INTEGER_ARRAY": "std::vector<int64_t>",
    "PARAMETER_DOUBLE_ARRAY": "std::vector<double>",
    "PARAMETER_STRING_ARRAY": "std::vector<std::string>",
}


def _literal_type(node: Any, depth: int = 0) -> tuple[str, ...]:
    """The type a literal default gives a parameter (`declare_parameter("x",
    false)`: bool, as rclcpp's ParameterValue of it; `-0.5`,
    `rclcpp::ParameterValue(0.5)` or `{0.5}`, `std::string("map")`, a
    `rclcpp::PARAMETER_DOUBLE` given for the type); () for anything else."""
    kind = node.type if node is not None else ""
    if kind in ("qualified_identifier", "identifier"):  # `rclcpp::PARAMETER_DOUBLE`
        found = _PARAMETER_TYPES.get(_text(node).split("::")[-1])
        return (found,) if found is not None else ()
    if kind == "unary_expression" and _text(node).startswith("-") and depth < 4:
        return _literal_type(node.child_by_field_name("argument"), depth + 1)
    if kind in ("call_expression", "compound_literal_expression") and depth < 4:
        func = node.child_by_field_name(
            "function" if kind == "call_expression" else "type"
        )
        made = re.sub(r"\s+", "", _text(func))
        args = node.child_by_field_name(
            "arguments" if kind == "call_expression" else "value"
        )
        inner = _arguments(args) if args is not None else []
        if made in ("rclcpp::ParameterValue", "ParameterValue") and len(inner) == 1:
            return _literal_type(inner[0], depth + 1)
        if made in ("std::string", "string") and len(inner) == 1:
            return ("std::string",) if inner[0].type == "string_literal" else ()
        if made.startswith("std::vector<"):  # `std::vector<double>{0.5, 0.0}`
            return (made,)
        return ()
    if kind in ("true", "false"):
        return ("bool",)
    if kind == "string_literal":
        return ("std::string",)
    if kind == "number_literal":
        text = _text(node).lower()
        real = not text.startswith("0x") and any(c in text for c in ".ef")
        return ("double",) if real else ("int",)
    return ()


def _string(node: Any) -> str | None:
    """A plain string literal's text (no escapes, no concatenation)."""
    if node is None or node.type != "string_literal":
        return None
    parts = [c for c in node.children if c.type not in ('"',)]
    if len(parts) > 1 or (parts and parts[0].type != "string_content"):
        return None
    return _text(parts[0]) if parts else ""


def _col(node: Any, data: bytes) -> int:
    """The character column (tree-sitter counts bytes)."""
    start = node.start_byte - node.start_point[1]
    return len(data[start : node.start_byte].decode("utf-8", "replace"))


def _qos(node: Any, depth: int = 0) -> Qos | None:
    if depth > 16:
        return None
    if node.type == "identifier":  # `auto qos = rclcpp::QoS(10);` ... `qos`
        return _local_qos(node, depth + 1)
    if node.type == "number_literal":
        try:
            return Q.depth_only(int(_text(node).rstrip("uUlL"), 0))
        except ValueError:
            return None
    if node.type != "call_expression":
        return None
    func = node.child_by_field_name("function")
    args_node = node.child_by_field_name("arguments")
    if func is None or args_node is None:
        return None
    args = [c for c in args_node.children if c.type not in ("(", ")", ",")]
    if func.type == "field_expression":  # a setter: QoS(10).best_effort()
        base = func.child_by_field_name("argument")
        field = _text(func.child_by_field_name("field"))
        inner = _qos(base, depth + 1) if base is not None else None
        if inner is None:
            return None
        if field in Q.CPP_SETTERS:
            policy, value = Q.CPP_SETTERS[field]
            return Qos(
                value if policy == "reliability" else inner.reliability,
                value if policy == "durability" else inner.durability,
                inner.depth,
            )
        if field in ("keep_last",) and args and args[0].type == "number_literal":
            return Qos(inner.reliability, inner.durability, int(_text(args[0]), 0))
        return inner if field in Q.CPP_NEUTRAL else None
    return _made(_text(func).split("::")[-1], args, depth)


def _made(name: str, args: list[Any], depth: int) -> Qos | None:
    """A profile built of a class: `SensorDataQoS()`, `QoS(10)`,
    `QoS(KeepLast(10))`, `QoS(rclcpp::QoSInitialization::from_rmw(
    rmw_qos_profile_sensor_data))`."""
    if name in Q.CPP_PROFILES:
        return Q.CPP_PROFILES[name]
    if name == "QoS" and args:
        first = args[0]
        text = _text(first)
        if "rmw_qos_profile_sensor_data" in text:
            return Q.CPP_PROFILES["SensorDataQoS"]
        if first.type == "number_literal":
            return _qos(first, depth + 1)
        if (
            first.type == "call_expression"
            and _text(first.child_by_field_name("function")).split("::")[-1]
            == "KeepLast"
        ):
            inner_args = [
                c
                for c in first.child_by_field_name("arguments").children
                if c.type == "number_literal"
            ]
            depth_value = int(_text(inner_args[0]), 0) if inner_args else None
            return Q.depth_only(depth_value)
    return None


MAX_BODY_NODES = 20_000  # syntax nodes of a function body a local is looked for in
# the calls a local profile may be passed to without being changed
_READERS = frozenset({*METHODS, "make_unique", "make_shared"})


def _local_qos(use: Any, depth: int) -> Qos | None:
    """The profile of a local variable (`auto qos = rclcpp::QoS(10);`,
    `rclcpp::QoS qos(10);`, `rclcpp::SensorDataQoS qos;`) declared once in the
    function body around `use` and only read after: never assigned, never given
    a setter (`qos.best_effort();`) outside `use`, and passed to no call but those
    that make endpoints. Anything else is unknown, as is a body over
    `MAX_BODY_NODES`."""
    body = _body(use)
    if body is None or body.descendant_count > MAX_BODY_NODES:
        return None
    found: list[Any] = []  # the declaration's init_declarator or declaration
    for node in _mentions(body, use):
        parent = node.parent
        if parent.type in ("init_declarator", "declaration") and (
            parent.child_by_field_name("declarator") == node
        ):
            found.append(parent)
        elif not _read(node, use):
            return None
    if len(found) != 1 or found[0].start_byte > use.start_byte:
        return None
    declared = found[0]
    statement = declared if declared.type == "declaration" else declared.parent
    kind = statement.child_by_field_name("type") if statement is not None else None
    cls = _text(kind).split("<")[0].split("::")[-1] if kind is not None else ""
    value = declared.child_by_field_name("value")
    if value is None:  # `rclcpp::SensorDataQoS qos;`
        return Q.CPP_PROFILES.get(cls)
    if value.type in ("argument_list", "initializer_list"):  # `rclcpp::QoS qos(10)`
        args = [c for c in value.children if c.type not in ("(", ")", ",", "{", "}")]
        return _made(cls, args, depth)
    return _qos(value, depth + 1)


def _mentions(body: Any, use: Any) -> Iterator[Any]:
    """The identifiers of `body` spelled as the identifier `use`, but `use`:
    found in its bytes, each the node at the place (not a walk of its nodes)."""
    word, text = use.text, body.text
    at = text.find(word)
    while at >= 0:
        start = body.start_byte + at
        node = body.descendant_for_byte_range(start, start + len(word))
        if (
            node is not None
            and node.type == "identifier"
            and (node.start_byte, node.end_byte) == (start, start + len(word))
            and node != use
        ):
            yield node
        at = text.find(word, at + 1)


def _body(node: Any) -> Any:
    """The body of the function definition `node` lies in, or None."""
    parent = node.parent
    for _ in range(MAX_DEPTH):
        if parent is None:
            return None
        if parent.type == "function_definition":
            return parent.child_by_field_name("body")
        parent = parent.parent
    return None


def _read(node: Any, use: Any) -> bool:
    """Whether this mention of a local only reads it: within `use`, or passed
    as it is to a call that makes an endpoint."""
    if use.start_byte <= node.start_byte and node.end_byte <= use.end_byte:
        return True
    if node.parent is None or node.parent.type != "argument_list":
        return False
    call = node.parent.parent
    func = call.child_by_field_name("function") if call is not None else None
    for _ in range(8):  # `node->create_subscription<T>`: to the method's name
        if func is None or func.type in ("identifier", "field_identifier"):
            break
        field = "field" if func.type == "field_expression" else "name"
        func = func.child_by_field_name(field)
    return func is not None and _text(func) in _READERS
