"""A rospy bridge for a six-joint arm: servo callbacks report each joint's angle in
rad, a timer republishes them as a JointState and logs them in degrees. A literal
180/pi on a value already in rad, stored where rad belongs, is a conversion done by
mistake (issue 8, item 5: found when annotating rbx1's joint state publisher)."""
import math
from typing import Annotated

import rospy
from sensor_msgs.msg import JointState

JOINTS = ["shoulder_pan", "shoulder_lift", "elbow", "wrist_1", "wrist_2", "wrist_3"]


class ArmBridge:
    def __init__(self) -> None:
        self.angles: Annotated[
            list[float], "Unit('rad') and abs(_) <= 3.1416 and len(_) == 6"
        ] = [0.0] * 6
        self.rate = rospy.get_param("~rate", 20.0)
        self.pub = rospy.Publisher("joint_states", JointState, queue_size=5)
        rospy.Timer(rospy.Duration(1.0 / self.rate), self.on_timer)

    def on_servo(
        self, index: int, reading: Annotated[float, "Unit('rad') and abs(_) <= 3.1416"]
    ) -> None:
        self.angles[index] = reading
        rospy.logdebug("joint %d at %.1f deg", index, reading * 180 / math.pi)

    def on_servo_in_degrees(self, index: int, reading: Annotated[float, "Unit('rad')"]) -> None:
        self.angles[index] = reading * 180 / math.pi  # error: RF201

    def on_timer(self, event) -> None:
        msg = JointState()
        msg.header.stamp = rospy.Time.now()
        msg.name = JOINTS
        msg.position = [a for a in self.angles]
        shown: Annotated[list[float], "Unit('degree')"] = [a * 180 / math.pi for a in self.angles]
        rospy.logdebug("arm at %s deg", shown)
        self.pub.publish(msg)

    def on_timer_in_degrees(self, event) -> None:
        msg = JointState()
        msg.name = JOINTS
        msg.position = [a * 180 / math.pi for a in self.angles]  # error: RF201
        self.pub.publish(msg)


if __name__ == "__main__":
    rospy.init_node("arm_bridge")
    ArmBridge()
    rospy.spin()
