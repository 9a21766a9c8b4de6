"""The code after a `while True` loop left by `break` runs, and is checked like any
other (it was skipped as unreachable: a unit mix-up or a broken limit there went
unreported). After a `while True` with no `break`, nothing runs."""
import time
from typing import Annotated

from geometry_msgs.msg import Twist
from rclpy.node import Node

Hz = Annotated[float, "Unit('Hz') and 0 < _ <= 50"]
Speed = Annotated[float, "Unit('m/s') and 0 <= _ <= 0.5"]


class KeyTeleop(Node):
    def __init__(self, interface):
        super().__init__("key_teleop")
        self._interface = interface
        self._hz: Hz = self.declare_parameter("hz", 10.0).value
        self._pub = self.create_publisher(Twist, "key_vel", 10)
        self._running = False

    def run(self) -> None:
        self._running = True
        while self._running:
            while True:  # read every key pressed since the last tick
                keycode = self._interface.read_key()
                if keycode is None:
                    break
            time.sleep(self._hz)  # error: RF201

    def run_fixed(self) -> None:
        self._running = True
        while self._running:
            while True:
                keycode = self._interface.read_key()
                if keycode is None:
                    break
            time.sleep(1.0 / self._hz)

    def wait_then_drive(self) -> None:
        while True:
            if self._pub.get_subscription_count() > 0:
                break
            time.sleep(0.1)
        speed: Speed = 0.6  # error: RF101
        cmd = Twist()
        cmd.linear.x = speed
        self._pub.publish(cmd)

    def wait_then_drive_fixed(self) -> None:
        while 1:
            if self._pub.get_subscription_count() > 0:
                break
            time.sleep(0.1)
        speed: Speed = 0.5
        cmd = Twist()
        cmd.linear.x = speed
        self._pub.publish(cmd)

    def spin_forever(self) -> None:
        while True:
            time.sleep(1.0 / self._hz)
        time.sleep(self._hz)  # never runs: nothing to report
