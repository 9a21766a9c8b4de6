"""The near miss of night_mode: the same local client, a limit the motors do; and
a second function whose own local `cli` is another client (each is its own)."""
import rclpy
from speed_interfaces.srv import SetSpeed

DAY_SPEED = 1.5


def main(args=None):
    rclpy.init(args=args)
    node = rclpy.create_node('day_mode')
    cli = node.create_client(SetSpeed, 'set_max_speed')
    req = SetSpeed.Request()
    req.speed = DAY_SPEED
    future = cli.call_async(req)
    rclpy.spin_until_future_complete(node, future)


def other_robot(node):
    cli = node.create_client(SetSpeed, '/robot2/set_max_speed')
    req = SetSpeed.Request()
    req.speed = 3.0  # robot2's limit server is not in this workspace
    return cli.call_async(req)
