"""An arm controller node whose imports must not be confused with each other."""
from typing import Annotated

from rclpy.node import Node

from arm_pkg import other
from arm_pkg.tuning import GAIN, JOINT_LIMIT, scale


class ArmNode(Node):
    def __init__(self) -> None:
        super().__init__("arm")
        self.timer = self.create_timer(0.5, self.step)

    def step(self) -> None:
        other.scale(5.0)  # the other module's scale: no refinement
        scale(0.5)
        limit: Annotated[float, "_ <= 2.5"] = JOINT_LIMIT
        tight: Annotated[float, "_ < 2"] = JOINT_LIMIT  # error: RF101
        gain: Annotated[float, "_ < 1"] = GAIN  # changed by retune(): not 1.0
        args = [0.5]
        scale(*args)  # starred: not followed
        options = {"x": 3.0}
        scale(**options)  # not followed either


def local_shadow() -> None:
    def scale(x: float) -> float:  # a local function hides the imported one
        return x

    scale(10.0)
