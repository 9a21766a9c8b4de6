#!/usr/bin/env python
"""Opens the gripper wide before a grasp: wider than its fingers reach."""
import rospy
from arm_msgs.srv import SetGripper

OPEN_WIDTH = 0.1


class Pick:
    def __init__(self):
        rospy.wait_for_service('set_gripper')
        self.set_gripper = rospy.ServiceProxy('set_gripper', SetGripper)

    def open(self):
        return self.set_gripper(OPEN_WIDTH, 10.0)  # error: RF101


if __name__ == "__main__":
    rospy.init_node('pick')
    Pick().open()
    rospy.spin()
