"""Drives a fixed pattern, faster than the limiter assumes."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Planner(Node):
    def __init__(self) -> None:
        super().__init__('planner')
        self.cmd_pub = self.create_publisher(Twist, 'cmd_vel_safe', 10)
        self.create_timer(0.1, self.step)

    def step(self) -> None:
        cmd = Twist()
        cmd.linear.x = 0.8
        self.cmd_pub.publish(cmd)  # error: RF101


def main() -> None:
    rclpy.init()
    rclpy.spin(Planner())
