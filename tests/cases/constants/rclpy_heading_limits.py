"""A class-based rclpy node: class constants, `Final` module constants and `pi` in
refinements, headings wrapped with atan2 (issue 8, item 1)."""
import math
from math import pi
from typing import Annotated, Final

import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.node import Node

TWO_PI: Final = 2 * math.pi
MAX_RANGE: Final = 3.5
LIMITS = (0.22, 2.84)  # linear m/s, angular rad/s


def normalize(
    angle: Annotated[float, "Unit('rad')"],
) -> Annotated[float, "Unit('rad') and -pi <= _ <= pi"]:
    return math.atan2(math.sin(angle), math.cos(angle))


def half_turn() -> Annotated[float, "Unit('rad') and abs(_) <= math.pi"]:
    return TWO_PI / 2


def full_turn() -> Annotated[float, "Unit('rad') and abs(_) <= math.pi"]:
    return TWO_PI  # error: RF101


class HeadingController(Node):
    MAX_ANG_VEL = 2.84
    KP = 0.8
    turn_rate: Annotated[float, "Unit('rad/s') and abs(_) <= MAX_ANG_VEL"]
    stop_distance: Annotated[float, "Unit('m') and 0 < _ <= MAX_RANGE"]
    goal: Annotated[float, "Unit('rad') and -math.pi <= _ <= math.pi"]

    def __init__(self) -> None:
        super().__init__("heading_controller")
        self.turn_rate = 0.0
        self.stop_distance = 0.5
        self.goal = 0.0
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_subscription(Odometry, "odom", self.on_odom, 10)
        self.create_timer(0.1, self.on_timer)

    def set_goal(self, yaw: Annotated[float, "Unit('rad')"]) -> None:
        self.goal = normalize(yaw)
        self.goal = normalize(yaw) + TWO_PI  # warning: RF102

    def set_stop_distance(self, distance: Annotated[float, "Unit('m')"]) -> None:
        self.stop_distance = 4.0  # error: RF101
        self.stop_distance = min(distance, MAX_RANGE)  # warning: RF102
        if distance > 0:
            self.stop_distance = min(distance, MAX_RANGE)

    def on_odom(self, odom: Odometry) -> None:
        q = odom.pose.pose.orientation
        heading = math.atan2(2.0 * (q.w * q.z), 1.0 - 2.0 * (q.z * q.z))
        error = normalize(self.goal - heading)
        rate = self.KP * error
        self.turn_rate = max(-self.MAX_ANG_VEL, min(self.MAX_ANG_VEL, rate))  # warning: RF203
        self.turn_rate = self.MAX_ANG_VEL + 0.01  # error: RF101
        lin, ang = LIMITS
        self.turn_rate = ang
        self.turn_rate = LIMITS[0] * 20  # error: RF101

    def on_timer(self) -> None:
        cmd = Twist()
        cmd.angular.z = self.turn_rate
        limit: Annotated[float, "_ <= HeadingController.MAX_ANG_VEL"] = abs(cmd.angular.z)
        self.pub.publish(cmd)


def main() -> None:
    rclpy.init()
    rclpy.spin(HeadingController())
