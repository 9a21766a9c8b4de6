"""Which Python names are classes of ROS interface packages, by their spelling
alone: `pkg.msg.Name`, `pkg.srv.Name` (and its `.Request`/`.Response`),
`pkg.action.Name` (and its `.Goal`...), for a `pkg` that is not a client library
with a module of that name (`rclpy.action`). Stdlib only, below every layer that
asks: the interpreter (RF508) and the annotation reader (a refinement of such a
class the catalog lacks is not used)."""

from __future__ import annotations

INTERFACE_MODULES = ("msg", "srv", "action")

# Python packages with a `msg`/`srv`/`action` module that is not an interface package.
CLIENT_LIBRARIES = frozenset(
    {"rclpy", "rospy", "actionlib", "tf", "tf2_ros", "rosbag", "launch", "launch_ros"}
)


def interface_class(qualified: str | None) -> bool:
    """`example_interfaces.srv.AddTwoInts.Request`, `std_msgs.msg.Float64`."""
    parts = (qualified or "").split(".")
    return (
        len(parts) in (3, 4)
        and parts[1] in INTERFACE_MODULES
        and parts[0] not in CLIENT_LIBRARIES
    )
