"""Sets the base's speed limit (after ros2/demos' add_two_ints_server): the
callback assumes the limit it is asked for is one the motors can do."""
from typing import Annotated

import rclpy
from rclpy.node import Node
from speed_interfaces.srv import SetSpeed


class LimitServer(Node):
    def __init__(self):
        super().__init__('limit_server')
        self.limit = 0.5
        self.srv = self.create_service(SetSpeed, 'set_max_speed', self.set_max_speed_callback)

    def set_max_speed_callback(
        self, request: Annotated[SetSpeed.Request, "0 <= speed <= 2"], response
    ):
        self.limit = request.speed
        response.actual = request.speed
        response.success = True
        return response


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(LimitServer())
