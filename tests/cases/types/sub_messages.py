"""A whole sub-message stored into a field of another type (an odometry relay, a
pose estimator): its fields of the same names must fit their new place, so a
Vector3 in m/s stored as a Point in m is a unit mix-up; a message of the field's own
type, or another type in the same units, is fine."""
import rclpy
from geometry_msgs.msg import Pose, PoseWithCovarianceStamped, TransformStamped
from nav_msgs.msg import Odometry
from rclpy.node import Node


class Relay(Node):
    def __init__(self) -> None:
        super().__init__("odom_relay")
        self.pose_pub = self.create_publisher(PoseWithCovarianceStamped, "pose", 10)
        self.create_subscription(Odometry, "odom", self.on_odom, 10)

    def on_odom(self, odom: Odometry) -> None:
        pose = Pose()
        pose.position = odom.twist.twist.linear  # error: RF201
        pose.position = odom.pose.pose.position
        pose.orientation = odom.pose.pose.orientation
        out = PoseWithCovarianceStamped()
        out.header = odom.header
        out.pose.pose = pose
        self.pose_pub.publish(out)
        t = TransformStamped()
        t.transform.translation = odom.pose.pose.position
        t.transform.translation = odom.twist.twist.angular  # error: RF201
        t.transform.rotation = odom.pose.pose.orientation


def main() -> None:
    rclpy.init()
    rclpy.spin(Relay())
