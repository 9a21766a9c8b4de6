"""`get_parameter(name).value` is an unknown of the declared type within the
declared range: a refinement the range implies needs no assert, one no value in the
range satisfies is an error. Assigned straight to a refined target, a read of a
parameter its class declares makes the refinement the parameter's (its default and
parameter files are checked against it: `params/declared_then_read.py`); stored
first in a plain variable, a refinement the range does not imply is a warning."""
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
        read_gain = self.get_parameter("gain").value
        half: Annotated[float, "_ <= 0.5"] = read_gain  # warning: RF102
        attached: Annotated[float, "_ <= 0.5"] = self.get_parameter("gain").value
        same: Annotated[float, "_ <= 1"] = (
            self.get_parameter("gain").get_parameter_value().double_value
        )
        window: Annotated[int, "_ >= 5"] = self.get_parameter("window").value
        small: Annotated[int, "_ < 5"] = self.get_parameter("window").value  # error: RF101
        # the integer field of a double parameter's ParameterValue is never set
        zero: Annotated[int, "_ == 0"] = (
            self.get_parameter("gain").get_parameter_value().integer_value
        )
        read_mode = self.get_parameter("mode").value
        mode: Annotated[str, "_ == 'fast' or _ == 'slow'"] = read_mode  # warning: RF102
        read_wheels = self.get_parameter("wheels").value
        wheels: Annotated[int, "_ > 0"] = read_wheels  # warning: RF102
        read_radius = self.get_parameter("radius").value
        radius: Annotated[float, "_ <= 1"] = read_radius  # warning: RF102
        radius_ok: Annotated[float, "_ <= 1"] = self.get_parameter("radius").value
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
