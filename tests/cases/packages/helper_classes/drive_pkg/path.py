"""Motion helpers grouped in a class, as turtlebot3's examples write them."""
from typing import Annotated

from geometry_msgs.msg import Twist


class Path:
    @staticmethod
    def turn(
        angular_velocity: Annotated[float, "Unit('rad/s') and 0 < _ <= 2.84"],
    ) -> Twist:
        twist = Twist()
        twist.angular.z = angular_velocity
        return twist

    @classmethod
    def forward(cls, speed: Annotated[float, "Unit('m/s') and 0 < _ <= 0.26"]) -> Twist:
        return cls.turn(0.5) if speed == 0 else Twist()

    def brake(self, decel: Annotated[float, "Unit('m/s^2') and 0 < _ <= 2.0"]) -> None:
        print(decel)
