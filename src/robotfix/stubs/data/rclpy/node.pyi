# rclpy.node (ROS 2), checked against ros2/rclpy rclpy/node.py (rolling, 2024-12):
# create_timer(self, timer_period_sec, callback, callback_group=None, clock=None,
# autostart=True), create_rate(self, frequency, clock=None).
from typing import Annotated

from rclpy.client import Client
from rclpy.clock import Clock
from rclpy.timer import Rate, Timer

class Node:
    def get_clock(self) -> Clock: ...
    def create_timer(
        self,
        timer_period_sec: Annotated[float, "Unit('s')"],
        callback: object,
        callback_group: object = None,
        clock: object = None,
        autostart: bool = True,
    ) -> Timer: ...
    def create_rate(
        self, frequency: Annotated[float, "Unit('Hz')"], clock: object = None
    ) -> Rate: ...
    def create_client(
        self,
        srv_type: object,
        srv_name: str,
        *,
        qos_profile: object = None,
        callback_group: object = None,
    ) -> Client: ...
