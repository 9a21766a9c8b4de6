"""`Frame(...)` alone says where a number is, not in what unit: it meets a value of
any unit, and only another frame can disagree with it. (It was read as a
dimensionless unit, so a position in m was RF201 against it.) Modelled on
nav2_system_tests' pose testers, which keep coordinates in plain floats."""
from typing import Annotated

from nav_msgs.msg import Odometry

MapX = Annotated[float, "Frame('map')"]
OdomX = Annotated[float, "Frame('odom')"]


def on_odom(msg: Odometry, goal_x: MapX, odom_x: OdomX) -> None:
    x: MapX = msg.pose.pose.position.x  # clean: a value in m, of no known frame
    y: Annotated[float, "Unit('m') and Frame('map')"] = goal_x  # clean: the same frame
    t: Annotated[float, "Unit('s')"] = goal_x  # clean: no unit is claimed for goal_x
    z: MapX = odom_x  # error: RF201 "frame odom"
    w: Annotated[float, "Unit('m') and Frame('odom')"] = goal_x  # error: RF201 "frame map"
