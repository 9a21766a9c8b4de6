"""A rospy script with helper functions: refined parameters and returns."""
from typing import Annotated

import rospy
from geometry_msgs.msg import Twist

MAX: Annotated[float, "Unit('m/s') and _ > 0"] = 1.0


def clamp(
    v: Annotated[float, "Unit('m/s')"], limit: Annotated[float, "Unit('m/s') and _ > 0"]
) -> Annotated[float, "Unit('m/s') and abs(_) <= limit"]:
    if v > limit:
        return limit
    if v < -limit:
        return -limit
    return v


def clamp_wrong(
    v: Annotated[float, "Unit('m/s')"], limit: Annotated[float, "Unit('m/s') and _ > 0"]
) -> Annotated[float, "Unit('m/s') and abs(_) <= limit"]:
    if v > limit:
        return v  # error: RF101
    return max(v, -limit)


def send(pub: rospy.Publisher, requested: float) -> None:
    cmd = Twist()
    cmd.linear.x = clamp(requested, MAX)
    safe: Annotated[float, "abs(_) <= 1"] = clamp(requested, 1.0)
    known: Annotated[float, "abs(_) <= 1"] = clamp(requested, MAX)  # MAX is 1.0
    unsure: Annotated[float, "abs(_) <= 1"] = clamp(requested, 2 * MAX)  # warning: RF102
    cmd.linear.y = clamp(requested, 0)  # error: RF101
    cmd.linear.z = clamp(limit=MAX, v=requested)
    pub.publish(cmd)


rospy.init_node("teleop")
publisher = rospy.Publisher("cmd_vel", Twist, queue_size=1)
send(publisher, 3.0)
