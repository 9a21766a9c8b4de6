"""Time objects as ROS code computes with them (issue 22, section 3): rclpy's
`Time - Time` is a Duration (`.nanoseconds` in ns), `Time + Duration` a Time,
`Duration.from_msg` and `to_msg()` read and give builtin_interfaces messages (`sec` in
s, `nanosec` in ns); rospy's `Time - Time` is a Duration, `Duration * k` one too, and
`to_sec()` is in s. Each wrong unit sits beside its correct form."""
from typing import Annotated

import rclpy
import rospy
from builtin_interfaces.msg import Time as TimeMsg
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.time import Time

TIMEOUT_S: Annotated[float, "Unit('s')"] = 0.5


class CommandWatchdog(Node):
    def __init__(self) -> None:
        super().__init__("command_watchdog")
        self.create_timer(0.1, self.check)

    def check(self) -> None:
        start = self.get_clock().now()
        now = self.get_clock().now()
        age_ns: Annotated[float, "Unit('ns')"] = (now - start).nanoseconds
        age_s: Annotated[float, "Unit('s')"] = (now - start).nanoseconds / 1e9
        age_ns = (now - start).nanoseconds / 1e9  # error: RF201
        if age_s > TIMEOUT_S:
            return
        deadline = now + Duration(seconds=TIMEOUT_S)
        left_s: Annotated[float, "Unit('s')"] = (deadline - now).nanoseconds / 1e9
        left_s = (deadline - now).nanoseconds  # error: RF201

    def eta(self, remaining: TimeMsg) -> None:
        eta_s: Annotated[float, "Unit('s')"] = Duration.from_msg(remaining).nanoseconds / 1e9
        eta_s = Duration.from_msg(remaining).nanoseconds / 1e6  # error: RF201
        stamp = self.get_clock().now().to_msg()
        whole_s: Annotated[int, "Unit('s')"] = stamp.sec
        whole_s = stamp.nanosec  # error: RF201
        back = Time.from_msg(stamp)
        since_ns: Annotated[int, "Unit('ns')"] = back.nanoseconds


def ros1_loop(hz: Annotated[float, "Unit('Hz') and _ > 0"]) -> None:
    last = rospy.Time.now()
    now = rospy.Time.now()
    elapsed = now - last
    dt: Annotated[float, "Unit('s')"] = elapsed.to_sec()
    dt_ms: Annotated[float, "Unit('ms')"] = elapsed.to_sec() * 1000
    dt_ms = elapsed.to_sec()  # error: RF201
    twice: Annotated[float, "Unit('s')"] = (elapsed * 2).to_sec()
    twice = (elapsed * 2).to_nsec()  # error: RF201
    earlier: Annotated[float, "Unit('s')"] = (now - elapsed).to_sec()
    rospy.sleep(elapsed.to_sec())
    rospy.sleep(elapsed.to_nsec())  # error: RF201


def main() -> None:
    rclpy.init()
    rclpy.spin(CommandWatchdog())
