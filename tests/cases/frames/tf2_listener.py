"""A tf2 listener: `lookup_transform(target, source, time)` is the transform from
`source` to `target`; `do_transform_point` moves a stamped value into `target`."""
import rclpy
import tf2_geometry_msgs
from geometry_msgs.msg import PointStamped, PoseStamped, Vector3Stamped
from rclpy.node import Node
from tf2_ros import Buffer, TransformListener


class ObstacleLocator(Node):
    def __init__(self) -> None:
        super().__init__("obstacle_locator")
        self.tf_buffer = Buffer()
        self.listener = TransformListener(self.tf_buffer, self)
        self.base_frame = "base_link"
        self.sub = self.create_subscription(PointStamped, "obstacle", self.on_obstacle, 10)
        self.timer = self.create_timer(0.1, self.tick)

    def tick(self) -> None:
        seen = PointStamped()
        seen.header.frame_id = self.base_frame
        seen.point.x = 1.5
        wrong = self.tf_buffer.lookup_transform("map", "odom", rclpy.time.Time())
        lost = tf2_geometry_msgs.do_transform_point(seen, wrong)  # error: RF204
        right = self.tf_buffer.lookup_transform("map", self.base_frame, rclpy.time.Time())
        in_map = tf2_geometry_msgs.do_transform_point(seen, right)
        goal = PointStamped()
        goal.header.frame_id = "map"
        gap = goal.point.x - in_map.point.x  # both in map now: clean
        stale = goal.point.x - seen.point.x  # error: RF202
        odom = self.tf_buffer.transform(seen, "odom")
        mixed = goal.point.y - odom.point.y  # error: RF202
        slash = self.tf_buffer.lookup_transform("/map", "base_link", rclpy.time.Time())  # error: RF204
        old_style = PointStamped()
        old_style.header.frame_id = "/base_link"
        same = old_style.point.x - seen.point.x  # `/base_link` is `base_link`: clean
        fails = self.tf_buffer.transform(old_style, "map")  # error: RF204

    def on_obstacle(self, msg: PointStamped) -> None:
        # the frame of a received point is not known: any transform may fit it
        t = self.tf_buffer.lookup_transform("map", "odom", rclpy.time.Time())
        moved = tf2_geometry_msgs.do_transform_point(msg, t)
        goal = PointStamped()
        goal.header.frame_id = "map"
        close = goal.point.x - moved.point.x  # moved into map: clean
        v = Vector3Stamped()
        v.header.frame_id = "odom"
        unknown_target = self.tf_buffer.lookup_transform(msg.header.frame_id, "odom", rclpy.time.Time())
        fine = tf2_geometry_msgs.do_transform_vector3(v, unknown_target)  # source odom, target unknown
        p = PoseStamped()
        p.header.frame_id = "odom"
        ok = tf2_geometry_msgs.do_transform_pose_stamped(p, t)
