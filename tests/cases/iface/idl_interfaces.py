"""An interface defined in a .idl file: @unit, @range, @max and a RobotFix# verbatim."""
from typing import Annotated

import rclpy
from rclpy.node import Node

from iface.msg import Gripper


class GripperDriver(Node):
    def __init__(self) -> None:
        super().__init__("gripper_driver")
        self.pub = self.create_publisher(Gripper, "gripper", 10)

    def open_mm(self, width: Annotated[float, "Unit('mm') and 0 <= _ <= 100"]) -> None:
        cmd = Gripper()
        cmd.width = width  # error: RF201
        self.pub.publish(cmd)

    def open_m(self, width: Annotated[float, "Unit('mm') and 0 <= _ <= 100"]) -> None:
        cmd = Gripper()
        cmd.width = width / 1000  # clean: 0..0.1 m
        cmd.force = 10.0
        self.pub.publish(cmd)

    def too_wide(self) -> None:
        cmd = Gripper()
        cmd.width = 0.5  # error: RF101
        cmd.force = 50.0  # error: RF101
        self.pub.publish(cmd)

    def wide_and_open(self) -> None:
        cmd = Gripper()
        cmd.width = 0.15
        cmd.mode = 0
        self.pub.publish(cmd)  # error: RF101

    def squeeze(self, newtons: Annotated[float, "Unit('kN') and 0 <= _ <= 0.01"]) -> None:
        cmd = Gripper()
        cmd.force = newtons  # error: RF201
        self.pub.publish(cmd)
