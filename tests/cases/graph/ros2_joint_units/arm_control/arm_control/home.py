"""Sends the joint home: a plain number has no unit to contradict (the near miss)."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import Float64


class Home(Node):
    def __init__(self) -> None:
        super().__init__('home')
        self.pub = self.create_publisher(Float64, 'joint1/command', 10)
        self.create_timer(1.0, self.step)

    def step(self) -> None:
        self.pub.publish(Float64(data=0.5))


def main() -> None:
    rclpy.init()
    rclpy.spin(Home())
