"""What a call's evaluation keeps instead of asking again at every call (issue 25):
a stub set's answer for a qualified name (`StubSet.lookup`), and what a module's
attribute stands for in one file (`Program.module_attributes`). Each answer
depends on what it is kept with: a memo kept wider would give one file, or one
stub set, the answer of another."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from robotfix.api import check_paths
from robotfix.config import Config
from robotfix.stubs.load import DATA, Function, StubSet, _module_names, _text_of

NODE = """from typing import Annotated

import limits

reach: Annotated[float, "Unit('m')"] = limits.MAX


def step() -> None:
    far: Annotated[float, "Unit('m')"] = limits.MAX
    print(far)
"""


def test_a_module_attribute_is_what_its_own_file_imports(tmp_path: Path) -> None:
    """`limits.MAX` is in m beside a/node.py and in s beside b/node.py: one name,
    two meanings in one run; read twice in each file (the second read is kept)."""
    for folder, unit in (("a", "m"), ("b", "s")):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "limits.py").write_text(
            "from typing import Annotated\n\n"
            f"MAX: Annotated[float, \"Unit('{unit}')\"] = 1.0\n"
        )
        (tmp_path / folder / "node.py").write_text(NODE)
    for order in (["a", "b"], ["b", "a"]):
        result = check_paths([tmp_path / f for f in order], Config(root=tmp_path))
        found = sorted(
            (Path(d.path).parent.name, d.span.line, d.code) for d in result.diagnostics
        )
        assert found == [("b", 5, "RF201"), ("b", 9, "RF201")]


def test_a_stub_lookup_is_kept_per_stub_set(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The user's stub paths make `my_motor.move` known to one set only; each set
    searches its modules for a name once."""
    (tmp_path / "my_motor.pyi").write_text("def move(distance: float) -> None: ...\n")
    searched: list[str] = []
    search = StubSet._lookup

    def counting(self: StubSet, qualified: str, hops: int):  # type: ignore[no-untyped-def]
        searched.append(qualified)
        return search(self, qualified, hops)

    monkeypatch.setattr(StubSet, "_lookup", counting)
    users, shipped = StubSet((tmp_path,)), StubSet()
    for _ in range(2):
        assert isinstance(users.lookup("my_motor.move"), Function)
        assert shipped.lookup("my_motor.move") is None
        assert isinstance(shipped.lookup("math.radians"), Function)
    assert searched == ["my_motor.move", "my_motor.move", "math.radians"]


def test_the_modules_defining_a_method_are_those_whose_text_has_its_def(
    tmp_path: Path,
) -> None:
    """`StubSet._modules_defining` reads every stub's text once for all names: its
    answer for a method's name is still every module whose text has `def name(`
    (a user stub's odd spellings too), in the modules' order, as a search of each
    text for that name finds them."""
    (tmp_path / "motors.pyi").write_text(
        "class Motor:\n"
        "    def spin(self, speed: float) -> None: ...\n"
        "    async def stop(self) -> None: ...\n"
        "    def café(self) -> None: ...\n"
        "    def def_(self) -> None: ...\n"
        "xdef odd(\n"
        "def  spaced(self) -> None: ...\n"
    )
    (tmp_path / "wheels.pyi").write_text(
        "class Wheel:\n    def spin(self, rate: float) -> None: ...\n"
    )
    stubs, shipped = StubSet((tmp_path,)), StubSet()
    assert shipped._modules_defining("spin")  # the shipped set reads its texts first
    modules = sorted({*_module_names(tmp_path), *_module_names(DATA)})

    def searched(name: str) -> list[str]:
        return [
            m
            for m in modules
            if (where := stubs._file_of(m)) is not None
            and f"def {name}(" in _text_of(where[0])
        ]

    texts = "".join(_text_of(stubs._file_of(m)[0]) for m in modules)  # type: ignore[index]
    names = {*re.findall(r"def (\w+)", texts), "odd", "spaced", "de", "café"}
    for name in sorted(names):  # method names: identifiers
        assert [m.name for m in stubs._modules_defining(name)] == searched(name)
        assert [m.name for m in shipped._modules_defining(name)] == [
            m for m in searched(name) if m not in ("motors", "wheels")
        ]
    assert {"motors", "wheels"} <= {m.name for m in stubs._modules_defining("spin")}
