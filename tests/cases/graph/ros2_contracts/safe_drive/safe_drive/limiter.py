"""Forwards velocity commands to the base; assumes they are already slow."""
from typing import Annotated

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Limiter(Node):
    def __init__(self) -> None:
        super().__init__('limiter')
        self.create_subscription(Twist, 'cmd_vel_safe', self.on_cmd, 10)
        self.out = self.create_publisher(Twist, 'cmd_vel', 10)  # note: RF607

    def on_cmd(self, msg: Annotated[Twist, "abs(linear.x) <= 0.5"]) -> None:
        self.out.publish(msg)


def main() -> None:
    rclpy.init()
    rclpy.spin(Limiter())
