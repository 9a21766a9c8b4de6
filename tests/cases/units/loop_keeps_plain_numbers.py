"""A number set in a loop to literals only (a teleop key table's entries) stays a
plain number, which takes the unit of its context: `z * turn` is in rad/s."""
from typing import Annotated

import rclpy
from geometry_msgs.msg import Twist

MOVE_BINDINGS = {
    "i": (1, 0, 0, 0),
    "o": (1, 0, 0, -1),
    "t": (0, 0, 1, 0),
    "b": (0, 0, -1, 0),
}
SPEED_MPS: Annotated[float, "Unit('m/s')"] = 0.5


def teleop(pub, get_key, turn: Annotated[float, "Unit('rad/s')"]) -> None:
    x = 0.0
    z = 0.0
    th = 0.0
    while rclpy.ok():
        key = get_key()
        if key in MOVE_BINDINGS:
            x = MOVE_BINDINGS[key][0]
            z = MOVE_BINDINGS[key][2]
            th = MOVE_BINDINGS[key][3]
        elif key == "k":
            x = 0.0
            z = -1.0
        twist = Twist()
        twist.linear.x = x * SPEED_MPS  # a plain number times m/s: clean
        twist.linear.z = z * turn  # error: RF201 "rad/s"
        twist.angular.z = th * turn  # a plain number times rad/s: clean
        pub.publish(twist)


def teleop_unit_set_in_loop(pub, get_key, turn: Annotated[float, "Unit('rad/s')"]) -> None:
    z = 0.0
    while rclpy.ok():
        twist = Twist()
        # z is in m/s from the second key on: not a plain number here
        twist.linear.z = z * turn
        if get_key() == "u":
            z = SPEED_MPS
        pub.publish(twist)


def teleop_rebound_by_for(pub, speeds: list[Annotated[float, "Unit('m/s')"]],
                          turn: Annotated[float, "Unit('rad/s')"]) -> None:
    z = 0.0
    while rclpy.ok():
        twist = Twist()
        twist.linear.z = z * turn  # z may be any element of speeds: not plain
        for z in speeds:
            pass
        z = 1.0
        pub.publish(twist)
