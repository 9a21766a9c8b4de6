"""Another robot's cruise: its relative service name resolves under /robot2."""
import rclpy
from rclpy.node import Node
from speed_interfaces.srv import SetSpeed


class Fleet(Node):
    def __init__(self):
        super().__init__('fleet')
        self.cli = self.create_client(SetSpeed, 'set_max_speed')

    def cruise(self):
        self.cli.call_async(SetSpeed.Request(speed=3.0))


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Fleet())
