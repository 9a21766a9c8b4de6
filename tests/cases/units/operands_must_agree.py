"""RF202: +, - and comparisons need equal units; * and / compose them."""
from typing import Annotated

v: Annotated[float, "Unit('m/s')"] = 2
w: Annotated[float, "Unit('rad/s')"] = 1
k: Annotated[float, "Unit('km/h')"] = 10
dt: Annotated[float, "Unit('s')"] = 0.1

total = v + w  # error: RF202
faster = v > k  # error: RF202
mixed = v + k / 3.6
distance: Annotated[float, "Unit('m')"] = v * dt
rate: Annotated[float, "Unit('Hz')"] = 1 / dt
accel: Annotated[float, "Unit('m/s^2')"] = v / dt
wrong: Annotated[float, "Unit('m')"] = v / dt  # error: RF201
bumped = v + 1
