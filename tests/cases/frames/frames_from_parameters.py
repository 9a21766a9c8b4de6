"""A frame from a parameter's default (`declare_parameter('frame', 'odom')`) is that
frame; a parameter without a default names no known frame."""
import rospy
from geometry_msgs.msg import PointStamped
from rclpy.node import Node


class Follower(Node):
    def __init__(self) -> None:
        super().__init__("follower")
        self.declare_parameter("odom_frame", "odom")
        self.declare_parameter("global_frame", "map")
        self.declare_parameter("sensor_frame")
        self.odom_frame = self.get_parameter("odom_frame").value
        self.global_frame = self.declare_parameter("goal_frame", "map").value
        self.timer = self.create_timer(0.2, self.tick)

    def tick(self) -> None:
        here = PointStamped()
        here.header.frame_id = self.odom_frame
        goal = PointStamped()
        goal.header.frame_id = self.global_frame
        error = goal.point.x - here.point.x  # error: RF202
        target = PointStamped()
        target.header.frame_id = self.get_parameter("global_frame").value
        same = target.point.x - goal.point.x  # both default to map: clean
        sensor = PointStamped()
        sensor.header.frame_id = self.get_parameter("sensor_frame").value
        unknown = sensor.point.x - goal.point.x  # no default: silent
        named = PointStamped()
        named.header.frame_id = f"{self.global_frame}_offset"  # formatted: silent
        formatted = named.point.x - goal.point.x


def ros1_main() -> None:
    rospy.init_node("ros1_follower")
    base = rospy.get_param("~base_frame", "base_link")
    world = rospy.get_param("~world_frame", "map")
    unset = rospy.get_param("~other_frame")
    a = PointStamped()
    a.header.frame_id = base
    b = PointStamped()
    b.header.frame_id = world
    c = PointStamped()
    c.header.frame_id = unset
    wrong = a.point.x > b.point.x  # error: RF202
    silent = c.point.x > b.point.x
