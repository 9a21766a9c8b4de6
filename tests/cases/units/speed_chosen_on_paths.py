"""A number set on several paths in different units: a store into a field of one
unit is RF201 when a path on which it is in another one is feasible."""
from typing import Annotated

from geometry_msgs.msg import Twist
from rclpy.node import Node
from std_msgs.msg import Bool

CRUISE_KMH: Annotated[float, "Unit('km/h')"] = 3.0
CREEP_MPS: Annotated[float, "Unit('m/s')"] = 0.1


def steer() -> tuple[Annotated[float, "Unit('m/s')"], Annotated[float, "Unit('rad/s')"]]:
    return 0.1, 0.2


class ModeNode(Node):
    def __init__(self) -> None:
        super().__init__("mode")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_subscription(Bool, "cruise", self.on_mode, 10)

    def on_mode(self, msg: Bool) -> None:
        if msg.data:
            speed = CRUISE_KMH
        else:
            speed = CREEP_MPS
        cmd = Twist()
        cmd.linear.x = speed  # error: RF201 "km/h on some path"
        self.pub.publish(cmd)

    def on_mode_converted(self, msg: Bool) -> None:
        if msg.data:
            speed = CRUISE_KMH / 3.6
        else:
            speed = CREEP_MPS
        cmd = Twist()
        cmd.linear.x = speed  # both paths in m/s: clean
        self.pub.publish(cmd)

    def on_mode_converted_later(self, msg: Bool) -> None:
        cruise = msg.data
        if cruise:
            speed = CRUISE_KMH
        else:
            speed = CREEP_MPS
        if cruise:
            speed = speed / 3.6
        cmd = Twist()
        cmd.linear.x = speed  # the km/h path was converted: clean
        self.pub.publish(cmd)

    def on_mode_elif(self, mode: int) -> None:
        if mode == 0:
            speed = 0.0
        elif mode == 1:
            speed = CREEP_MPS
        else:
            speed = CRUISE_KMH
        cmd = Twist()
        cmd.linear.x = speed  # error: RF201 "km/h on some path"
        self.pub.publish(cmd)

    def on_mode_never_cruise(self, msg: Bool) -> None:
        cruise = False
        if cruise:
            speed = CRUISE_KMH
        else:
            speed = CREEP_MPS
        cmd = Twist()
        cmd.linear.x = speed  # the km/h path is never taken: clean
        self.pub.publish(cmd)


def unpacked(pub, reverse: bool) -> None:
    if reverse:
        omega, v = steer()  # the wrong order, on this path only
    else:
        v, omega = steer()
    cmd = Twist()
    cmd.linear.x = v  # error: RF201 "rad/s on some path"
    cmd.angular.z = omega  # error: RF201 "m/s on some path"
    pub.publish(cmd)


def unpacked_scaled(pub, reverse: bool) -> None:
    if reverse:
        omega, v = steer()
    else:
        v, omega = steer()
    cmd = Twist()
    cmd.linear.x = 2 * v  # a new number: its unit is not known (silent, as before)
    pub.publish(cmd)
