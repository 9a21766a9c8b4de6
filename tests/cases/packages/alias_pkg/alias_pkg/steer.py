"""A node that uses geometry.py's aliases without importing `math` itself."""
from typing import Annotated

import rclpy
from rclpy.node import Node

from alias_pkg.geometry import Accel, Heading, Limits


def steer(heading: Heading, accel: Accel) -> None:
    print(heading, accel)


class Steer(Node):
    def __init__(self) -> None:
        super().__init__("steer")
        self.timer = self.create_timer(0.1, self.tick)

    def tick(self) -> None:
        steer(3.0, 0.5)
        steer(3.5, 0.0)  # error: RF101
        steer(0.0, 0.6)  # error: RF101
        rate: Annotated[float, "_ == 10"] = Limits.RATE
        period: Annotated[float, "_ == 0.2"] = 1 / Limits.RATE  # error: RF101
        print(rate, period)


def main() -> None:
    rclpy.init()
    rclpy.spin(Steer())
