"""An integer field holds what its type holds (issue 22, section 2): a `uint8`
read from a received message is in 0..255, an `int8` in -128..127, and each
element of a `uint16[]` in 0..65535, so a refinement that needs no more is proved.
Writing a number outside the type's range into such a field is RF101 when the
number is certain (`UInt8(data=-1)` as a "no reading" sentinel, as C code would)."""
from typing import Annotated

import rclpy
import rospy
from rclpy.node import Node
from robot_msgs.msg import Battery
from std_msgs.msg import Int8, UInt8

NO_READING = -1


def to_ratio(percent: Annotated[int, "_ >= 0"]) -> float:
    return percent / 100.0


def cell_ok(millivolts: Annotated[int, "0 <= _ and _ < 70000"]) -> bool:
    return millivolts > 3300


class BatteryMonitor(Node):
    def __init__(self) -> None:
        super().__init__("battery_monitor")
        self.create_subscription(Battery, "battery", self.on_battery, 10)
        self.level_pub = self.create_publisher(UInt8, "level", 10)
        self.temp_pub = self.create_publisher(Int8, "temperature", 10)

    def on_battery(self, msg: Battery) -> None:
        ratio = to_ratio(msg.percentage)
        healthy = all(cell_ok(mv) for mv in msg.cell_mv)
        above_max: Annotated[int, "_ > 255"] = msg.percentage  # error: RF101
        freezing: Annotated[int, "_ >= -128"] = msg.temperature_c
        if ratio < 0.1 or not healthy:
            self.level_pub.publish(UInt8(data=NO_READING))  # error: RF101
            self.level_pub.publish(UInt8(data=255))
        level = UInt8()
        level.data = 256  # error: RF101
        level.data = msg.percentage
        self.level_pub.publish(level)
        self.temp_pub.publish(Int8(data=msg.temperature_c))


brightness_pub = rospy.Publisher("brightness", UInt8, queue_size=1)


def on_battery_ros1(battery: Battery) -> None:
    brightness_pub.publish(UInt8(data=battery.percentage))
    ratio = to_ratio(battery.percentage)
    brightness_pub.publish(UInt8(data=int(ratio * 255)))
    brightness_pub.publish(UInt8(data=battery.percentage + 256))  # error: RF101
    brightness_pub.publish(UInt8(data=battery.percentage + 1))  # may hold: silent


def ros1_main() -> None:
    rospy.init_node("led_bar")
    rospy.Subscriber("battery", Battery, on_battery_ros1)


def main() -> None:
    rclpy.init()
    rclpy.spin(BatteryMonitor())
