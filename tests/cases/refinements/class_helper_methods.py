"""A helper class's static and class methods, called through the class
(`Path.turn(...)`, as turtlebot3_relative_move does), and a method of an instance
that is not a name (`Path().turn(...)`): their refined parameters are checked at
the call, as a function's are (they were not looked up)."""
import math
from typing import Annotated

from geometry_msgs.msg import Twist
from rclpy.node import Node


class Path:
    MAX_TURN = 2.84

    @staticmethod
    def turn(
        angle: Annotated[float, "Unit('rad')"],
        angular_velocity: Annotated[float, "Unit('rad/s') and 0 < _ <= 2.84"],
        step: int,
    ) -> tuple[Twist, int]:
        twist = Twist()
        if abs(angle) > 0.01:
            twist.angular.z = angular_velocity if angle > 0 else -angular_velocity
        else:
            step += 1
        return twist, step

    @classmethod
    def straight(
        cls, linear_velocity: Annotated[float, "Unit('m/s') and 0 < _ <= 0.22"]
    ) -> Twist:
        twist = Twist()
        twist.linear.x = linear_velocity
        return twist

    def stop(self, decel: Annotated[float, "Unit('m/s^2') and 0 < _ <= 1.0"]) -> Twist:
        return Twist()


class Mover(Node):
    def __init__(self):
        super().__init__("mover")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.step = 1
        self.heading = 0.0

    def tick(self, goal: float) -> None:
        angle = goal - self.heading
        twist, self.step = Path.turn(angle, 3.0, self.step)  # error: RF101
        twist, self.step = Path.turn(math.degrees(angle), 0.3, self.step)  # error: RF201
        twist, self.step = Path.turn(angle, 0.3, self.step)
        twist, self.step = Path.turn(angle, Path.MAX_TURN, self.step)
        self.pub.publish(Path.straight(0.25))  # error: RF101
        self.pub.publish(Path.straight(0.22))
        self.pub.publish(Path().stop(1.5))  # error: RF101
        self.pub.publish(Path().stop(0.5))
        self.pub.publish(twist)
