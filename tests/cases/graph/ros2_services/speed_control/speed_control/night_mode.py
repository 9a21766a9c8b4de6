"""Sets a night-time limit once and exits (after ros2/demos' add_two_ints_client:
the client is a local of `main`)."""
import rclpy
from speed_interfaces.srv import SetSpeed

NIGHT_SPEED = 2.5  # meant as km/h, sent as m/s


def main(args=None):
    rclpy.init(args=args)
    node = rclpy.create_node('night_mode')
    cli = node.create_client(SetSpeed, 'set_max_speed')
    while not cli.wait_for_service(timeout_sec=1.0):
        node.get_logger().info('service not available, waiting again...')
    req = SetSpeed.Request()
    req.speed = NIGHT_SPEED
    future = cli.call_async(req)  # error: RF101
    rclpy.spin_until_future_complete(node, future)
    node.destroy_node()
    rclpy.shutdown()
