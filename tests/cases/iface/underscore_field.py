"""`_` on a field's line (and in an IDL verbatim line) names that field, in
`Unit(_) == "..."`, `Frame(_)`, comparisons, `len(_)` and `_.x` of a sub-message."""

from typing import Annotated

from rclpy.node import Node

from iface.msg import DriveCommand, Joint


class Base(Node):
    def __init__(self) -> None:
        super().__init__("base")
        self.pub = self.create_publisher(DriveCommand, "drive", 10)
        self.joint_pub = self.create_publisher(Joint, "joint", 10)

    def drive_kmh(self, v: Annotated[float, "Unit('km/h') and 0 <= _ <= 5"]) -> None:
        cmd = DriveCommand()
        cmd.speed = v  # error: RF201
        cmd.mode = DriveCommand.MODE_VELOCITY
        self.pub.publish(cmd)

    def drive(self, v: Annotated[float, "Unit('km/h') and 0 <= _ <= 5"]) -> None:
        cmd = DriveCommand()
        cmd.speed = v / 3.6  # clean: at most 1.39 m/s
        cmd.mode = DriveCommand.MODE_VELOCITY
        self.pub.publish(cmd)

    def too_fast(self) -> None:
        cmd = DriveCommand()
        cmd.speed = 2.0  # error: RF101
        cmd.mode = DriveCommand.MODE_VELOCITY
        self.pub.publish(cmd)

    def turn(
        self,
        yaw: Annotated[float, "Unit('degree')"],
        yaw_rad: Annotated[float, "Unit('rad') and abs(_) <= 3"],
    ) -> None:
        cmd = DriveCommand()
        cmd.heading = yaw  # error: RF201
        cmd.heading = yaw_rad  # clean
        cmd.mode = DriveCommand.MODE_IDLE
        self.pub.publish(cmd)

    def frames(self, x: Annotated[float, "Frame('map') and abs(_) <= 3"]) -> None:
        cmd = DriveCommand()
        cmd.heading = x  # clean: a frame alone names no unit (heading's is rad)
        cmd.mode = 7  # error: RF101
        self.pub.publish(cmd)

    def wheels(self) -> None:
        cmd = DriveCommand()
        cmd.wheel_speeds = [1.0, -1.0]  # clean
        cmd.wheel_speeds = [1.0, 25.0]  # error: RF101
        cmd.wheel_speeds = [0.0, 0.0, 0.0, 0.0, 0.0]  # error: RF101
        cmd.mode = DriveCommand.MODE_IDLE
        self.pub.publish(cmd)

    def accelerate(
        self, a: Annotated[float, "Unit('m/s^2')"], d: Annotated[float, "Unit('m')"]
    ) -> None:
        cmd = DriveCommand()
        cmd.accel.x = 4.0  # error: RF101
        cmd.accel.x = 1.0  # clean
        cmd.accel.y = d  # error: RF201
        cmd.accel.y = a if a <= 1.0 else 1.0  # clean
        cmd.mode = DriveCommand.MODE_IDLE
        self.pub.publish(cmd)

    def move_joint(self, deg: Annotated[float, "Unit('degree')"]) -> None:
        j = Joint()
        j.position = deg  # error: RF201
        j.position = 4.0  # error: RF101
        j.position = 3.0  # clean
        j.velocity = 1.0  # clean
        self.joint_pub.publish(j)
