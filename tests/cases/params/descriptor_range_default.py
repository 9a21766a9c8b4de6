"""A default outside its ParameterDescriptor range is RF101 at the default: rclpy
raises InvalidParameterValueException when nothing overrides it. Inline and local
descriptors, float and integer ranges, steps, and rclpy's tolerance at the bounds."""
import rclpy
from rclpy.node import Node
from rcl_interfaces.msg import FloatingPointRange, IntegerRange, ParameterDescriptor

MAX_SPEED = 1.5
NAME = "max_speed"


class Limits(Node):
    def __init__(self):
        super().__init__("limits")
        self.declare_parameter(
            "scale",
            2.5,  # error: RF101 "its declared range [0.0, 2.0]"
            ParameterDescriptor(
                floating_point_range=[FloatingPointRange(from_value=0.0, to_value=2.0)]
            ),
        )
        self.declare_parameter(
            "gain",
            0.5,
            ParameterDescriptor(
                floating_point_range=[FloatingPointRange(from_value=0.0, to_value=2.0)]
            ),
        )
        speed = ParameterDescriptor(description="top speed [m/s]")
        speed.floating_point_range = [
            FloatingPointRange(from_value=0.0, to_value=MAX_SPEED, step=0.5)
        ]
        self.declare_parameter(NAME, 1.2, speed)  # error: RF101 "with step 0.5"
        self.declare_parameter("cruise", 1.0, speed)
        self.declare_parameter("edge", 1.5000001, speed)  # within rclpy's tolerance
        self.declare_parameter("reversed", 3, ParameterDescriptor(integer_range=[IntegerRange(from_value=10, to_value=0)]))
        rate = IntegerRange()
        rate.from_value = 1
        rate.to_value = 50
        self.declare_parameter("rate_hz", 100, ParameterDescriptor(integer_range=[rate]))  # error: RF101 "[1, 50]"
        # an int default with a floating-point range: rclpy applies no range
        self.declare_parameter("retries", 7, speed)


def main():
    rclpy.init()
    node = rclpy.create_node("helper")
    unknown = make_descriptor()
    node.declare_parameter("depth", 99.0, unknown)  # not a descriptor RobotFix can read
    node.declare_parameter("width", -1, ParameterDescriptor(integer_range=[IntegerRange(from_value=0, to_value=4)]))  # error: RF101
    rclpy.spin(Limits())
