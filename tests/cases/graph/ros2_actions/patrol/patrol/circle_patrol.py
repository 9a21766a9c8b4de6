"""Asks for a circle, a mode the server does not have: it would loop forever."""
import rclpy
from patrol_interfaces.action import Patrol
from rclpy.action import ActionClient
from rclpy.node import Node

CIRCLE = 3.0


class CirclePatrol(Node):
    def __init__(self):
        super().__init__('circle_patrol')
        self._action_client = ActionClient(self, Patrol, 'turtlebot3')

    def send_goal(self, radius: float):
        goal_msg = Patrol.Goal()
        goal_msg.goal.x = CIRCLE
        goal_msg.goal.y = radius
        self._action_client.send_goal_async(goal_msg)  # error: RF101


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(CirclePatrol())
