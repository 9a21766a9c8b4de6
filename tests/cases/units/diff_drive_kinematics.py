"""A diff-drive node: wheel speeds, arcs and turning radii, where the radian cancels
against a length (issue 9, item 4) and degrees or rpm stay mistakes."""
import math
from typing import Annotated

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node

Meters = Annotated[float, "Unit('m') and _ > 0"]

WHEEL_RADIUS: Annotated[float, "Unit('m')"] = 0.033
WHEEL_SEPARATION: Annotated[float, "Unit('m')"] = 0.16
WHEELBASE: Annotated[float, "Unit('m')"] = 0.25


def wheel_speeds(
    v: Annotated[float, "Unit('m/s')"], w: Annotated[float, "Unit('rad/s')"]
) -> Annotated[float, "Unit('rad/s')"]:
    left_rim: Annotated[float, "Unit('m/s')"] = v - w * WHEEL_SEPARATION / 2
    return left_rim / WHEEL_RADIUS


def body_twist(
    left: Annotated[float, "Unit('rad/s')"], right: Annotated[float, "Unit('rad/s')"]
) -> Twist:
    cmd = Twist()
    cmd.linear.x = (left + right) * WHEEL_RADIUS / 2
    cmd.angular.z = (right - left) * WHEEL_RADIUS / WHEEL_SEPARATION
    return cmd


def arc_and_radius(
    theta: Annotated[float, "Unit('rad')"],
    r: Annotated[float, "Unit('m')"],
    v: Annotated[float, "Unit('m/s')"],
    omega: Annotated[float, "Unit('rad/s') and _ > 0"],
) -> None:
    arc: Annotated[float, "Unit('m')"] = theta * r
    radius: Annotated[float, "Unit('m')"] = v / omega
    lateral: Annotated[float, "Unit('m/s^2')"] = v * omega
    steer: Annotated[float, "Unit('rad')"] = math.atan(WHEELBASE / radius)
    ackermann: Annotated[float, "Unit('rad')"] = math.atan(WHEELBASE * omega / v)
    arc = theta  # error: RF201
    turn_rate: Annotated[float, "Unit('rad/s')"] = v / r
    bad_rate: Annotated[float, "Unit('rad/s')"] = v  # error: RF201


def from_encoders(
    rpm: Annotated[float, "Unit('rpm')"],
    deg_s: Annotated[float, "Unit('degree/s')"],
    hz: Annotated[float, "Unit('Hz')"],
) -> None:
    cmd = Twist()
    cmd.angular.z = rpm  # error: RF201
    cmd.angular.z = rpm * 2 * math.pi / 60
    cmd.angular.z = deg_s  # error: RF201
    cmd.angular.z = math.radians(deg_s)
    cmd.linear.x = deg_s * WHEEL_RADIUS  # error: RF201
    cmd.linear.x = math.radians(deg_s) * WHEEL_RADIUS
    cmd.angular.z = hz  # error: RF201
    cmd.angular.z = 2 * math.pi * hz
    cmd.linear.x = 0.5 * cmd.angular.z  # error: RF201
    cmd.linear.x = 0.5 * cmd.angular.z * WHEEL_RADIUS


class DiffDrive(Node):
    def __init__(self) -> None:
        super().__init__("diff_drive")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)

    def drive(self, w: Annotated[float, "Unit('rad/s')"]) -> None:
        self.pub.publish(body_twist(w, w))


def main() -> None:
    rclpy.init()
    rclpy.spin(DiffDrive())
