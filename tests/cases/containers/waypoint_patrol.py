#!/usr/bin/env python
"""A rospy patrol script: module-level lists of waypoints, leg speeds and dwell
times drive a square patrol. Refinements on the lists hold for every element, what
the script appends is checked, and sums and extremes of them are bounded
(issue 8, item 5)."""
from typing import Annotated

import rospy
from geometry_msgs.msg import Twist

ARENA = 20.0  # m, half the side of the arena
waypoints_x: Annotated[list[float], "Unit('m') and abs(_) <= ARENA"] = [1.0, 4.5, -2.0]
waypoints_y: Annotated[list[float], "Unit('m') and abs(_) <= ARENA"] = [0.0, 3.0, 25.0]  # error: RF101
SPEEDS: Annotated[tuple[float, ...], "Unit('m/s') and 0 < _ <= 0.5"] = (0.2, 0.3, 0.5)
DWELL: Annotated[tuple[float, ...], "Unit('s') and _ >= 0"] = (2.0, 0.0, 5.0)


def add_waypoint(
    x: Annotated[float, "Unit('m') and abs(_) <= 10"],
    y: Annotated[float, "Unit('m')"],
    x_cm: Annotated[float, "Unit('cm')"],
) -> None:
    waypoints_x.append(x)
    waypoints_y.append(y)  # warning: RF102
    waypoints_x.append(x_cm)  # error: RF201
    waypoints_x.append(x_cm / 100.0)  # warning: RF102
    waypoints_x.extend([x, -x, 0.5 * x])
    waypoints_x.extend([x, 2.5 * ARENA])  # error: RF101
    waypoints_x.insert(0, x)


def patrol_time() -> Annotated[float, "Unit('s') and 0 <= _ <= 60"]:
    legs = len(SPEEDS)
    waiting: Annotated[float, "Unit('s') and _ == 7"] = sum(DWELL)
    fastest: Annotated[float, "Unit('m/s') and _ == 0.5"] = max(SPEEDS)
    slowest: Annotated[float, "Unit('m/s') and _ > 0.2"] = min(SPEEDS)  # error: RF101
    if legs == 0:
        return 0.0
    return waiting + 10.0 * legs


def run(pub: rospy.Publisher) -> None:
    cmd = Twist()
    for speed in SPEEDS:
        cmd.linear.x = speed
        pub.publish(cmd)
    for wait in DWELL:
        cmd.linear.x = wait  # error: RF201
        rospy.sleep(wait)
    for index, x in enumerate(waypoints_x):
        target: Annotated[float, "Unit('m') and abs(_) <= ARENA"] = x
        cmd.angular.z = x  # error: RF201


if __name__ == "__main__":
    rospy.init_node("waypoint_patrol")
    run(rospy.Publisher("cmd_vel", Twist, queue_size=1))
