"""A call of a method of a value of unknown type (`x.wait_for_service(1.0)`,
`super().__init__("talker")`) is checked against every stub method of its name, as
far as they agree (`analysis/library.py`): the agreement of those candidates, and
which arguments it lets the analysis check.

`checked` is a fact of the stubs alone: for the shipped stubs it is computed once
(tools/build_package_data.py writes it into `shipped_names.json`), so that a
call such as `super().__init__(...)` in every node class parses no stub module
that defines an `__init__` (17 M instructions of every process) to find that no
argument of it can be checked."""

from __future__ import annotations

from collections.abc import Sequence

from robotfix.stubs.model import Function, Param


def signature(function: Function) -> tuple[object, ...]:
    return (
        tuple(
            (p.name, p.positional, p.keyword, _unit_text(p)) for p in function.params
        ),
        None if function.returns is None else f"{function.returns.text}",
        function.returns_type,
    )


def _unit_text(param: Param) -> str | None:
    return None if param.decl is None else f"{param.decl.text}"


def param_at(function: Function, index: int | None, key: str | None) -> Param | None:
    for param in function.params:
        if key is not None and param.keyword and param.name == key:
            return param
        if index is not None and param.positional == index and not param.variadic:
            return param
    return None


def one_unit(params: Sequence[Param | None]) -> bool:
    units = {
        (p.decl.unit.dims, p.decl.unit.factor)
        if p is not None and p.decl is not None and p.decl.unit is not None
        else None
        for p in params
    }
    return len(units) == 1 and None not in units


def agree(candidates: Sequence[Function]) -> bool:
    """Whether the candidates have one signature: a call is then one of them."""
    return len({signature(f) for f in candidates}) == 1


def position_checked(candidates: Sequence[Function], index: int) -> bool:
    params = [param_at(f, index, None) for f in candidates]
    return all(p is not None for p in params) and one_unit(params)


def keyword_checked(candidates: Sequence[Function], key: str) -> bool:
    given = [p for p in (param_at(f, None, key) for f in candidates) if p is not None]
    return bool(given) and one_unit(given)


def checked(candidates: Sequence[Function]) -> tuple[list[int], list[str]]:
    """The positions and keywords of the arguments a call by name may have checked,
    when the candidates (at least one) do not agree."""
    positions = {p.positional for f in candidates for p in f.params}
    keys = {p.name for f in candidates for p in f.params if p.keyword}
    return (
        sorted(
            i for i in positions if i is not None and position_checked(candidates, i)
        ),
        sorted(k for k in keys if keyword_checked(candidates, k)),
    )
