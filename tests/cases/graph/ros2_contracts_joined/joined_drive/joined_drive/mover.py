"""Every other tick, a message a helper builds (fresh-eyes r2: it was silent)."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


def go_straight(linear_velocity):
    twist = Twist()
    twist.linear.x = linear_velocity
    return twist


class Mover(Node):
    def __init__(self) -> None:
        super().__init__('mover')
        self.moving = False
        self.pub = self.create_publisher(Twist, 'cmd_vel_safe', 10)
        self.create_timer(0.1, self.tick)

    def tick(self) -> None:
        self.moving = not self.moving
        twist = Twist()
        if self.moving:
            twist = go_straight(1.0)
        self.pub.publish(twist)  # warning: RF102


def main() -> None:
    rclpy.init()
    rclpy.spin(Mover())
