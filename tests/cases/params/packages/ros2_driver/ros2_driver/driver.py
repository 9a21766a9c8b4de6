"""A diff-drive driver: its limits are parameters with ranges and refinements."""
import math
from typing import Annotated

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from rclpy.parameter import Parameter
from rcl_interfaces.msg import FloatingPointRange, IntegerRange, ParameterDescriptor

from .limits import TurnRate

MAX_BRAKE = 0.8
MODE = "diff"
# an alias and module constants: a parameter file's value is checked against them
Ratio = Annotated[float, "0 <= _ <= MAX_BRAKE"]


class Driver(Node):
    MAX_ACCEL = 2.5
    max_speed: Annotated[float, "Unit('m/s') and 0 < _ <= 1.5"]

    def __init__(self):
        super().__init__("driver")
        speed_range = ParameterDescriptor(
            description="speed limit",
            floating_point_range=[FloatingPointRange(from_value=0.0, to_value=1.5)],
        )
        self.max_speed = self.declare_parameter("max_speed", 0.5, speed_range).value
        self.declare_parameter(
            "rate_hz",
            20,
            ParameterDescriptor(
                integer_range=[IntegerRange(from_value=1, to_value=100, step=1)]
            ),
        )
        self.declare_parameter("wheel_base", 0.3)
        self.declare_parameter("odom_rate", Parameter.Type.DOUBLE)  # no default
        self.declare_parameter("frame_id", "base_link")
        self.declare_parameter("holonomic", False)
        self.declare_parameter("gains", [1.0, 0.1, 0.0])
        self.declare_parameter("anything", 1.0, ParameterDescriptor(dynamic_typing=True))
        self.declare_parameters(
            "limits",
            [
                ("max_turn", 1.0, ParameterDescriptor(
                    floating_point_range=[FloatingPointRange(from_value=0.0, to_value=2.0)])),
            ],
        )
        timeout: Annotated[float, "Unit('s') and 0 < _ <= 5"] = self.declare_parameter(
            "timeout", 0.5
        ).value
        self.brake: Ratio = self.declare_parameter("brake_ratio", 0.5).value
        self.turn: TurnRate = self.declare_parameter("turn_rate", 1.0).value
        # math.pi and class constants, in the node's own refinements
        self.yaw_tolerance: Annotated[float, "Unit('rad') and 0 < _ <= math.pi / 4"] = (
            self.declare_parameter("yaw_tolerance", 0.1).value
        )
        self.accel: Annotated[float, "0 < _ <= Driver.MAX_ACCEL"] = (
            self.declare_parameter("accel", 1.0).value
        )
        self.decel: Annotated[float, "0 < _ <= MAX_ACCEL"] = (
            self.declare_parameter("decel", 1.0).value
        )
        self.jerk: Annotated[float, "0 < _ <= self.MAX_ACCEL * 2"] = (
            self.declare_parameter("jerk", 1.0).value
        )
        drive: Annotated[str, "_ == MODE"] = self.declare_parameter("drive", "diff").value
        self.publisher = self.create_publisher(Twist, "cmd_vel", 10)
        self.timer = self.create_timer(
            1.0 / self.get_parameter("rate_hz").value, self.tick
        )

    def tick(self) -> None:
        command = Twist()
        command.linear.x = self.max_speed
        self.publisher.publish(command)


def main():
    rclpy.init()
    rclpy.spin(Driver())
