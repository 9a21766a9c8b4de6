"""A gain beside a conversion (the fresh tester's m7): each literal of a chain is a
factor of its own, so `2 * D_CM / 100` holds the cm -> m conversion and a gain of 2,
whatever the order or the parentheses. Near misses: no conversion at all stays an
error (`2 * D_CM`), and so does a conversion applied to a value already in the
target's unit, gain or not (`x_s * 1000 * 1.5` into s); one number that may fold the
conversion with a gain (`D_CM * 0.02`) is a warning."""
from typing import Annotated

D_CM: Annotated[float, "Unit('cm')"] = 50.0
V_KMH: Annotated[float, "Unit('km/h')"] = 5.0
T_S: Annotated[float, "Unit('s')"] = 0.5


def f(d: Annotated[float, "Unit('m')"], v: Annotated[float, "Unit('m/s')"], t: Annotated[float, "Unit('ms')"]):
    a = d < 2 * D_CM / 100
    b = d < D_CM / 100 * 2
    c = d < (D_CM / 100) * 2
    e = v < 0.5 * V_KMH / 3.6
    g = t < T_S * 1000 * 1.5
    h = t < 1.5 * (T_S * 1000)
    k = d < 2 * (D_CM / 100)
    return a, b, c, e, g, h, k


def near_misses(
    d: Annotated[float, "Unit('m')"],
    t: Annotated[float, "Unit('ms')"],
    x_s: Annotated[float, "Unit('s')"],
):
    a = d < 2 * D_CM  # error: RF202
    b = d < D_CM * 0.5  # error: RF202
    c = t < T_S * 2  # error: RF202
    e = x_s < x_s * 1000 * 1.5  # error: RF202
    g = x_s < 1.5 * (x_s * 1000)  # error: RF202
    h = d < D_CM * 0.02  # warning: RF203
    k = t < T_S * 1500  # warning: RF203
    return a, b, c, e, g, h, k


def stored(x_s: Annotated[float, "Unit('s')"]) -> None:
    later: Annotated[float, "Unit('s')"] = x_s * 1000 * 1.5  # error: RF201
    later = x_s * 1.5
    period_ms: Annotated[float, "Unit('ms')"] = 1.5 * (x_s * 1000)
    period_ms = x_s * 2  # error: RF201
    width: Annotated[float, "Unit('m')"] = D_CM * 0.02  # warning: RF203
    width = 2 * D_CM  # error: RF201
    width = D_CM * 2 / 100
