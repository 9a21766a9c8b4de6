"""A lambda is analysed where it is written: it sees the enclosing function's
names by their declarations (a refined parameter, a typed parameter, `self`), as a
nested `def` does, whether it is a timer's callback, a subscription's, or bound to
a name (ros2/demos' deadline example: `lambda: talker.pause_for(pause_for_ms)`)."""
import time
from typing import Annotated

from geometry_msgs.msg import Twist
from rclpy.node import Node

PAUSE_MS: Annotated[int, "Unit('ms')"] = 100


class Talker(Node):
    def __init__(self) -> None:
        super().__init__("talker")

    def pause_for(self, seconds: Annotated[float, "Unit('s')"]) -> None:
        time.sleep(seconds)


class MotorDriver:
    def set_rpm(self, rpm: Annotated[float, "Unit('rpm')"]) -> None:
        self.rpm = rpm


def deadline(node: Node, talker: Talker, pause_for_ms: Annotated[int, "Unit('ms')"]):
    node.create_timer(5.0, lambda: talker.pause_for(pause_for_ms))  # error: RF201
    node.create_timer(5.0, lambda: talker.pause_for(pause_for_ms / 1000.0))
    talker_node = Talker()
    node.create_timer(1.0, lambda: talker_node.pause_for(pause_for_ms))  # error: RF201
    later = lambda: time.sleep(PAUSE_MS)  # error: RF201
    fine = lambda: time.sleep(PAUSE_MS / 1000.0)
    return later, fine


class Base(Node):
    def __init__(self) -> None:
        super().__init__("base")
        self.left = MotorDriver()
        self.w: Annotated[float, "Unit('rad/s')"] = 0.0
        self.create_timer(0.1, lambda: self.left.set_rpm(self.w))  # error: RF201
        self.create_timer(0.1, lambda: self.left.set_rpm(self.w * 60.0 / 6.283185307179586))
        self.create_subscription(
            Twist, "cmd", lambda msg: self.left.set_rpm(msg.angular.z), 10  # error: RF201
        )
