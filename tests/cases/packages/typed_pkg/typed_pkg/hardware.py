"""The base's hardware: a RoboClaw-style controller per wheel, the chassis that
holds them, and command helpers, as a node's package keeps them apart from the
node."""
from typing import Annotated

from geometry_msgs.msg import Twist

MAX_AMPS = 7.5


class WheelController:
    """Speed in rpm at the motor shaft; current limited in amperes."""

    def __init__(self, address: int) -> None:
        self.address = address
        self.ticks = 0

    def drive_rpm(self, rpm: Annotated[float, "Unit('rpm')"]) -> None:
        self.ticks += int(rpm)

    def limit_current(self, amps: Annotated[float, "Unit('A') and 0 < _ <= MAX_AMPS"]) -> None:
        self.ticks = 0 if amps > MAX_AMPS else self.ticks


class Chassis:
    def __init__(self) -> None:
        self.left = WheelController(0x80)
        self.right = WheelController(0x81)

    def wheel(self, side: str) -> WheelController:
        return self.left if side == "left" else self.right


def stop_command():
    cmd = Twist()
    cmd.linear.x = 0.0
    return cmd


def open_controller(address: int):
    return WheelController(address)
