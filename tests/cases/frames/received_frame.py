"""A `Frame(...)` on a message that arrives (a callback's parameter) says its data
is in that frame, as its header would: numbers read from it carry the frame, and a
part of it (`msg.pose.pose`, a Pose: no header of its own) stored where another
frame is declared is RF201. Modelled on nav2_system_tests' nav_to_pose tester,
which keeps the robot's pose from a subscription and compares it with a goal."""
from typing import Annotated, Optional

from geometry_msgs.msg import Pose, PoseStamped, PoseWithCovarianceStamped
from nav_msgs.msg import Odometry
from rclpy.node import Node

MapPose = Annotated[Pose, "Frame('map')"]


class NavTester(Node):
    def __init__(self, goal_pose: MapPose) -> None:
        super().__init__("nav_tester")
        self.goal_pose: MapPose = goal_pose
        self.current_pose: Optional[MapPose] = None
        self.create_subscription(Odometry, "odom", self.on_odom, 10)
        self.create_subscription(PoseWithCovarianceStamped, "amcl_pose", self.on_amcl, 10)

    def on_odom(self, msg: Annotated[Odometry, "Frame('odom')"]) -> None:
        self.current_pose = msg.pose.pose  # error: RF201 "frame `odom`"

    def on_amcl(self, msg: Annotated[PoseWithCovarianceStamped, "Frame('map')"]) -> None:
        self.current_pose = msg.pose.pose  # clean: map, as declared

    def on_any(self, msg: Odometry) -> None:
        self.current_pose = msg.pose.pose  # clean: a frame not known compares with nothing


def distance_x(msg: Annotated[Odometry, "Frame('odom')"]) -> float:
    goal = PoseStamped()
    goal.header.frame_id = "map"
    goal.pose.position.x = 2.0
    return msg.pose.pose.position.x - goal.pose.position.x  # error: RF202 "frame map"


def distance_x_map(msg: Annotated[PoseWithCovarianceStamped, "Frame('map')"]) -> float:
    goal = PoseStamped()
    goal.header.frame_id = "map"
    return msg.pose.pose.position.x - goal.pose.position.x  # clean
