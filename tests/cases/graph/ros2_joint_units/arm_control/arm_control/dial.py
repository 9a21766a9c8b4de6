"""A dial that reads the angle in rad and sends it in degrees: the bug."""
import math
from typing import Annotated

import rclpy
from rclpy.node import Node
from std_msgs.msg import Float64


class Dial(Node):
    def __init__(self) -> None:
        super().__init__('dial')
        self.pub = self.create_publisher(Float64, 'joint1/command', 10)

    def send(self, angle: Annotated[float, "Unit('rad')"]) -> None:
        cmd = Float64()
        cmd.data = math.degrees(angle)
        self.pub.publish(cmd)  # error: RF201


def main() -> None:
    rclpy.init()
    rclpy.spin(Dial())
