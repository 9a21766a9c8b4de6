"""Grants a speed (after ros2/demos' add_two_ints_server): in boost mode it
always answers with its top speed, more than its clients can drive."""
import rclpy
from rclpy.node import Node
from speed_interfaces.srv import SetSpeed

TOP_SPEED = 3.0


class BoostServer(Node):
    def __init__(self):
        super().__init__('boost_server')
        self.srv = self.create_service(SetSpeed, 'set_speed', self.set_speed_callback)

    def set_speed_callback(self, request, response):
        response.actual = TOP_SPEED
        response.success = True
        self.get_logger().info('Incoming request\nspeed: %f' % request.speed)
        return response  # error: RF101


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(BoostServer())
