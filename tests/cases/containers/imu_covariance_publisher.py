"""An rclpy IMU driver: fixed-size covariance arrays (float64[9]), whose length
rclpy's setters assert, filled from a helper that takes a Sequence of variances
(issue 8, item 5)."""
from typing import Annotated, Sequence

import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Imu

GYRO_NOISE = (0.0002, 0.0002, 0.0003)


def diagonal(
    variances: Annotated[Sequence[float], "_ >= 0 and len(_) == 3"],
) -> Annotated[list[float], "_ >= 0 and len(_) == 9"]:
    x, y, z = variances
    return [x, 0.0, 0.0, 0.0, y, 0.0, 0.0, 0.0, z]


def spread(
    variances: Annotated[Sequence[float], "_ >= 0 and len(_) == 3"],
) -> Annotated[list[float], "_ >= 0 and len(_) == 9"]:
    x, y, z = variances
    return [x, 0.0, 0.0, 0.0, y, 0.0, 0.0, 0.0, -z]  # warning: RF102 "spread()[8] >= 0"


class ImuDriver(Node):
    def __init__(self) -> None:
        super().__init__("imu_driver")
        self.pub = self.create_publisher(Imu, "imu/data", 10)
        self.timer = self.create_timer(0.01, self.on_timer)

    def on_timer(self) -> None:
        imu = Imu()
        imu.orientation_covariance = [-1.0] + [0.0] * 8
        imu.angular_velocity_covariance = diagonal(GYRO_NOISE)
        imu.angular_velocity_covariance = diagonal((0.0002, -0.0002, 0.0003))  # error: RF101
        imu.angular_velocity_covariance = diagonal([0.0002, 0.0002])  # error: RF101
        imu.linear_acceleration_covariance = [0.01, 0.0, 0.0, 0.0, 0.01, 0.0, 0.0, 0.0]  # error: RF101
        imu.linear_acceleration_covariance = [0.01, 0.0, 0.0, 0.0, 0.01, 0.0, 0.0, 0.0, 0.01]
        self.pub.publish(imu)


def main() -> None:
    rclpy.init()
    rclpy.spin(ImuDriver())
