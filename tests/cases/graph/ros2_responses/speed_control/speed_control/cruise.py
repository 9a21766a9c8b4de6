"""Asks the servers for a speed and drives at what they grant, assuming the
motors can do it (after ros2/demos' add_two_ints_client, a synchronous call)."""
from typing import Annotated

import rclpy
from rclpy.node import Node
from speed_interfaces.srv import SetSpeed

Granted = Annotated[SetSpeed.Response, "actual <= 2.0"]


class Cruise(Node):
    def __init__(self):
        super().__init__('cruise')
        self.boost_cli = self.create_client(SetSpeed, 'set_speed')
        self.scale_cli = self.create_client(SetSpeed, 'scale_speed')
        self.clamp_cli = self.create_client(SetSpeed, 'clamped_speed')
        # near miss: the simulator's service, which this workspace does not serve
        self.sim_cli = self.create_client(SetSpeed, 'sim/set_speed')

    def boost(self, speed: float) -> float:
        req = SetSpeed.Request(speed=speed)
        # the client's own check cannot prove what it assumes of the response
        # warning: RF102
        resp: Annotated[SetSpeed.Response, "actual <= 2.0"] = self.boost_cli.call(req)
        return resp.actual

    def scaled(self, speed: float) -> float:
        resp: Granted = self.scale_cli.call(SetSpeed.Request(speed=speed))  # warning: RF102
        return resp.actual

    def clamped(self, speed: float) -> float:
        resp: Granted = self.clamp_cli.call(SetSpeed.Request(speed=speed))  # warning: RF102
        return resp.actual

    def simulated(self, speed: float) -> float:
        resp: Granted = self.sim_cli.call(SetSpeed.Request(speed=speed))  # warning: RF102
        return resp.actual


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Cruise())
