# rclpy.time (ROS 2): Time(*, seconds=0, nanoseconds=0, clock_type=...), keyword-only.
# Time - Time is a Duration; Time - Duration and Time + Duration are Times (rclpy's
# Time.__sub__, __add__, __radd__); to_msg() gives a builtin_interfaces/Time.
from typing import Annotated, overload

from builtin_interfaces.msg import Time as TimeMsg
from rclpy.duration import Duration

class Time:
    def __init__(
        self,
        *,
        seconds: Annotated[float, "Unit('s')"] = 0,
        nanoseconds: Annotated[int, "Unit('ns')"] = 0,
        clock_type: object = None,
    ) -> None: ...
    @property
    def nanoseconds(self) -> Annotated[int, "Unit('ns')"]: ...
    def seconds_nanoseconds(
        self,
    ) -> tuple[Annotated[int, "Unit('s')"], Annotated[int, "Unit('ns')"]]: ...
    def to_msg(self) -> TimeMsg: ...
    @classmethod
    def from_msg(cls, msg: TimeMsg, clock_type: object = None) -> Time: ...
    @overload
    def __sub__(self, other: Time) -> Duration: ...
    @overload
    def __sub__(self, other: Duration) -> Time: ...
    def __add__(self, other: Duration) -> Time: ...
    def __radd__(self, other: Duration) -> Time: ...
