"""Joystick teleop: sends the stick's value as it comes (nothing proves the bound)."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from sensor_msgs.msg import Joy


class Joystick(Node):
    def __init__(self) -> None:
        super().__init__('joystick')
        self.pub = self.create_publisher(Twist, 'cmd_vel_safe', 10)
        self.create_subscription(Joy, 'joy', self.on_joy, 10)  # note: RF606

    def on_joy(self, joy: Joy) -> None:
        cmd = Twist()
        cmd.linear.x = joy.axes[1]
        self.pub.publish(cmd)  # warning: RF102


def main() -> None:
    rclpy.init()
    rclpy.spin(Joystick())
