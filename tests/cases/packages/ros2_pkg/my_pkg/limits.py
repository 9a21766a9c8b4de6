"""The robot's limits, in one place."""
from typing import Annotated

MAX_SPEED: Annotated[float, "Unit('m/s')"] = 0.22
MAX_TURN = 2.84
WHEEL_BASE: Annotated[float, "Unit('m')"] = 0.16
