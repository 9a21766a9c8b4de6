"""A module-level helper that builds a message and returns it (`twist = Twist()`,
stores into its fields, `return twist`) is run at each call with its parameters
bound to the arguments: the caller's message has the fields it set. Any other
body (a branch, a call with an effect), or a parameter with a refinement (a unit
too), keeps the result a message of the type whose fields are not known.
(Here rather than in tests/cases/messages/: `robotfix suggest` would give these
parameters a unit, after which the helpers are not run at their calls.)"""
from typing import Annotated

from geometry_msgs.msg import Twist

LIMIT = 0.5


def send(cmd: Annotated[Twist, "abs(linear.x) <= 0.5"]) -> None: ...


def go_straight(linear_velocity):
    """The velocity, straight ahead."""
    twist = Twist()
    twist.linear.x = linear_velocity
    twist.angular.z = 0.0
    return twist


def go_clamped(linear_velocity):
    twist = Twist()
    twist.linear.x = max(-LIMIT, min(LIMIT, linear_velocity))
    return twist


def go_logged(linear_velocity):
    twist = Twist()
    twist.linear.x = linear_velocity
    print(twist)
    return twist


def go_if_far(distance, linear_velocity):
    twist = Twist()
    if distance > 0.01:
        twist.linear.x = linear_velocity
    return twist


def too_fast() -> None:
    send(go_straight(1.0))  # error: RF101


def within() -> None:
    send(go_straight(0.1))


def clamped(requested: float) -> None:
    send(go_clamped(requested))


def logged() -> None:
    send(go_logged(0.1))  # warning: RF102


def branching() -> None:
    send(go_if_far(1.0, 0.1))  # warning: RF102


def joined(moving: bool) -> None:
    twist = Twist()
    if moving:
        twist = go_straight(1.0)
    send(twist)  # warning: RF102


def joined_within(moving: bool) -> None:
    twist = Twist()
    if moving:
        twist = go_straight(0.1)
    send(twist)
