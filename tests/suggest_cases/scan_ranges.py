"""A list that reaches LaserScan's `ranges` (in m) holds no float: it gets no
`Annotated[float, ...]` (its applied file would fail with RF401), while the scalar
beside it that reaches `range_max` still gets its unit."""

import rclpy
from rclpy.node import Node
from sensor_msgs.msg import LaserScan


class ScanBridge(Node):
    def __init__(self, scans):
        super().__init__("scan_bridge")
        self.ego_scan = list(scans[0])
        self.history = []
        self.limit = 30.0  # suggest: limit m
        self.pub = self.create_publisher(LaserScan, "scan", 10)

    def publish(self):
        scan = LaserScan()
        scan.ranges = self.ego_scan
        scan.range_max = self.limit
        self.pub.publish(scan)

    def keep(self, reading):
        self.history.append(reading)
        copy = list(self.history)
        scan = LaserScan()
        scan.ranges = copy
        self.pub.publish(scan)


def main():
    rclpy.init()
    rclpy.spin(ScanBridge([[1.0, 2.0]]))
