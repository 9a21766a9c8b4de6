#!/usr/bin/env python3
"""Keyboard teleop for one turtle (rospy), as turtle_teleop_key."""
import rospy
from geometry_msgs.msg import Twist


def main() -> None:
    rospy.init_node('teleop')
    pub = rospy.Publisher('cmd_vel', Twist, queue_size=1)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        pub.publish(Twist())
        rate.sleep()


if __name__ == '__main__':
    main()
