"""A stamped value built before a loop keeps its frame inside the loop, unless the
loop body writes it: the turtle_tf2 listener's shape (ROS 1, `while not
rospy.is_shutdown()`), and an rclpy retry loop. Only what the body writes (the
header, a field through an alias, a call that may store into it) is forgotten."""
import math

import rclpy
import rospy
import tf2_geometry_msgs
import tf2_ros
from geometry_msgs.msg import PointStamped, Twist


def follow_carrot() -> None:
    rospy.init_node("turtle_tf2_listener")
    buffer = tf2_ros.Buffer()
    listener = tf2_ros.TransformListener(buffer)
    pub = rospy.Publisher("turtle2/cmd_vel", Twist, queue_size=1)
    carrot = PointStamped()
    carrot.header.frame_id = "carrot1"
    carrot.point.x = 0.5
    rate = rospy.Rate(10.0)
    while not rospy.is_shutdown():
        try:
            trans = buffer.lookup_transform("turtle2", "turtle1", rospy.Time())
        except (tf2_ros.LookupException, tf2_ros.ConnectivityException):
            rate.sleep()
            continue
        goal = tf2_geometry_msgs.do_transform_point(carrot, trans)  # error: RF204
        msg = Twist()
        msg.angular.z = 4 * math.atan2(goal.point.y, goal.point.x)  # warning: RF203
        msg.linear.x = 0.5 * math.sqrt(goal.point.x ** 2 + goal.point.y ** 2)  # warning: RF203
        pub.publish(msg)
        rate.sleep()


def follow_carrot_right() -> None:
    buffer = tf2_ros.Buffer()
    carrot = PointStamped()
    carrot.header.frame_id = "carrot1"
    rate = rospy.Rate(10.0)
    while not rospy.is_shutdown():
        carrot.point.x = carrot.point.x + 0.1  # a field written: the frame stays
        trans = buffer.lookup_transform("turtle2", "carrot1", rospy.Time())
        goal = tf2_geometry_msgs.do_transform_point(carrot, trans)
        rate.sleep()


def scan_targets(targets: list[str]) -> None:
    buffer = tf2_ros.Buffer()
    probe = PointStamped()
    probe.header.frame_id = "base_link"
    for name in targets:
        t = buffer.lookup_transform(name, "odom", rospy.Time())
        moved = tf2_geometry_msgs.do_transform_point(probe, t)  # error: RF204


def retarget_in_loop(frames: list[str]) -> None:
    buffer = tf2_ros.Buffer()
    probe = PointStamped()
    probe.header.frame_id = "base_link"
    for name in frames:
        t = buffer.lookup_transform("map", "odom", rospy.Time())
        moved = tf2_geometry_msgs.do_transform_point(probe, t)  # the body sets the frame below
        probe.header.frame_id = name


def retarget_through_alias(frames: list[str]) -> None:
    buffer = tf2_ros.Buffer()
    probe = PointStamped()
    probe.header.frame_id = "base_link"
    alias = probe
    for name in frames:
        t = buffer.lookup_transform("map", "odom", rospy.Time())
        moved = tf2_geometry_msgs.do_transform_point(probe, t)
        alias.header.frame_id = name


def restamp(p: PointStamped, frame: str) -> None:
    p.header.frame_id = frame


def retarget_through_call(frames: list[str]) -> None:
    buffer = tf2_ros.Buffer()
    probe = PointStamped()
    probe.header.frame_id = "base_link"
    for name in frames:
        t = buffer.lookup_transform("map", "odom", rospy.Time())
        moved = tf2_geometry_msgs.do_transform_point(probe, t)
        restamp(probe, name)


def retarget_unknown_call(frames: list[str], fix) -> None:
    buffer = tf2_ros.Buffer()
    probe = PointStamped()
    probe.header.frame_id = "base_link"
    for name in frames:
        t = buffer.lookup_transform("map", "odom", rospy.Time())
        moved = tf2_geometry_msgs.do_transform_point(probe, t)
        fix(probe)


class Follower:
    def __init__(self, node) -> None:
        self.node = node
        self.buffer = tf2_ros.Buffer()

    def run(self) -> None:
        target = PointStamped()
        target.header.frame_id = "base_link"
        target.point.x = 1.0
        for attempt in range(10):
            try:
                t = self.buffer.lookup_transform("map", "odom", rclpy.time.Time())
            except tf2_ros.TransformException:
                continue
            seen = target.point.x  # a read leaves the frame
            in_map = tf2_geometry_msgs.do_transform_point(target, t)  # error: RF204
            break


def describe(p: PointStamped) -> float:
    rospy.loginfo("carrot at %f", p.point.x)
    return math.hypot(p.point.x, p.point.y)


def report_then_transform(frames: list[str]) -> None:
    buffer = tf2_ros.Buffer()
    probe = PointStamped()
    probe.header.frame_id = "base_link"
    for name in frames:
        far = describe(probe)  # only reads it
        t = buffer.lookup_transform("map", "odom", rospy.Time())
        moved = tf2_geometry_msgs.do_transform_point(probe, t)  # error: RF204


def kept_by_node(node, frames: list[str]) -> None:
    buffer = tf2_ros.Buffer()
    probe = PointStamped()
    probe.header.frame_id = "base_link"
    node.last = probe  # escapes: the node may change it during the loop
    for name in frames:
        node.retarget(name)
        t = buffer.lookup_transform("map", "odom", rospy.Time())
        moved = tf2_geometry_msgs.do_transform_point(probe, t)


def retarget_alias_in_body(frames: list[str]) -> None:
    buffer = tf2_ros.Buffer()
    probe = PointStamped()
    probe.header.frame_id = "base_link"
    for name in frames:
        t = buffer.lookup_transform("map", "odom", rospy.Time())
        moved = tf2_geometry_msgs.do_transform_point(probe, t)
        header = probe.header
        header.frame_id = name


def restamp_each_time() -> None:
    buffer = tf2_ros.Buffer()
    carrot = PointStamped()
    carrot.header.frame_id = "carrot1"
    while not rospy.is_shutdown():
        carrot.header.stamp = rospy.Time.now()  # another field: the frame stays
        carrot.point.x = carrot.point.x + 0.1
        trans = buffer.lookup_transform("turtle2", "turtle1", rospy.Time())
        goal = tf2_geometry_msgs.do_transform_point(carrot, trans)  # error: RF204


def restamp_header(frames: list[str]) -> None:
    buffer = tf2_ros.Buffer()
    carrot = PointStamped()
    carrot.header.frame_id = "carrot1"
    for name in frames:
        trans = buffer.lookup_transform("turtle2", "turtle1", rospy.Time())
        goal = tf2_geometry_msgs.do_transform_point(carrot, trans)  # the header is replaced below
        carrot.header = goal.header
