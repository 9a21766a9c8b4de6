"""REP 103 suffixes name frames of their own: `camera_link_optical` (z forward,
x right, y down) is not `camera_link` (x forward)."""
from typing import Annotated

import rospy
from geometry_msgs.msg import PointStamped

Depth = Annotated[float, "Unit('m') and Frame('camera_link_optical')"]
Ahead = Annotated[float, "Unit('m') and Frame('camera_link')"]


def publish_target(pub: rospy.Publisher, depth: Depth, ahead: Ahead) -> None:
    target = PointStamped()
    target.header.frame_id = "camera_link"
    target.point.x = depth  # error: RF201
    target.point.y = ahead
    pub.publish(target)
    optical = PointStamped()
    optical.header.frame_id = "camera_link_optical"
    optical.point.z = depth
    optical.point.x = ahead  # error: RF201
    pub.publish(optical)


def main() -> None:
    rospy.init_node("target_publisher")
    pub = rospy.Publisher("target", PointStamped, queue_size=1)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        publish_target(pub, 1.0, 1.0)
        rate.sleep()
