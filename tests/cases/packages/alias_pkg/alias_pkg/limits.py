"""The robot's limits, and aliases whose refinements name them."""
from typing import Annotated

MAX_SPEED = 0.5
MAX_TURN = 1.2

Speed = Annotated[float, "Unit('m/s') and 0 <= _ <= MAX_SPEED"]
TurnRate = Annotated[float, "Unit('rad/s') and abs(_) <= MAX_TURN"]
