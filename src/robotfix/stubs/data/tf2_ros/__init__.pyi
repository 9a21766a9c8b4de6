# tf2_ros (ROS 1 and ROS 2): Buffer.lookup_transform(target_frame, source_frame, time,
# timeout=...) -> geometry_msgs/TransformStamped, the transform that takes data from
# source_frame to target_frame; its translation is in m (REP 103, on the message).

from tf2_ros.buffer import Buffer as Buffer
