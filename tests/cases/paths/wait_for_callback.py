"""A loop that waits for a callback (`while not received: rospy.sleep(0.1)`) ends
when the callback changes the flag: the code after it is checked, not dead."""
from typing import Annotated

import rospy
from sensor_msgs.msg import CameraInfo

received = False


def on_info(msg: CameraInfo) -> None:
    global received
    received = True


class Tracker:
    width: Annotated[int, "_ >= 0"]

    def __init__(self) -> None:
        self.width = 0
        rospy.Subscriber("camera_info", CameraInfo, self.on_camera_info)
        while self.width == 0:
            rospy.sleep(1)
        half: Annotated[float, "_ > 0"] = self.width / 2
        limit: Annotated[float, "_ < 1"] = 5.0  # error: RF101

    def on_camera_info(self, msg: CameraInfo) -> None:
        self.width = max(msg.width, 0)


rospy.init_node("tracker")
rospy.Subscriber("camera_info", CameraInfo, on_info)
while not received:
    rospy.sleep(0.1)
speed: Annotated[float, "_ < 1"] = 2.0  # error: RF101
