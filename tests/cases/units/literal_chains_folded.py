"""A chain of literal factors is folded before the units are compared (issue 22,
section 3): `avg_rpm * 2.0 * math.pi / 60.0` is rad/s even when `avg_rpm` is an
average (`(l + r) / 2`, a plain factor kept apart); a plain gain on an angle leaves it
in its unit (`-math.degrees(fov) / 2.` is in degrees: remove `math.degrees`)."""
import math
from typing import Annotated

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from sensor_msgs.msg import LaserScan

WHEEL_RADIUS: Annotated[float, "Unit('m')"] = 0.033
WHEEL_SEPARATION: Annotated[float, "Unit('m')"] = 0.16
SCAN_FOV: Annotated[float, "Unit('rad')"] = 4.71


class WheelOdometry(Node):
    def __init__(self) -> None:
        super().__init__("wheel_odometry")
        self.pub = self.create_publisher(Twist, "wheel_twist", 10)
        self.scan_pub = self.create_publisher(LaserScan, "fake_scan", 10)

    def on_encoders(
        self,
        left_rpm: Annotated[float, "Unit('rpm')"],
        right_rpm: Annotated[float, "Unit('rpm')"],
    ) -> None:
        avg_rpm = (left_rpm + right_rpm) / 2
        msg = Twist()
        msg.linear.x = avg_rpm * 2.0 * math.pi / 60.0 * WHEEL_RADIUS
        msg.linear.x = avg_rpm * (2.0 * math.pi / 60.0) * WHEEL_RADIUS
        msg.linear.x = avg_rpm * WHEEL_RADIUS  # error: RF201
        msg.angular.z = (right_rpm - left_rpm) * math.pi / 30.0 * WHEEL_RADIUS / WHEEL_SEPARATION
        wheel: Annotated[float, "Unit('rad/s')"] = avg_rpm * 2.0 * math.pi / 60.0
        wheel = avg_rpm / 2  # error: RF201
        self.pub.publish(msg)

    def fake_scan(self) -> None:
        scan = LaserScan()
        scan.angle_min = -SCAN_FOV / 2.0
        scan.angle_max = SCAN_FOV / 2.0
        scan.angle_min = -math.degrees(SCAN_FOV) / 2.  # error: RF201 "remove `math.degrees()`"
        self.scan_pub.publish(scan)


def main() -> None:
    rclpy.init()
    rclpy.spin(WheelOdometry())
