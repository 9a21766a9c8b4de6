"""A sensor read that returns several values, each with its own unit."""
import math
from typing import Annotated, Tuple

from geometry_msgs.msg import Twist

Degrees = Annotated[float, "Unit('degree')"]
Range = Annotated[float, "Unit('m') and 0 <= _ <= 10"]


def read_imu() -> tuple[Annotated[float, "Unit('degree')"], float]:
    return 12.0, 3.0


def read_orientation() -> Tuple[Degrees, Degrees]:
    return 1.0, 2.0


def read_range() -> tuple[Range, int]:
    return 12.0, 1  # error: RF101


def read_range_ok() -> tuple[Range, int]:
    return 4.0, 1


def nearest(readings: tuple[Range, Range]) -> Range:
    near, far = readings
    return min(near, far)


def control() -> None:
    cmd = Twist()
    yaw, pitch = read_imu()
    cmd.angular.z = yaw  # error: RF201
    heading: Annotated[float, "Unit('rad')"] = math.radians(yaw)
    cmd.angular.y = pitch
    roll, tilt = read_orientation()
    cmd.angular.x = tilt  # error: RF201
    distance, quality = read_range_ok()
    safe: Annotated[float, "_ <= 10"] = distance
    nearest((1.0, 20.0))  # error: RF101
    nearest((1.0, 2.0))
    closest: Annotated[float, "Unit('m') and _ <= 10"] = nearest((1.0, 2.0))
