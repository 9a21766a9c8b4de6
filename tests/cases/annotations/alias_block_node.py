"""A node that keeps its units in an alias block at the top, as a shared units.py
would (within one file: imports across modules come with whole-package analysis)."""
from typing import Annotated, Final, TypeAlias

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node

# -- units ------------------------------------------------------------------
MetersPerSec = Annotated[float, "Unit('m/s') and 0 <= _ <= 1"]
RadPerSec: TypeAlias = Annotated[float, "Unit('rad/s')"]
Degrees = Annotated[float, "Unit('degree')"]
Meters = Annotated[float, "Unit('m')"]
SlowSpeed = Annotated[MetersPerSec, "_ <= 0.3"]  # an alias refining an alias
NONNEGATIVE = "_ >= 0"

MAX_SPEED: Final[MetersPerSec] = 0.8
TOO_FAST: MetersPerSec = 1.5  # error: RF101
HEADING: Degrees = 90.0


def turn_rate(deg_per_s: float) -> RadPerSec:
    return deg_per_s * 3.141592653589793 / 180.0


def clamp(v: MetersPerSec) -> MetersPerSec:
    return v


def bad_clamp(v: float) -> MetersPerSec:
    if v > 2.0:
        return v  # error: RF101
    return 0.0


class Driver(Node):
    def __init__(self) -> None:
        super().__init__("driver")
        self.speed: MetersPerSec = 0.5
        self.creep: SlowSpeed = 0.2
        self.range_m: Annotated[Meters, NONNEGATIVE] = 0.0
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)

    def go(self) -> None:
        msg = Twist()
        msg.linear.x = clamp(self.speed)
        msg.angular.z = turn_rate(10.0)
        self.speed = 1.2  # error: RF101
        self.creep = 0.5  # error: RF101
        self.range_m = -1.0  # error: RF101
        clamp(3.0)  # error: RF101
        msg.angular.z = HEADING  # error: RF201
        distance: Meters = self.speed  # error: RF201
        self.pub.publish(msg)


def main() -> None:
    rclpy.init()
    rclpy.spin(Driver())
