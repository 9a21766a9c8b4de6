"""`declare_parameters(namespace, [(name, default, descriptor), ...])`: each tuple is
a declaration named `namespace.name`, its default checked against its range, and
reads of it assume the range."""
from typing import Annotated

from rclpy.node import Node
from rcl_interfaces.msg import FloatingPointRange, ParameterDescriptor

PERCENT = ParameterDescriptor(
    floating_point_range=[FloatingPointRange(from_value=0.0, to_value=100.0)]
)


class Battery(Node):
    def __init__(self):
        super().__init__("battery_monitor")
        ratio = ParameterDescriptor(
            floating_point_range=[FloatingPointRange(from_value=0.0, to_value=1.0)]
        )
        self.declare_parameters(
            namespace="thresholds",
            parameters=[
                ("low", 0.2, ratio),
                ("critical", 1.5, ratio),  # error: RF101 "parameter `thresholds.critical`"
                ("warn_percent", 120.0, PERCENT),  # a module-level descriptor: not read
                ("cells", 4),
            ],
        )
        self.declare_parameters("", [("topic", "battery")])

    def check(self) -> None:
        low: Annotated[float, "0 <= _ <= 1"] = self.get_parameter("thresholds.low").value
        count = self.get_parameter("thresholds.cells").value  # no range: any int
        cells: Annotated[int, "_ > 0"] = count  # warning: RF102
        # assigned straight from the read, the refinement is the parameter's (its
        # default 4 is checked against it, and parameter files are)
        at_least_one: Annotated[int, "_ > 0"] = self.get_parameter("thresholds.cells").value
