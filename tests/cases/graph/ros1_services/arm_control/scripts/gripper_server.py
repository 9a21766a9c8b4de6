#!/usr/bin/env python
"""The gripper's driver (after rospy_tutorials' add_two_ints_server): it assumes
the width it is asked for is one the fingers can reach."""
from typing import Annotated

import rospy
from arm_msgs.srv import SetGripper, SetGripperRequest, SetGripperResponse


def handle_set_gripper(req: Annotated[SetGripperRequest, "0 <= width <= 0.08"]):
    rospy.loginfo("opening to %s m", req.width)
    return SetGripperResponse(True)


def gripper_server():
    rospy.init_node('gripper')
    rospy.Service('set_gripper', SetGripper, handle_set_gripper)
    rospy.spin()


if __name__ == "__main__":
    gripper_server()
