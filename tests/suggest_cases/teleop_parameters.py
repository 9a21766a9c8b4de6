"""A ROS 2 teleop node: limits from parameters, a timer publishing Twist."""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from sensor_msgs.msg import Joy


class Teleop(Node):
    def __init__(self):
        super().__init__("teleop")
        self.declare_parameter("linear", 0.5)
        self.declare_parameter("max_angular", 1.0)
        self.declare_parameter("publish_period", 0.05)
        self.max_linear = self.get_parameter("linear").value  # suggest: max_linear m/s
        angular = self.get_parameter("max_angular").value  # suggest: angular rad/s
        self.max_angular = angular  # suggest: max_angular rad/s
        period = self.get_parameter("publish_period").value  # suggest: period s
        self.axis_scale = 1.0  # near miss: multiplied by an unknown axis value
        self.axes = [0.0, 0.0]
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_subscription(Joy, "joy", self.on_joy, 10)
        self.timer = self.create_timer(period, self.tick)

    def on_joy(self, msg):
        self.axes = [msg.axes[1], msg.axes[0]]

    def tick(self):
        cmd = Twist()
        cmd.linear.x = self.max_linear * self.axes[0] * self.axis_scale
        cmd.linear.y = self.max_linear
        cmd.angular.z = -self.max_angular
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(Teleop())
