"""`len(xs)` in code and `len(_)` in a refinement are one number, and a local list
handed to a function keeps its known length at that call (issue 22, section 2):
`history: list[float] = []; mean(history)` is `mean([])`. After the call the
callee may have kept or filled the list, so only its declaration is known."""
from typing import Annotated

import rclpy
import rospy
from rclpy.node import Node
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Float32

Samples = Annotated[list[float], "Unit('m') and len(_) > 0"]


def mean(samples: Samples) -> Annotated[float, "Unit('m')"]:
    return sum(samples) / len(samples)


def fill_from_driver(buffer: list[float]) -> None:
    buffer.append(0.5)


class RangeFilter(Node):
    def __init__(self) -> None:
        super().__init__("range_filter")
        self.last: Annotated[float, "Unit('m')"] = 0.0
        self.pub = self.create_publisher(Float32, "nearest", 10)
        self.create_subscription(LaserScan, "scan", self.on_scan, 10)
        history: list[float] = []
        self.baseline = mean(history)  # error: RF101
        history = [self.last]
        self.baseline = mean(history)

    def on_scan(self, scan: LaserScan) -> None:
        valid = [r for r in scan.ranges if scan.range_min <= r <= scan.range_max]
        if len(valid) > 0:
            self.last = mean(valid)
        if len(valid) < 1:  # (mean could have changed `valid`: it is lent to it)
            self.last = mean(valid)  # warning: RF102

    def on_far(self, scan: LaserScan) -> None:
        far = [r for r in scan.ranges if r > 2.0]
        if len(far) < 1:
            self.last = mean(far)  # error: RF101
        front: list[float] = []
        fill_from_driver(front)
        self.last = mean(front)  # warning: RF102
        out = Float32()
        out.data = self.last
        self.pub.publish(out)


def smooth(window: list[float]) -> float:
    if len(window) == 0:
        return mean(window)  # error: RF101
    return mean(window)


def ros1_main() -> None:
    rospy.init_node("range_average")
    readings: list[float] = []
    pub = rospy.Publisher("average", Float32, queue_size=1)
    pub.publish(Float32(mean(readings)))  # error: RF101
    while not rospy.is_shutdown():
        readings.append(rospy.wait_for_message("scan", LaserScan).range_min)
        pub.publish(Float32(mean(readings)))


def main() -> None:
    rclpy.init()
    rclpy.spin(RangeFilter())
