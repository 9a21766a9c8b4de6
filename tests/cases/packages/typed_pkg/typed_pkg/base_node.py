"""The node: what the hardware module's classes and helpers are is known here
too, so their refined methods are checked through `self.chassis.left`, a
helper's result, and a parameter of the imported class."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node

from typed_pkg.hardware import Chassis, WheelController, open_controller, stop_command


def protect(controller: WheelController) -> None:
    controller.limit_current(5.0)
    controller.limit_current(10.0)  # error: RF101


class Base(Node):
    def __init__(self) -> None:
        super().__init__("base")
        self.chassis = Chassis()
        self.spare = open_controller(0x82)
        self.pub = self.create_publisher(Twist, "cmd_vel_out", 10)
        self.create_subscription(Twist, "cmd_vel", self.on_cmd_vel, 10)

    def on_cmd_vel(self, msg: Twist) -> None:
        self.chassis.left.drive_rpm(msg.angular.z)  # error: RF201
        self.chassis.right.drive_rpm(msg.angular.z * 60.0 / (2 * math.pi))
        self.chassis.wheel("left").limit_current(8.0)  # error: RF101
        self.spare.limit_current(0.0)  # error: RF101
        self.spare.limit_current(2.5)
        out = stop_command()
        out.angular.z = msg.linear.x  # error: RF201
        out.angular.z = msg.angular.z
        self.pub.publish(out)


def main() -> None:
    rclpy.init()
    rclpy.spin(Base())
