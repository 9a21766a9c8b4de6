"""Which C++ files `cpp.read_cpp` parses, decided on their bytes before any
parse, and the tables of what makes an endpoint that the reading shares.

A file without any of `WORDS` is not parsed; nor one where no name that makes
an endpoint (`METHODS`, `ACTIONS`, `CLASSES`) stands as a word and is called
(`makers_in`, `may_make`: `@param` in a comment is not, nor a call in a `/* */`
comment that surely is one: `_in_block_comment`), unless it names a
node class of another package (`_other_node`) or the reading wants its node
names. The words of `OPENING` (parameters this file does not name) are found
here too, as parameter endpoints without a name (`opening`). The makers are
found with `bytes.find`: a regex of them between `\\b`s has no byte to look
for and tries every one. (`OPENING` keeps its `\\b`: without it, or with the
word's end in a lookahead, it ran more instructions on corpus25, not fewer.)
"""

from __future__ import annotations

import re

from robotfix.ros.graph import model as M
from robotfix.ros.graph.model import OPENS, Endpoint

# a file that holds none of these makes no endpoint: not parsed
WORDS = (
    b"create_",
    b"advertise",
    b"subscribe",
    b"serviceClient",
    b"param",
    b"TwistPublisher",
    b"TwistSubscriber",
    b"ClassLoader",
)

# method -> (kind, ros, name position, qos position, default position)
METHODS: dict[str, tuple[str, int, int, int | None, int | None]] = {
    "create_publisher": (M.PUBLISHER, 2, 0, 1, None),
    "create_subscription": (M.SUBSCRIPTION, 2, 0, 1, None),
    "create_service": (M.SERVICE, 2, 0, None, None),
    "create_client": (M.CLIENT, 2, 0, None, None),
    "declare_parameter": (M.PARAMETER, 2, 0, None, 1),
    # nav2_util's helper: (node, name, default), declares when not yet declared
    "declare_parameter_if_not_declared": (M.PARAMETER, 2, 1, None, 2),
    "advertise": (M.PUBLISHER, 1, 0, None, None),
    "subscribe": (M.SUBSCRIPTION, 1, 0, None, None),
    "advertiseService": (M.SERVICE, 1, 0, None, None),
    "serviceClient": (M.CLIENT, 1, 0, None, None),
    "param": (M.PARAMETER, 1, 0, None, 2),
}
# classes that make an endpoint when built (`std::make_unique<C>(args)`, `C(args)`):
# kind, name position, qos position, its possible types. nav2_util's Twist
# publisher and subscriber use `Twist` or `TwistStamped` as the node's
# `enable_stamped_cmd_vel` parameter says: two possible types.
_TWIST = ("geometry_msgs/msg/Twist", "geometry_msgs/msg/TwistStamped")
CLASSES: dict[str, tuple[str, int, int | None, tuple[str, ...]]] = {
    "nav2_util::TwistPublisher": (M.PUBLISHER, 1, 2, _TWIST),
    "nav2_util::TwistSubscriber": (M.SUBSCRIPTION, 1, 2, _TWIST),
}
# rclcpp_action's free functions: (kind, name position)
ACTIONS = {"create_server": M.ACTION_SERVER, "create_client": M.ACTION_CLIENT}
# a file where none of the names that make an endpoint stands as a word (`param`
# in `get_parameter` does not) makes none: not parsed either (`makers_in`)
_MAKERS = frozenset(
    w.encode() for w in {*METHODS, *ACTIONS, *(c.split("::")[-1] for c in CLASSES)}
)
# what each of `_MAKERS` begins with: found by `bytes.find` (a regex of the words
# between `\b`s has no prefix to look for: it tries every byte, 1% of corpus25's run)
_MAKER_STARTS = (
    b"create_",
    b"declare_parameter",
    b"advertise",
    b"subscribe",
    b"serviceClient",
    b"param",
    b"Twist",
)
_WORDS_AT = re.compile(rb"\w+")
# the last names of `CLASSES`: one of them is made by a parse wherever it stands
_CLASS_WORDS = frozenset(c.split("::")[-1].encode() for c in CLASSES)
# roscpp's methods: made of only on a receiver (`nh.advertise`), as
# `cpp._File._call` reads
_RECEIVED = frozenset(m.encode() for m, spec in METHODS.items() if spec[1] == 1)
_WORD = re.compile(rb"\w")
_BLANKS = b" \t\r\n\f\v"  # what `bytes.strip` and `re`'s `\s` take
NODE_BASES = frozenset({"Node", "LifecycleNode"})
RCLCPP_BASES = frozenset(
    {"Node", "LifecycleNode", "rclcpp::Node", "rclcpp_lifecycle::LifecycleNode"}
)
# what declares parameters this file does not name: a node that takes its
# parameters from overrides or lets any be set, parameters declared in bulk or by
# a base class's helper (nav2's `add_parameter`), generated code
# (generate_parameter_library's ParamListener), plugins (pluginlib, which declare
# parameters under their own names). Each is a parameter endpoint without a name,
# its `value` the word (an OPENS endpoint: `cppparams` reads them, the graph not).
OPENING = re.compile(
    rb"\b(?:(allow_undeclared_parameters|automatically_declare_parameters_from_"
    rb"overrides)\s*\(\s*true\b|(declare_parameters|add_parameter|ParamListener|"
    rb"ClassLoader|createUniqueInstance|createSharedInstance|"
    rb"createUnmanagedInstance)\b)"
)
OPENING_WORDS = (  # one of which `OPENING` needs (a quick test)
    b"allow_undeclared",
    b"automatically_declare",
    b"declare_parameters",
    b"add_parameter",
    b"ParamListener",
    b"ClassLoader",
    b"Instance",
)
AUTO = "automatically_declare_parameters_from_overrides"
# what may make a file ROS 1 or name a node without any endpoint (`cpp._File._handle`,
# `ros::init(argc, argv, "talker")`; a base class or an initializer: `_other_node`)
_NAMING = re.compile(rb"NodeHandle|make_shared|\bros\s*::\s*init\b")
_OURS = frozenset(b.encode() for b in RCLCPP_BASES)  # (`_other_node`)


def makers_in(data: bytes) -> list[tuple[int, int, bytes]]:
    """Where a word of `_MAKERS` stands as a whole word in `data` (start, end,
    the word), in no particular order."""
    out = []
    for start in _MAKER_STARTS:
        at = data.find(start)
        while at >= 0:
            if at == 0 or data[at - 1] not in WORD_BYTES:
                word = _WORDS_AT.match(data, at)
                assert word is not None
                if word.group() in _MAKERS:
                    out.append((at, word.end(), word.group()))
            at = data.find(start, at + 1)
    return out


WORD_BYTES = frozenset(b for b in range(256) if _WORD.match(bytes([b])))


def may_make(data: bytes, makers: list[tuple[int, int, bytes]], names: bool) -> bool:
    """Whether a parse of `data` may find an endpoint, `opening`'s apart: a
    name of `_MAKERS` called (then `<` or `(`, or a comment, a line continued:
    `makers`; roscpp's methods on a receiver only), a class of `CLASSES`, or a
    base class `x::Node` not rclcpp's; with `names`, also a node class or name
    (`_other_node`), or a ROS 1 file or a node named otherwise (`_NAMING`).
    Nav2's and ros_comm's headers say `@param` in their comments: 36% of
    corpus25's parsed C++ bytes; roscpp's headers declare `Publisher
    advertise(...)`."""
    for start, end, word in makers:
        if word in _CLASS_WORDS:
            return True
        after = data[end : end + 80].lstrip()
        called = not after or after[:1] in b"<(/\\"  # (all blanks: unsure, parsed)
        if (
            called
            and (word not in _RECEIVED or _received(data, start))
            and not _in_block_comment(data, start)
        ):
            return True
    return _other_node(data, names) or (names and _NAMING.search(data) is not None)


def _in_block_comment(data: bytes, at: int) -> bool:
    """Whether `at` is surely inside a `/* */` comment, as tree-sitter's lexer
    reads it (the example code of roscpp's `node_handle.h`, 103 KB): the last
    `/*` before it, with no `*/` after that, begins its line (blanks before
    it), the line before does not end with a backslash, blanks apart (a `//`
    comment or a string going on), and no raw string (`R"`) comes before it.
    Anything else: not surely, False."""
    opener = data.rfind(b"/*", 0, at)
    if opener < 0 or data.find(b"*/", opener + 1, at) >= 0:
        return False
    line = data.rfind(b"\n", 0, opener) + 1
    if data[line:opener].strip(_BLANKS):
        return False  # (`x = 1; /*`, `"/*"`: a lexer would have to say)
    if data[max(line - 8, 0) : line].rstrip(_BLANKS).endswith(b"\\"):
        return False  # (refused with blanks after it too, going on or not)
    return data.rfind(b'R"', 0, opener) < 0


def _received(data: bytes, start: int) -> bool:
    """Whether the name at `start` may be called on a receiver (`nh.advertise`,
    `nh->param`), as `_File._call` takes roscpp's methods; when a comment or a
    continued line stands before it, or only blanks: unsure, True."""
    before = data[max(start - 80, 0) : start].rstrip()
    return not before or before.endswith((b".", b"->", b"/", b"\\"))


def _other_node(data: bytes, names: bool) -> bool:
    """Whether `data` names `Node` or `LifecycleNode` with a qualifier that is not
    rclcpp's (`nav2_util::LifecycleNode`, `::rclcpp::Node`), as `_File._bases`
    reads a base class (its text without blanks): an endpoint if it is one (not
    when `::` goes on after it, blanks apart: a base's last name is no scope;
    nav2's headers name `nav2::LifecycleNode::WeakPtr`, 142 of the 150 files of
    corpus25 parsed for no endpoint before); or,
    with `names`, any as a base class or built (`: public rclcpp::Node`,
    `: Node("talker")`): a node class, its name."""
    at = data.find(b"Node")
    while at >= 0:
        end = at + 4
        if end == len(data) or not _WORD.match(data, end):
            start = at - 9 if data[max(at - 9, 0) : at] == b"Lifecycle" else at
            found = _qualifier(data, start)
            if found is not None:
                qualifier, begin = found
                if qualifier + data[start:end] not in _OURS:
                    if data[end : end + 80].lstrip(_BLANKS)[:2] != b"::":
                        return True  # (`nav2::LifecycleNode::SharedPtr`: a type in it)
                elif names and _based_or_built(data, begin, end):
                    return True
        at = data.find(b"Node", end)
    return False


def _based_or_built(data: bytes, begin: int, end: int) -> bool:
    """Whether the `Node` named from `begin` to `end` is built (`Node("x")`) or
    stands as a base class."""
    if data[end : end + 80].lstrip()[:1] in (b"(", b"{"):
        return True
    before = data[max(begin - 80, 0) : begin].rstrip()
    return before.endswith(_BEFORE_BASE) and not before.endswith(b"::")


# what stands before a base class (`class A : public B, virtual C`)
_BEFORE_BASE = (b":", b",", b"public", b"protected", b"private", b"virtual")


def _qualifier(data: bytes, start: int) -> tuple[bytes, int] | None:
    """The names and `::`s that stand before `start`, without blanks
    (`::a :: b::` of `::a :: b::Node`), and where they begin; None when a word
    goes on into it."""
    if start > 0 and _WORD.match(data, start - 1):
        return None  # `MyNode`: no name of its own
    parts: list[bytes] = []
    while True:
        at = start
        while at > 0 and data[at - 1 : at] in _BLANKS:
            at -= 1
        if data[max(at - 2, 0) : at] != b"::":
            break
        parts.append(b"::")
        at -= 2
        start = at
        while at > 0 and data[at - 1 : at] in _BLANKS:
            at -= 1
        word = at
        while word > 0 and _WORD.match(data, word - 1):
            word -= 1
        if word == at:
            break  # a leading `::`
        parts.append(data[word:at])
        start = word
    return b"".join(reversed(parts)), start


def opening(data: bytes) -> list[Endpoint]:
    """The words of `OPENING` in a file, as parameter endpoints without a name."""
    out = []
    for match in OPENING.finditer(data):
        line = data.count(b"\n", 0, match.start()) + 1
        word = (match.group(1) or match.group(2)).decode()
        col = match.start() - data.rfind(b"\n", 0, match.start()) - 1
        out.append(Endpoint(OPENS, None, (), line, col, "", None, 2, "", word))
    return out
