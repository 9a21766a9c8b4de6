"""A node whose helper method writes the command: the helper's parameters and the
attributes its callers pass get the field's unit."""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node

CRUISE = 0.4  # suggest: CRUISE m/s


class Patrol(Node):
    BACKUP = -0.1  # suggest: BACKUP m/s

    def __init__(self, turn_speed=0.6):  # suggest: turn_speed rad/s
        super().__init__("patrol")
        self.turn_speed = turn_speed  # suggest: turn_speed rad/s
        self.slow = CRUISE * 0.5  # suggest: slow m/s
        self.both = 0.2  # near miss: flows into m/s and rad/s
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_timer(0.1, self.tick)

    def drive(self, speed, turn):  # suggest: speed m/s, turn rad/s
        cmd = Twist()
        cmd.linear.x = speed
        cmd.angular.z = turn
        self.pub.publish(cmd)

    def hold(self, seconds=None):  # near miss: None is not a float
        if seconds is not None:
            self.create_timer(seconds, self.tick)

    def wait(self, seconds):  # near miss: also given None
        if seconds is not None:
            self.create_timer(seconds, self.tick)

    def start(self):
        self.wait(None)
        self.wait(2.0)

    def tick(self):
        self.drive(CRUISE, 0.0)
        self.drive(self.slow, self.turn_speed)
        self.drive(self.both, self.both)
        self.drive(self.BACKUP, 0.0)


def main():
    rclpy.init()
    rclpy.spin(Patrol())
