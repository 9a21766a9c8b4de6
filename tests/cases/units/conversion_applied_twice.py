"""A conversion factor (1000, 1e9, 100, 60, 3.6, 180/pi) applied to a value that is
already in its target's unit converts it a second time (issue 22, section 3): a
period in s times 1000 is in ms, a stamp in ns over 1e9 is in s. The correct
conversions beside them, and plain gains (`2 * T`, `/ 2`), stay silent."""
from typing import Annotated

import rclpy
import rospy
from geometry_msgs.msg import Twist
from rclpy.node import Node

PERIOD_S: Annotated[float, "Unit('s')"] = 0.05
PUBLISH_HZ: Annotated[float, "Unit('Hz') and _ > 0"] = 20.0
MAX_SPEED: Annotated[float, "Unit('m/s')"] = 0.22


class CommandTimeout(Node):
    def __init__(self) -> None:
        super().__init__("command_timeout")
        self.stale_s: Annotated[float, "Unit('s')"] = 0.5
        self.create_timer(PERIOD_S * 1000, self.check)  # error: RF201
        self.create_timer(PERIOD_S, self.check)
        self.create_timer(2 * PERIOD_S, self.check)
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)

    def check(self) -> None:
        now_ns: Annotated[int, "Unit('ns')"] = self.get_clock().now().nanoseconds
        age_ns: Annotated[float, "Unit('ns')"] = now_ns / 1e9  # error: RF201
        age_s: Annotated[float, "Unit('s')"] = now_ns / 1e9
        if age_s > self.stale_s * 1000:  # error: RF202
            return
        if age_s > self.stale_s / 2:
            cmd = Twist()
            cmd.linear.x = MAX_SPEED * 3.6  # error: RF201
            cmd.linear.x = MAX_SPEED / 2
            self.pub.publish(cmd)


def blink(off_time: Annotated[float, "Unit('s')"]) -> None:
    rospy.sleep(off_time * 1000)  # error: RF201
    rospy.sleep(off_time)
    period: Annotated[float, "Unit('s')"] = 1000.0 / PUBLISH_HZ  # error: RF201
    period = 1.0 / PUBLISH_HZ
    period_ms: Annotated[float, "Unit('ms')"] = 1000.0 / PUBLISH_HZ
    rospy.Duration(1000 / PUBLISH_HZ)  # error: RF201
    rospy.Duration(1 / PUBLISH_HZ)
    minutes: Annotated[float, "Unit('min')"] = off_time * 60  # error: RF201
    minutes = off_time / 60


def heading(
    current_pos: Annotated[float, "Unit('rad')"],
    offset_cm: Annotated[float, "Unit('cm')"],
) -> None:
    target: Annotated[float, "Unit('rad')"] = current_pos * 180 / 3.141592653589793  # error: RF201
    target = current_pos / 2
    offset: Annotated[float, "Unit('cm')"] = offset_cm * 100  # error: RF201
    offset_m: Annotated[float, "Unit('m')"] = offset_cm / 100


def main() -> None:
    rclpy.init()
    rclpy.spin(CommandTimeout())
