"""An rclpy bridge for an ultrasonic ring whose driver reports centimetres: each
sweep is republished as a LaserScan in metres (issue 8, item 5: literal factors on
the elements of a list)."""
from typing import Annotated

import rclpy
from rclpy.node import Node
from sensor_msgs.msg import LaserScan

Centimetres = Annotated[list[float], "Unit('cm') and _ >= 0"]


class RingBridge(Node):
    def __init__(self) -> None:
        super().__init__("ring_bridge")
        self.declare_parameter("rate", 10.0)
        self.pub = self.create_publisher(LaserScan, "scan", 10)
        self.raw: Centimetres = []
        self.create_timer(0.1, self.on_timer)

    def on_timer(self) -> None:
        scan = LaserScan()
        scan.range_min = 0.02
        scan.range_max = 4.0
        scan.ranges = [r / 100 for r in self.raw]
        self.pub.publish(scan)

    def forgot_the_factor(self) -> None:
        scan = LaserScan()
        scan.range_min = 0.02
        scan.ranges = [r for r in self.raw]  # error: RF201
        self.pub.publish(scan)

    def wrong_way(self) -> None:
        scan = LaserScan()
        scan.range_min = 0.02
        scan.ranges = [r * 100 for r in self.raw]  # error: RF201
        scan.range_max = self.raw[0] * 100  # error: RF201
        self.pub.publish(scan)

    def back_to_cm(self, scan: LaserScan) -> None:
        self.raw = [r * 100 for r in scan.ranges]
        self.raw = [r / 100 for r in scan.ranges]  # error: RF201
        nearest_mm: Annotated[list[int], "Unit('mm')"] = [round(r * 1000) for r in scan.ranges]
        self.raw.append(scan.ranges[0] * 100)


def main() -> None:
    rclpy.init()
    rclpy.spin(RingBridge())
