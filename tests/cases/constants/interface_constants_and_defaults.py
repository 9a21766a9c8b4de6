"""Interface constants and default values (issue 8, item 2): `DriveMode.MODE_AUTO`,
`msg.ULTRASOUND` and GoalStatus codes in code and in refinements; a field never set
holds its interface file's default (ROS 2's `Quaternion().w` is 1.0)."""
from typing import Annotated

import rclpy
from action_msgs.msg import GoalStatus
from geometry_msgs.msg import Pose, Quaternion
from rclpy.node import Node
from sensor_msgs.msg import Range

from constants_pkg.msg import DriveMode
from constants_pkg.srv import SetLimit


class ModeSwitcher(Node):
    def __init__(self) -> None:
        super().__init__("mode_switcher")
        self.mode_pub = self.create_publisher(DriveMode, "drive_mode", 10)
        self.home_pub = self.create_publisher(Pose, "home", 10)
        self.create_subscription(Range, "sonar", self.on_range, 10)
        self.create_service(SetLimit, "set_limit", self.on_set_limit)
        self.limit_client = self.create_client(SetLimit, "set_limit")

    def manual(self) -> None:
        cmd = DriveMode()
        cmd.mode = DriveMode.MODE_MANUAL
        cmd.max_accel = 1.0
        self.mode_pub.publish(cmd)  # max_speed keeps its default 0.5: fine

    def auto(self) -> None:
        cmd = DriveMode()
        cmd.mode = cmd.MODE_AUTO
        self.mode_pub.publish(cmd)  # error: RF302

    def stop(self) -> None:
        cmd = DriveMode()
        cmd.max_accel = 2.0
        self.mode_pub.publish(cmd)  # error: RF302

    def toggle(self, cmd: DriveMode) -> None:
        cmd.mode = DriveMode.MODE_AUTO if cmd.mode == DriveMode.MODE_MANUAL else 1
        cmd.mode = DriveMode.MODE_AUTO + 1  # error: RF101
        cmd.heading = 3.0
        cmd.heading = 3.2  # error: RF101

    def go_home(self) -> None:
        self.home_pub.publish(Pose())
        self.home_pub.publish(Quaternion())
        flipped = Quaternion()
        flipped.w = -1.0  # error: RF101

    def on_range(self, msg: Range) -> None:
        kind: Annotated[int, "_ == Range.ULTRASOUND"] = Range.ULTRASOUND
        sonar: Annotated[int, "_ == Range.ULTRASOUND"] = msg.ULTRASOUND
        ir: Annotated[int, "_ == Range.ULTRASOUND"] = msg.INFRARED  # error: RF101

    def on_goal_status(self, status: GoalStatus) -> None:
        done: Annotated[int, "_ >= GoalStatus.STATUS_SUCCEEDED"] = status.STATUS_ABORTED
        # error: RF101
        busy: Annotated[int, "_ >= GoalStatus.STATUS_SUCCEEDED"] = status.STATUS_EXECUTING

    def on_set_limit(self, request, response):
        if request.limit > 1.5:
            response.code = response.REJECTED
        else:
            response.code = SetLimit.Response.OK
        return response

    def request_limit(self, speed: Annotated[float, "Unit('m/s') and 0 < _ <= 1"]) -> None:
        req = SetLimit.Request()
        self.limit_client.call_async(req)  # limit keeps its default 1.0: fine
        req.limit = speed * 2
        req.limit = SetLimit.Request.MAX_LIMIT + 0.5  # error: RF101
        self.limit_client.call_async(req)


def main() -> None:
    rclpy.init()
    rclpy.spin(ModeSwitcher())
