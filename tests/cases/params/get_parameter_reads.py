"""`get_parameter(name).value` is an unknown of the declared type within the
declared range: a refinement the range implies needs no assert, one it does not
is a warning, one no value in the range satisfies is an error."""
from typing import Annotated

from rclpy.node import Node
from rcl_interfaces.msg import FloatingPointRange, IntegerRange, ParameterDescriptor


def unit_range(low, high):
    return ParameterDescriptor(
        floating_point_range=[FloatingPointRange(from_value=low, to_value=high)]
    )


class Controller(Node):
    limit: Annotated[float, "0 < _ <= 2"]

    def __init__(self):
        super().__init__("controller")
        self.declare_parameter(
            "gain",
            0.5,
            ParameterDescriptor(
                floating_point_range=[FloatingPointRange(from_value=0.0, to_value=1.0)]
            ),
        )
        self.declare_parameter(
            "window",
            7,
            ParameterDescriptor(integer_range=[IntegerRange(from_value=5, to_value=10)]),
        )
        self.declare_parameter("mode", "fast")
        self.declare_parameter("wheels", 4)
        self.declare_parameter("radius", 0.1, unit_range(0.0, 1.0))
        self.limit = self.declare_parameter("limit", 1.0).value

    def step(self) -> None:
        gain: Annotated[float, "0 <= _ <= 1"] = self.get_parameter("gain").value
        half: Annotated[float, "_ <= 0.5"] = self.get_parameter("gain").value  # warning: RF102
        same: Annotated[float, "_ <= 1"] = (
            self.get_parameter("gain").get_parameter_value().double_value
        )
        window: Annotated[int, "_ >= 5"] = self.get_parameter("window").value
        small: Annotated[int, "_ < 5"] = self.get_parameter("window").value  # error: RF101
        # the integer field of a double parameter's ParameterValue is never set
        zero: Annotated[int, "_ == 0"] = (
            self.get_parameter("gain").get_parameter_value().integer_value
        )
        mode: Annotated[str, "_ == 'fast' or _ == 'slow'"] = self.get_parameter("mode").value  # warning: RF102
        wheels: Annotated[int, "_ > 0"] = self.get_parameter("wheels").value  # warning: RF102
        radius: Annotated[float, "_ <= 1"] = self.get_parameter("radius").value  # warning: RF102
        limit: Annotated[float, "_ <= 2"] = self.get_parameter("limit").value  # attached where declared
        other: Annotated[float, "_ < 1"] = self.get_parameter("undeclared").value  # warning: RF102


class ReadOnly(Node):
    def __init__(self):
        super().__init__("read_only")
        self.declare_parameter("wheels", 4, ParameterDescriptor(read_only=True))
        self.declare_parameter("axles", 2)

    def step(self) -> None:
        first = self.get_parameter("wheels").value
        # a read-only parameter never changes: every read is the same value
        same: Annotated[int, "_ == first"] = self.get_parameter("wheels").value
        before = self.get_parameter("axles").value
        # warning: RF102
        again: Annotated[int, "_ == before"] = self.get_parameter("axles").value
