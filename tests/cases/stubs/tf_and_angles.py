"""tf2 and tf_transformations: lookup_transform gives a TransformStamped (translation
in m), euler_from_quaternion radians, quaternion_from_euler takes radians; numpy and
math convert; time.sleep takes seconds."""
import math
import time
from typing import Annotated

import numpy as np
import rclpy
import tf2_ros
from geometry_msgs.msg import Twist
from rclpy.node import Node
from tf_transformations import euler_from_quaternion, quaternion_from_euler

MAX_TILT_DEG: Annotated[float, "Unit('degree')"] = 15.0
POLL_MS: Annotated[float, "Unit('ms')"] = 20.0
STANDOFF_CM: Annotated[float, "Unit('cm')"] = 40.0
K_APPROACH: Annotated[float, "Unit('1/s')"] = 0.5


class Follower(Node):
    def __init__(self) -> None:
        super().__init__("follower")
        self.tf_buffer = tf2_ros.Buffer()
        self.publisher = self.create_publisher(Twist, "cmd_vel", 10)
        self.timer = self.create_timer(0.1, self.follow)

    def follow(self) -> None:
        t = self.tf_buffer.lookup_transform("base_link", "target", rclpy.time.Time())
        q = t.transform.rotation
        roll, pitch, yaw = euler_from_quaternion([q.x, q.y, q.z, q.w])
        heading_deg: Annotated[float, "Unit('degree')"] = yaw  # error: RF201
        heading_deg = math.degrees(yaw)
        heading_deg = np.rad2deg(yaw)
        if abs(pitch) > MAX_TILT_DEG:  # error: RF202
            return
        if abs(pitch) > math.radians(MAX_TILT_DEG):
            return
        level = quaternion_from_euler(0.0, 0.0, heading_deg)  # error: RF201
        level = quaternion_from_euler(0.0, 0.0, yaw)
        gap: Annotated[float, "Unit('cm')"] = t.transform.translation.x  # error: RF201
        gap = t.transform.translation.x * 100.0
        cmd = Twist()
        cmd.linear.x = K_APPROACH * (gap - STANDOFF_CM) / 100.0
        cmd.angular.z = 0.8 * np.deg2rad(heading_deg)  # warning: RF203
        turn = np.deg2rad(yaw)  # error: RF201
        turn = np.deg2rad(heading_deg)
        bearing = np.arctan2(t.transform.translation.y, STANDOFF_CM)  # error: RF202
        bearing = np.arctan2(t.transform.translation.y, t.transform.translation.x)
        self.publisher.publish(cmd)


def poll() -> None:
    time.sleep(POLL_MS)  # error: RF201
    time.sleep(POLL_MS / 1000.0)
    start = time.monotonic()
    spent_ms: Annotated[float, "Unit('ms')"] = time.monotonic() - start  # error: RF201
    spent_ms = (time.monotonic() - start) * 1000.0
    side = math.hypot(STANDOFF_CM, POLL_MS)  # error: RF202
    side = math.hypot(STANDOFF_CM, 30.0)
    reach: Annotated[float, "Unit('cm')"] = side
    reach = float(np.clip(side, 0.0, 100.0))
