"""The near miss: it clamps what it grants to what the motors do."""
import rclpy
from rclpy.node import Node
from speed_interfaces.srv import SetSpeed

MAX_SPEED = 2.0


class ClampServer(Node):
    def __init__(self):
        super().__init__('clamp_server')
        self.srv = self.create_service(SetSpeed, 'clamped_speed', self.clamp_callback)

    def clamp_callback(self, request, response):
        response.actual = min(MAX_SPEED, request.speed)
        response.success = response.actual == request.speed
        return response


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(ClampServer())
