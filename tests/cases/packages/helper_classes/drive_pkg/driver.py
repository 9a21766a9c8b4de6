"""Calls into another module's helper class: through the class (a staticmethod, a
classmethod) and on an instance that is not a name."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node

from drive_pkg import path
from drive_pkg.path import Path


class Driver(Node):
    def __init__(self):
        super().__init__("driver")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.timer = self.create_timer(0.1, self.tick)

    def tick(self) -> None:
        self.pub.publish(Path.turn(3.0))  # error: RF101
        self.pub.publish(Path.turn(2.84))
        self.pub.publish(path.Path.turn(-0.1))  # error: RF101
        self.pub.publish(Path.forward(0.3))  # error: RF101
        self.pub.publish(Path.forward(0.26))
        Path().brake(2.5)  # error: RF101
        Path().brake(2.0)


def main():
    rclpy.init()
    rclpy.spin(Driver())
