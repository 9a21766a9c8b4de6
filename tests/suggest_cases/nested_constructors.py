"""Positional and nested message constructors (newuser2 §5: `tv` and `rv` flow into
`Twist(Vector3(self.tv, 0.0, 0.0), Vector3(0.0, 0.0, self.rv))` and were not
proposed), also when the message is stored into a field of another."""

import rospy
from geometry_msgs.msg import Quaternion, Twist, Vector3
from nav_msgs.msg import Odometry


class DeadReckoning:
    def __init__(self):
        self.tv = 0.0  # suggest: tv m/s
        self.rv = 0.0  # suggest: rv rad/s
        self.speed = 0.0  # suggest: speed m/s
        self.q = [0.0, 0.0, 0.0, 1.0]  # near miss: unpacked into a Quaternion
        self.pub = rospy.Publisher("odom", Odometry, queue_size=1)
        self.cmd_pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)

    def publish_odometry(self):
        odom = Odometry()
        odom.twist.twist = Twist(Vector3(self.tv, 0.0, 0.0), Vector3(0.0, 0.0, self.rv))
        odom.pose.pose.orientation = Quaternion(*self.q)
        self.pub.publish(odom)

    def drive(self):
        self.cmd_pub.publish(Twist(linear=Vector3(x=self.speed)))
