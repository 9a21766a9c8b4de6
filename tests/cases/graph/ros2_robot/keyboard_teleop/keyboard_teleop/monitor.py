"""A command monitor written for the stamped teleop."""
from typing import Annotated

import rclpy
from geometry_msgs.msg import TwistStamped
from nav_msgs.msg import OccupancyGrid, Odometry
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, qos_profile_sensor_data
from sensor_msgs.msg import LaserScan

LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)


class Monitor(Node):
    def __init__(self) -> None:
        super().__init__('monitor')
        self.create_subscription(  # error: RF603
            TwistStamped, '/robot1/base/cmd_vel', self.on_cmd, 10
        )
        self.create_subscription(Odometry, 'odom', self.on_odom, 10)
        # near miss: the sensor-data profile hears the driver's best-effort scan
        self.create_subscription(LaserScan, 'scan', self.on_scan, qos_profile_sensor_data)
        self.create_subscription(OccupancyGrid, 'zones', self.on_zones, LATCHED)  # error: RF604

    def on_cmd(self, msg: TwistStamped) -> None:
        pass

    def on_odom(
        self, msg: Annotated[Odometry, "abs(twist.twist.linear.x) <= 0.5"]
    ) -> None:
        pass

    def on_scan(self, msg: LaserScan) -> None:
        pass

    def on_zones(self, msg: OccupancyGrid) -> None:
        pass


def main() -> None:
    rclpy.init()
    rclpy.spin(Monitor())
