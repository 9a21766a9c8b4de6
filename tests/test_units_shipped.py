"""A first run reads units without pint (issue 13, item 7): the shipped vocabulary of
common spellings, and the no-pint rejection of text that is no unit pint reads, which
must give pint's own answer wherever it answers at all."""

from __future__ import annotations

import importlib.util
import json
import re
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix.annotations import units
from robotfix.annotations.units import UnitError, check_text, shipped_rejection

ROOT = Path(__file__).resolve().parent.parent
CORPORA = [Path("/work/corpus"), Path("/work/corpus2")]


def tool():  # type: ignore[no-untyped-def]
    path = ROOT / "tools" / "build_package_data.py"
    spec = importlib.util.spec_from_file_location("build_package_data", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def pint_answer(text: str) -> Any:
    """pint's answer as the machine cache and units.json hold it (JSON)."""
    return json.loads(json.dumps(units._resolve_with_pint(text)))


def agrees(text: str) -> bool:
    """The no-pint answer, where there is one, is pint's; True when it answered."""
    try:
        check_text(text)
    except UnitError:
        return False  # never given to pint
    ours = shipped_rejection(text)
    if ours is not None:
        assert ours == pint_answer(text), text
    return ours is not None


@pytest.fixture
def no_pint(monkeypatch: pytest.MonkeyPatch) -> None:
    def refuse(text: str) -> list[Any]:
        raise AssertionError(f"pint was asked about {text!r}")

    monkeypatch.setattr(units, "_resolve_with_pint", refuse)
    monkeypatch.setattr(units._CACHE, "_entries", {})
    monkeypatch.setattr(units._CACHE, "put", lambda text, entry: None)


def test_the_vocabulary_is_shipped_with_pints_answers() -> None:
    build = tool()
    vocabulary = build.vocabulary()
    assert {"mm", "cm/s", "ms", "rpm", "KiB/s", "MiB", "kg*m^2", "mAh"} <= set(
        vocabulary
    )
    shipped = units._shipped()
    for text in vocabulary:
        assert shipped[text] == pint_answer(text), text
        agrees(text)  # a unit pint reads is never rejected


def test_typo_advice_comes_from_the_names_of_a_fresh_registry() -> None:
    """The same advice with and without pint, whatever pint's disk cache holds."""
    names = units._shipped_names()
    assert names is not None
    assert units._registry_names() == names[0]
    assert "kilometer" in names[0]  # a prefixed unit a fresh registry defines
    assert pint_answer("kilometr") == shipped_rejection("kilometr")


@pytest.mark.usefixtures("no_pint")
def test_common_units_and_non_units_resolve_without_pint() -> None:
    assert units.resolve("mm").factor == pytest.approx(0.001)
    assert units.resolve("rpm").dims == (("radian", 1), ("second", -1))
    for tag in ("GPS_FIX_TYPE", "enum", "cells", "degE7", "device-specific"):
        assert units.resolve(tag).is_label, tag
    for text in ("[[end", "device-specific units", "m/cell", "kg-m^2", "m-s/x"):
        with pytest.raises(UnitError, match="not a unit pint understands"):
            units.resolve(text)
    with pytest.raises(UnitError, match="did you mean `meter`"):
        units.resolve("meterz")


def test_no_pint_answers_are_pints_on_the_first_run_misses() -> None:
    """The strings a first run on corpus2 asked pint about before the vocabulary."""
    rejected = [
        "GPS_FIX_TYPE",
        "[[end",
        "cells",
        "degE5",
        "degE7",
        "device-specific units",
        "enum",
        "m/cell",
    ]
    for text in rejected:
        assert agrees(text), text
    for text in ("m", "m/s", "foo/foo", "m/m", "kg m", "nan", "m per s", "sq m"):
        assert not agrees(text), text  # units, or left to pint


@pytest.mark.parametrize(
    "stale", [("_PINT_NAMES_VERSION", 99), ("_installed_pint", lambda: "0.1")]
)
def test_names_of_another_version_or_pint_reject_nothing(
    monkeypatch: pytest.MonkeyPatch, stale: tuple[str, Any]
) -> None:
    units._shipped_names.cache_clear()
    try:
        assert shipped_rejection("GPS_FIX_TYPE") == ["tag"]
        units._shipped_names.cache_clear()
        monkeypatch.setattr(units, *stale)
        assert shipped_rejection("GPS_FIX_TYPE") is None
    finally:
        units._shipped_names.cache_clear()


_BRACKETS = re.compile(r"\[([^,\]]+)\]")


def interface_units() -> list[str]:
    found: set[str] = set()
    for corpus in CORPORA:
        for suffix in ("msg", "srv", "action"):
            for path in corpus.rglob(f"*.{suffix}"):
                for line in path.read_text("utf-8", errors="replace").splitlines():
                    comment = line.partition("#")[2]
                    found.update(m.strip() for m in _BRACKETS.findall(comment))
    return sorted(t for t in found if t)


@pytest.mark.slow
@pytest.mark.skipif(
    not all(c.is_dir() for c in CORPORA), reason="the real-code corpora are absent"
)
def test_no_pint_answers_are_pints_on_real_interface_comments() -> None:
    texts = interface_units()
    assert len(texts) > 40
    answered = sum(agrees(text) for text in texts)
    assert answered > 10


_TOKENS = st.sampled_from(
    [
        "m", "s", "kg", "mm", "ms", "rad", "deg", "Hz", "N", "meter", "meters",
        "kilometer", "inch", "in", "if", "per", "squared", "cubic", "sq",
        "dimensionless", "nan", "NaN", "inf", "cell", "cells", "foo", "Meter",
        "meterz", "x_1", "_", "GPS_FIX", "enum", "degE7", "ks", "kk", "[", "]",
        "[length]", " ", "*", "/", "-", "**", "^", "2", "-1", "(", ")", ".", ",",
        "1", "%", "e", "E", "µ", "²",
    ]
)  # fmt: skip


@settings(max_examples=400, deadline=None)
@given(st.lists(_TOKENS, min_size=1, max_size=6))
def test_no_pint_answers_are_pints_on_random_text(tokens: list[str]) -> None:
    agrees("".join(tokens))
