# rclpy.time (ROS 2): Time(*, seconds=0, nanoseconds=0, clock_type=...), keyword-only.
from typing import Annotated

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
