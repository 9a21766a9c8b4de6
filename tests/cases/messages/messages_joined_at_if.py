"""A name bound to two different messages on two paths (`twist = Twist()`, then
`twist = go_straight(1.0)` on one branch), or to one a loop builds again, is not
followed field by field: given for a refined message, it is any message of the
type, so the refinement is not proved (RF102), never silently accepted."""
from typing import Annotated

from geometry_msgs.msg import Twist


def send(cmd: Annotated[Twist, "abs(linear.x) <= 0.5"]) -> None: ...


def go_straight(linear_velocity: float) -> Twist:
    twist = Twist()
    twist.linear.x = linear_velocity
    return twist


def helper_on_one_branch(moving: bool) -> None:
    twist = Twist()
    if moving:
        twist = go_straight(1.0)
    send(twist)  # warning: RF102


def built_on_one_branch(moving: bool) -> None:
    twist = Twist()
    if moving:
        twist = Twist()
        twist.linear.x = 1.0
    send(twist)  # warning: RF102


def built_in_a_loop() -> None:
    twist = Twist()
    for speed in (0.2, 1.0):
        twist = Twist()
        twist.linear.x = speed
    send(twist)  # warning: RF102


def one_message_set_on_one_branch(moving: bool) -> None:
    twist = Twist()
    if moving:
        twist.linear.x = 0.1
    send(twist)
