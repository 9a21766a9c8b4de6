"""A class-based rclpy node: LaserScan in, Twist out, stop before obstacles."""
from typing import Annotated

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from sensor_msgs.msg import LaserScan


class SafetyStop(Node):
    cruise: Annotated[float, "Unit('m/s') and 0 < _ <= 0.5"]
    stop_distance: Annotated[float, "Unit('m') and _ > 0"]
    rate_hz: Annotated[float, "Unit('Hz') and _ > 0"]

    def __init__(self) -> None:
        super().__init__("safety_stop")
        self.cruise = 0.4
        self.stop_distance = 0.5
        self.rate_hz = 10.0
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_subscription(LaserScan, "scan", self.on_scan, 10)
        self.create_timer(self.rate_hz, self.tick)  # error: RF201
        self.create_timer(1.0 / self.rate_hz, self.tick)

    def on_scan(self, scan) -> None:
        nearest = min(scan.ranges)
        cmd = Twist()
        if nearest < self.stop_distance:
            cmd.linear.x = 0.0
        else:
            cmd.linear.x = self.cruise
        cmd.angular.z = nearest  # error: RF201
        self.pub.publish(cmd)

    def tick(self) -> None:
        self.cruise = 0.6  # error: RF101


def main() -> None:
    rclpy.init()
    rclpy.spin(SafetyStop())
