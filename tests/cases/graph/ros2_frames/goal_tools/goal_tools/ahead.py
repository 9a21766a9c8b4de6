"""Sends a goal one metre ahead of where odometry says the robot is: a goal in
the `odom` frame, which the goal checker reads as map coordinates."""
import rclpy
from geometry_msgs.msg import PoseStamped
from rclpy.node import Node


class Ahead(Node):
    def __init__(self):
        super().__init__('ahead')
        self.goal_pub = self.create_publisher(PoseStamped, 'goal_pose', 10)

    def send(self, x: float, y: float):
        goal = PoseStamped()
        goal.header.frame_id = 'odom'
        goal.header.stamp = self.get_clock().now().to_msg()
        goal.pose.position.x = x + 1.0
        goal.pose.position.y = y
        goal.pose.orientation.w = 1.0
        self.goal_pub.publish(goal)  # error: RF201


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Ahead())
