"""What ROS says about frames: pure data, no logic (the analysis side is
`analysis/frames.py`).

- Which fields of a stamped standard message hold data in the frame its header (or
  another string field) names. Left out on purpose: `TransformStamped` (its
  translation relates two frames: `R * p + t` adds a point in `child_frame_id` to a
  vector in `header.frame_id`, and is right), arrays of stamped messages (`Path`:
  each pose has a header of its own) and any message not listed (a user's stamped
  message may keep data in several frames).
- The tf2 calls that look up or apply a transform, and where their frame arguments
  are (tf2_ros `Buffer`, `tf2_geometry_msgs`; same signatures in ROS 1 noetic and
  ROS 2).
- Frame names: tf2 strips one leading `/` from the frames of every transform it
  stores (`BufferCore::setTransform`, `stripSlash`, in ros/geometry2 for ROS 1 and
  ros2/geometry2 for ROS 2), so `/map` and `map` in a header name the same frame;
  but its lookups refuse a leading `/` (`validateFrameId` throws
  InvalidArgumentException: "in tf2 frame_ids cannot start with a '/'").
"""

from __future__ import annotations

from dataclasses import dataclass

# message type -> ((field path prefix, path of the string naming its frame), ...)
FRAMED_FIELDS: dict[str, tuple[tuple[str, str], ...]] = {
    "geometry_msgs/PointStamped": (("point", "header.frame_id"),),
    "geometry_msgs/PoseStamped": (("pose", "header.frame_id"),),
    "geometry_msgs/Vector3Stamped": (("vector", "header.frame_id"),),
    "geometry_msgs/TwistStamped": (("twist", "header.frame_id"),),
    "geometry_msgs/AccelStamped": (("accel", "header.frame_id"),),
    "geometry_msgs/WrenchStamped": (("wrench", "header.frame_id"),),
    "geometry_msgs/QuaternionStamped": (("quaternion", "header.frame_id"),),
    "geometry_msgs/PoseWithCovarianceStamped": (("pose.pose", "header.frame_id"),),
    "geometry_msgs/TwistWithCovarianceStamped": (("twist.twist", "header.frame_id"),),
    "geometry_msgs/AccelWithCovarianceStamped": (("accel.accel", "header.frame_id"),),
    # nav_msgs/Odometry: "The pose in this message should be specified in the
    # coordinate frame given by header.frame_id. The twist in this message should be
    # specified in the coordinate frame given by the child_frame_id"
    "nav_msgs/Odometry": (
        ("pose.pose", "header.frame_id"),
        ("twist.twist", "child_frame_id"),
    ),
    # "Pose of the object with respect the frame_id specified in the header."
    "visualization_msgs/Marker": (("pose", "header.frame_id"),),
    "visualization_msgs/InteractiveMarker": (("pose", "header.frame_id"),),
    # MapMetaData.origin: "the real-world pose of the cell (0,0) in the map"
    "nav_msgs/OccupancyGrid": (("info.origin", "header.frame_id"),),
}


@dataclass(frozen=True)
class Tf2Call:
    """A tf2 call. kind: "lookup" (returns a TransformStamped from `source` to
    `target`), "apply" (`do_transform_*(stamped, transform)`: the stamped value moved
    into the transform's target), "transform" (`buffer.transform(stamped, target)`)."""

    kind: str
    target: tuple[int, str] | None = None  # (position, keyword) of the target frame
    source: tuple[int, str] | None = None
    data: tuple[int, str] | None = None  # the stamped value
    transform: tuple[int, str] | None = None


# Keyed by the called name's last part (a method of tf2_ros.Buffer, or a function of
# tf2_geometry_msgs, however imported).
TF2_CALLS: dict[str, Tf2Call] = {
    "lookup_transform": Tf2Call(
        "lookup", target=(0, "target_frame"), source=(1, "source_frame")
    ),
    "do_transform_point": Tf2Call(
        "apply", data=(0, "point"), transform=(1, "transform")
    ),
    "do_transform_vector3": Tf2Call(
        "apply", data=(0, "vector3"), transform=(1, "transform")
    ),
    "do_transform_pose": Tf2Call("apply", data=(0, "pose"), transform=(1, "transform")),
    "do_transform_pose_stamped": Tf2Call(
        "apply", data=(0, "pose"), transform=(1, "transform")
    ),
    "do_transform_pose_with_covariance_stamped": Tf2Call(
        "apply", data=(0, "pose"), transform=(1, "transform")
    ),
    "transform": Tf2Call(
        "transform", target=(1, "target_frame"), data=(0, "object_stamped")
    ),
}
# The calls whose frame arguments tf2 validates (a leading `/` throws).
VALIDATED = frozenset({"lookup_transform", "transform"})
TRANSFORM_TYPE = "geometry_msgs/TransformStamped"

# REP 103 / REP 105 frame names and suffixes: every one is a frame of its own.
# `camera_link` and `camera_link_optical` differ (z forward, x right, y down), as do
# `base_link` and `base_link_ned` (x forward, y right, z down).
STANDARD_FRAMES = frozenset({"map", "odom", "base_link", "base_footprint", "earth"})
FRAME_SUFFIXES = ("_optical", "_ned", "_enu")
