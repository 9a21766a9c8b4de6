"""Grants a speed in turbo mode: always its top speed, more than its async
clients can drive (after ros2/demos' add_two_ints_server)."""
import rclpy
from rclpy.node import Node
from speed_interfaces.srv import SetSpeed

TURBO_SPEED = 4.0


class TurboServer(Node):
    def __init__(self):
        super().__init__('turbo_server')
        self.srv = self.create_service(SetSpeed, 'turbo_speed', self.turbo_callback)

    def turbo_callback(self, request, response):
        response.actual = TURBO_SPEED
        response.success = True
        return response  # error: RF101


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(TurboServer())
