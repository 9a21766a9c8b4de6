#!/usr/bin/env python
"""Releases the object (the near miss: the widths it asks for are in range)."""
import rospy
from arm_msgs.srv import SetGripper, SetGripperRequest


class Place:
    def __init__(self):
        self.set_gripper = rospy.ServiceProxy('set_gripper', SetGripper)

    def release(self):
        self.set_gripper(width=0.05, effort=5.0)
        self.set_gripper.call(SetGripperRequest(0.08, 0.0))


if __name__ == "__main__":
    rospy.init_node('place')
    Place().release()
