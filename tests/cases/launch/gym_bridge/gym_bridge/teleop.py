import rclpy
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("teleop", allow_undeclared_parameters=True)
    node.declare_parameter("speed", 0.5)
    rclpy.spin(node)
