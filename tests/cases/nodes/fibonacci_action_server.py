"""A ROS 2 action server: the goal arrives refined, the result leaves checked."""
from typing import Annotated

from rclpy.action import ActionServer
from rclpy.node import Node

from example_pkg.action import Fibonacci


class FibonacciServer(Node):
    def __init__(self) -> None:
        super().__init__("fibonacci")
        self.server = ActionServer(self, Fibonacci, "fibonacci", self.execute)

    def execute(self, goal_handle):
        order = goal_handle.request.order
        steps: Annotated[int, "_ > 0"] = order
        small: Annotated[int, "_ <= 20"] = order  # warning: RF102
        feedback = Fibonacci.Feedback()
        goal_handle.publish_feedback(feedback)
        result = Fibonacci.Result()
        result.count = order
        goal_handle.succeed()
        return result

    def bad_result(self):
        result = Fibonacci.Result()
        result.count = -1  # error: RF101
        return result
