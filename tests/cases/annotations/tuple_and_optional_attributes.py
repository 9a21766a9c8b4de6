"""Tuple and optional refinements on node attributes and module names."""
from typing import Annotated, Optional

from geometry_msgs.msg import Twist

Deg = Annotated[float, "Unit('degree')"]
MOUNT: tuple[Deg, float] = (1.0, 2.0)


class Tracker:
    def __init__(self) -> None:
        self.orient: tuple[Deg, Annotated[float, "_ > 0"]] = (1.0, 2.0)
        self.limit: Optional[Annotated[float, "_ > 0"]] = None

    def run(self) -> None:
        t = Twist()
        yaw, gain = self.orient
        t.angular.z = yaw  # error: RF201
        positive: Annotated[float, "_ > 0"] = gain
        self.orient = (1.0, -1.0)  # error: RF101
        self.orient = (3.0, 0.5)
        maybe: Annotated[float, "_ > 0"] = self.limit  # warning: RF102
        self.limit = -2.0  # error: RF101
        self.limit = None


def mount() -> None:
    t = Twist()
    roll, height = MOUNT
    t.angular.x = roll  # error: RF201
    t.linear.z = height
