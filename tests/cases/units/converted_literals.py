"""A literal converted by a call is in the call's result unit: `math.radians(90.0)`
took the parameter's unit (degree) and is in rad, so into a parameter in degrees it
was converted once too often (the patrol server's `turn(math.radians(90.0))`, where
`turn` converts itself). What the literal carries besides the angle is still the
context's: `math.radians(30)` is a fine yaw rate in rad/s. Into degree/s it is not."""
import math
from typing import Annotated

from rclpy.node import Node

RIGHT_ANGLE: Annotated[float, "Unit('degree')"] = 90.0


class Patrol(Node):
    def __init__(self) -> None:
        super().__init__("patrol")
        self.max_yaw_rate: Annotated[float, "Unit('rad/s')"] = math.radians(30)
        self.heading: Annotated[float, "Unit('rad')"] = math.radians(45.0)

    def turn(self, target_angle: Annotated[float, "Unit('degree')"]) -> None:
        self.target = target_angle * math.pi / 180.0

    def spin_deg(self, rate: Annotated[float, "Unit('degree/s')"]) -> None:
        self.rate = rate

    def square(self) -> None:
        self.turn(90.0)
        self.turn(RIGHT_ANGLE)
        self.turn(math.radians(90.0))  # error: RF201
        self.turn(math.radians(RIGHT_ANGLE))  # error: RF201
        quarter = math.radians(90.0)
        self.turn(quarter)  # error: RF201
        self.spin_deg(math.radians(30))  # error: RF201
        self.spin_deg(30.0)
        self.heading = math.sin(math.radians(45))
        back: Annotated[float, "Unit('degree')"] = math.degrees(math.pi / 2)
        wrong: Annotated[float, "Unit('rad')"] = math.degrees(math.pi / 2)  # error: RF201
