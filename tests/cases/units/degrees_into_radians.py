"""RF201: degree/s is not rad/s; math.pi / 180 converts."""
import math
from typing import Annotated

from geometry_msgs.msg import Twist

turn: Annotated[float, "Unit('degree/s')"] = 45
cmd = Twist()
cmd.angular.z = turn  # error: RF201 "math.radians"
cmd.angular.z = turn * math.pi / 180
cmd.angular.z = turn / 180 * math.pi
