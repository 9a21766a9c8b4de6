#!/usr/bin/env python3
from typing import Annotated

import rclpy
from rclpy.node import Node


class Lidar(Node):
    def __init__(self):
        super().__init__("lidar")
        self.rate: Annotated[float, "Unit('Hz') and 0 < _ <= 40"] = (
            self.declare_parameter("rate", 10.0).value
        )
        self.declare_parameter("frame_id", "laser")
        self.declare_parameter("angles.min", -3.14)


def main():
    rclpy.init()
    rclpy.spin(Lidar())


if __name__ == "__main__":
    main()
