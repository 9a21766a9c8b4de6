"""Odometry keeps its pose in `header.frame_id` and its twist in `child_frame_id`; a
rospy script transforms a pose with tf2_ros and tf2_geometry_msgs (ROS 1 noetic)."""
import rospy
import tf2_geometry_msgs
import tf2_ros
from geometry_msgs.msg import PointStamped, PoseStamped, TwistStamped
from nav_msgs.msg import Odometry

ODOM = "odom"
BASE = "base_link"


def republish(odom_pub: rospy.Publisher, x: float, vx: float) -> None:
    odom = Odometry()
    odom.header.frame_id = ODOM
    odom.child_frame_id = BASE
    odom.pose.pose.position.x = x
    odom.twist.twist.linear.x = vx
    odom_pub.publish(odom)
    cmd = TwistStamped()
    cmd.header.frame_id = BASE
    cmd.twist.linear.x = odom.twist.twist.linear.x  # the twist is in child_frame_id
    where = PointStamped()
    where.header.frame_id = BASE
    where.point.x = odom.pose.pose.position.x  # error: RF201
    here = PointStamped()
    here.header.frame_id = ODOM
    here.point.x = odom.pose.pose.position.x


def main() -> None:
    rospy.init_node("pose_in_map")
    buffer = tf2_ros.Buffer()
    listener = tf2_ros.TransformListener(buffer)
    rate = rospy.Rate(10.0)
    while not rospy.is_shutdown():
        pose = PoseStamped()
        pose.header.frame_id = "base_footprint"
        pose.pose.position.x = 0.2
        t = buffer.lookup_transform("map", "base_link", rospy.Time(0), rospy.Duration(1.0))
        wrong = tf2_geometry_msgs.do_transform_pose(pose, t)  # error: RF204
        right = buffer.lookup_transform("map", "base_footprint", rospy.Time(0))
        in_map = tf2_geometry_msgs.do_transform_pose(pose, right)
        goal = PoseStamped()
        goal.header.frame_id = "map"
        ahead = goal.pose.position.x - in_map.pose.position.x
        rate.sleep()
