"""Numbers as Python computes them (issue 22, section 2): `** 0.5` takes the unit's
root, a conditional expression's arms must agree in unit, numpy's elementwise
functions keep units as their `math` counterparts do, and a branch a literal test
rules out (`if False:`) is not run. Each has its correct form beside it."""
import math
from typing import Annotated

import numpy as np
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node

MAX_SPEED: Annotated[float, "Unit('m/s')"] = 0.22
MAX_SPEED_FT: Annotated[float, "Unit('ft/s')"] = 0.7
USE_METRIC = True


class Follower(Node):
    def __init__(self) -> None:
        super().__init__("follower")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)

    def follow(
        self,
        dx: Annotated[float, "Unit('m')"],
        dy: Annotated[float, "Unit('m')"],
        area: Annotated[float, "Unit('m^2') and _ >= 0"],
        timeout: Annotated[float, "Unit('s')"],
        fast: bool,
    ) -> None:
        dist: Annotated[float, "Unit('m')"] = (dx**2 + dy**2) ** 0.5
        side: Annotated[float, "Unit('m')"] = area**0.5
        side = area**2  # error: RF201
        wait: Annotated[float, "Unit('s')"] = area**0.5  # error: RF201
        cmd = Twist()
        cmd.linear.x = MAX_SPEED if fast else MAX_SPEED / 2
        cmd.linear.x = MAX_SPEED if fast else 0.0
        cmd.linear.x = MAX_SPEED if fast else MAX_SPEED_FT  # error: RF202
        cmd.linear.x = float(np.clip(dist / timeout, -MAX_SPEED, MAX_SPEED))
        cmd.linear.x = float(np.clip(dist / timeout, 0.0, MAX_SPEED_FT))  # error: RF202
        cmd.linear.x = float(np.minimum(MAX_SPEED, dist / timeout))
        cmd.angular.z = float(np.maximum(MAX_SPEED, 0.1))  # error: RF201
        cmd.linear.x = float(np.where(fast, MAX_SPEED, dist / timeout))
        cmd.linear.x = float(np.where(fast, MAX_SPEED, dist))  # error: RF202
        cmd.angular.z = float(np.arctan2(dy, dx)) / timeout
        cmd.angular.z = math.atan2(dy, dx) / timeout
        if False:
            cmd.linear.x = dist  # never runs: not reported
        else:
            cmd.linear.x = dist / timeout
        if True:
            cmd.angular.z = MAX_SPEED  # error: RF201
        if USE_METRIC:
            self.pub.publish(cmd)


def main() -> None:
    rclpy.init()
    rclpy.spin(Follower())
