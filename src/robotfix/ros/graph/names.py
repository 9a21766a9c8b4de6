"""Names as ROS resolves them (ROS 2: rcl's `rcl_expand_topic_name` and its
remapping rules; ROS 1: `ros::names::resolve`), for one node instance.

- absolute `/scan` stays;
- private `~/out` (ROS 2) or `~out` (ROS 1) is under the node: `/ns/node/out`;
- relative `cmd_vel` is under the node's namespace: `/ns/cmd_vel`; in ROS 1 C++
  under its NodeHandle's namespace too (`ros::NodeHandle nh("~")` makes it private);
- a remapping rule `from:=to` of the launch entry (or of the code) applies when its
  `from`, expanded for the same node, is the name; its `to` is then expanded so.

What is not known (a name computed at run time, a `{substitution}`, a namespace a
launch argument sets) gives None: unknown, never a guess.
"""

from __future__ import annotations

import re

_VALID = re.compile(r"^[~/]?[A-Za-z_][A-Za-z0-9_]*(/[A-Za-z_][A-Za-z0-9_]*)*/?$|^~$")


def join(namespace: str, name: str) -> str:
    """`namespace` (absolute) and a relative `name`, with one slash between."""
    return namespace.rstrip("/") + "/" + name.strip("/")


def namespace_of(namespace: str | None) -> str | None:
    """A launch entry's namespace as an absolute one (`robot1` -> `/robot1`)."""
    if namespace is None or "$" in namespace or "{" in namespace:
        return None
    stripped = namespace.strip("/")
    return "/" + stripped if stripped else "/"


def expand(
    name: str | None,
    namespace: str | None,
    node: str | None,
    handle: str = "",
) -> str | None:
    """The fully qualified name of `name` for a node `node` in `namespace`
    (absolute, from `namespace_of`); `handle` a ROS 1 NodeHandle's namespace."""
    if name is None or not name or "{" in name or "$" in name or " " in name:
        return None
    if not _VALID.match(name.replace("~/", "~").replace("//", "/")):
        return None
    if name.startswith("/"):
        return "/" + name.strip("/")
    if name.startswith("~"):
        if node is None or namespace is None:
            return None
        rest = name[1:].lstrip("/")
        base = join(namespace, node)
        return join(base, rest) if rest else base
    if namespace is None:
        return None
    if handle:
        if handle == "~":
            if node is None:
                return None
            return join(join(namespace, node), name)
        if handle.startswith("~"):
            if node is None:
                return None
            return join(join(join(namespace, node), handle[1:]), name)
        if handle.startswith("/"):
            return join(handle, name)
        return join(join(namespace, handle), name)
    return join(namespace, name)


def remap(
    resolved: str | None,
    rules: list[tuple[str | None, str | None]],
    namespace: str | None,
    node: str | None,
) -> tuple[str | None, bool]:
    """The name after the first rule that matches it (rcl's order: the first
    rule wins), and whether any rule could not be read (a rule with an unknown
    side may match: the name is then not certain)."""
    out, uncertain, _ = remap_rule(resolved, rules, namespace, node)
    return out, uncertain


def remap_rule(
    resolved: str | None,
    rules: list[tuple[str | None, str | None]],
    namespace: str | None,
    node: str | None,
) -> tuple[str | None, bool, int | None]:
    """`remap`, with the index of the rule that matched (None: none did)."""
    if resolved is None:
        return None, False, None
    uncertain = False
    for index, (source, target) in enumerate(rules):
        expanded = expand(source, namespace, node)
        if expanded is None:
            uncertain = True
            continue
        if expanded == resolved:
            out = expand(target, namespace, node)
            return out, uncertain or out is None, index
    return resolved, uncertain, None
