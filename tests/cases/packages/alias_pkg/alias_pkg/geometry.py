"""Aliases whose refinements name an import (`math.pi`) and a class constant."""
import math
from typing import Annotated


class Limits:
    MAX_ACCEL = 0.5
    RATE = 10.0


Heading = Annotated[float, "Unit('rad') and -math.pi <= _ <= math.pi"]
Accel = Annotated[float, "_ <= Limits.MAX_ACCEL"]
