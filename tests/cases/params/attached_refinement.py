"""A refinement on the variable a parameter is read into, right where it is read,
is the parameter's: its default is checked (RF101 names the default), and later
reads assume it, with no assert (newuser report P5)."""
from typing import Annotated

from rclpy.node import Node
from rcl_interfaces.msg import FloatingPointRange, ParameterDescriptor


class Driver(Node):
    max_speed: Annotated[float, "Unit('m/s') and 0 < _ <= 1"]
    timeout: Annotated[float, "Unit('s') and _ > 0"]

    def __init__(self):
        super().__init__("driver")
        # error: RF101 "the default `500.0` of parameter `hz`"
        hz: Annotated[float, "Unit('Hz') and 0 < _ <= 100"] = self.declare_parameter("hz", 500.0).value
        rate: Annotated[float, "Unit('Hz') and 0 < _ <= 100"] = self.declare_parameter("rate", 50.0).value
        self.max_speed = self.declare_parameter("max_speed", 0.5).value
        self.timeout = self.declare_parameter("timeout", 0.0).value  # error: RF101 "`self.timeout > 0`"
        # error: RF401
        count: Annotated[int, "_ >= 0"] = self.declare_parameter("count", 2.5).value
        gain: Annotated[float, "0 <= _ <= 1"] = (
            self.declare_parameter("gain", 0.3).get_parameter_value().double_value
        )
        self.period: Annotated[float, "Unit('s') and _ > 0"] = 1.0 / rate

    def command(self) -> None:
        fast: Annotated[float, "_ <= 1"] = self.max_speed  # assumed: no warning
        wait: Annotated[float, "_ > 0"] = self.timeout


class Unattached(Node):
    def __init__(self):
        super().__init__("unattached")
        raw = self.declare_parameter("limit", 0.5).value
        # warning: RF102 "parameter `limit`"
        limit: Annotated[float, "0 < _ <= 1"] = raw
