"""A goal publisher: a `Frame(...)` value may go into a standard message's field (the
frame lives in header.frame_id); values known to be in different frames may not meet."""
from typing import Annotated

from geometry_msgs.msg import Point, PoseStamped


def goal(
    pub,
    x: Annotated[float, "Unit('m') and Frame('map')"],
    y: Annotated[float, "Unit('m') and Frame('map')"],
    odom_x: Annotated[float, "Unit('m') and Frame('odom')"],
    offset: Annotated[float, "Unit('m')"],
):
    p = Point()
    p.x = x
    p.y = y + offset
    p.z = odom_x
    msg = PoseStamped()
    msg.header.frame_id = "map"
    msg.pose.position.x = x
    msg.pose.position.y = x - odom_x  # error: RF202
    if x < odom_x:  # error: RF202
        x = odom_x  # error: RF201
    msg.pose.position.z = offset * 2
    pub.publish(msg)
