"""Stops the robot near obstacles (a reliable subscription to a sensor topic)."""
import rclpy
from nav_msgs.msg import OccupancyGrid
from rclpy.node import Node
from sensor_msgs.msg import LaserScan
from std_msgs.msg import String


class ObstacleStop(Node):
    def __init__(self) -> None:
        super().__init__('obstacle_stop')
        self.scan_sub = self.create_subscription(LaserScan, 'scan', self.on_scan, 10)  # error: RF604
        # near miss: the driver's private `~/status`, under its launch name `driver`
        self.status_sub = self.create_subscription(String, 'driver/status', self.on_status, 10)
        self.reason_pub = self.create_publisher(String, 'stop_reason', 10)  # note: RF607
        self.zones_pub = self.create_publisher(OccupancyGrid, 'zones', 1)

    def on_scan(self, msg: LaserScan) -> None:
        pass

    def on_status(self, msg: String) -> None:
        pass


def main() -> None:
    rclpy.init()
    rclpy.spin(ObstacleStop())
