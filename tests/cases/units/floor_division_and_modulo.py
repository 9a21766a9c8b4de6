"""`//` and `%` as Python computes them (issue 22, section 2): the quotient floored
and the remainder with the divisor's sign, for ints and floats, in code and in
refinements. `a // b` is in a's unit over b's (`ns // 1_000_000_000` is in s), and
`a % b` in a's unit. Each bug has its correct form beside it."""
from typing import Annotated

import rclpy
from builtin_interfaces.msg import Time
from rclpy.node import Node
from std_msgs.msg import UInt8

NS_PER_S = 1_000_000_000
NUM_LEDS = 12
BLINK_PERIOD_MS: Annotated[int, "Unit('ms')"] = 1500

Heading = Annotated[float, "Unit('deg') and -180.0 <= _ and _ < 180.0"]
Nanos = Annotated[int, "Unit('ns') and 0 <= _ and _ < 1000000000"]
LedIndex = Annotated[int, "0 <= _ and _ < 12"]
StereoSamples = Annotated[int, "_ >= 0 and _ % 2 == 0"]


def stamp_from_ns(now_ns: Annotated[int, "Unit('ns') and _ >= 0"]) -> Time:
    stamp = Time()
    stamp.sec = now_ns // NS_PER_S
    stamp.nanosec = now_ns % NS_PER_S
    stamp.sec = now_ns % NS_PER_S  # error: RF201
    nanos: Nanos = now_ns % NS_PER_S
    nanos = now_ns // NS_PER_S  # error: RF201
    stamp.nanosec = nanos
    return stamp


def wrap(yaw_deg: Annotated[float, "Unit('deg')"]) -> None:
    heading: Heading = (yaw_deg + 180.0) % 360.0 - 180.0
    heading = yaw_deg % 360.0 + 180.0  # error: RF101
    heading = -7.5 // 2 * 10.0
    heading = -7.5 // -2 * 100.0  # error: RF101


class LedRing(Node):
    def __init__(self) -> None:
        super().__init__("led_ring")
        self.led: LedIndex = 0
        self.pub = self.create_publisher(UInt8, "led", 10)
        self.timer = self.create_timer(BLINK_PERIOD_MS // 1000, self.tick)

    def tick(self) -> None:
        self.led = (self.led + 1) % NUM_LEDS
        self.led = (self.led - 1) % NUM_LEDS  # Python's remainder: never negative
        self.led = (self.led - 1) % -NUM_LEDS  # warning: RF102 "does not hold for every"
        msg = UInt8()
        msg.data = self.led
        self.pub.publish(msg)

    def buffer(self, pairs: Annotated[int, "_ >= 0"]) -> StereoSamples:
        samples: StereoSamples = 2 * pairs
        samples = 2 * pairs + 1  # error: RF101
        return samples


def main() -> None:
    rclpy.init()
    rclpy.spin(LedRing())
