"""Values handed to a refined function, or returned from one, take its units;
quotients of two unknowns and conversions do not."""

import math
from typing import Annotated

from geometry_msgs.msg import Twist

LIMIT = 1.0  # suggest: LIMIT m/s


def limited(
    speed: Annotated[float, "Unit('m/s')"],
) -> Annotated[float, "Unit('m/s')"]:
    return max(-LIMIT, min(speed, LIMIT))


def heading(target_deg):
    error = target_deg * math.pi / 180  # near miss: degrees converted to radians
    return error


def command(distance, duration, requested):  # suggest: requested m/s
    """`distance` and `duration` are near misses: only their quotient is m/s."""
    cmd = Twist()
    speed = distance / duration  # suggest: speed m/s
    cmd.linear.x = limited(speed)
    cmd.linear.y = limited(requested + 0.1)
    cmd.angular.z = heading(90.0)
    return cmd


def spin_rate(rate_kmh):
    cmd = Twist()
    cmd.linear.x = rate_kmh / 3.6  # near miss: km/h converted to m/s
    return cmd


def braking(v0, decel):  # suggest: v0 m/s
    margin: Annotated[float, "Unit('m/s')"] = v0 - 0.1
    return margin * decel
