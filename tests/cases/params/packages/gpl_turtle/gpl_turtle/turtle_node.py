"""A node that reads its parameters through generate_parameter_library."""
import rclpy
from rclpy.node import Node

from gpl_turtle.turtle_parameters import turtle


class Turtle(Node):
    def __init__(self):
        super().__init__("painter")
        self.param_listener = turtle.ParamListener(self)
        self.params = self.param_listener.get_params()
