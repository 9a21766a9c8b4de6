"""Several metadata strings are a conjunction; Final, string annotations and
`from __future__ import annotations` read the same; metadata RobotFix cannot use is
a note in a ROS file."""
from __future__ import annotations

import typing as t
from typing import Annotated, ClassVar, Final

from geometry_msgs.msg import Twist
from my_pkg.spec import SPEC_CONSTANT


class ValueRange:
    def __init__(self, low: float, high: float) -> None:
        self.low, self.high = low, high


POSITIVE = "_ > 0"

width: Annotated[float, "Unit('m')", "_ > 0"] = -1.0  # error: RF101
height: Annotated[float, "Unit('m')", "_ > 0"] = 1.0
depth: Annotated[float, "Unit('m')", POSITIVE] = 0.0  # error: RF101
doc_and_rule: Annotated[float, "const", "_ < 3"] = 4  # error: RF101
LIMIT: Final[Annotated[float, "Unit('m/s')", "_ <= 0.2"]] = 0.3  # error: RF101
quoted: "Annotated[float, 'Unit(\"m\")']" = width
quoted_bad: "Annotated[float, '_ < 1']" = 2.0  # error: RF101
whole: "t.Annotated[float, '_ < 1']" = 0.5
unused: Annotated[float, SPEC_CONSTANT] = 1.0  # note: RF511
ranged: Annotated[float, ValueRange(0, 1)] = 5.0  # note: RF511
# error: RF101
mixed: Annotated[float, "_ <= 1", ValueRange(0, 1)] = 2.0  # note: RF511
mixed_ok: Annotated[float, "_ <= 1", ValueRange(0, 1)] = 1.0  # note: RF511


class Base:
    rate: ClassVar[Annotated[int, "Unit('Hz')", "_ > 0"]] = 10
    wrong: ClassVar[Annotated[int, "Unit('Hz')", "_ > 0"]] = 0  # error: RF101


def send(cmd: "Annotated[float, 'Unit(\"m/s\")']") -> Final[Annotated[float, "_ >= 0"]]:
    msg = Twist()
    msg.angular.z = cmd  # error: RF201
    return -cmd  # warning: RF102


Meters = Annotated[float, "Unit('m')"]
not_a_string: Annotated[float, Meters] = 1.0  # note: RF511
