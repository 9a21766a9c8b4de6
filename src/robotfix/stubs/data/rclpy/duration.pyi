# rclpy.duration (ROS 2): Duration(*, seconds=0, nanoseconds=0), keyword-only;
# to_msg() gives a builtin_interfaces/Duration, from_msg() reads one.
from typing import Annotated

from builtin_interfaces.msg import Duration as DurationMsg

class Duration:
    def __init__(
        self,
        *,
        seconds: Annotated[float, "Unit('s')"] = 0,
        nanoseconds: Annotated[int, "Unit('ns')"] = 0,
    ) -> None: ...
    @property
    def nanoseconds(self) -> Annotated[int, "Unit('ns')"]: ...
    def to_msg(self) -> DurationMsg: ...
    @classmethod
    def from_msg(cls, msg: DurationMsg) -> Duration: ...
