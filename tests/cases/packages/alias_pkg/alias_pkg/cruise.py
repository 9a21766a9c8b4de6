"""A node whose callbacks take the package's aliases: the aliases' names are the
constants of the module that defines them (limits.py), not of this one."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node

from alias_pkg.types import Cruise, TurnRate

MAX_SPEED = 3.0  # this node's own constant of the same name: not the alias's


def command(speed: Cruise, turn: TurnRate) -> Twist:
    msg = Twist()
    msg.linear.x = speed
    msg.angular.z = turn
    return msg


class CruiseNode(Node):
    def __init__(self) -> None:
        super().__init__("cruise")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.timer = self.create_timer(0.1, self.tick)

    def tick(self) -> None:
        self.pub.publish(command(0.5, -1.2))  # the limits themselves: fine
        self.pub.publish(command(0.6, 0.0))  # error: RF101
        self.pub.publish(command(0.2, 1.3))  # error: RF101
        fast: Cruise = 0.45
        self.pub.publish(command(fast, 0.0))


def main() -> None:
    rclpy.init()
    rclpy.spin(CruiseNode())
