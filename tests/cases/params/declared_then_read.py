"""A simulator bridge that declares its parameters first and reads them a few lines
later (as f1tenth's gym bridge does): `get_parameter('x').value` of a parameter its
class declared, assigned straight to a refined target, makes that refinement the
parameter's, as `declare_parameter('x', d).value` does: the declaration's default is
checked against it, parameter files are, and the read is assumed to satisfy it (no
RF102). A name that is not a literal, a parameter no class here declares, or a value
stored in a plain variable first, stays an unknown read."""
import math
from typing import Annotated

import rclpy
from rclpy.node import Node

ScanFov = Annotated[float, "Unit('rad') and 0 < _ <= 2 * math.pi"]
Heading = Annotated[float, "Unit('rad') and abs(_) <= math.pi"]
BEAMS_PARAM = "scan_beams"


class GymBridge(Node):
    def __init__(self) -> None:
        super().__init__("gym_bridge")
        self.declare_parameter("scan_fov", 4.7)
        self.declare_parameter("start_heading", 180.0)  # error: RF101
        self.declare_parameter("opp_heading")
        self.declare_parameter("lidar_offset", 0.27)
        self.declare_parameters("", [("wheelbase", 0.33), ("max_steer", 24.0)])  # error: RF101
        self.declare_parameter(BEAMS_PARAM, 1080)

        self.scan_fov: ScanFov = self.get_parameter("scan_fov").value
        start: Heading = self.get_parameter("start_heading").value
        again: Heading = self.get_parameter("start_heading").value
        opponent: Heading = self.get_parameter("opp_heading").value
        offset: Annotated[float, "Unit('m') and 0 <= _ < 1"] = (
            self.get_parameter("lidar_offset").get_parameter_value().double_value
        )
        base: Annotated[float, "Unit('m') and _ > 0"] = self.get_parameter("wheelbase").value
        steer: Annotated[float, "Unit('rad') and 0 < _ <= 0.5"] = (
            self.get_parameter("max_steer").value
        )
        self.half_fov = self.scan_fov / 2.0
        self.wrap(start)
        self.wrap(opponent)

        beams: Annotated[int, "_ > 0"] = self.get_parameter(BEAMS_PARAM).value  # warning: RF102
        unknown: Annotated[float, "_ > 0"] = self.get_parameter("never_declared").value  # warning: RF102
        stored = self.get_parameter("scan_fov").value
        later: ScanFov = stored  # warning: RF102

    def wrap(self, angle: Heading) -> float:
        return angle

    def on_timer(self) -> None:
        fov: ScanFov = self.get_parameter("scan_fov").value
        self.wrap(fov / 2.0)
