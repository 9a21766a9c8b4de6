"""Launch XML as a small tree with the line and column of every element and
attribute value; ROS 2 YAML launch files become the same tree (`from_yaml`), so
one interpreter reads both (`xml.py`).

XML is parsed with the standard library's expat, safely: a document type
declaration (and with it every entity definition, so no "billion laughs" and no
external entity) is refused, files are read through `robotfix.fs` with a size
limit, and elements are bounded in number and depth.
"""

from __future__ import annotations

import re
from bisect import bisect_right
from dataclasses import dataclass, field
from xml.parsers import expat

from robotfix.ros import yamlfile as Y

MAX_LAUNCH_BYTES = 2 * 1024 * 1024
MAX_ELEMENTS = 50_000
MAX_DEPTH = 100


@dataclass
class Element:
    """An XML (or YAML launch) element with its places."""

    tag: str
    attrs: dict[str, str]
    line: int  # 1-based
    col: int  # 0-based
    children: list[Element] = field(default_factory=list)
    text: str = ""
    where: dict[str, tuple[int, int]] = field(default_factory=dict)  # attr -> l, c
    nodes: dict[str, Y.Node] = field(default_factory=dict)  # YAML launch: typed

    def at(self, attr: str) -> tuple[int, int]:
        """Where an attribute's value starts (the element's start if unknown)."""
        return self.where.get(attr, (self.line, self.col))


class LaunchSyntaxError(Exception):
    def __init__(self, message: str, line: int, col: int) -> None:
        super().__init__(message)
        self.line, self.col = line, col


def parse_xml(text: str) -> Element:
    """The root element; LaunchSyntaxError for what is not well-formed or is
    refused (a DOCTYPE, too many or too deeply nested elements)."""
    data = text.encode("utf-8", "surrogatepass")
    starts = _line_starts(data)
    parser = expat.ParserCreate()
    stack: list[Element] = []
    roots: list[Element] = []

    def place(index: int) -> tuple[int, int]:
        line = bisect_right(starts, index)  # (1-based: `starts[0]` is 0)
        return line, len(data[starts[line - 1] : index].decode("utf-8", "replace"))

    def refuse(*_: object) -> None:
        raise LaunchSyntaxError(
            "a document type declaration (launch files need none)",
            *place(parser.CurrentByteIndex),
        )

    def start(tag: str, attrs: dict[str, str]) -> None:
        if len(stack) >= MAX_DEPTH or (len(starts) and counter[0] >= MAX_ELEMENTS):
            raise LaunchSyntaxError("too many or too deeply nested elements", 1, 0)
        counter[0] += 1
        index = parser.CurrentByteIndex
        element = Element(tag, dict(attrs), *place(index))
        element.where = _attribute_places(data, index, attrs, place)
        (stack[-1].children if stack else roots).append(element)
        stack.append(element)

    def end(_: str) -> None:
        stack.pop()

    def chars(content: str) -> None:
        if stack:
            stack[-1].text += content

    counter = [0]
    parser.StartDoctypeDeclHandler = refuse
    parser.EntityDeclHandler = refuse
    parser.SetParamEntityParsing(expat.XML_PARAM_ENTITY_PARSING_NEVER)
    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CharacterDataHandler = chars
    try:
        parser.Parse(data, True)
    except expat.ExpatError as err:
        raise LaunchSyntaxError(
            f"not well-formed XML: {expat.ErrorString(err.code)}",
            err.lineno,
            err.offset,
        ) from None
    finally:  # those that close over the parser: else a cycle only the collector
        # frees, with every element of the file
        parser.StartElementHandler = parser.StartDoctypeDeclHandler = None
        parser.EntityDeclHandler = None
    if not roots:
        raise LaunchSyntaxError("no root element", 1, 0)
    return roots[0]


def _line_starts(data: bytes) -> list[int]:
    return [0] + [m.end() for m in re.finditer(rb"\n", data)]


def _attribute_places(
    data: bytes, index: int, attrs: dict[str, str], place: object
) -> dict[str, tuple[int, int]]:
    end = data.find(b">", index)
    tag = data[index : end if end >= 0 else len(data)]
    found: dict[str, tuple[int, int]] = {}
    for name in attrs:
        pattern = rb"\s" + re.escape(name.encode()) + rb"\s*=\s*[\"']"
        match = re.search(pattern, tag)
        if match is not None:
            found[name] = place(index + match.end())  # type: ignore[operator]
    return found


def from_yaml(root: Y.Node | None) -> Element | None:
    """A ROS 2 YAML launch file (`launch: [- node: {pkg: ..., param: [...]}]`) as
    the XML tree it stands for: a mapping's scalars are attributes (their YAML
    nodes kept in `nodes`: launch reads a YAML value with its YAML type), each
    mapping of a list under a key a child of that tag; None when it is not a
    launch file."""
    budget = [Y.WALK_BUDGET]
    root = Y.resolve(root, budget)
    if not isinstance(root, Y.Mapping):
        return None
    body = Y.resolve(root.get("launch"), budget)
    if not isinstance(body, Y.Sequence):
        return None
    element = Element("launch", {}, root.line, root.col)
    _yaml_actions(element, body, budget, 0)
    return element


def _yaml_actions(
    parent: Element, node: Y.Sequence, budget: list[int], depth: int
) -> None:
    """`- node: {...}`, `- arg: {...}`: one action per list item."""
    for raw in node.items:
        item = Y.resolve(raw, budget)
        if isinstance(item, Y.Mapping):
            for key, value in item.items:
                if isinstance(key, Y.Scalar):
                    parent.children.append(
                        _yaml_element(key.text, key, value, budget, depth + 1)
                    )


def _yaml_element(
    tag: str, at: Y.Node, value: Y.Node | None, budget: list[int], depth: int
) -> Element:
    element = Element(tag, {}, getattr(at, "line", 1), getattr(at, "col", 0))
    body = Y.resolve(value, budget)
    if not isinstance(body, Y.Mapping) or depth > MAX_DEPTH:
        return element
    for key, raw in body.items:
        v = Y.resolve(raw, budget)
        if not isinstance(key, Y.Scalar) or v is None:
            continue
        if key.text == "children" and isinstance(v, Y.Sequence):
            _yaml_actions(element, v, budget, depth + 1)
            continue
        items = (
            [Y.resolve(i, budget) for i in v.items] if isinstance(v, Y.Sequence) else []
        )
        if (
            isinstance(v, Y.Sequence)
            and items
            and all(isinstance(i, Y.Mapping) for i in items)
        ):
            for i in items:  # `param: [{name: a, value: 1}]`, `remap:`, `arg:`
                assert i is not None
                element.children.append(
                    _yaml_element(key.text, i, i, budget, depth + 1)
                )
        elif isinstance(v, Y.Mapping):
            element.children.append(_yaml_element(key.text, key, v, budget, depth + 1))
        else:
            element.nodes[key.text] = v
            if isinstance(v, Y.Scalar):
                element.attrs[key.text] = v.text
            element.where[key.text] = (v.line, v.col)
    return element
