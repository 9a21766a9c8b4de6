"""Asks for a speed through a future and drives at what is granted, assuming
the motors can do it (after ros2/demos' add_two_ints_client_async and the
ros2/examples minimal async client)."""
from typing import Annotated

import rclpy
from speed_interfaces.srv import SetSpeed

def main(args=None):
    rclpy.init(args=args)
    node = rclpy.create_node('turbo_cruise')
    cli = node.create_client(SetSpeed, 'turbo_speed')
    while not cli.wait_for_service(timeout_sec=1.0):
        node.get_logger().info('service not available, waiting again...')
    future = cli.call_async(SetSpeed.Request(speed=1.5))
    rclpy.spin_until_future_complete(node, future)
    response: Annotated[SetSpeed.Response, "actual <= 2.0"] = future.result()  # warning: RF102
    node.get_logger().info('driving at %f' % response.actual)
