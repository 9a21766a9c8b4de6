"""A differential-drive base node (as turtlebot3's and linorobot's bridges are
written): the motor drivers are built in `__init__` and used in the callbacks, so
their refined methods are checked through `self.left`, `self.right`; an attribute
whose assignments disagree has no type, and says nothing."""
from typing import Annotated, Optional

import rclpy
from geometry_msgs.msg import Pose, Twist
from nav_msgs.msg import Odometry
from rclpy.node import Node

WHEEL_RADIUS: Annotated[float, "Unit('m')"] = 0.033
PERIOD: Annotated[float, "Unit('s')"] = 0.1
MAX_PWM = 255


class MotorDriver:
    """A serial motor controller, one wheel."""

    def __init__(self, port: str) -> None:
        self.port = port

    def set_velocity(self, wheel: Annotated[float, "Unit('rad/s')"]) -> None:
        print(self.port, wheel)

    def set_pwm(self, duty: Annotated[int, "0 <= _ <= 255"]) -> None:
        print(self.port, duty)


class SimulatedDriver:
    def set_velocity(self, wheel: float) -> None:
        print(wheel)

    def set_pwm(self, duty: int) -> None:
        print(duty)


class DiffDriveBase(Node):
    def __init__(self) -> None:
        super().__init__("diff_drive_base")
        self.left = MotorDriver("/dev/ttyACM0")
        self.right = MotorDriver("/dev/ttyACM1")
        self.backup = MotorDriver("/dev/ttyUSB0")
        self.last_pose: Optional[Pose] = None
        self.last_cmd = None
        self.create_subscription(Twist, "cmd_vel", self.on_cmd_vel, 10)
        self.create_subscription(Odometry, "odom", self.on_odom, 10)
        self.create_timer(PERIOD, self.on_timer)

    def use_simulation(self) -> None:
        self.backup = SimulatedDriver()  # `self.backup` is one of two classes now

    def on_cmd_vel(self, msg: Twist) -> None:
        self.last_cmd = msg
        self.left.set_velocity(msg.linear.x)  # error: RF201
        self.right.set_velocity(msg.linear.x / WHEEL_RADIUS)
        self.left.set_pwm(MAX_PWM + 1)  # error: RF101
        self.right.set_pwm(MAX_PWM)
        self.backup.set_velocity(msg.linear.x)
        self.backup.set_pwm(MAX_PWM + 1)

    def on_odom(self, msg: Odometry) -> None:
        self.last_pose = msg.pose.pose

    def on_timer(self) -> None:
        """Dead reckoning between odometry messages."""
        if self.last_pose is None or self.last_cmd is None:
            return
        self.last_pose.position.x += self.last_cmd.linear.x  # error: RF202
        self.last_pose.position.x += self.last_cmd.linear.x * PERIOD


class Teleop(DiffDriveBase):
    """A subclass: `self.left` is its base class's driver."""

    def boost(self, msg: Twist) -> None:
        self.left.set_velocity(msg.angular.z)
        self.left.set_pwm(300)  # error: RF101


def main() -> None:
    rclpy.init()
    rclpy.spin(DiffDriveBase())
