"""`Annotated[Twist, "abs(linear.x) <= 0.22"]`: a refinement on a message-typed
parameter, variable or attribute (field paths relative to the value) is checked
where a value reaches it and assumed where it is read."""
from typing import Annotated

from geometry_msgs.msg import Twist
from rclpy.node import Node


class Limiter(Node):
    last: Annotated[Twist, "abs(angular.z) <= 2.84"]

    def __init__(self) -> None:
        super().__init__("limiter")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.last = Twist()

    def publish_limited(self, cmd: Annotated[Twist, "abs(_.linear.x) <= 0.22"]) -> None:
        speed: Annotated[float, "abs(_) <= 0.22"] = cmd.linear.x
        cmd.linear.x = 0.3  # error: RF101
        self.pub.publish(cmd)

    def forward(self, v: Annotated[float, "0 <= _ <= 0.2"]) -> None:
        t = Twist()
        t.linear.x = v
        self.publish_limited(t)
        fast = Twist()
        fast.linear.x = 0.5
        self.publish_limited(fast)  # error: RF101
        unknown = Twist()
        unknown.linear.x = v * 2
        self.publish_limited(unknown)  # warning: RF102

    def turn(self, w: float) -> None:
        cmd: Annotated[Twist, "abs(angular.z) <= 2.84"] = Twist()
        cmd.angular.z = 1.0
        cmd.angular.z = 3.0  # error: RF101
        self.last = cmd
        spun = Twist()
        spun.angular.z = -4.0
        self.last = spun  # error: RF101

    def replay(self) -> None:
        bounded: Annotated[float, "abs(_) <= 2.84"] = self.last.angular.z
        self.last.angular.z = 2.9  # error: RF101


def helper(t: Annotated[Twist, "t.linear.x <= 0.22 and t.linear.y == 0"]) -> None:
    t.linear.y = 0.0


def bad_paths(
    a: Annotated[Twist, "linear.q <= 1"],  # error: RF505
    b: Annotated[Twist, "abs(linear) <= 1"],  # error: RF505
) -> None:
    pass
