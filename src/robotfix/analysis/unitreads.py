"""What an item of the editor's memo (`analysis/unitmemo.py`) asked the type model
while it ran, logged with the answers, and asked again before a replay: the model
reads other functions' bodies, which an item's key does not hold."""

from __future__ import annotations

import ast
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from robotfix.analysis.program import Function, Program
    from robotfix.analysis.types import TypeModel
    from robotfix.analysis.typeterms import Type
    from robotfix.stubs import load as stubs


class Reads:
    """The type model as an item's run sees it (`program.types` while it runs):
    every question the interpreter asks is answered by the model and logged with
    its answer, by names that find it again in a later check. The model reads
    other functions' bodies (what a method returns, what `self.x` is assigned),
    so a replay asks the log again (`same_reads`): the answers must be alike,
    and the model's tables fill in the order a run fills them."""

    def __init__(self, model: TypeModel, program: Program) -> None:
        self.model = model
        self.program = program
        self.log: list[tuple[tuple[object, ...], object]] = []
        self.unknown = False  # asked something it cannot name

    def __getattr__(self, name: str) -> object:
        self.unknown = True
        return getattr(self.model, name)

    def _named(self, function: Function) -> str | None:
        if self.program.functions.get(function.key) is function:
            return function.key
        self.unknown = True
        return None

    def infer(
        self, node: ast.expr, function: Function | None, env: object = None
    ) -> Type | None:
        found = self.model.infer(node, function, env)  # type: ignore[arg-type]
        if not isinstance(node, ast.Name) or function is None or env is not None:
            self.unknown = True
        else:
            self.log.append((("infer", self._named(function), node.id), found))
        return found

    def parameter(self, function: Function, name: str) -> Type | None:
        found = self.model.parameter(function, name)
        self.log.append((("parameter", self._named(function), name), found))
        return found

    def returns(self, key: str) -> Type | None:
        found = self.model.returns(key)
        self.log.append((("returns", key), found))
        return found

    def attribute(self, class_name: str, attr: str) -> Type | None:
        found = self.model.attribute(class_name, attr)
        self.log.append((("attribute", class_name, attr), found))
        return found

    def library_bases(self, class_name: str) -> list[stubs.Class]:
        found = self.model.library_bases(class_name)
        self.log.append((("library_bases", class_name), _qualnames(found)))
        return found


def _qualnames(classes: list[stubs.Class]) -> tuple[str, ...]:
    return tuple(c.qualname for c in classes)


# questions whose answer the model keeps once asked (`TypeModel._attributes`,
# `_returns` of a function of the file, `_library_bases`): asking one again
# within a check gives the kept answer and fills nothing
_KEPT = frozenset({"attribute", "returns", "library_bases"})
_UNASKED = object()


def same_reads(
    program: Program,
    reads: tuple[tuple[tuple[object, ...], object], ...],
    answered: dict[tuple[object, ...], object],
) -> bool:
    """Whether the type model answers an item's logged questions alike now (asked
    in their order, as its run asked them). `answered`: what the model answered
    so far in this check to the questions whose answers it keeps (`_KEPT`),
    taken from there instead of asked again (items of a node ask the same ones:
    `library_bases` of the node's class at every `self.x`)."""
    model = program.types
    for question, answer in reads:
        known = answered.get(question, _UNASKED)
        if known is not _UNASKED:
            if known != answer:
                return False
            continue
        kind = question[0]
        if kind in ("infer", "parameter"):
            function = program.functions.get(str(question[1]))
            if function is None:
                return False
            name = str(question[2])
            if kind == "infer":
                found: object = model.infer(ast.Name(id=name, ctx=ast.Load()), function)
            else:
                found = model.parameter(function, name)
        elif kind == "returns":
            found = model.returns(str(question[1]))
        elif kind == "attribute":
            found = model.attribute(str(question[1]), str(question[2]))
        else:
            found = _qualnames(model.library_bases(str(question[1])))
        if kind in _KEPT and (kind != "returns" or question[1] in program.functions):
            answered[question] = found  # (a function not made yet is not kept)
        if found != answer:
            return False
    return True
