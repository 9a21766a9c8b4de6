"""A list that reaches LaserScan's `ranges` (in m) holds no float: it gets
`Annotated[list[float], "Unit('m')"]`, the form the check reads (newuser2 §3.5: it
got `Annotated[float, ...]`, and the applied file failed with RF401), while the
scalar beside it that reaches `range_max` gets `Annotated[float, ...]`."""

import rclpy
from rclpy.node import Node
from sensor_msgs.msg import LaserScan


class ScanBridge(Node):
    def __init__(self, scans):
        super().__init__("scan_bridge")
        self.ego_scan = list(scans[0])  # suggest: ego_scan m list[float]
        self.history = []  # near miss: reaches the field only through a copy
        self.pairs = [(1.0, 2.0)]  # near miss: a list of tuples, not of numbers
        self.ring = (1.0, 2.0)  # near miss: a tuple, not a list
        self.limit = 30.0  # suggest: limit m
        self.pub = self.create_publisher(LaserScan, "scan", 10)

    def publish(self):
        scan = LaserScan()
        scan.ranges = self.ego_scan
        scan.range_max = self.limit
        self.pub.publish(scan)

    def keep(self, reading):
        self.history.append(reading)
        copy = list(self.history)  # suggest: copy m list[float]
        scan = LaserScan()
        scan.ranges = copy
        self.pub.publish(scan)

    def others(self):
        scan = LaserScan()
        scan.intensities = self.pairs
        scan.ranges = self.ring
        self.pub.publish(scan)


def main():
    rclpy.init()
    rclpy.spin(ScanBridge([[1.0, 2.0]]))
