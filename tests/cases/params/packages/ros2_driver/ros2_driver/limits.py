"""The driver's limits, shared with its tools: an alias whose refinement names a
constant of this module, read by driver.py and checked in its parameter files."""
from typing import Annotated

MAX_TURN_RATE = 2.0
TurnRate = Annotated[float, "Unit('rad/s') and abs(_) <= MAX_TURN_RATE"]
