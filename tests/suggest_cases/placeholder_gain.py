"""A name that reaches a place through a placeholder gain (`error * 1.0`) meets that
place's unit too: turtlebot3's absolute_move got `heading_error` in rad (from
`math.degrees`), which also reaches rad/s through `abs(error) * 1.0`, and the
applied file then warned RF203 there."""

import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class AbsoluteMove(Node):
    def __init__(self):
        super().__init__("absolute_move")
        self.heading_error = 0.0  # near miss: rad, and rad/s through `* 1.0`
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        timer_period = 0.05  # suggest: timer_period s
        self.create_timer(timer_period, self.step)

    def step(self):
        cmd = Twist()
        error = self.heading_error  # near miss: the same
        turn_speed = max(min(abs(error) * 1.0, 1.0), 0.1)  # suggest: turn_speed rad/s
        cmd.angular.z = turn_speed if self.heading_error > 0 else -turn_speed
        if abs(math.degrees(self.heading_error)) < 1.0:
            cmd.angular.z = 0.0
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(AbsoluteMove())
