"""`list[Annotated[float, "Unit('s')"]]` is read as `Annotated[list[float],
"Unit('s')"]`: the refinement is on each element (it was ignored, silently)."""
from typing import Annotated, List, Sequence

from sensor_msgs.msg import LaserScan


class Bridge:
    def __init__(self, scans: list) -> None:
        self.times: list[Annotated[float, "Unit('s')"]] = list(scans[0])
        self.ranges: List[Annotated[float, "Unit('m') and 0 <= _ <= 30"]] = [1.0, 40.0]  # error: RF101
        self.raw: list[Annotated[float, "len(_) > 2"]] = [1.0]  # no refinement: an element has no len

    def publish(self) -> LaserScan:
        scan = LaserScan()
        scan.ranges = self.ranges
        scan.ranges = self.times  # error: RF201 "the elements of `scan.ranges` are in m"
        first: Annotated[float, "Unit('m')"] = self.times[0]  # error: RF201
        return scan


def widths(sizes: Sequence[Annotated[float, "Unit('mm')"]]) -> float:
    total: Annotated[float, "Unit('m')"] = sizes[0]  # error: RF201 "1000"
    return total
