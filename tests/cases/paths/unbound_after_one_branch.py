"""RF301: a name bound in one branch of an `if` (no `else`) and read after it raises
UnboundLocalError on the other path. Names bound on every path, or read only where
the same test holds again, are fine."""
import math
import sys

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from sensor_msgs.msg import LaserScan

if sys.platform == "win32":
    import msvcrt
else:
    import termios

try:
    input = raw_input  # noqa: F821  (Python 2 compatibility)
except NameError:
    pass

RATE = 10.0


class Follower(Node):
    def __init__(self) -> None:
        super().__init__("follower")
        self.verbose = self.declare_parameter("verbose", False).value
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_subscription(LaserScan, "scan", self.on_scan, 10)

    def on_scan(self, scan: LaserScan) -> None:
        nearest = min(scan.ranges)
        if nearest < 1.0:
            turn = 0.5
        cmd = Twist()
        cmd.angular.z = turn  # error: RF301
        self.pub.publish(cmd)

    def on_scan_elif(self, scan: LaserScan) -> None:
        if scan.range_min > 0.5:
            speed = 0.2
        elif scan.range_min > 0.2:
            speed = 0.1
        cmd = Twist()
        cmd.linear.x = speed  # error: RF301
        self.pub.publish(cmd)

    def on_scan_else(self, scan: LaserScan) -> None:
        if scan.range_min > 0.5:
            speed = 0.2
        else:
            speed = 0.0
        cmd = Twist()
        cmd.linear.x = speed
        self.pub.publish(cmd)

    def on_scan_flag(self, scan: LaserScan) -> None:
        found = False
        if scan.range_min < 0.5:
            angle = scan.angle_min
            found = True
        if found:
            self.get_logger().info(f"obstacle at {math.degrees(angle)}")

    def on_scan_same_test(self, scan: LaserScan) -> None:
        if self.verbose:
            started = self.get_clock().now()
        self.pub.publish(Twist())
        if self.verbose:
            self.get_logger().info(f"took {self.get_clock().now() - started}")

    def on_scan_is_none(self, scan: LaserScan, last) -> None:
        if last is not None:
            dt = scan.scan_time - last.scan_time
        if last is not None:
            self.get_logger().info(f"dt {dt}")

    def on_value(self, value) -> None:
        if isinstance(value, float):
            scaled = value * 2.0
        if isinstance(value, float):
            self.get_logger().info(f"{scaled}")
        if isinstance(value, int):
            self.get_logger().info(f"{scaled}")  # error: RF301

    def on_scan_deleted(self, scan: LaserScan) -> None:
        ranges = list(scan.ranges)
        del ranges
        self.get_logger().info(f"{len(scan.ranges)}")

    def on_scan_global(self, scan: LaserScan) -> None:
        global RATE
        if scan.range_min < 0.1:
            RATE = 20.0
        self.create_timer(1.0 / RATE, self.tick)

    def tick(self) -> None:
        if (count := self.count_subscribers("cmd_vel")) > 0:
            self.get_logger().info(f"{count} listeners")
        self.get_logger().info(f"{count} listeners")


def main() -> None:
    rclpy.init()
    node = Follower()
    rclpy.spin(node)


def collect(scan: LaserScan) -> None:
    close = []
    close.append(scan.range_min)
    if close:
        nearest = close[0]
    rclpy.logging.get_logger("collect").info(f"{nearest}")
    hits = []
    if scan.range_min < 0.5:
        hits = [scan.range_min]
        first = scan.range_min
    if hits:
        rclpy.logging.get_logger("collect").info(f"{first}")
