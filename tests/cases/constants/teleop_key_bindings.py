"""A rospy keyboard teleop: module constants and key-binding tables are known in
every function and in refinements (issue 8, item 1)."""
from typing import Annotated

import rospy
from geometry_msgs.msg import Twist

MAX_LIN_VEL = 0.22
MAX_ANG_VEL = 2.84
LIN_VEL_STEP = 0.01

moveBindings = {
    "i": (1, 0, 0, 0),
    "o": (1, 0, 0, -1),
    "j": (0, 0, 0, 1),
    "l": (0, 0, 0, -1),
    ",": (-1, 0, 0, 0),
    "t": (0, 0, 1, 0),
}
speedBindings = {"q": (1.1, 1.1), "z": (0.9, 0.9), "w": (1.1, 1.0)}
# changed below, so not a constant: lookups stay unknown
presets = {"s": (0.1,), "f": (0.2,)}


def check_linear(vel: float) -> Annotated[float, "abs(_) <= MAX_LIN_VEL"]:
    return max(-MAX_LIN_VEL, min(MAX_LIN_VEL, vel))


def check_angular(vel: float) -> Annotated[float, "abs(_) <= MAX_ANG_VEL"]:
    if vel > MAX_ANG_VEL:
        return MAX_ANG_VEL + 0.1  # error: RF101
    return max(-MAX_ANG_VEL, vel)


def learn_preset(key: str, value: float) -> None:
    presets[key] = (value,)


def on_key(key: str, speed: Annotated[float, "Unit('m/s') and 0 <= _ <= 1"]) -> Twist:
    x: Annotated[float, "-1 <= _ <= 1"] = moveBindings[key][0]
    th: Annotated[float, "abs(_) <= 1"] = moveBindings[key][3]
    up: Annotated[float, "_ >= 0"] = moveBindings["t"][2]
    forward: Annotated[float, "_ >= 0"] = moveBindings[key][0]  # warning: RF102
    back: Annotated[float, "_ > 0"] = moveBindings[","][0]  # error: RF101
    boost: Annotated[float, "_ <= 1.1"] = speedBindings[key][0]
    slower: Annotated[float, "_ < 1"] = speedBindings["z"][0]
    faster: Annotated[float, "_ < 1"] = speedBindings["q"][0]  # error: RF101
    shrink: Annotated[float, "_ < 0.5"] = speedBindings[key][1]  # error: RF101
    preset: Annotated[float, "_ <= 0.2"] = presets[key][0]  # warning: RF102
    twist = Twist()
    twist.linear.x = check_linear(x * speed)
    twist.linear.z = up * LIN_VEL_STEP
    twist.angular.z = check_angular(th * MAX_ANG_VEL)
    return twist


def step(current: float) -> None:
    target: Annotated[float, "_ <= MAX_LIN_VEL"] = check_linear(current + LIN_VEL_STEP)
    top: Annotated[float, "_ <= MAX_LIN_VEL"] = MAX_LIN_VEL
    over: Annotated[float, "_ <= MAX_LIN_VEL"] = MAX_LIN_VEL + LIN_VEL_STEP  # error: RF101


if __name__ == "__main__":
    rospy.init_node("teleop_keyboard")
    pub = rospy.Publisher("cmd_vel", Twist, queue_size=10)
    while not rospy.is_shutdown():
        pub.publish(on_key(input(), 0.5))
