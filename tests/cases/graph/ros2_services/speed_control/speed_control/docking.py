"""Slows down near the dock (the near miss: it clamps what it asks for)."""
import rclpy
from rclpy.node import Node
from speed_interfaces.srv import SetSpeed

MAX_SPEED = 2.0


class Docking(Node):
    def __init__(self):
        super().__init__('docking')
        self.cli = self.create_client(SetSpeed, 'set_max_speed')

    def approach(self, distance: float):
        req = SetSpeed.Request()
        req.speed = max(0.0, min(MAX_SPEED, 0.5 * distance))
        return self.cli.call_async(req)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Docking())
