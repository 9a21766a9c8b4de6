"""A racing-car simulator bridge and a keyboard teleop (as f1tenth's gym bridge and
teleop_tools' key_teleop keep their timestamps): rclpy Times kept on `self` in one
method and read in another, passed as typed parameters, kept in a `dict[int, Time]`
or a list, returned by a helper; rospy Times and Durations likewise. Each is an
object of the stub class its stub names (`robotfix/stubs/`), so `Time - Time` is a
Duration and `.nanoseconds` is in ns wherever the value was made. Each unit bug
sits beside its correct form."""
from typing import Annotated, Optional

import rclpy
import rospy
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.time import Time

DRIVE_TIMEOUT_S: Annotated[float, "Unit('s')"] = 0.5
KEY_TIMEOUT_MS: Annotated[float, "Unit('ms')"] = 250.0


class SimBridge(Node):
    def __init__(self) -> None:
        super().__init__("sim_bridge")
        self.clock = self.get_clock()
        self.last_drive = self.get_clock().now()  # no annotation: the stub says Time
        self.last_scan: Time = self.get_clock().now()
        self.pressed: dict[int, Time] = {}
        self.history = [self.get_clock().now()]
        self.grace: Optional[Duration] = None
        self.create_timer(0.02, self.tick)

    def on_drive(self) -> None:
        self.last_drive = self.clock.now()

    def tick(self) -> None:
        now = self.get_clock().now()
        if (now - self.last_drive).nanoseconds / 1e6 > DRIVE_TIMEOUT_S:  # error: RF202
            self.stop()
        if (now - self.last_drive).nanoseconds / 1e9 > DRIVE_TIMEOUT_S:
            self.stop()
        scan_age_s: Annotated[float, "Unit('s')"] = self.last_scan.nanoseconds / 1e9
        scan_age_s = self.last_scan.nanoseconds  # error: RF201
        if self.grace is not None and self.grace.nanoseconds / 1e9 > DRIVE_TIMEOUT_S:
            self.stop()
        if self.grace is not None and self.grace.nanoseconds > DRIVE_TIMEOUT_S:  # error: RF202
            self.stop()
        for stamp in self.history:
            kept_ns: Annotated[int, "Unit('ns')"] = stamp.nanoseconds
            kept_s: Annotated[float, "Unit('s')"] = stamp.nanoseconds  # error: RF201

    def key_expired(self, key: int) -> bool:
        now = self.clock.now()
        if (now - self.pressed[key]).nanoseconds < KEY_TIMEOUT_MS * 1e6:
            return False
        return (now - self.pressed[key]).nanoseconds < KEY_TIMEOUT_MS * 1e3  # error: RF202

    def seconds_since(self, then: Time) -> float:
        since_s: Annotated[float, "Unit('s')"] = (self.clock.now() - then).nanoseconds / 1e9
        since_s = (self.clock.now() - then).nanoseconds / 1e6  # error: RF201
        return since_s

    def newest(self) -> Time:
        return self.history[-1]

    def report(self) -> None:
        newest_ms: Annotated[float, "Unit('ms')"] = self.newest().nanoseconds / 1e6
        newest_ms = self.newest().nanoseconds / 1e9  # error: RF201

    def stop(self) -> None:
        pass


class Rospy1Watchdog:
    def __init__(self) -> None:
        self.started = rospy.Time.now()
        self.window = rospy.Duration(2)

    def check(self) -> None:
        up_s: Annotated[float, "Unit('s')"] = (rospy.Time.now() - self.started).to_sec()
        up_s = (rospy.Time.now() - self.started).to_nsec()  # error: RF201
        window_ms: Annotated[float, "Unit('ms')"] = self.window.to_sec() * 1000
        window_ms = self.window.to_sec()  # error: RF201


class Unknown:
    def __init__(self, source) -> None:
        self.stamp = source.stamp()  # nothing known of it: nothing said

    def read(self) -> None:
        anything: Annotated[float, "Unit('s')"] = self.stamp.nanoseconds
