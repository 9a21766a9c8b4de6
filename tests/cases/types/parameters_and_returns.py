"""Typed parameters, classmethods and helpers' results (as nav2's simple commander
and turtlebot3's examples write them): a method called through a parameter's
declared class, an object built by `cls(...)`, and a message a helper returns,
annotated or not, then filled in and published."""
from typing import Annotated

import rclpy
from geometry_msgs.msg import PoseStamped, Twist
from nav_msgs.msg import Odometry
from rclpy.node import Node


class Client:
    """A hardware client with a timeout in milliseconds."""

    def __init__(self, host: str) -> None:
        self.host = host

    @classmethod
    def local(cls) -> "Client":
        return cls("localhost")

    def set_timeout(self, timeout: Annotated[float, "Unit('ms') and 0 < _ <= 5000"]) -> None:
        print(self.host, timeout)


def configure(client: Client, timeout_s: Annotated[float, "Unit('s') and 0 < _ <= 5"]) -> None:
    client.set_timeout(timeout_s)  # error: RF201
    client.set_timeout(timeout_s * 1000.0)
    client.set_timeout(0.0)  # error: RF101


def reconnect(client: Client = None) -> None:
    """`client` may be None: the branch that makes one is checked too."""
    if client is None:
        client = Client("robot.local")
        client.set_timeout(9000.0)  # error: RF101
    client.set_timeout(100.0)


def configure_local() -> None:
    Client.local().set_timeout(6000.0)  # error: RF101
    client = Client.local()
    client.set_timeout(2500.0)
    client.set_timeout(-1.0)  # error: RF101


def stop_command() -> Twist:
    return Twist()


def turn_command(rate):
    cmd = Twist()
    cmd.angular.z = rate
    return cmd


def goal_pose(frame, x, y):
    goal = PoseStamped()
    goal.header.frame_id = frame
    goal.pose.position.x = x
    goal.pose.position.y = y
    return goal


def either(flag):
    """Two kinds of results: no type."""
    if flag:
        return Twist()
    return PoseStamped()


class Follower(Node):
    def __init__(self) -> None:
        super().__init__("follower")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.goal_pub = self.create_publisher(PoseStamped, "goal_pose", 10)
        self.create_subscription(Odometry, "odom", self.on_odom, 10)

    def on_odom(self, odom: Odometry) -> None:
        cmd = stop_command()
        cmd.linear.x = odom.twist.twist.angular.z  # error: RF201
        cmd.linear.x = odom.twist.twist.linear.x
        turn = turn_command(0.5)
        turn.linear.y = odom.twist.twist.angular.z  # error: RF201
        turn.angular.x = odom.twist.twist.angular.z
        goal = goal_pose("map", 1.0, 2.0)
        goal.pose.position.z = odom.twist.twist.linear.z  # error: RF201
        goal.pose.position.z = odom.pose.pose.position.z
        self.goal_pub.publish(goal)
        other = either(True)
        other.linear.x = odom.twist.twist.angular.z
        self.pub.publish(cmd)


def main() -> None:
    rclpy.init()
    rclpy.spin(Follower())
