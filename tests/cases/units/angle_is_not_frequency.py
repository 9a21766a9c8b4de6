"""Angle is a dimension of its own: rad/s is not Hz, and rad is not a plain number."""
from typing import Annotated

rate: Annotated[float, "Unit('Hz')"] = 10
spin: Annotated[float, "Unit('rad/s')"] = 1.5
spin = rate  # error: RF201
angle: Annotated[float, "Unit('rad')"] = 0.5
ratio: Annotated[float, "Unit('1')"] = 0.5
ratio = angle  # error: RF201
per_second: Annotated[float, "Unit('1/s')"] = rate
