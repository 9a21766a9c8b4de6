"""Unit algebra through pint: spellings, scales, angle as its own dimension, tags."""

from __future__ import annotations

import pytest

from robotfix.annotations.units import UnitError, resolve
from robotfix.messages import conversion


def test_spellings_of_one_unit_are_equal() -> None:
    assert resolve("meter").same_as(resolve("m"))
    assert resolve("seconds").same_as(resolve("s"))
    assert resolve("m/s").same_as(resolve("meter / second"))


def test_scale_differences_name_the_factor() -> None:
    kmh, ms = resolve("km/h"), resolve("m/s")
    assert kmh.same_dimension(ms) and not kmh.same_as(ms)
    assert conversion(kmh, ms) == "divide by 3.6 to convert km/h to m/s"
    assert "math.radians" in conversion(resolve("degree/s"), resolve("rad/s"))


def test_angle_is_a_dimension_of_its_own() -> None:
    assert not resolve("rad/s").same_dimension(resolve("Hz"))
    assert not resolve("rad").same_dimension(resolve("1"))
    assert resolve("rpm").same_dimension(resolve("rad/s"))


def test_composition() -> None:
    assert (resolve("m/s") * resolve("s")).same_as(resolve("m"))
    assert (resolve("m") / resolve("s") / resolve("s")).same_as(resolve("m/s^2"))


def test_non_units_are_tags_and_typos_are_errors() -> None:
    assert resolve("ENU").dims == (("tag:ENU", 1),)
    assert not resolve("ENU").same_as(resolve("NED"))
    for frame in ("map", "odom", "base_link", "rear", "world"):
        resolve(frame)
    for typo, meant in (("meterz", "meter"), ("secnds", "seconds"), ("Meter", "meter")):
        with pytest.raises(UnitError) as info:
            resolve(typo)
        assert info.value.suggestion == meant


def test_offset_units() -> None:
    assert not resolve("degC").same_as(resolve("K"))
    assert "273.15" in conversion(resolve("degC"), resolve("K"))
