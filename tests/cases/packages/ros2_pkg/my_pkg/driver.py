"""A ROS 2 driver node whose limits, conversions and helpers live in other modules."""
import math
from typing import Annotated

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node

import my_pkg.util as tu
from my_pkg import limits
from my_pkg.units import MetersPerSec, Radians, Seconds

from .limits import MAX_SPEED, MAX_TURN
from .util import Limiter, clamp_speed, normalize, ramp


class Driver(Node):
    def __init__(self) -> None:
        super().__init__("driver")
        self.declare_parameter("speed", 0.1)
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.timer = self.create_timer(0.1, self.on_timer)
        self.limiter = Limiter(0.5)
        self.heading: Radians = 0.0

    def on_timer(self) -> None:
        msg = Twist()
        msg.linear.x = clamp_speed(0.1)
        msg.linear.x = clamp_speed(0.5)  # error: RF101
        msg.linear.x = tu.clamp_speed(MAX_SPEED)
        msg.linear.x = tu.clamp_speed(MAX_SPEED + 0.1)  # error: RF101
        msg.angular.z = MAX_TURN
        self.heading = normalize(math.radians(90.0))
        self.heading = normalize(math.degrees(self.heading))  # error: RF201
        wrapped = normalize(self.heading)
        small: Annotated[float, "_ <= 4"] = wrapped
        large: Annotated[float, "_ <= 3"] = wrapped  # warning: RF102
        self.pub.publish(msg)

    def speeds(self) -> None:
        cruise: MetersPerSec = limits.MAX_SPEED
        turn: Radians = limits.MAX_SPEED  # error: RF201
        period: Seconds = 0.0  # error: RF101
        period_ok: Seconds = 0.5
        ramp(3, 10)
        ramp(10, 10)  # error: RF101

    def limiter(self) -> None:
        limiter = Limiter(0.3)
        limiter.limit = 0.8
        limiter.limit = 1.5  # error: RF101
        bad = Limiter(-1.0)  # error: RF101
        limiter.apply(0.2)
        distance: Annotated[float, "Unit('m')"] = limiter.apply(0.2)  # error: RF201
        rate: Annotated[float, "_ == 10"] = Limiter.RATE


def main() -> None:
    rclpy.init()
    rclpy.spin(Driver())
