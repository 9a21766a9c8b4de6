"""An odometry integrator: a literal time step is an implicit unit change (RF203); a
named time step is clean; a rate with no step at all is a mismatch. Inferred units
survive a default literal and an accumulating loop."""
import math
from typing import Annotated

from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan

DT: Annotated[float, "Unit('s')"] = 0.1


def integrate(
    x: Annotated[float, "Unit('m')"],
    theta: Annotated[float, "Unit('rad')"],
    vx: Annotated[float, "Unit('m/s')"],
    wz: Annotated[float, "Unit('rad/s')"],
) -> None:
    x += vx * math.cos(theta) * DT
    theta += wz * DT
    x += vx * 0.1  # warning: RF203
    theta = theta + wz * 0.05  # warning: RF203
    x = x + vx  # error: RF202
    x += wz * 0.1  # error: RF202


def stamp(odom: Odometry) -> None:
    odom.pose.pose.position.x = odom.twist.twist.linear.x * DT
    odom.pose.pose.position.x = odom.twist.twist.linear.x * 0.1  # warning: RF203
    odom.pose.pose.position.x = odom.twist.twist.linear.x  # error: RF201


def nearest(scan: LaserScan, use_min: bool) -> Twist:
    t = Twist()
    d = 0.0
    if use_min:
        d = scan.range_min
    t.angular.z = d  # error: RF201
    total = 0.0
    for _ in scan.ranges:
        total += scan.range_min
    t.angular.y = total  # error: RF201
    count = 0
    for _ in scan.ranges:
        count = count + 1
    t.angular.x = count
    return t
