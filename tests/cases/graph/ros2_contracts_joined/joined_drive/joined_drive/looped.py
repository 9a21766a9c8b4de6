"""A message built again in a loop: what the loop leaves is not followed."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Looped(Node):
    def __init__(self) -> None:
        super().__init__('looped')
        self.pub = self.create_publisher(Twist, 'cmd_vel_safe', 10)
        self.create_timer(0.1, self.tick)

    def tick(self) -> None:
        cmd = Twist()
        for speed in (0.2, 1.0):
            cmd = Twist()
            cmd.linear.x = speed
        self.pub.publish(cmd)  # warning: RF102


def main() -> None:
    rclpy.init()
    rclpy.spin(Looped())
