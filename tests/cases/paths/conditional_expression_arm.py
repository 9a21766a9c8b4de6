"""RF101: `a if c else b` is two paths; when one arm always breaks the refinement,
that path is a bug. Arms that both keep it are fine."""
from typing import Annotated

from geometry_msgs.msg import Twist
from rclpy.node import Node

MAX_SPEED = 0.22


class Cruise(Node):
    speed: Annotated[float, "Unit('m/s') and 0 <= _ <= 0.22"]

    def __init__(self) -> None:
        super().__init__("cruise")
        self.speed = 0.1
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)

    def on_button(self, boost: bool) -> None:
        self.speed = 0.5 if boost else 0.1  # error: RF101

    def on_button_capped(self, boost: bool) -> None:
        self.speed = 0.2 if boost else 0.1

    def on_obstacle(self, blocked: bool, requested: Annotated[float, "0 <= _ <= 0.2"]) -> None:
        self.speed = 0.0 if blocked else requested
