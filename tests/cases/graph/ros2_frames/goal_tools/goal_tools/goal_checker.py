"""Checks goals against the static map before they reach the planner: it reads
their coordinates as map cells, so it assumes every goal is in the `map` frame."""
from typing import Annotated

import rclpy
from geometry_msgs.msg import PoseStamped
from rclpy.node import Node


class GoalChecker(Node):
    def __init__(self):
        super().__init__('goal_checker')
        self.create_subscription(PoseStamped, 'goal_pose', self.on_goal, 10)
        self.resolution = 0.05

    def on_goal(self, msg: Annotated[PoseStamped, "Frame('map')"]):
        cell = int(msg.pose.position.x / self.resolution)
        self.get_logger().info(f'goal in cell {cell}')


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(GoalChecker())
