"""Sets the limit from a joystick axis, scaled but never checked."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Joy
from speed_interfaces.srv import SetSpeed


class JoyLimit(Node):
    def __init__(self):
        super().__init__('joy_limit')
        self.cli = self.create_client(SetSpeed, 'set_max_speed')
        self.create_subscription(Joy, 'joy', self.on_joy, 10)  # note: RF606

    def on_joy(self, joy: Joy):
        req = SetSpeed.Request(speed=2.0 * abs(joy.axes[3]))
        self.cli.call_async(req)  # warning: RF102


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(JoyLimit())
