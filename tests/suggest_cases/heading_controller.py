"""A heading controller: angles from math.atan2 and a clamped turn rate. An angle
that reaches a rate through a declared gain gets nothing. (Written into the rate
straight, or times the literal `1.0`, it is RF203, an implicit gain, since a
difference with an angle is an angle.)"""

import math
from typing import Annotated

import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.node import Node

K_HEADING: Annotated[float, "Unit('1/s')"] = 1.0  # a declared gain


def wrap(angle):  # suggest: angle rad
    return math.atan2(math.sin(angle), math.cos(angle))


class HeadingController(Node):
    def __init__(self):
        super().__init__("heading_controller")
        self.declare_parameter("max_turn", 1.0)
        self.max_turn = self.get_parameter("max_turn").value  # suggest: max_turn rad/s
        self.goal_x = 2.0  # near miss: only a difference of it reaches math.atan2
        self.goal_y = 1.0
        self.x = 0.0
        self.y = 0.0
        self.yaw = 0.0  # near miss: holds rad, reaches rad/s through `error`
        self.goal_heading = 0.0  # suggest: goal_heading rad
        self.heading_error = 0.0  # near miss: times the declared gain
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_subscription(Odometry, "odom", self.on_odom, 10)
        self.create_timer(0.1, self.tick)

    def on_odom(self, msg):
        q = msg.pose.pose.orientation
        self.yaw = math.atan2(
            2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z)
        )
        self.x = msg.pose.pose.position.x
        self.y = msg.pose.pose.position.y

    def tick(self):
        cmd = Twist()
        direction = math.atan2(self.goal_y - self.y, self.goal_x - self.x)
        error = direction - self.yaw  # near miss: an angle that reaches a rate
        cmd.angular.z = K_HEADING * error
        self.pub.publish(cmd)

    def rotate(self):
        self.heading_error = wrap(self.goal_heading)
        gained = abs(self.heading_error) * K_HEADING  # suggest: gained rad/s
        turn = max(min(gained, self.max_turn), 0.1)  # suggest: turn rad/s
        cmd = Twist()
        cmd.angular.z = turn if self.heading_error > 0 else -turn
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(HeadingController())
