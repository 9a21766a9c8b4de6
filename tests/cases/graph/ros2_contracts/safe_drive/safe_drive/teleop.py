"""Keyboard teleop that clamps its speed (the near miss: it proves the contract)."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node

MAX_SPEED = 0.5


class Teleop(Node):
    def __init__(self) -> None:
        super().__init__('teleop')
        self.pub = self.create_publisher(Twist, 'cmd_vel_safe', 10)
        self.speed = 0.0

    def send(self, speed: float) -> None:
        cmd = Twist()
        cmd.linear.x = max(-MAX_SPEED, min(MAX_SPEED, speed))
        self.pub.publish(cmd)


def main() -> None:
    rclpy.init()
    rclpy.spin(Teleop())
