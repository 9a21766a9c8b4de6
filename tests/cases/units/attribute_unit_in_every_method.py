"""A number with a unit stored in an attribute bound once in the file (`None` aside)
keeps its unit in every method, as a frame name does: its unit, not its value.
Modelled on teleop_tools' mouse_teleop, which starts its publish timer in another
method than the one that computed the period."""
from typing import Annotated

from rclpy.node import Node

Hz = Annotated[float, "Unit('Hz') and _ > 0"]


class MouseTeleop(Node):
    def __init__(self, frequency: Hz) -> None:
        super().__init__("mouse_teleop")
        self._frequency = frequency
        if self._frequency > 0.0:
            self._period = 1000.0 / self._frequency  # ms
        else:
            self._period = None
        self._interval = 1.0 / frequency  # s

    def start(self) -> None:
        if self._period is not None:
            self.create_timer(self._period, self._publish)  # error: RF201 "ms"
        self.create_timer(self._interval, self._publish)  # clean: s

    def _publish(self) -> None:
        pass


class Rebound(Node):
    """Stored twice: the rule claims no unit for it (both stores are in s here)."""

    def __init__(self, frequency: Hz) -> None:
        super().__init__("rebound")
        self._slow = 2.0 / frequency

    def faster(self, frequency: Hz) -> None:
        self._slow = 1.0 / frequency

    def start(self) -> None:
        self.create_timer(self._slow, self.start)  # clean


class Literal(Node):
    def __init__(self) -> None:
        super().__init__("literal")
        self._tick = 100  # a plain number: it has no unit to keep

    def start(self) -> None:
        self.create_timer(self._tick, self.start)  # clean
