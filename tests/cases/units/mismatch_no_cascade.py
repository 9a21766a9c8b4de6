"""A clamp that mixes degrees and radians is reported once, where the units meet:
its result has no unit afterwards, as the result of a mismatched `+` has none, so
the same bug is not reported again at every later use of the result."""
from typing import Annotated

import numpy as np

LIMIT_DEG: Annotated[float, "Unit('degree')"] = 30.0
LIMIT_RAD: Annotated[float, "Unit('rad')"] = 0.5


def steer(angle: Annotated[float, "Unit('rad')"]) -> None:
    print(angle)


def clamp_mixed(phi: Annotated[float, "Unit('rad')"]) -> None:
    wide = phi + LIMIT_DEG  # error: RF202
    steer(wide)
    clipped = np.maximum(LIMIT_DEG, phi)  # error: RF202
    steer(clipped)
    nested = np.maximum(-LIMIT_DEG, np.minimum(phi, LIMIT_DEG))  # error: RF202
    steer(nested)


def clamp_converted(phi: Annotated[float, "Unit('rad')"]) -> None:
    clipped = np.maximum(np.deg2rad(-LIMIT_DEG), np.minimum(phi, LIMIT_RAD))
    steer(clipped)
    steer(np.maximum(-LIMIT_RAD, phi))
