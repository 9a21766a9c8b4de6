"""A slider in degrees that converts before it sends (the near miss)."""
import math
from typing import Annotated

import rclpy
from rclpy.node import Node
from std_msgs.msg import Float64


class Slider(Node):
    def __init__(self) -> None:
        super().__init__('slider')
        self.pub = self.create_publisher(Float64, 'joint1/command', 10)

    def send(self, position: Annotated[float, "Unit('degree')"]) -> None:
        cmd = Float64()
        cmd.data = math.radians(position)
        self.pub.publish(cmd)


def main() -> None:
    rclpy.init()
    rclpy.spin(Slider())
