"""annotated-types constraints, as pydantic users write them, are refinements in ROS
code: `Gt(0), Le(1.5)` is `_ > 0 and _ <= 1.5`, conjoined with string refinements;
`at.Unit('m/s')` is `Unit('m/s')`. Read from the AST, only when the name is
annotated_types' own; bounds are numbers or constants' names, anything else is RF511."""
import math
from typing import Annotated

import annotated_types as at
import rclpy
from annotated_types import Ge, Interval, Le, MaxLen, MinLen, MultipleOf
from geometry_msgs.msg import Twist
from rclpy.node import Node

MAX_SPEED = 0.5


class Gt:  # a class of this file named like annotated_types' is not it
    def __init__(self, bound: float) -> None:
        self.bound = bound


Speed = Annotated[float, at.Unit("m/s"), at.Ge(0), at.Le(MAX_SPEED)]
Ratio = Annotated[float, Interval(ge=0, le=1)]


class Follower(Node):
    def __init__(self) -> None:
        super().__init__("follower")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.gain: Annotated[float, at.Gt(0), "_ <= 2"] = 3.0  # error: RF101
        self.slow: Speed = 0.6  # error: RF101
        self.cruise: Speed = 0.4  # clean
        self.blend: Ratio = 1.2  # error: RF101
        self.mix: Ratio = 0.7  # clean
        self.waypoints: Annotated[list[float], MinLen(1), MaxLen(3)] = []  # error: RF101
        self.route: Annotated[list[float], MinLen(1), MaxLen(3)] = [1.0, 2.0]  # clean

    def drive(self, v: Speed, w: Annotated[float, at.Unit("rad/s"), Ge(-math.pi), Le(math.pi)]) -> None:
        cmd = Twist()
        cmd.linear.x = v
        cmd.angular.z = w
        self.pub.publish(cmd)

    def tick(
        self,
        d: Annotated[float, at.Unit("m")],
        dt: Annotated[float, at.Unit("s"), at.Gt(0)],
        kmh: Annotated[float, at.Unit("km/h"), at.Interval(ge=0, le=1)],
    ) -> None:
        self.drive(0.7, 0.0)  # error: RF101
        self.drive(0.3, 4.0)  # error: RF101
        self.drive(0.3, -3.0)  # clean
        self.drive(kmh, 0.0)  # error: RF201
        self.drive(kmh / 3.6, 0.0)  # clean
        self.drive(min(d / dt, MAX_SPEED), 0.0) if d >= 0 else None  # clean

    def steps(self) -> None:
        # MultipleOf reads as Python's `%` (annotated-types' meaning)
        step: Annotated[int, MultipleOf(5)] = 10  # clean
        odd: Annotated[int, MultipleOf(5)] = 12  # error: RF101
        ticks: Annotated[float, MultipleOf(0.5)] = 2.5  # clean

    def unread(self) -> None:
        # not read, and each says why (RF511: a note, in ROS code)
        near: Annotated[float, at.Gt(MAX_SPEED / 2)] = 1.0  # note: RF511
        name: Annotated[str, MaxLen(10)] = "follower"  # note: RF511
        own: Annotated[float, Gt(0)] = -1.0  # note: RF511
        unit: Annotated[float, at.Unit("[length]")] = 1.0  # note: RF511
        timezone: Annotated[float, at.Timezone(None)] = 0.0  # note: RF511
