"""An rclpy path follower: a plan arrives as a nav_msgs/Path, a PoseArray of
waypoints as markers. Each element of a message array is a message of its type, so
`path.poses[-1].pose.position.x` is in m (REP 103 for Point), in a subscript, a
`for`, or a comprehension (issue 8, item 5: lists of messages)."""
import math
from typing import Annotated

import rclpy
from geometry_msgs.msg import PoseArray, Twist
from nav_msgs.msg import Path
from rclpy.node import Node

K_P: Annotated[float, "Unit('1/s')"] = 0.8
MAX_SPEED: Annotated[float, "Unit('m/s')"] = 0.22


class PathFollower(Node):
    def __init__(self) -> None:
        super().__init__("path_follower")
        self.declare_parameter("lookahead", 0.5)
        self.create_subscription(Path, "plan", self.on_plan, 10)
        self.create_subscription(PoseArray, "waypoints", self.on_waypoints, 10)
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_timer(0.1, self.on_timer)

    def on_plan(self, path: Path) -> None:
        if not path.poses:
            return
        goal_x: Annotated[float, "Unit('m')"] = path.poses[-1].pose.position.x
        heading: Annotated[float, "Unit('rad')"] = path.poses[0].pose.position.y  # error: RF201
        xs: Annotated[list[float], "Unit('m')"] = [p.pose.position.x for p in path.poses]
        times: Annotated[list[float], "Unit('s')"] = [p.pose.position.x for p in path.poses]  # error: RF201
        twist = Twist()
        for stamped in path.poses:
            error: Annotated[float, "Unit('m')"] = stamped.pose.position.x - goal_x
            twist.linear.x = min(MAX_SPEED, K_P * abs(error))
            twist.angular.z = stamped.pose.position.y  # error: RF201
        self.pub.publish(twist)

    def on_waypoints(self, msg: PoseArray) -> None:
        for index, pose in enumerate(msg.poses):
            north: Annotated[float, "Unit('m')"] = pose.position.y
            yaw: Annotated[float, "Unit('rad')"] = 2.0 * math.atan2(
                pose.orientation.z, pose.orientation.w
            )
        first = msg.poses[0]
        height: Annotated[float, "Unit('m')"] = first.position.z
        angle: Annotated[float, "Unit('degree')"] = first.position.z  # error: RF201

    def on_timer(self) -> None:
        plan = Path()
        plan.header.frame_id = "map"
        for stamped in plan.poses:
            depth: Annotated[float, "Unit('m')"] = stamped.pose.position.z


def main() -> None:
    rclpy.init()
    rclpy.spin(PathFollower())
