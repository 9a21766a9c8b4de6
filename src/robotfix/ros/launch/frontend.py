"""ROS 2 XML and YAML launch files and ROS 1 roslaunch XML, read from their tree
(`tree.py`), never run.

ROS 2: `<arg name default>`, `<let>`, `<node pkg exec name namespace>` with
`<param name value>` (typed by YAML rules, as launch's `get_typed_value` does,
then as rcl reads what launch writes of it: `values.py`),
`<param from="file.yaml">`, nested `<param name="group">`, `<remap from to>`;
`<group>`, `<push-ros-namespace>`, `<include file>` with its `<arg>`s;
`<composable_node>` entries. ROS 1: `<arg name default|value>`, `<node pkg type
name ns>` with `<param name value type>` (typed as roslaunch's `convert_value`),
`<rosparam command="load" file ns>`, `<remap>`; `<group ns>`, `<include file
ns>`, and `<param>` outside any node (global names).
"""

from __future__ import annotations

from pathlib import Path

from robotfix.ros import paramfile as P
from robotfix.ros import yamlfile as Y
from robotfix.ros.launch import substitution as S
from robotfix.ros.launch import values as V
from robotfix.ros.launch.model import (
    FileParam,
    Include,
    InlineParam,
    LaunchFile,
    NodeEntry,
    Place,
    Remap,
)
from robotfix.ros.launch.tree import Element

NODE_TAGS = ("node", "composable_node", "lifecycle_node")


def read_tree(root: Element, ctx: S.Context, ros: int | None = None) -> LaunchFile:
    """The launch entries of a parsed XML or YAML launch file; `ros` None: ROS 1
    if any `<node>` has `type=` and none `exec=`."""
    if ros is None:
        ros = _flavour(root)
    out = LaunchFile(str(ctx.path), ros)
    _Reader(out, ctx, ros).actions(root, "", dict(ctx.args))
    return out


def _flavour(root: Element) -> int:
    todo, kinds = [root], set[int]()
    while todo and len(kinds) < 2:
        element = todo.pop()
        if element.tag == "node":
            kinds |= {1} if "type" in element.attrs else set()
            kinds |= {2} if "exec" in element.attrs else set()
        todo.extend(element.children)
    return 1 if kinds == {1} else 2


class _Reader:
    def __init__(self, out: LaunchFile, ctx: S.Context, ros: int) -> None:
        self.out, self.ctx, self.ros = out, ctx, ros

    def place(self, element: Element, attr: str | None = None) -> Place:
        line, col = element.at(attr) if attr else (element.line, element.col)
        return Place(self.out.path, line, col)

    def text(
        self, element: Element, attr: str, args: dict[str, str | None]
    ) -> str | None:
        raw = element.attrs.get(attr)
        if raw is None:
            return None
        return S.expand(
            raw, S.Context(self.ctx.path, self.ctx.packages, args), self.ros
        )

    def actions(
        self, parent: Element, ns: str | None, args: dict[str, str | None]
    ) -> None:
        for element in parent.children:
            tag = element.tag.replace("-", "_")
            if tag == "arg":
                self.arg(element, args)
            elif tag == "let":
                name = element.attrs.get("name")
                if name:
                    args[name] = self.text(element, "value", args)
            elif tag == "group":
                self.actions(element, self.namespace(element, ns, args), dict(args))
            elif tag == "push_ros_namespace":
                ns = S.push_namespace(ns, self.text(element, "namespace", args))
            elif tag in NODE_TAGS:
                self.node(element, ns, args)
            elif tag in ("node_container", "composable_node_container"):
                self.node(element, ns, args)
                for child in element.children:
                    if child.tag.replace("-", "_") == "composable_node":
                        self.node(child, ns, args)
            elif tag == "include":
                self.include(element, ns, args)
            elif tag == "param" and self.ros == 1:
                self.out.global_params.extend(
                    p
                    for p in self.params(element, ns or "", args)
                    if isinstance(p, InlineParam)
                )

    def namespace(
        self, element: Element, ns: str | None, args: dict[str, str | None]
    ) -> str | None:
        """`ns=` (ROS 1, ROS 2 `<node>`) or `namespace=` pushed onto `ns`."""
        for attr in ("ns", "namespace"):
            if attr in element.attrs:
                return S.push_namespace(ns, self.text(element, attr, args))
        return ns

    def arg(self, element: Element, args: dict[str, str | None]) -> None:
        name = element.attrs.get("name")
        if not name:
            return
        if "value" in element.attrs:  # ROS 1: fixed, whatever the includer says
            args[name] = self.text(element, "value", args)
        elif name not in args:
            args[name] = (
                self.text(element, "default", args)
                if "default" in element.attrs
                else None
            )

    def node(
        self, element: Element, ns: str | None, args: dict[str, str | None]
    ) -> None:
        namespace = self.namespace(element, ns, args)
        entry = NodeEntry(
            self.ros,
            self.place(element),
            self.text(element, "pkg", args) or self.text(element, "package", args),
            self.text(element, "type" if self.ros == 1 else "exec", args)
            or self.text(element, "executable", args),
            self.text(element, "name", args),
            namespace,
            plugin=self.text(element, "plugin", args),
        )
        if "args" in element.attrs:
            entry.arguments = [*(self.text(element, "args", args) or "").split()]
        for child in element.children:
            tag = child.tag
            if tag == "param":
                entry.parameters.extend(self.params(child, "", args))
            elif tag == "rosparam":
                found = self.rosparam(child, args)
                if found is not None:
                    entry.parameters.append(found)
            elif tag == "remap":
                entry.remappings.append(
                    Remap(
                        self.text(child, "from", args),
                        self.text(child, "to", args),
                        self.place(child),
                    )
                )
        self.out.entries.append(entry)

    def params(
        self, element: Element, prefix: str, args: dict[str, str | None]
    ) -> list[InlineParam | FileParam]:
        if "from" in element.attrs:  # ROS 2 `<param from="file.yaml"/>`
            shown = element.attrs["from"]
            path = S.in_tree(self.ctx, self.text(element, "from", args))
            return [FileParam(path, shown, self.place(element, "from"))]
        name = self.text(element, "name", args)
        if name is None:
            return []
        sep = "." if self.ros == 2 else "/"
        full = f"{prefix}{sep}{name}" if prefix else name
        if element.children and self.ros == 2:  # `<param name="group"><param .../>`
            return [
                p
                for child in element.children
                if child.tag == "param"
                for p in self.params(child, full, args)
            ]
        value = self.value(element, args)
        return [
            InlineParam(
                full, value, self.place(element, "value"), self.place(element, "name")
            )
        ]

    def value(
        self, element: Element, args: dict[str, str | None]
    ) -> P.Typed | P.Unread | None:
        if "value" in element.nodes:  # YAML launch: the YAML value, typed as YAML
            return V.from_yaml(element.nodes["value"])
        raw = element.attrs.get("value")
        if raw is None or "$(" in raw:
            return None  # `textfile=`, `command=`, or a substitution: launch time
        if self.ros == 1:
            return roslaunch_value(raw, element.attrs.get("type", ""))
        if "value-sep" in element.attrs:
            return None
        node = Y.parse(raw)  # launch's `yaml.safe_load`; a text it refuses stays
        return (
            V.from_python(raw) if isinstance(node, Y.YamlProblem) else V.from_yaml(node)
        )

    def rosparam(
        self, element: Element, args: dict[str, str | None]
    ) -> FileParam | None:
        if (
            element.attrs.get("command", "load") != "load"
            or "file" not in element.attrs
        ):
            return None
        path = S.in_tree(self.ctx, self.text(element, "file", args))
        ns = self.text(element, "ns", args) if "ns" in element.attrs else ""
        return FileParam(
            path, element.attrs["file"], self.place(element, "file"), ns or ""
        )

    def include(
        self, element: Element, ns: str | None, args: dict[str, str | None]
    ) -> None:
        shown = element.attrs.get("file", "")
        path = S.in_tree(self.ctx, self.text(element, "file", args))
        self.out.includes.append(Include(path, shown, self.place(element, "file")))
        if path is None or self.ctx.follow is None:
            return
        passed = {
            child.attrs["name"]: self.text(child, "value", args)
            for child in element.children
            if child.tag == "arg" and "name" in child.attrs
        }
        included = self.ctx.follow(Path(path), passed)
        if included is None:
            return
        if "ns" in element.attrs:
            ns = S.push_namespace(ns, self.text(element, "ns", args))
        for entry in included.entries:
            entry.namespace = S.push_namespace(ns, entry.namespace)
            self.out.entries.append(entry)


def roslaunch_value(text: str, type_: str) -> P.Typed | None:
    """roslaunch's `convert_value`: with no type, an int, a float (a `.` in it),
    `true`/`false` in any case, else a string."""
    kind = type_.lower()
    if kind in ("str", "string"):
        return P.Typed("string", text, text)
    if kind in ("", "int", "double"):
        try:
            if kind == "double" or (not kind and "." in text):
                return P.Typed("double", float(text), text)
            return P.Typed("integer", int(text), text)
        except ValueError:
            if kind:
                return None  # roslaunch refuses it: not ours to report
    lowered = text.strip().lower()
    if lowered in ("true", "false") or (
        kind in ("bool", "boolean") and lowered in ("1", "0")
    ):
        return P.Typed("bool", lowered in ("true", "1"), text)
    return P.Typed("string", text, text) if not kind else None
