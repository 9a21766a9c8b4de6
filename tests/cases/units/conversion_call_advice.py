"""The advice on a conversion call comes from what the value knows of that call (the
fresh tester's c07: `math.degrees(SETPOINT_DEG)` stored into rad was two errors, one
saying "remove `degrees()`: the value is in rad without it", which is false: without
the call the value is in degrees). One diagnostic per bug; near misses stay silent."""
import math
from typing import Annotated

import numpy as np

SETPOINT_DEG: Annotated[float, "Unit('degree')"] = 45.0


def setpoints(
    yaw: Annotated[float, "Unit('rad')"], rate: Annotated[float, "Unit('rad/s')"]
) -> None:
    wrong: Annotated[float, "Unit('rad')"] = math.degrees(SETPOINT_DEG)  # error: RF201 "use `math.radians()` in place of `math.degrees()`"
    right: Annotated[float, "Unit('rad')"] = math.radians(SETPOINT_DEG)
    half: Annotated[float, "Unit('rad')"] = -math.degrees(yaw) / 2.  # error: RF201 "remove `math.degrees()`"
    half = -yaw / 2.
    spin: Annotated[float, "Unit('rad/s')"] = np.degrees(rate)  # error: RF201 "remove `np.degrees()`"
    shown: Annotated[float, "Unit('degree')"] = math.degrees(SETPOINT_DEG)  # error: RF201 "drop the call"
    shown = math.degrees(yaw)
    again = math.radians(yaw)  # error: RF201 "drop the call"
    del wrong, right, half, spin, shown, again
