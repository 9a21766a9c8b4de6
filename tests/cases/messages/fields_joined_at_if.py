"""Message fields set on both branches of an `if` keep both values at the join (as
plain variables do), so what holds on both branches is proved after it."""
from typing import Annotated

from geometry_msgs.msg import Twist
from rclpy.node import Node
from sensor_msgs.msg import LaserScan


def limit(w: Annotated[float, "abs(_) <= 2.84"]) -> None: ...


class ObstacleStop(Node):
    cruise: Annotated[float, "Unit('m/s') and _ >= 0"]

    def __init__(self) -> None:
        super().__init__("obstacle_stop")
        self.cruise = 0.2
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_subscription(LaserScan, "scan", self.on_scan, 10)

    def send(self, cmd: Annotated[Twist, "0 <= linear.x <= 0.22"]) -> None:
        self.pub.publish(cmd)

    def on_scan(self, scan: LaserScan) -> None:
        twist = Twist()
        if scan.range_min < 0.5:
            twist.linear.x = 0.0
            twist.angular.z = 0.5
        else:
            twist.linear.x = min(self.cruise, 0.22)
            twist.angular.z = 1.0
        limit(twist.angular.z)
        self.send(twist)

    def on_scan_loose_clamp(self, scan: LaserScan) -> None:
        twist = Twist()
        if scan.range_min < 0.5:
            twist.linear.x = 0.0
        else:
            twist.linear.x = min(self.cruise, 0.23)
        self.send(twist)  # warning: RF102

    def on_scan_one_branch(self, scan: LaserScan) -> None:
        twist = Twist()
        if scan.range_min < 0.5:
            twist.angular.z = 3.0
        limit(twist.angular.z)  # warning: RF102
