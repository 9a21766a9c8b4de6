"""Patrols a square, one lap (the near miss: the mode is a literal 1)."""
import rclpy
from patrol_interfaces.action import Patrol
from rclpy.action import ActionClient
from rclpy.node import Node


class SquarePatrol(Node):
    def __init__(self):
        super().__init__('square_patrol')
        self._action_client = ActionClient(self, Patrol, 'turtlebot3')

    def send_goal(self, side: float):
        goal_msg = Patrol.Goal()
        goal_msg.goal.x = 1.0
        goal_msg.goal.y = side
        goal_msg.goal.z = 1.0
        return self._action_client.send_goal_async(goal_msg)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(SquarePatrol())
