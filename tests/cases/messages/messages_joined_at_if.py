"""A name bound to a different message on each path of an `if` (`twist = Twist()`,
then `twist = Twist()` again on one branch) holds, after the join, one message
whose fields are joined one by one, when nothing else holds either message or a
part of it, and the function lets it escape nowhere (`writes.py`). Else (another
name holds a part of one, a container holds it), or when a loop builds it again,
it is not followed: given for a refined message, it is any message of the
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


def built_on_one_branch_within(moving: bool) -> None:
    twist = Twist()
    if moving:
        twist = Twist()
        twist.linear.x = 0.1
    send(twist)


def built_on_each_branch_too_fast(moving: bool) -> None:
    twist = Twist()
    twist.linear.x = 0.8
    if moving:
        twist = Twist()
        twist.linear.x = 0.9
    send(twist)  # error: RF101


def set_after_the_join(moving: bool) -> None:
    twist = Twist()
    if moving:
        twist = Twist()
        twist.angular.z = 3.0
    twist.linear.x = 1.0
    send(twist)  # error: RF101


def set_after_the_join_within(moving: bool) -> None:
    twist = Twist()
    if moving:
        twist = Twist()
        twist.angular.z = 3.0
    twist.linear.x = 0.2
    send(twist)


def part_held_by_another_name(moving: bool) -> None:
    twist = Twist()
    linear = twist.linear
    if moving:
        twist = Twist()
    linear.x = 1.0  # changes `twist` on the path that kept the first message
    send(twist)  # warning: RF102


def other_name_holds_the_first(moving: bool) -> None:
    first = Twist()
    twist = first
    if moving:
        twist = Twist()
    first.linear.x = 1.0
    send(twist)  # warning: RF102


def stored_where_the_analysis_does_not_follow(moving: bool, box: dict) -> None:
    twist = Twist()
    if moving:
        twist = Twist()
        box["last"] = twist
    box["last"].linear.x = 1.0  # changes `twist` on the path that stored it
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
