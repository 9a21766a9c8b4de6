"""Drive forward at cruise speed; stop when the laser sees an obstacle too close."""

from typing import Annotated

import rclpy
from rclpy.node import Node
from sensor_msgs.msg import LaserScan

from safety_stop.msg import DriveCommand

CRUISE_SPEED: Annotated[float, "Unit('km/h') and 0 < _ <= 5"] = 4.0
STOP_DISTANCE: Annotated[float, "Unit('m') and _ > 0"] = 0.5


class SafetyStop(Node):
    def __init__(self) -> None:
        super().__init__("safety_stop")
        self.pub = self.create_publisher(DriveCommand, "drive", 10)
        self.create_subscription(LaserScan, "scan", self.on_scan, 10)

    def on_scan(self, scan: LaserScan) -> None:
        command = DriveCommand()
        if scan.range_min < STOP_DISTANCE:
            command.speed = 0.0
        else:
            command.speed = CRUISE_SPEED  # km/h where the controller expects m/s
        command.turn_rate = 0.0
        self.pub.publish(command)


def main() -> None:
    rclpy.init()
    rclpy.spin(SafetyStop())


if __name__ == "__main__":
    main()
