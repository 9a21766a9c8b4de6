"""Asks for speeds through futures kept in the node (after the ros2/examples
minimal async client). Near misses: the future it reads is the clamping
server's (the turbo client's future is never refined), and a future of
either client is not followed."""
from typing import Annotated

import rclpy
from rclpy.node import Node
from speed_interfaces.srv import SetSpeed

Granted = Annotated[SetSpeed.Response, "actual <= 2.0"]


class AsyncCruise(Node):
    def __init__(self):
        super().__init__('async_cruise')
        self.turbo_cli = self.create_client(SetSpeed, 'turbo_speed')
        self.clamp_cli = self.create_client(SetSpeed, 'clamped_speed')
        self.future = None

    def send_request(self, speed: float) -> None:
        self.future = self.clamp_cli.call_async(SetSpeed.Request(speed=speed))

    def granted(self) -> float:
        response: Granted = self.future.result()  # warning: RF102
        return response.actual

    def either(self, speed: float, fast: bool) -> float:
        if fast:
            pending = self.turbo_cli.call_async(SetSpeed.Request(speed=speed))
        else:
            pending = self.clamp_cli.call_async(SetSpeed.Request(speed=speed))
        rclpy.spin_until_future_complete(self, pending)
        response: Granted = pending.result()  # warning: RF102
        return response.actual


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(AsyncCruise())
