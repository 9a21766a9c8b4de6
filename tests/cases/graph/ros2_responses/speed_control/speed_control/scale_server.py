"""Scales the speed it is asked for by a gear ratio, never checked."""
import rclpy
from rclpy.node import Node
from speed_interfaces.srv import SetSpeed

GEAR_RATIO = 1.2


class ScaleServer(Node):
    def __init__(self):
        super().__init__('scale_server')
        self.srv = self.create_service(SetSpeed, 'scale_speed', self.scale_callback)

    def scale_callback(self, request, response):
        response.actual = request.speed * GEAR_RATIO
        response.success = True
        return response  # warning: RF102


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(ScaleServer())
