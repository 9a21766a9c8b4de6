"""The new-user report's "container refinements" (P3): a refinement on a list is on
its elements, so the 20.0 is the error (no RF102 about the list as a whole), an
appended -5.0 is reported, and reading an element assumes the refinement."""
from typing import Annotated

from sensor_msgs.msg import LaserScan


def scan_window(scan: LaserScan) -> Annotated[float, "Unit('m') and _ >= 0"]:
    ranges: Annotated[list[float], "Unit('m') and 0 <= _ <= 10"] = [1.0, 20.0]  # error: RF101 "`20.0` violates `ranges[1] <= 10`"
    ranges.append(-5.0)  # error: RF101 "`ranges.append(-5.0)` violates `0 <= ranges[-1]`"
    ranges.append(9.5)
    first: Annotated[float, "_ >= 0"] = ranges[0]
    last: Annotated[float, "_ <= 10"] = ranges[-1]
    clean: Annotated[list[float], "Unit('m') and 0 <= _ <= 10"] = [1.0, 2.0, 10.0]
    clean += [0.0]
    clean += [11.0]  # error: RF101
    total: Annotated[float, "_ >= 0"] = sum(clean)
    return min(clean)
