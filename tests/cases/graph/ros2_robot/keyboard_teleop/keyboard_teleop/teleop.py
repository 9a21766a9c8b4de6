"""Keyboard teleop, as turtlebot3_teleop's: a parameter chooses Twist or TwistStamped."""
import rclpy
from geometry_msgs.msg import Twist, TwistStamped
from rclpy.node import Node
from rclpy.qos import QoSProfile


class Teleop(Node):
    def __init__(self) -> None:
        super().__init__('teleop_keyboard')
        self.declare_parameter('use_stamped', False)
        stamped = self.get_parameter('use_stamped').value
        qos = QoSProfile(depth=10)
        # near miss: two possible types on one topic, chosen at run time
        if stamped:
            self.pub = self.create_publisher(TwistStamped, 'cmd_vel', qos)
        else:
            self.pub = self.create_publisher(Twist, 'cmd_vel', qos)


def main() -> None:
    rclpy.init()
    rclpy.spin(Teleop())
