# rclpy.duration (ROS 2): Duration(*, seconds=0, nanoseconds=0), keyword-only.
from typing import Annotated

class Duration:
    def __init__(
        self,
        *,
        seconds: Annotated[float, "Unit('s')"] = 0,
        nanoseconds: Annotated[int, "Unit('ns')"] = 0,
    ) -> None: ...
    @property
    def nanoseconds(self) -> Annotated[int, "Unit('ns')"]: ...
