"""turtlebot3_example's patrol server: its goal callback accepts every goal, and
the execute callback loops until the mode is a square (1) or a triangle (2), so
it assumes every goal names one of them."""
from typing import Annotated

import rclpy
from geometry_msgs.msg import Twist
from patrol_interfaces.action import Patrol
from rclpy.action import ActionServer, GoalResponse
from rclpy.node import Node


class PatrolServer(Node):
    def __init__(self):
        super().__init__('patrol_server')
        self._action_server = ActionServer(
            self,
            Patrol,
            'turtlebot3',
            self.execute_callback,
            goal_callback=self.goal_callback)
        self.goal_msg = Patrol.Goal()
        self.cmd_vel_pub = self.create_publisher(Twist, 'cmd_vel', 10)  # note: RF607

    def goal_callback(self, goal_request: Annotated[Patrol.Goal, "goal.x == 1 or goal.x == 2"]):
        self.goal_msg = goal_request
        return GoalResponse.ACCEPT

    def execute_callback(self, goal_handle):
        result = Patrol.Result()
        result.result = 'square' if self.goal_msg.goal.x == 1 else 'triangle'
        goal_handle.succeed()
        return result


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(PatrolServer())
