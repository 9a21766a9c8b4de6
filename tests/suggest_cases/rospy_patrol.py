#!/usr/bin/env python
"""A ROS 1 script: rates, sleeps and timeouts of the ROS API carry units."""

import rospy
from geometry_msgs.msg import Twist

RATE_HZ = 10  # suggest: RATE_HZ Hz
SETTLE = 2.0  # suggest: SETTLE s
STEPS = 50  # near miss: a loop bound


def wait_for_simulator(timeout):  # suggest: timeout s
    name = rospy.get_param("~reset_service", "gazebo/reset_world")  # near miss
    rospy.wait_for_service(name, timeout)


def connect(robot):
    service = "/" + robot + "/reset"  # near miss: a service name, not a timeout
    rospy.wait_for_service(service)


def main():
    rospy.init_node("patrol")
    pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
    wait_for_simulator(5.0)
    connect("robot1")
    pause = rospy.Duration(SETTLE)  # near miss: a Duration, not a float
    rospy.sleep(pause)
    rate = rospy.Rate(RATE_HZ)
    forward = rospy.get_param("~forward", 0.2)  # suggest: forward m/s
    for step in range(STEPS):  # near miss: `step` is a loop variable
        cmd = Twist()
        cmd.linear.x = forward
        cmd.angular.z = step * 0.02
        pub.publish(cmd)
        rate.sleep()


if __name__ == "__main__":
    main()
