"""RF301: a name bound only inside a loop body is unbound after a loop that ran no
time (`range(n)` with n <= 0, a `while` whose test is false at once). A `while True`
left by `break`, a loop `else`, loop variables, and iterables whose emptiness is
not known are fine; a name only the `else` binds is unbound after a `break`."""
import math
from typing import Annotated

import rospy
from geometry_msgs.msg import Twist


def ramp(pub, steps: Annotated[int, "_ >= 0"]) -> None:
    for i in range(steps):
        speed = 0.1 * i
        cmd = Twist()
        cmd.linear.x = speed
        pub.publish(cmd)
    rospy.loginfo(f"final speed {speed}")  # error: RF301


def ramp_at_least_once(pub, steps: Annotated[int, "_ >= 1"]) -> None:
    for i in range(steps):
        speed = 0.1 * i
    rospy.loginfo(f"final speed {speed}")


def ramp_fixed(pub) -> None:
    for i in range(5):
        speed = 0.1 * i
    rospy.loginfo(f"final speed {speed}")


def wait_for_odom(timeout: float) -> None:
    waited = 0.0
    while waited < timeout:
        odom = rospy.wait_for_message("odom", Twist, 1.0)
        waited += 1.0
    rospy.loginfo(f"last {odom}")  # error: RF301


def read_key() -> str:
    while True:
        key = input()
        if key:
            break
    return key


def first_close(ranges) -> float:
    for r in ranges:
        if r < 0.5:
            hit = r
            break
    else:
        hit = math.inf
    return hit


def last_range(ranges) -> None:
    for r in ranges:
        pass
    rospy.loginfo(f"last {r}")


def drain(queue) -> None:
    while (item := queue.get()) is not None:
        rospy.loginfo(f"{item}")
    rospy.loginfo(f"stopped at {item}")


def wait_until_done() -> None:
    done = False
    while not done:
        reply = rospy.wait_for_message("status", Twist, 1.0)
        done = reply is not None
    rospy.loginfo(f"done: {reply}")


def nearest_obstacle(ranges) -> float:
    for r in ranges:
        if r < 0.5:
            break  # leaves with `nearest` unbound: only the `else` binds it
    else:
        nearest = math.inf
    return nearest  # error: RF301


def wait_for_goal(client) -> None:
    while client.pending():
        if client.aborted():
            break
    else:
        result = client.result()
    rospy.loginfo(f"goal: {result}")  # error: RF301


def wait_for_goal_fixed(client) -> None:
    while client.pending():
        if client.aborted():
            result = None
            break
    else:
        result = client.result()
    rospy.loginfo(f"goal: {result}")
