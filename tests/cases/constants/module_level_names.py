"""Module code names constants in refinements as functions do: `math.pi`, `np.pi`,
`pi` from math, a module constant (issue 22: at the top level `math.pi` was unknown,
so a heading in degrees was only RF102). A class's constants are known once its body
ran, which is after the module code: at the top level they are still unknown."""
import math
from math import pi, tau
from typing import Annotated

import numpy as np
from geometry_msgs.msg import Twist

MAX_SPEED: Annotated[float, "Unit('m/s')"] = 0.22


class Limits:
    MAX_TURN = 1.5
    HALF_TURN = math.pi


# a start heading written in degrees where radians belong
START_HEADING: Annotated[float, "Unit('rad') and abs(_) <= 2 * math.pi"] = 270.0  # error: RF101
HOME_HEADING: Annotated[float, "Unit('rad') and abs(_) <= 2 * math.pi"] = 4.71  # clean
GOAL_YAW: Annotated[float, "Unit('rad') and 0 <= _ < np.pi"] = 3.5  # error: RF101
DOCK_YAW: Annotated[float, "Unit('rad') and 0 <= _ < np.pi"] = 3.1  # clean
SWEEP: Annotated[float, "0 < _ <= tau"] = 360.0  # error: RF101
HALF_SWEEP: Annotated[float, "0 < _ <= pi"] = 3.14  # clean
TURN_RATE: Annotated[float, "Unit('rad/s') and _ <= Limits.MAX_TURN"] = 2.0  # warning: RF102
CRUISE: Annotated[float, "Unit('m/s') and _ <= MAX_SPEED"] = 0.3  # error: RF101
CREEP: Annotated[float, "Unit('m/s') and _ <= MAX_SPEED / 2"] = 0.1  # clean


def turn(rate: Annotated[float, "Unit('rad/s') and _ <= Limits.MAX_TURN"]) -> None:
    pass


def main() -> None:
    turn(TURN_RATE)  # error: RF101
    turn(Limits.MAX_TURN)  # clean


def command() -> Twist:
    cmd = Twist()
    cmd.linear.x = CREEP
    cmd.angular.z = Limits.MAX_TURN
    return cmd
