"""A script beside the package: its imports resolve from its own folder."""
import time
from typing import Annotated

from geo import SPEED_LIMIT, wrap
from geo.angles import turn_rate
from geo.speeds import limited


def main() -> None:
    heading: Annotated[float, "Unit('degree')"] = 45.0
    wrap(heading)  # error: RF201
    wrap(0.5)
    turn_rate(0.1)
    turn_rate(0.0)  # error: RF101
    limited(SPEED_LIMIT)
    limited(2 * SPEED_LIMIT)  # error: RF101
    time.sleep(0.1)


if __name__ == "__main__":
    main()
