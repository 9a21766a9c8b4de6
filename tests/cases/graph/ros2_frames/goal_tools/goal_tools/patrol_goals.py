"""Sends patrol goals in the frame its `frame_id` parameter names: the default
is `odom`, which the launch file changes to `map` (a warning, not an error: the
analysis does not read the launch file's value)."""
import rclpy
from geometry_msgs.msg import PoseStamped
from rclpy.node import Node


class PatrolGoals(Node):
    def __init__(self):
        super().__init__('patrol_goals')
        self.goal_frame = self.declare_parameter('frame_id', 'odom').value
        self.goal_pub = self.create_publisher(PoseStamped, 'goal_pose', 10)

    def send(self, x: float, y: float):
        goal = PoseStamped()
        goal.header.frame_id = self.goal_frame
        goal.pose.position.x = x
        goal.pose.position.y = y
        self.goal_pub.publish(goal)  # warning: RF201


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(PatrolGoals())
