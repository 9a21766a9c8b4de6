"""Forwards RViz's clicked points as goals in the frame they came in: a frame
the analysis does not know, so nothing is said."""
import rclpy
from geometry_msgs.msg import PointStamped, PoseStamped
from rclpy.node import Node


class Clicked(Node):
    def __init__(self):
        super().__init__('clicked')
        self.goal_pub = self.create_publisher(PoseStamped, 'goal_pose', 10)
        self.create_subscription(PointStamped, 'clicked_point', self.on_click, 10)  # note: RF606

    def on_click(self, point: PointStamped):
        goal = PoseStamped()
        goal.header = point.header
        goal.pose.position = point.point
        goal.pose.orientation.w = 1.0
        self.goal_pub.publish(goal)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Clicked())
