"""What a stub says, as data: the functions, classes and modules `reader.py` makes
of a `.pyi` file and a `StubSet` (`load.py`) hands the analysis. A function or
method is read when it is first asked for (`pending`: the reader's closures)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from robotfix.annotations.extract import Refinement


@dataclass(frozen=True)
class Param:
    """A parameter of a stub function: where a call passes it, and its annotation."""

    name: str
    positional: int | None  # its position among the arguments a call passes
    keyword: bool  # may be passed by keyword
    decl: Refinement | None
    variadic: bool = False  # `*args`: this and every later position
    flag: bool = False  # annotated `bool`: a condition, not a quantity (`where`)


@dataclass(frozen=True)
class Function:
    """A stub function or method, its annotations read."""

    qualname: str  # `rclpy.node.Node.create_timer`, `rospy.sleep`
    params: tuple[Param, ...]  # without `self`/`cls` of a method or class method
    returns: Refinement | None
    returns_type: str | None  # the qualified name of a returned class, if one
    returns_kind: str | None  # `int`, `float` when the return is a plain one
    rule: str | None  # a `unit_rule`
    kind: str  # function, method, staticmethod, classmethod, property
    origin: str  # where it is written: `rclpy/node.pyi:42` (shipped) or a user path
    path: str | None  # the user stub's path (None: shipped with RobotFix)
    line: int
    # `@ros_parameter`: (role, the parameter that holds it): name, default, low, high
    parameter: tuple[tuple[str, str], ...] = ()

    @property
    def short(self) -> str:
        """How messages name it: `rospy.sleep`, `Node.create_timer`, `Duration`."""
        parts = self.qualname.split(".")
        if self.kind == "function":
            return self.qualname
        if parts[-1] == "__init__":
            return parts[-2]
        return ".".join(parts[-2:])


@dataclass(frozen=True)
class Attribute:
    """A stub class's annotated attribute."""

    decl: Refinement | None
    type: str | None  # qualified class name


def _built(
    pending: dict[str, Callable[[], Function | None]],
    built: dict[str, Function],
    name: str,
) -> Function | None:
    """A stub function, its annotations read the first time it is asked for."""
    build = pending.pop(name, None)
    if build is not None:
        found = build()
        if found is not None:
            built[name] = found
    return built.get(name)


@dataclass
class Class:
    """A stub class: its bases, methods (read when first asked for), attributes."""

    qualname: str
    bases: tuple[str, ...]
    members: dict[str, Function] = field(default_factory=dict)
    attributes: dict[str, Attribute] = field(default_factory=dict)
    # methods not read yet: a method's annotations are read when it is first asked for
    pending: dict[str, Callable[[], Function | None]] = field(default_factory=dict)

    def method(self, name: str) -> Function | None:
        return _built(self.pending, self.members, name)

    def force(self) -> None:
        for name in list(self.pending):
            self.method(name)


@dataclass(frozen=True)
class Problem:
    """What is wrong in a user's stub, at its line and column."""

    path: str
    line: int
    col: int
    message: str


@dataclass
class Module:
    """One stub module: its functions, classes, re-exports and problems."""

    name: str
    functions: dict[str, Function] = field(default_factory=dict)
    classes: dict[str, Class] = field(default_factory=dict)
    exports: dict[str, str] = field(default_factory=dict)  # name -> qualified
    problems: list[Problem] = field(default_factory=list)
    pending: dict[str, Callable[[], Function | None]] = field(default_factory=dict)
    # `from m import *`: (m, line, col), in the stub's order
    stars: list[tuple[str, int, int]] = field(default_factory=list)

    def function(self, name: str) -> Function | None:
        return _built(self.pending, self.functions, name)

    def has(self, name: str) -> bool:
        """Does the module itself define or re-export `name`?"""
        return (
            name in self.functions
            or name in self.pending
            or name in self.classes
            or name in self.exports
        )

    def force(self) -> None:
        """Read every function and method (for the problems of a user stub)."""
        for name in list(self.pending):
            self.function(name)
        for cls in self.classes.values():
            cls.force()
