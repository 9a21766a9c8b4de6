"""A battery monitor: REP 103 units of BatteryState, class invariants."""
from typing import Annotated

from rclpy.node import Node
from sensor_msgs.msg import BatteryState
from std_msgs.msg import Bool


class BatteryMonitor(Node):
    def __init__(self) -> None:
        super().__init__("battery_monitor")
        self.low: Annotated[float, "Unit('1') and 0 < _ < 1"] = 0.2
        self.min_millivolts: Annotated[float, "Unit('mV') and _ > 0"] = 11000
        self.alarm = self.create_publisher(Bool, "battery_low", 1)
        self.create_subscription(BatteryState, "battery", self.on_battery, 1)

    def on_battery(self, msg: BatteryState) -> None:
        flag = Bool()
        flag.data = msg.percentage < self.low
        if msg.voltage < self.min_millivolts:  # error: RF202 "divide by 1000"
            flag.data = True
        if msg.voltage * 1000 < self.min_millivolts:
            flag.data = True
        self.alarm.publish(flag)

    def configure(self, percent: float) -> None:
        self.low = 20  # error: RF101
        self.low = percent / 100  # warning: RF102
        if 0 < percent < 100:
            self.low = percent / 100
