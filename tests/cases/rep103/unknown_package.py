"""A message class whose definition is not found: unknown fields, one note per type."""
from typing import Annotated

from my_robot_msgs.msg import Command  # note: RF508
from my_robot_msgs.msg import Command as Again  # the same type: noted once per run

speed: Annotated[float, "Unit('m/s') and _ < 2"] = 1
cmd = Command()
cmd.speed = speed
cmd.anything = 3
