"""Issue 24: a parameter file never goes quiet. A refinement with `math.pi` or
`math.inf` is checked; one naming what only the running code knows is said, in a
note, not to be checked; a section naming no node is a note (RF602)."""

import math
from typing import Annotated

from rclpy.node import Node


class Steer(Node):
    def __init__(self) -> None:
        super().__init__("steer")
        self.declare_parameter("fov", 1.0)
        fov: Annotated[float, "0 < _ <= 2 * math.pi"] = self.get_parameter("fov").value
        self.declare_parameter("low", 0.0)
        low: Annotated[float, "-math.inf < _ <= 1"] = self.get_parameter("low").value
        self.declare_parameter("wheelbase", 0.3)
        base: Annotated[float, "_ > 0"] = self.get_parameter("wheelbase").value
        self.declare_parameter("max_steer", 0.4)
        steer: Annotated[float, "0 < _ <= base"] = self.get_parameter(  # warning: RF102
            "max_steer"
        ).value
        self.limit = 2.0
        self.declare_parameter("speed", 1.0)
        speed: Annotated[float, "_ <= self.limit"] = self.get_parameter("speed").value
        self.total = fov + low + base + steer + speed
