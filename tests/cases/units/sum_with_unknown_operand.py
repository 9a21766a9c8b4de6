"""A sum whose one operand has no known unit is in the other's unit: on every path
where it means anything (a sum of two units is the bug itself). Modelled on
turtlebot3's teleop_keyboard, whose target velocity is stepped in a key loop."""
from typing import Annotated

import rclpy
from geometry_msgs.msg import Twist

RadPerSec = Annotated[float, "Unit('rad/s')"]
ANG_STEP_DEG: Annotated[float, "Unit('deg/s')"] = 5.0
ANG_STEP: Annotated[float, "Unit('rad/s')"] = 0.1
LIN_STEP: Annotated[float, "Unit('m/s')"] = 0.01


def constrain(velocity: RadPerSec, low: float, high: float) -> RadPerSec:
    return min(max(velocity, low), high)


def teleop(pub, get_key) -> None:
    target_angular = 0.0
    target_linear = 0.0
    while rclpy.ok():
        key = get_key()
        if key == "a":
            # target_angular's unit is lost to the loop; the step's is not
            target_angular = constrain(target_angular + ANG_STEP_DEG, -2.8, 2.8)  # error: RF201 "deg/s"
        elif key == "d":
            target_angular = constrain(target_angular - ANG_STEP, -2.8, 2.8)  # clean: rad/s
        elif key == "w":
            target_linear = target_linear + LIN_STEP
        twist = Twist()
        twist.linear.x = target_linear  # clean: m/s, the field's unit
        twist.angular.z = target_angular
        pub.publish(twist)


def from_a_parameter(pub, current) -> None:
    twist = Twist()
    twist.angular.z = current + ANG_STEP_DEG  # error: RF201 "deg/s"
    pub.publish(twist)


def near_miss_parameter(pub, current) -> None:
    twist = Twist()
    twist.angular.z = current + ANG_STEP  # clean: rad/s
    pub.publish(twist)
