#!/usr/bin/env python
"""Shows off the simulated gripper, which opens wider than the real one."""
import rospy
from arm_msgs.srv import SetGripper


class Demo:
    def __init__(self):
        self.set_gripper = rospy.ServiceProxy('set_gripper', SetGripper)

    def wave(self):
        self.set_gripper(0.2, 1.0)


if __name__ == "__main__":
    rospy.init_node('demo')
    Demo().wave()
