"""Asks for highway speed when the path ahead is clear: more than the motors do."""
import rclpy
from rclpy.node import Node
from speed_interfaces.srv import SetSpeed

CRUISE_SPEED = 3.0


class Cruise(Node):
    def __init__(self):
        super().__init__('cruise')
        self.cli = self.create_client(SetSpeed, 'set_max_speed')
        while not self.cli.wait_for_service(timeout_sec=1.0):
            self.get_logger().info('service not available, waiting again...')
        self.req = SetSpeed.Request()

    def send_request(self):
        self.req.speed = CRUISE_SPEED
        self.future = self.cli.call_async(self.req)  # error: RF101


def main(args=None):
    rclpy.init(args=args)
    node = Cruise()
    node.send_request()
    rclpy.spin_until_future_complete(node, node.future)
