"""A dead-reckoning node that accumulates with `+=` and `-=`: each augmented
assignment with operands in other units is its own finding, however many of them
follow one another (each is reported once per statement, never once per file)."""
from typing import Annotated

import rclpy
from rclpy.node import Node

Meters = Annotated[float, "Unit('m')"]
Seconds = Annotated[float, "Unit('s')"]
RadPerSec = Annotated[float, "Unit('rad/s')"]


class DeadReckoning(Node):
    def __init__(self) -> None:
        super().__init__("dead_reckoning")
        self.x: Meters = 0.0
        self.elapsed: Seconds = 0.0
        self.create_timer(0.1, self.step)

    def step(self) -> None:
        dt: Seconds = 0.1
        vx: Annotated[float, "Unit('m/s')"] = 0.2
        wz: RadPerSec = 0.3
        self.x += vx * dt
        self.elapsed += dt
        self.x += wz  # error: RF202 "cannot add m and rad/s"
        self.x += dt  # error: RF202 "cannot add m and s"
        self.x -= wz  # error: RF202 "cannot subtract m and rad/s"
        self.x -= dt  # error: RF202 "cannot subtract m and s"
        self.elapsed += vx  # error: RF202 "cannot add s and m/s"
        self.elapsed -= dt


def odometry(x: Meters, wz: RadPerSec, dt: Seconds) -> Meters:
    x += wz  # error: RF202 "cannot add m and rad/s"
    x += wz  # error: RF202 "cannot add m and rad/s"
    x += dt  # error: RF202 "cannot add m and s"
    x += wz * dt  # error: RF202 "cannot add m and rad"
    return x


def main() -> None:
    rclpy.init()
    rclpy.spin(DeadReckoning())
