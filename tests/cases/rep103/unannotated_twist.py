"""REP 103 units of standard messages, with no annotation anywhere in the file."""
import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry


def mirror(odom: Odometry, pub) -> None:
    cmd = Twist()
    cmd.linear.x = odom.twist.twist.linear.x
    cmd.angular.z = odom.twist.twist.angular.z
    total = cmd.linear.x + cmd.angular.z  # error: RF202
    cmd.linear.y = odom.twist.twist.angular.z  # error: RF201
    cmd.header_less = 1
    pub.publish(cmd)


def stamp(odom: Odometry, node) -> None:
    odom.header.frame_id = "odom"
    odom.header.stamp = node.get_clock().now().to_msg()
    odom.header.stamp.sec = 5
    odom.pose.pose.position.x = odom.twist.twist.linear.x  # error: RF201
    odom.pose.pose.position.x = odom.twist.twist.linear.x * 0.1  # warning: RF203
