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
    def straight(
        cls, linear_velocity: Annotated[float, "Unit('m/s') and 0 < _ <= 0.22"]
    ) -> Twist:
        twist = Twist()
        twist.linear.x = linear_velocity
        return twist

    def stop(self, decel: Annotated[float, "Unit('m/s^2') and 0 < _ <= 1.0"]) -> Twist:
        return Twist()
