"""`units.fit`: literal factors convert within a dimension but never change one, the
radian cancels only against a length, and Hz meets rad/s only through 2*pi."""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix.annotations.units import converts, fit, resolve
from robotfix.messages import conversion

UNITS = [
    "m",
    "km",
    "cm",
    "s",
    "ms",
    "ns",
    "m/s",
    "km/h",
    "rad",
    "degree",
    "rad/s",
    "degree/s",
    "rpm",
    "Hz",
    "m/s^2",
    "1",
]
scales = st.sampled_from([0.1, 0.5, 2.0, 3.6, 1 / 3.6, 100.0, 1e-9, 1e9])


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(UNITS), st.sampled_from(UNITS), scales)
def test_a_literal_factor_never_bridges_dimensions_but_time(
    got: str, expected: str, scale: float
) -> None:
    a, b = resolve(got), resolve(expected)
    found = fit(a, b, (scale,))
    ours, theirs = dict(a.dims), dict(b.dims)
    diff = {
        d: ours.get(d, 0) - theirs.get(d, 0)
        for d in ours.keys() | theirs.keys()
        if ours.get(d, 0) != theirs.get(d, 0)
    }
    if not diff:
        needed = math.isclose(a.factor / scale, b.factor, rel_tol=1e-3)
        plain = a.same_as(b) and not converts(a, scale)
        assert (found.kind == "ok") == (needed or plain)
    elif found.kind == "ok":  # only a revolution: 2*pi between Hz and rad/s
        assert set(diff) == {"radian"}
    elif found.kind == "time":
        assert set(diff) == {"second"} and abs(diff["second"]) == 1


@settings(max_examples=30, deadline=None)
@given(st.sampled_from(["rad/s", "degree/s", "rpm"]), st.sampled_from(["m", "cm"]))
def test_the_radian_cancels_against_a_length_with_its_scale(
    angular: str, length: str
) -> None:
    product = resolve(angular) * resolve(length)
    found = fit(product, resolve("m/s"), rad_free=True)
    natural = angular == "rad/s" and length == "m"
    assert (found.kind == "ok") == natural
    assert fit(product, resolve("m/s")).kind == "mismatch"  # no length involved


def test_hz_and_rad_per_second() -> None:
    hz, rad_s = resolve("Hz"), resolve("rad/s")
    plain = fit(hz, rad_s)
    assert plain.kind == "mismatch"
    assert "2*math.pi" in conversion(hz, rad_s)
    assert fit(hz, rad_s, factors=(2 * math.pi,)).kind == "ok"
    assert fit(rad_s, hz, factors=(1 / (2 * math.pi),)).kind == "ok"
    assert fit(hz, rad_s, factors=(0.5,)).kind == "mismatch"
    assert conversion(resolve("rad"), resolve("1")) == ""


def test_conversions_are_named_in_the_unit_the_value_has() -> None:
    assert str(fit(resolve("s"), resolve("ns"), factors=(1e6,)).got) == "us"
    assert fit(resolve("1/Hz"), resolve("ms"), factors=(1000.0,)).kind == "ok"
    assert fit(resolve("ns"), resolve("s"), factors=(1e-9,)).kind == "ok"


def test_frames_only_one_side_names_do_not_clash() -> None:
    from robotfix.annotations.units import label

    in_map = resolve("m") * label("frame", "map")
    in_odom = resolve("m") * label("frame", "odom")
    assert fit(in_map, resolve("m")).kind == "ok"
    assert fit(resolve("m"), in_map).kind == "ok"
    assert fit(in_map, in_odom).kind == "mismatch"


def test_an_implicit_gain_needs_the_same_scale() -> None:
    """rad into rad/s is a unit gain (RF203); degrees into rad/s are degrees for
    radians first, an error whatever the gain (the alias case's HEADING)."""
    assert fit(resolve("rad"), resolve("rad/s")).kind == "time"
    assert fit(resolve("m"), resolve("m/s")).kind == "time"
    assert fit(resolve("degree"), resolve("rad/s")).kind == "mismatch"
    assert fit(resolve("cm"), resolve("m/s")).kind == "mismatch"


def test_a_folded_conversion_beside_a_plain_factor_fits() -> None:
    """`avg * 2 * math.pi / 60` with `avg = (l + r) / 2`: the factors hold the rpm ->
    rad/s conversion and a plain 1/2 (issue 22: it was "multiply by 2")."""
    rpm, rad_s = resolve("rpm"), resolve("rad/s")
    assert fit(rpm, rad_s, (0.5, 2 * math.pi / 60)).kind == "ok"
    assert fit(rpm, rad_s, (0.5,)).kind == "mismatch"
    assert fit(resolve("km/h"), resolve("m/s"), (0.5,)).got == resolve("km/h")


def test_a_conversion_of_a_value_already_in_the_target_unit_is_a_mismatch() -> None:
    seconds, ns = resolve("s"), resolve("ns")
    twice = fit(seconds, seconds, (1000.0,))
    assert (twice.kind, str(twice.got), twice.twice) == ("mismatch", "ms", 1000.0)
    assert fit(ns, ns, (1e-9,)).kind == "mismatch"
    assert fit(resolve("m/s"), resolve("m/s"), (3.6,)).kind == "mismatch"
    assert fit(seconds, seconds, (2.0,)).kind == "ok"
    assert fit(resolve("1"), resolve("1"), (1000.0,)).kind == "ok"  # a count
    assert fit(resolve("m"), resolve("m"), (60.0,)).kind == "ok"  # not a length's


def test_a_gain_beside_a_conversion_keeps_the_conversion() -> None:
    """Each literal of a chain is a factor of its own (the fresh tester's m7: `2 *
    D_CM / 100` into m was "divide by 100", an error on correct code)."""
    cm, m, s, ms = resolve("cm"), resolve("m"), resolve("s"), resolve("ms")
    assert fit(cm, m, (2.0, 0.01)).kind == "ok"
    assert fit(cm, m, (0.01, 2.0)).kind == "ok"
    assert fit(resolve("km/h"), resolve("m/s"), (0.5, 1 / 3.6)).kind == "ok"
    assert fit(s, ms, (1000.0, 1.5)).kind == "ok"
    assert fit(s, ms, (1.5, 1000.0)).kind == "ok"
    rpm = (2.0, math.pi, 1 / 60)  # `rpm * 2.0 * math.pi / 60.0`, unfolded
    assert fit(resolve("rpm"), resolve("rad/s"), rpm).kind == "ok"
    assert fit(resolve("rpm"), resolve("rad/s"), (0.5, *rpm)).kind == "ok"


def test_a_conversion_split_over_literals_still_converts_twice() -> None:
    rad = resolve("rad")
    twice = fit(rad, rad, (180.0, 1 / math.pi))  # `pos * 180 / math.pi`
    assert twice.kind == "mismatch" and str(twice.got) == "degree"
    again = fit(resolve("s"), resolve("s"), (1000.0, 1.5))  # `x_s * 1000 * 1.5`
    assert (again.kind, again.twice) == ("mismatch", 1000.0)
    assert fit(resolve("s"), resolve("s"), (1000.0, 1e-3)).kind == "ok"


def test_a_literal_nearer_the_conversion_than_one_may_fold_a_gain() -> None:
    """`d_cm * 0.02` into m may be `/ 100 * 2` in one number: a warning; `2 *
    d_cm` (2 is farther from 1/100 than 1 is) is still in cm: an error."""
    cm, m = resolve("cm"), resolve("m")
    folded = fit(cm, m, (0.02,))
    assert (folded.kind, folded.scale, str(folded.got)) == ("folded", 0.02, "cm")
    assert fit(cm, m, (2.0,)).kind == "mismatch"
    assert fit(cm, m, (0.5,)).kind == "mismatch"
    assert fit(cm, m, ()).kind == "mismatch"
    assert fit(resolve("s"), resolve("ms"), (1500.0,)).kind == "folded"
    assert fit(resolve("rpm"), resolve("rad/s"), (0.5, 0.5)).kind == "mismatch"
    assert fit(cm, m, (-0.02,)).kind == "folded"
    assert fit(cm, m, (math.inf,)).kind == "mismatch"
