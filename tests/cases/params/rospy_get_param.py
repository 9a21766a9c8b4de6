"""ROS 1: `rospy.get_param(name, default)` assigned to a refined variable checks
the default against the refinement and assumes it; a value read elsewhere and
assigned later is an unknown."""
from math import radians
from typing import Annotated

import rospy


class HeadTracker:
    rate: Annotated[float, "Unit('Hz') and 0 < _ <= 50"]

    def __init__(self):
        rospy.init_node("head_tracker")
        self.rate = rospy.get_param("~rate", 100)  # error: RF101 "the default `100` of parameter `~rate`"
        speed: Annotated[float, "0 <= _ <= 1"] = rospy.get_param("~speed", 0.5)
        max_pan: Annotated[float, "abs(_) <= 3.15"] = rospy.get_param("~max_pan", radians(145))
        min_pan: Annotated[float, "abs(_) <= 1"] = rospy.get_param("~min_pan", radians(-145))  # error: RF101
        joints: Annotated[int, "_ > 0"] = rospy.get_param("~joints")
        steps: Annotated[int, "_ > 0"] = rospy.get_param("~steps", 2.5)  # error: RF401
        threshold = rospy.get_param("~threshold", 0.05)
        # warning: RF102 "parameter `~threshold`"
        limited: Annotated[float, "_ < 1"] = threshold

    def loop(self) -> None:
        period: Annotated[float, "_ >= 0.02"] = 1.0 / self.rate
