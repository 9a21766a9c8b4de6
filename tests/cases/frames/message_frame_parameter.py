"""A stamped message given to a parameter whose refinement names its frame
(`Frame('map')` on a PoseStamped: the data its header frames is in `map`)."""
from typing import Annotated

from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Odometry

MAP = "map"


def cell_of(goal: Annotated[PoseStamped, "Frame('map')"], resolution: float) -> int:
    return int(goal.pose.position.x / resolution)


def travelled(odom: Annotated[Odometry, "Frame('odom')"]) -> float:
    return odom.pose.pose.position.x


def goals(received: PoseStamped) -> None:
    ahead = PoseStamped()
    ahead.header.frame_id = "odom"
    cell_of(ahead, 0.05)  # error: RF201
    ahead.header.frame_id = "/map"  # tf2 strips the slash: the same frame
    cell_of(ahead, 0.05)
    known = PoseStamped()
    known.header.frame_id = MAP
    cell_of(known, 0.05)
    cell_of(received, 0.05)  # a received frame is not known: silent
    blank = PoseStamped()  # no frame_id set: compared with nothing
    cell_of(blank, 0.05)
    odom = Odometry()
    odom.header.frame_id = "map"  # the header's frame, not child_frame_id
    odom.child_frame_id = "odom"
    travelled(odom)  # error: RF201
