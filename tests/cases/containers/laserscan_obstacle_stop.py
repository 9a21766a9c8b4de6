"""An rclpy obstacle stop: a LaserScan callback filters the ranges it trusts, keeps
the front sector, and slows down for the closest obstacle (issue 8, item 5)."""
from typing import Annotated

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from sensor_msgs.msg import LaserScan

MAX_SPEED = 0.22
STOP_DISTANCE = 0.35
K_P: Annotated[float, "Unit('1/s')"] = 0.5


class ObstacleStop(Node):
    front: Annotated[list[float], "Unit('m') and _ >= 0"]
    history: Annotated[list[float], "Unit('m') and 0 <= _ <= 12 and len(_) <= 50"]

    def __init__(self) -> None:
        super().__init__("obstacle_stop")
        self.front = []
        self.history = []
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_subscription(LaserScan, "scan", self.on_scan, 10)

    def on_scan(self, scan: LaserScan) -> None:
        self.front = list(scan.ranges[:30])
        usable = [r for r in scan.ranges if scan.range_min <= r <= scan.range_max]
        if not usable:
            return
        nearest: Annotated[float, "Unit('m') and 0 < _ <= 12"] = min(usable)
        anywhere: Annotated[float, "Unit('m') and _ <= 12"] = min(scan.ranges)  # warning: RF102
        ahead: Annotated[float, "Unit('m') and _ >= 0"] = scan.ranges[len(scan.ranges) // 2]
        heading: Annotated[float, "Unit('rad')"] = max(scan.ranges)  # error: RF201
        self.front.append(-1.0)  # error: RF101
        self.front.append(nearest)
        if len(self.history) < 50:
            self.history.append(nearest)
        self.history.append(ahead)  # warning: RF102 "self.history[-1] <= 12"
        twist = Twist()
        if nearest < STOP_DISTANCE:
            twist.linear.x = 0.0
        else:
            twist.linear.x = min(MAX_SPEED, K_P * (nearest - STOP_DISTANCE))
        twist.angular.z = min(self.front)  # error: RF201
        self.pub.publish(twist)

    def average_front(self) -> Annotated[float, "Unit('m') and _ >= 0"]:
        if not self.front:
            return 0.0
        return sum(self.front) / len(self.front)


def main() -> None:
    rclpy.init()
    rclpy.spin(ObstacleStop())
