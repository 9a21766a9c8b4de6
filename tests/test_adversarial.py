"""Adversarial input: each file gets a clear RF0xx/RF9xx diagnostic (or none), never
an exception, and the run goes on with the other files."""

from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings

from robotfix import budget
from robotfix.api import check_paths, check_source
from robotfix.config import Config

GOOD = 'from typing import Annotated\nx: Annotated[int, "_ < 10"] = 12\n'


def run(files: dict[str, bytes], tmp_path: Path) -> dict[str, list[str]]:
    for name, data in files.items():
        (tmp_path / name).write_bytes(data)
    (tmp_path / "good.py").write_text(GOOD)
    result = check_paths([tmp_path], Config(root=tmp_path))
    assert not result.internal_errors, result.internal_errors
    found: dict[str, list[str]] = {}
    for d in result.diagnostics:
        found.setdefault(Path(d.path).name, []).append(d.code)
    assert found.pop("good.py") == ["RF101"]  # the run went on
    return found


def test_deep_nesting(tmp_path: Path) -> None:
    found = run(
        {
            "parens.py": b"x = " + b"(" * 10_000 + b"1" + b")" * 10_000 + b"\n",
            "chain.py": b"x = " + b"+".join([b"1"] * 10_000) + b"\n",
            "calls.py": b"x = " + b"f(" * 10_000 + b")" * 10_000 + b"\n",
        },
        tmp_path,
    )
    # Python 3.10's parser builds the 10,000-term chain (3.11 and later refuse it), so
    # there the analysis is what stops, with RF902
    chain = ["RF902"] if sys.version_info < (3, 11) else ["RF001"]
    assert found == {"parens.py": ["RF001"], "chain.py": chain, "calls.py": ["RF001"]}


def test_deep_but_parseable(tmp_path: Path) -> None:
    code = "def f(v):\n" + "".join(
        f"{'    ' * (i + 1)}if v > {i}:\n" for i in range(90)
    )
    code += "    " * 91 + "y: \"typing.Annotated[int, '_ < 1']\" = 1\n"
    assert run({"nested.py": code.encode()}, tmp_path) == {}


def test_hundred_thousand_lines(tmp_path: Path) -> None:
    lines = [f"v{i} = {i} * 2 + v{i - 1}" if i else "v0 = 0" for i in range(100_000)]
    assert run({"big.py": "\n".join(lines).encode() + b"\n"}, tmp_path) == {}


def test_bytes_and_encodings(tmp_path: Path) -> None:
    found = run(
        {
            "latin.py": b"x = '\xff\xfe'\n",
            "nul.py": b"x = 1\x00\n",
            "crlf.py": GOOD.replace("\n", "\r\n").encode(),
            "tabs.py": b"def f():\n\tx = 1\n\tif x:\n\t\treturn x\n",
            "bom.py": b"\xef\xbb\xbf" + GOOD.encode(),
            "empty.py": b"",
            "py2.py": b'print "hello"\n',
        },
        tmp_path,
    )
    assert found == {
        "latin.py": ["RF003"],
        "nul.py": ["RF001"],
        "crlf.py": ["RF101"],
        "bom.py": ["RF101"],
        "py2.py": ["RF002"],
    }


def test_crlf_and_bom_keep_columns(tmp_path: Path) -> None:
    text = "\ufeff" + GOOD.replace("\n", "\r\n")
    (tmp_path / "f.py").write_bytes(text.encode())
    [diag] = check_paths([tmp_path], Config(root=tmp_path)).diagnostics
    assert (diag.span.line, diag.span.col) == (2, 0)


@pytest.mark.skipif(os.name != "posix", reason="symlinks")
def test_symlink_loops_and_unreadable_files(tmp_path: Path) -> None:
    (tmp_path / "loop").mkdir()
    (tmp_path / "loop" / "again").symlink_to(
        tmp_path / "loop", target_is_directory=True
    )
    (tmp_path / "a.py").symlink_to(tmp_path / "b.py")
    (tmp_path / "b.py").symlink_to(tmp_path / "a.py")
    (tmp_path / "dangling.py").symlink_to(tmp_path / "nowhere.py")
    found = run({}, tmp_path)
    assert found == {"a.py": ["RF003"], "b.py": ["RF003"], "dangling.py": ["RF003"]}


def test_one_pathological_file_is_cut_off(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(budget, "FILE_STEPS", 500)
    big = "\n".join(f"v{i} = {i}" for i in range(2_000)) + "\n"
    assert run({"huge.py": big.encode()}, tmp_path) == {"huge.py": ["RF902"]}


def test_nonlinear_arithmetic_cannot_hang() -> None:
    code = (
        "from typing import Annotated\n"
        "def f(a: float, b: float, c: float, d: float) -> None:\n"
        '    x: Annotated[float, "_ > 0"] = a * b * c * d - a * a * b * b + c * d * d\n'
    )
    codes = [d.code for d in check_source(code, "f.py")]  # bounded by rlimit
    assert codes in (["RF102"], ["RF901"])


hypothesmith = pytest.importorskip("hypothesmith")


@settings(
    max_examples=60,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)
@given(hypothesmith.from_grammar())
def test_generated_programs_never_raise(source: str) -> None:
    for diag in check_source(source, "generated.py"):
        assert diag.code.startswith("RF")
