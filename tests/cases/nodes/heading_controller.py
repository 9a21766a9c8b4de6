"""math with units: atan2 gives rad, radians() converts, sin() takes rad."""
import math
from typing import Annotated

from geometry_msgs.msg import Twist

GAIN: Annotated[float, "Unit('1/s') and _ > 0"] = 0.8


def steer(dx: float, dy: float, target: Annotated[float, "Unit('degree')"]) -> Twist:
    yaw = math.atan2(dy, dx)
    cmd = Twist()
    error = target - yaw  # error: RF202 "math.degrees"
    error = math.radians(target) - yaw
    cmd.angular.z = GAIN * error
    cmd.angular.z = GAIN * math.degrees(error)  # error: RF201
    wobble = math.sin(target)  # error: RF201
    wobble = math.sin(math.radians(target))
    bounded: Annotated[float, "-1 <= _ <= 1"] = wobble
    return cmd
