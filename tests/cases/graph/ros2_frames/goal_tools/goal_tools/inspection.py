"""Visits inspection points (after nav2_simple_commander's demo_inspection), in
the map frame: the near miss (`/map` is `map`, as tf2 strips the slash)."""
import rclpy
from geometry_msgs.msg import PoseStamped
from rclpy.node import Node

MAP_FRAME = '/map'
INSPECTION_POINTS = [(3.461, -0.450), (5.531, -0.450), (3.461, -2.200)]


class Inspection(Node):
    def __init__(self):
        super().__init__('inspection')
        self.goal_pub = self.create_publisher(PoseStamped, 'goal_pose', 10)

    def visit(self, index: int):
        pose = PoseStamped()
        pose.header.frame_id = MAP_FRAME
        pose.pose.position.x = INSPECTION_POINTS[index][0]
        pose.pose.position.y = INSPECTION_POINTS[index][1]
        self.goal_pub.publish(pose)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Inspection())
