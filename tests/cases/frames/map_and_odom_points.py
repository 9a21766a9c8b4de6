"""A node publishing a goal in `map` that mixes in a point in `odom`: a stamped
message's data is in the frame its `header.frame_id` names."""
import math
from typing import Annotated

import rclpy
from geometry_msgs.msg import PointStamped, PoseStamped
from rclpy.node import Node
from visualization_msgs.msg import Marker

MAP_FRAME = "map"


class GoalPublisher(Node):
    ODOM_FRAME = "odom"

    def __init__(self) -> None:
        super().__init__("goal_publisher")
        self.pub = self.create_publisher(PoseStamped, "goal", 10)
        self.sub = self.create_subscription(PointStamped, "clicked", self.on_click, 10)
        self.timer = self.create_timer(0.5, self.tick)

    def tick(self) -> None:
        goal = PointStamped()
        goal.header.frame_id = MAP_FRAME
        goal.point.x = 2.0
        robot = PointStamped()
        robot.header.frame_id = self.ODOM_FRAME
        robot.point.x = 0.5
        dx = goal.point.x - robot.point.x  # error: RF202
        if goal.point.y < robot.point.y:  # error: RF202
            dx = 0.0
        pose = PoseStamped()
        pose.header.frame_id = "map"
        pose.pose.position.x = robot.point.x  # error: RF201
        pose.pose.position.y = goal.point.y  # same frame: clean
        pose.pose.position.z = dx
        self.pub.publish(pose)

    def near_misses(self) -> None:
        a = PointStamped()
        a.header.frame_id = "map"
        b = PointStamped()
        b.header.frame_id = "/map"  # tf2 strips one leading `/`: the same frame
        dist = a.point.x - b.point.x
        late = PointStamped()
        late.point.x = a.point.x  # the frame is set below: checked when read
        late.header.frame_id = "map"
        ok = late.point.x - a.point.x
        blank = PointStamped()  # no frame_id: unknown, compared with nothing
        free = blank.point.x - robot_x(b)  # b may change in there: unknown after
        offset: Annotated[float, "Unit('m')"] = 0.3  # no frame: fits any
        a.point.z = offset
        shifted = a.point.x + offset
        obstacle = PointStamped()
        obstacle.header.frame_id = "base_link"
        reach = math.hypot(a.point.x, a.point.y)
        clearance = math.sqrt(obstacle.point.x**2 + obstacle.point.y**2)
        closer = clearance < reach  # a length is the same in every frame
        area = obstacle.point.x * obstacle.point.y < a.point.x * a.point.y
        yaw = math.atan2(a.point.y, a.point.x)
        ahead = a.point.x * math.cos(yaw) + a.point.y * math.sin(yaw)
        local = PointStamped()
        local.header.frame_id = "base_link"
        local.point.x = ahead  # rotated into the robot's frame: not known, clean
        local.point.y = a.point.x * 0.5  # error: RF201

    def on_click(self, msg: PointStamped) -> None:
        here = PointStamped()
        here.header.frame_id = "odom"
        delta = msg.point.x - here.point.x  # a received frame is not known: silent
        out = PointStamped()
        out.header = msg.header  # carries the (unknown) frame
        out.point.x = msg.point.x
        moved = out.point.x - here.point.x


def robot_x(p: PointStamped) -> float:
    return p.point.x


class LateFrames(Node):
    """The frame named after the data was stored: checked when the message leaves
    the node (a message reused for several frames is rewritten in between)."""

    def __init__(self) -> None:
        super().__init__("late_frames")
        self.pub = self.create_publisher(PointStamped, "point", 10)
        self.markers = self.create_publisher(Marker, "marker", 10)
        self.timer = self.create_timer(1.0, self.tick)

    def tick(self) -> None:
        x_odom: Annotated[float, "Unit('m') and Frame('odom')"] = 1.0
        p = PointStamped()
        p.point.x = x_odom
        p.header.frame_id = "map"
        self.pub.publish(p)  # error: RF201
        q = PointStamped()
        q.point.x = x_odom
        q.header.frame_id = "odom"  # the data's own frame: clean
        self.pub.publish(q)
        r = PointStamped()
        r.point.x = x_odom
        r.point.x = 0.0  # overwritten before the frame is named
        r.header.frame_id = "map"
        self.pub.publish(r)
        s = PointStamped()
        s.point.y = x_odom
        gap = s.point.y - p.point.x  # error: RF202
        reused = PointStamped()
        reused.header.frame_id = "odom"
        reused.point.x = x_odom
        self.pub.publish(reused)
        reused.header.frame_id = "map"  # rewritten below before it leaves: clean
        reused.point.x = p.point.x
        self.pub.publish(reused)
        renamed = PointStamped()
        renamed.header.frame_id = "odom"
        renamed.point.x = x_odom
        self.pub.publish(renamed)
        renamed.header.frame_id = "map"  # the odom data is still there
        self.pub.publish(renamed)  # error: RF201
        m = PointStamped()
        m.header.frame_id = "map"
        out = PointStamped()
        out.point.x = x_odom
        out.header = m.header
        self.pub.publish(out)  # error: RF201
        marker = Marker()
        marker.header.frame_id = "base_link"
        marker.pose.position.x = m.point.x  # error: RF201
        marker.pose.position.y = gap
        self.markers.publish(marker)
