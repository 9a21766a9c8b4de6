"""A unit written as other Python unit checkers write it (`Annotated[float, "m"]`,
`"unit:m/s"`) is not read as a unit; in ROS code it gets RF511 saying how RobotFix
writes it (`Unit('m')`), so nothing is dropped silently. Strings other libraries put
there (`"const"`, a description) stay silent, as do unit words on a `str`."""
from typing import Annotated

import rclpy
from sensor_msgs.msg import Range

wheel_radius: Annotated[float, "m"] = 0.033  # note: RF511 "Unit()"
max_speed: Annotated[float, "unit:m/s"] = 0.22  # note: RF511
max_accel: Annotated[float, "m/s^2"] = 1.5  # note: RF511
period: Annotated[float, "unit: ms"] = 100.0  # note: RF511
ranges: Annotated[list[float], "m"] = []  # note: RF511
read: Annotated[float, "Unit('m')"] = 0.033  # clean: RobotFix's spelling

mode: Annotated[int, "const"] = 1  # clean: another library's word
label: Annotated[str, "m"] = "left"  # clean: a str has no unit
wheels: Annotated[int, "count"] = 3  # clean: a counting word
share: Annotated[float, "percent"] = 5.0  # clean: dimensionless
doc: Annotated[float, "the wheel radius"] = 0.033  # clean: a description
frame: Annotated[str, "base_link"] = "base_link"  # clean


def publish(r: Range, distance: Annotated[float, "cm"]) -> None:  # note: RF511
    r.range = distance
