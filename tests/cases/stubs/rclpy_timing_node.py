"""An rclpy node with no annotation on the APIs it calls: the shipped stubs give
create_timer, create_rate, Duration, Time, the clock and wait_for_service their units."""
from typing import Annotated

import rclpy
from stubs_pkg.srv import AddTwoInts
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.time import Time

PUBLISH_PERIOD_MS: Annotated[float, "Unit('ms') and _ > 0"] = 50.0
CONTROL_RATE_HZ: Annotated[float, "Unit('Hz') and _ > 0"] = 20.0
SERVICE_TIMEOUT_MS: Annotated[int, "Unit('ms')"] = 1500


class Watchdog(Node):
    def __init__(self) -> None:
        super().__init__("watchdog")
        self.declare_parameter("stale_after", 0.5)
        self.timer = self.create_timer(PUBLISH_PERIOD_MS, self.tick)  # error: RF201
        self.timer = self.create_timer(PUBLISH_PERIOD_MS / 1000.0, self.tick)
        self.rate = self.create_rate(1.0 / CONTROL_RATE_HZ)  # error: RF201
        self.rate = self.create_rate(CONTROL_RATE_HZ)
        self.client = self.create_client(AddTwoInts, "add_two_ints")
        self.last_seen_ns = self.get_clock().now().nanoseconds

    def connect(self) -> bool:
        # the client's type is not known here: wait_for_service is found by its name
        ready = self.client.wait_for_service(timeout_sec=SERVICE_TIMEOUT_MS)  # error: RF201
        ready = self.client.wait_for_service(timeout_sec=SERVICE_TIMEOUT_MS / 1000)
        return ready

    def tick(self) -> None:
        now_ns = self.get_clock().now().nanoseconds
        age_s: Annotated[float, "Unit('s')"] = now_ns  # error: RF201
        age_s = now_ns / 1e9
        grace = Duration(seconds=PUBLISH_PERIOD_MS)  # error: RF201
        grace = Duration(seconds=PUBLISH_PERIOD_MS / 1000.0)
        grace = Duration(nanoseconds=int(PUBLISH_PERIOD_MS * 1e6))
        total_ms: Annotated[float, "Unit('ms')"] = grace.nanoseconds / 1e6
        stamp = Time(seconds=age_s, nanoseconds=now_ns)
        stamp = Time(seconds=now_ns)  # error: RF201


def main() -> None:
    rclpy.init()
    node = Watchdog()
    rclpy.spin_once(node, timeout_sec=PUBLISH_PERIOD_MS)  # error: RF201
    rclpy.spin_once(node, timeout_sec=PUBLISH_PERIOD_MS / 1000.0)
    future = node.client.call_async(AddTwoInts.Request())
    # spin_until_future_complete(node, future, executor=None, timeout_sec=None)
    rclpy.spin_until_future_complete(node, future, None, SERVICE_TIMEOUT_MS)  # error: RF201
    rclpy.spin_until_future_complete(node, future, None, 1.5)
    rclpy.spin_until_future_complete(node, future, timeout_sec=1.5)
    rclpy.shutdown()
