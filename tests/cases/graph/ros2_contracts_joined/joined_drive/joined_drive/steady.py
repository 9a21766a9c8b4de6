"""The near miss: one message, its speed set on one path only, within the limit."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Steady(Node):
    def __init__(self) -> None:
        super().__init__('steady')
        self.moving = False
        self.pub = self.create_publisher(Twist, 'cmd_vel_safe', 10)
        self.create_timer(0.1, self.tick)

    def tick(self) -> None:
        self.moving = not self.moving
        twist = Twist()
        if self.moving:
            twist.linear.x = 0.1
        self.pub.publish(twist)


def main() -> None:
    rclpy.init()
    rclpy.spin(Steady())
