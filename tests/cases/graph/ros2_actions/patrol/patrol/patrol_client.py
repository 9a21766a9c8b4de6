"""turtlebot3_example's patrol client: the mode comes from the keyboard, and a
wrong key leaves it as typed (nothing proves it is 1 or 2)."""
import rclpy
from patrol_interfaces.action import Patrol
from rclpy.action import ActionClient
from rclpy.node import Node


class PatrolClient(Node):
    def __init__(self):
        super().__init__('patrol_client')
        self._action_client = ActionClient(self, Patrol, 'turtlebot3')
        self.mode, self.travel_distance, self.patrol_count = self.get_key()

    def get_key(self):
        mode = str(input('mode(s: square, t: triangle): '))
        travel_distance = float(input('travel_distance: '))
        patrol_count = int(input('patrol_count: '))
        if mode == 's':
            mode = 1
        elif mode == 't':
            mode = 2
        else:
            self.get_logger().info('you selected wrong mode')
        return mode, travel_distance, patrol_count

    def send_goal(self):
        goal_msg = Patrol.Goal()
        goal_msg.goal.x = float(self.mode)
        goal_msg.goal.y = float(self.travel_distance)
        goal_msg.goal.z = float(self.patrol_count)
        self._action_client.wait_for_server()
        self._send_goal_future = self._action_client.send_goal_async(goal_msg)  # warning: RF102


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(PatrolClient())
