#!/usr/bin/env python
"""A rospy node that keeps its conversions in the package's transform_utils module."""
import math
from typing import Annotated

import rospy
from geometry_msgs.msg import Twist

import my_robot.transform_utils as tu
from my_robot.transform_utils import SCAN_RANGE_MAX, normalize_angle, to_degrees
from other_robot.helpers import clamp  # not in the tree: stays unknown


class Navigator:
    def __init__(self):
        rospy.init_node("navigator")
        self.pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
        self.rate = rospy.Rate(10)
        self.yaw = 0.0

    def turn(self, target_deg):
        heading: tu.Radians = normalize_angle(self.yaw + 0.1)
        shown: tu.Degrees = to_degrees(heading)
        wrong: tu.Degrees = normalize_angle(heading)  # error: RF201
        twist = Twist()
        error = normalize_angle(math.radians(target_deg))
        twist.angular.z = 0.5 if error > 0 else -0.5
        twist.angular.z = clamp(5.0, 1.0)
        reach: Annotated[float, "Unit('m') and _ <= 3.5"] = SCAN_RANGE_MAX
        near: Annotated[float, "Unit('m') and _ <= 3"] = tu.SCAN_RANGE_MAX  # error: RF101
        far = tu.scaled(0.5)
        too_far = tu.scaled(1.5)  # error: RF101
        self.pub.publish(twist)
        self.rate.sleep()


if __name__ == "__main__":
    Navigator().turn(90.0)
    rospy.spin()
