"""The types of the type model (`analysis/types.py`): what an expression is, as a
value that is compared, hashed and carried in summaries. Below every other module
of the analysis: values, summaries and the model all name them.
"""

from __future__ import annotations

from dataclasses import dataclass

# The types are values (compared, hashed, carried in summaries), never changed
# once made. Only what they need is generated (no repr, no frozen setters): each
# generated method is code compiled when the module is imported, in every run.


@dataclass(unsafe_hash=True, repr=False)
class Msg:
    """A message of the catalog's type `pkg/Name`."""

    name: str


@dataclass(unsafe_hash=True, repr=False)
class Obj:
    """An instance of a class of this file (`Driver`) or of another module of the
    tree (`drive_pkg.motor.Driver`)."""

    name: str


@dataclass(unsafe_hash=True, repr=False)
class Lib:
    """An object of a class a stub describes (`rclpy.time.Time`, `rospy.Duration`),
    by the stub's qualified name: its properties, methods and operators are the
    stub's."""

    name: str


@dataclass(unsafe_hash=True, repr=False)
class Seq:
    """A list, set, deque, iterable or homogeneous tuple of `item`s."""

    item: Type


@dataclass(unsafe_hash=True, repr=False)
class Tup:
    """A tuple of fixed length; None for an element of no known type."""

    items: tuple[Type | None, ...]


@dataclass(unsafe_hash=True, repr=False)
class Map:
    """A dict whose values are `value`s."""

    value: Type


@dataclass(unsafe_hash=True, repr=False)
class Maybe:
    """`Optional[T]`: a T, or None."""

    type: Type


Type = Msg | Obj | Lib | Seq | Tup | Map | Maybe


def plain(found: Type | None) -> Type | None:
    """The type without its `None`: what a value is once it is used as one."""
    return found.type if isinstance(found, Maybe) else found


def element(found: Type | None) -> Type | None:
    """The type of an element of a container (of a dict: of a value)."""
    found = plain(found)
    if isinstance(found, Seq):
        return found.item
    if isinstance(found, Map):
        return found.value
    if isinstance(found, Tup) and found.items:
        first = found.items[0]
        return first if all(i == first for i in found.items) else None
    return None


def qualified(found: Type | None, module: str, local: set[str]) -> Type | None:
    """`found` as another module names it: this module's classes get its name."""
    if isinstance(found, Obj) and found.name in local:
        return Obj(f"{module}.{found.name}")
    if isinstance(found, Seq):
        item = qualified(found.item, module, local)
        return Seq(item) if item is not None else None
    if isinstance(found, Map):
        value = qualified(found.value, module, local)
        return Map(value) if value is not None else None
    if isinstance(found, Maybe):
        inner = qualified(found.type, module, local)
        return Maybe(inner) if inner is not None else None
    if isinstance(found, Tup):
        return Tup(tuple(qualified(i, module, local) for i in found.items))
    return found
