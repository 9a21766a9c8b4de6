"""A P-controller heading node: a unit gain (or only a clamp) turns an angle error into
a turn rate, which is a warning asking for a named gain (RF203), not an error."""
import math
from typing import Annotated

from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

K_YAW: Annotated[float, "Unit('1/s')"] = 1.5
K_DIST: Annotated[float, "Unit('1/s')"] = 0.5
MAX_TURN: Annotated[float, "Unit('rad/s')"] = 0.5


def normalize(a: Annotated[float, "Unit('rad')"]) -> Annotated[float, "Unit('rad')"]:
    return math.atan2(math.sin(a), math.cos(a))


def on_odom(pub, odom: Odometry, goal_yaw: Annotated[float, "Unit('rad')"]) -> None:
    q = odom.pose.pose.orientation
    yaw = math.atan2(2.0 * (q.w * q.z), 1.0 - 2.0 * (q.z * q.z))
    yaw_error = normalize(goal_yaw - yaw)
    cmd = Twist()
    cmd.angular.z = max(-0.5, min(0.5, yaw_error))  # warning: RF203
    cmd.angular.z = 0.8 * yaw_error  # warning: RF203
    cmd.angular.z = max(-MAX_TURN, min(MAX_TURN, K_YAW * yaw_error))
    cmd.angular.z = K_YAW * yaw_error
    distance = math.hypot(odom.pose.pose.position.x, odom.pose.pose.position.y)
    cmd.linear.x = distance  # warning: RF203
    cmd.linear.x = K_DIST * distance
    cmd.linear.x = yaw_error  # error: RF201
    cmd.angular.z = odom.twist.twist.linear.x  # error: RF201
    pub.publish(cmd)


def turtlebot3_marker(pub, yaw_diff: Annotated[float, "Unit('rad')"]) -> None:
    twist = Twist()
    twist.angular.z = max(-0.5, min(0.5, yaw_diff))  # warning: RF203
    pub.publish(twist)
