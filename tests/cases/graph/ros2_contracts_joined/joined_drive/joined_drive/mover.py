"""Messages joined at an `if` or built again in a loop, published to the guard."""
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
        """Every other tick, the message a helper builds (fresh-eyes r2: it was
        silent): too fast on one path of the two."""
        self.moving = not self.moving
        twist = Twist()
        if self.moving:
            twist = go_straight(1.0)
        self.pub.publish(twist)  # warning: RF102

    def helper_on_every_tick(self) -> None:
        self.pub.publish(go_straight(1.0))  # error: RF101

    def helper_within(self) -> None:
        """The near miss: the helper's message within the limit."""
        twist = Twist()
        if self.moving:
            twist = go_straight(0.1)
        self.pub.publish(twist)

    def own_message_within(self) -> None:
        """A message of its own on one branch, within the limit."""
        twist = Twist()
        if self.moving:
            twist = Twist()
            twist.linear.x = 0.1
        self.pub.publish(twist)

    def own_message_too_fast_on_each_path(self) -> None:
        twist = Twist()
        twist.linear.x = 0.8
        if self.moving:
            twist = Twist()
            twist.linear.x = 0.9
        self.pub.publish(twist)  # error: RF101

    def one_message_set_on_one_path(self) -> None:
        twist = Twist()
        if self.moving:
            twist.linear.x = 0.1
        self.pub.publish(twist)

    def built_in_a_loop(self) -> None:
        cmd = Twist()
        for speed in (0.2, 1.0):
            cmd = Twist()
            cmd.linear.x = speed
        self.pub.publish(cmd)  # warning: RF102


def main() -> None:
    rclpy.init()
    rclpy.spin(Mover())
