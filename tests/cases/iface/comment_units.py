"""Units from interface comments (rosidl's `[unit]`), with no #RobotFix# unit."""
import math
from typing import Annotated

import rclpy
from rclpy.node import Node
from sensor_msgs.msg import LaserScan

from iface.msg import Sonar


class SonarBridge(Node):
    def __init__(self) -> None:
        super().__init__("sonar_bridge")
        self.pub = self.create_publisher(Sonar, "sonar", 10)

    def publish_cm(self, reading_cm: Annotated[float, "Unit('cm')"]) -> None:
        msg = Sonar()
        msg.distance = reading_cm  # error: RF201
        msg.max_distance = 4.0
        self.pub.publish(msg)

    def publish_m(self, reading_cm: Annotated[float, "Unit('cm')"]) -> None:
        msg = Sonar()
        msg.distance = reading_cm / 100  # converted: clean
        msg.cone = 30.0
        msg.kind = Sonar.LONG
        self.pub.publish(msg)

    def cone_in_radians(self, half: Annotated[float, "Unit('rad')"]) -> None:
        msg = Sonar()
        msg.cone = 2 * half  # error: RF201
        msg.cone = math.degrees(2 * half)  # clean
        self.pub.publish(msg)


def on_scan(scan: LaserScan) -> None:
    limit: Annotated[float, "Unit('mm')"] = scan.range_max  # error: RF201
    span: Annotated[float, "Unit('rad')"] = scan.angle_max - scan.angle_min
    step: Annotated[float, "Unit('s')"] = scan.time_increment
