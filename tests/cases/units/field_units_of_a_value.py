"""A message refinement gives a field whose interface has no unit one, for this
value only: std_msgs/Float64 `data` as a joint command in rad (ros2_control's
forward_command_controller, turtlebot3_manipulation)."""

import math
from typing import Annotated

from geometry_msgs.msg import Twist
from std_msgs.msg import Float64, Float64MultiArray


def on_command(msg: Annotated[Float64, "Unit(data) == 'rad'"]) -> None:
    shown: Annotated[float, "Unit('degree')"] = msg.data  # error: RF201 "math.degrees"
    print(shown)
    converted: Annotated[float, "Unit('degree')"] = math.degrees(msg.data)
    kept: Annotated[float, "Unit('rad')"] = msg.data
    print(converted, kept)


def on_plain(msg: Float64) -> None:
    shown: Annotated[float, "Unit('degree')"] = msg.data  # no unit: nothing to check
    print(shown)


def send(angle: Annotated[float, "Unit('rad')"]) -> None:
    cmd = Float64()
    cmd.data = math.degrees(angle)
    out: Annotated[Float64, "Unit(data) == 'rad'"] = cmd  # error: RF201
    home: Annotated[Float64, "Unit(data) == 'rad'"] = Float64(data=0.5)
    print(out, home)


def misplaced(msg: Annotated[Float64, "Unit(stamp) == 'rad'"]) -> None:  # error: RF505
    print(msg)


def framed(msg: Annotated[Float64, "Frame(data) == 'map'"]) -> None:  # error: RF507
    print(msg)


def plain(angle: Annotated[float, "Unit(data) == 'rad'"]) -> None:  # error: RF507
    print(angle)


def fill(angle: Annotated[float, "Unit('rad')"]) -> None:
    out: Annotated[Float64, "Unit(data) == 'rad'"] = Float64()
    out.data = math.degrees(angle)  # error: RF201
    out.data = angle
    out.data = 0.5
    print(out)


def on_commands(msg: Annotated[Float64MultiArray, "Unit(data) == 'rad'"]) -> None:
    first: Annotated[float, "Unit('degree')"] = msg.data[0]  # error: RF201
    print(first)


def declared(msg: Annotated[Twist, "Unit(linear.x) == 'km/h'"]) -> None:  # error: RF507
    speed: Annotated[float, "Unit('m/s')"] = msg.linear.x  # REP 103's unit is kept
    print(speed)


def agreed(msg: Annotated[Twist, "Unit(angular.z) == 'rad/s'"]) -> None:
    print(msg.angular.z)
