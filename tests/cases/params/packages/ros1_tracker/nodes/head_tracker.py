#!/usr/bin/env python3
"""Points the head at a target; its limits are private parameters."""
from math import radians
from typing import Annotated

import rospy
from geometry_msgs.msg import Twist


class HeadTracker:
    rate: Annotated[float, "Unit('Hz') and 0 < _ <= 50"]
    max_pan: Annotated[float, "Unit('rad') and 0 <= _ <= 3.15"]

    def __init__(self):
        rospy.init_node("head_tracker")
        self.rate = rospy.get_param("~rate", 20)
        self.max_pan = rospy.get_param("~max_pan", radians(145))
        gain: Annotated[float, "0 < _ <= 2"] = rospy.get_param("~gains/pan", 1.0)
        mode: Annotated[str, "_ == 'track' or _ == 'scan'"] = rospy.get_param("~mode", "track")
        self.speed = rospy.get_param("~speed", 0.3)
        self.lost_timeout: Annotated[float, "Unit('s') and _ >= 0"] = rospy.get_param(
            "/head_tracker/lost_timeout", 5.0
        )
        self.publisher = rospy.Publisher("cmd_vel", Twist, queue_size=1)

    def spin(self) -> None:
        period: Annotated[float, "Unit('s') and _ >= 0.02"] = 1.0 / self.rate
        rospy.sleep(period)


if __name__ == "__main__":
    HeadTracker().spin()
