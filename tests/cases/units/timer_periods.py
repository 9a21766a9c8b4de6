"""A timer node: periods, stamps and timeouts converted the ways people write them keep
their converted unit; a wrong factor names the right one, and never twice."""
from typing import Annotated

import rclpy
from rclpy.node import Node

RATE_HZ: Annotated[float, "Unit('Hz') and _ > 0"] = 20.0
STOP_DISTANCE: Annotated[float, "Unit('m')"] = 0.3


def timing(
    hz: Annotated[float, "Unit('Hz') and _ > 0"],
    t: Annotated[float, "Unit('s')"],
    x: Annotated[float, "Unit('m')"],
    now_ns: Annotated[int, "Unit('ns')"],
) -> None:
    period_ms: Annotated[float, "Unit('ms')"] = 1000.0 / hz
    period_s: Annotated[float, "Unit('s')"] = 1.0 / hz
    stamp_ns: Annotated[int, "Unit('ns')"] = int(t * 1e9)
    stamp_us: Annotated[int, "Unit('us')"] = round(t * 1e6)
    offset_cm: Annotated[int, "Unit('cm')"] = round(x * 100)
    seconds: Annotated[float, "Unit('s')"] = now_ns / 1e9
    millis: Annotated[float, "Unit('ms')"] = now_ns / 1e6
    stamp_ns = int(t * 1e6)  # error: RF201
    period_ms = 1.0 / hz  # error: RF201
    seconds = now_ns  # error: RF201
    timeout: Annotated[float, "Unit('s')"] = 2 * t
    timeout = 2 * x  # error: RF201
    late = now_ns + t * 1000  # error: RF202
    late = now_ns + t * 1e9


class Ticker(Node):
    def __init__(self) -> None:
        super().__init__("ticker")
        self.period_ms = int(1000 / RATE_HZ)
        self.create_timer(1.0 / RATE_HZ, self.tick)

    def tick(self) -> None:
        wait: Annotated[float, "Unit('ms')"] = self.period_ms
        wait = STOP_DISTANCE  # error: RF201


def main() -> None:
    rclpy.init()
    rclpy.spin(Ticker())
