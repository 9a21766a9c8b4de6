"""A ROS 1 wheel-encoder dead-reckoning script (as duckietown's deadreckoning node
is written): a `time` field of a ROS 1 message is genpy's Time, whose `secs` are in
s and `nsecs` in ns, as `to_sec()` and `to_nsec()` are. Adding the two parts without
scaling is the classic bug; each sits beside its correct form."""
from typing import Annotated

import rospy
from sensor_msgs.msg import Imu
from std_msgs.msg import Header

STALE_S: Annotated[float, "Unit('s')"] = 0.5


class DeadReckoning:
    def __init__(self) -> None:
        self.last_s: Annotated[float, "Unit('s')"] = 0.0
        rospy.Subscriber("imu", Imu, self.on_imu)

    def on_imu(self, imu: Imu) -> None:
        stamp = imu.header.stamp
        now_s: Annotated[float, "Unit('s')"] = stamp.secs + stamp.nsecs * 1e-9
        wrong = stamp.secs + stamp.nsecs  # error: RF202
        also_s: Annotated[float, "Unit('s')"] = stamp.to_sec()
        nanos: Annotated[int, "Unit('ns')"] = stamp.nsecs
        whole_ms: Annotated[float, "Unit('ms')"] = stamp.secs  # error: RF201
        if now_s - self.last_s > STALE_S:
            self.last_s = now_s

    def age(self, header: Header) -> None:
        age_s: Annotated[float, "Unit('s')"] = (rospy.Time.now() - header.stamp).to_sec()
        part_s: Annotated[float, "Unit('s')"] = header.stamp.nsecs / 1e9
        part_s = header.stamp.nsecs  # error: RF201


def main() -> None:
    rospy.init_node("dead_reckoning")
    DeadReckoning()
    rospy.spin()
