"""Messages, requests and goals kept on `self` keep their type, units and
refinements in every method: their fields are unknown but refined there."""
from typing import Annotated

import rclpy
from geometry_msgs.msg import Twist
from rclpy.action import ActionClient
from rclpy.node import Node

from robot_pkg.action import BackUp
from robot_pkg.msg import BackUpGoal
from robot_pkg.srv import AddTwoInts


class Driver(Node):
    twist: Twist

    def __init__(self) -> None:
        super().__init__("driver")
        self.twist = Twist()
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_timer(0.1, self.on_timer)

    def on_timer(self) -> None:
        self.twist.linear.x = "fast"  # error: RF401
        w: Annotated[float, "Unit('m/s')"] = self.twist.angular.z  # error: RF201
        v: Annotated[float, "Unit('m/s')"] = self.twist.linear.x
        self.twist.linear.x = 0.2
        self.pub.publish(self.twist)


class AdderClient(Node):
    def __init__(self) -> None:
        super().__init__("adder_client")
        self.cli = self.create_client(AddTwoInts, "add_two_ints")
        self.req = AddTwoInts.Request()

    def send_request(self, a: int) -> None:
        self.req.a = a  # warning: RF102
        self.req.b = 5000000  # error: RF101
        self.future = self.cli.call_async(self.req)

    def send_small(self) -> None:
        self.req.a = 41
        self.req.b = 1
        self.future = self.cli.call_async(self.req)


class Recovery(Node):
    def __init__(self) -> None:
        super().__init__("recovery")
        self.client = ActionClient(self, BackUp, "backup")
        self.goal_msg = BackUp.Goal()
        self.ros1_goal = BackUpGoal()

    def back_up(self, distance: float) -> None:
        self.goal_msg.speed = 0.8  # error: RF101
        self.goal_msg.speed = 0.25
        self.ros1_goal.target.x = -1.0  # error: RF101
        self.client.send_goal_async(self.goal_msg)


class Inherited(Driver):
    def stop(self) -> None:
        self.twist.angular.z = "zero"  # error: RF401


def main() -> None:
    rclpy.init()
    rclpy.spin(Driver())
