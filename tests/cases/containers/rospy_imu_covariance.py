#!/usr/bin/env python
"""The same covariance in a rospy node: ROS 1 messages are plain lists, checked
only when published, so a list that is one short and then completed is fine
(the near miss of imu_covariance_publisher.py)."""
import rospy
from sensor_msgs.msg import Imu


def publish_once(pub: rospy.Publisher) -> None:
    imu = Imu()
    imu.orientation_covariance = [0.0] * 8
    imu.orientation_covariance.append(0.0)
    imu.angular_velocity_covariance = [0.0002, 0.0, 0.0, 0.0, 0.0002, 0.0, 0.0, 0.0, 0.0003]
    pub.publish(imu)


if __name__ == "__main__":
    rospy.init_node("imu_driver")
    publish_once(rospy.Publisher("imu/data", Imu, queue_size=10))
