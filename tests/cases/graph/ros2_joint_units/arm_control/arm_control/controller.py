"""A joint position controller: the command's `data` is the joint angle in rad
(as ros2_control's forward_command_controller and turtlebot3_manipulation take it;
std_msgs/Float64 itself gives no unit)."""
import math
from typing import Annotated

import rclpy
from rclpy.node import Node
from std_msgs.msg import Float64


class Controller(Node):
    def __init__(self) -> None:
        super().__init__('controller')
        self.create_subscription(Float64, 'joint1/command', self.on_cmd, 10)
        self.target = 0.0

    def on_cmd(self, msg: Annotated[Float64, "Unit(data) == 'rad'"]) -> None:
        self.target = msg.data
        self.get_logger().info(f'joint1 to {math.degrees(msg.data):.1f} degrees')


def main() -> None:
    rclpy.init()
    rclpy.spin(Controller())
