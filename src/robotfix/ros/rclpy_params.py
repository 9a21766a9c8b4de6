"""rclpy's rules for parameter values: a descriptor's range and the type a value
is declared with. Shared by the analysis (`analysis/parameters.py`) and the
parameter files' check (`ros/paramfile.py`, which the analysis does not need)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

PARAM_REL_TOL = 1e-6  # rclpy Node.PARAM_REL_TOL


@dataclass(frozen=True)
class Range:
    """A ParameterDescriptor's floating_point_range or integer_range."""

    integer: bool
    from_value: int | float
    to_value: int | float
    step: int | float
    low: Fraction  # exact: the decimal written in the source
    high: Fraction
    line: int

    def text(self) -> str:
        low, high = sorted((self.from_value, self.to_value))
        step = f" with step {self.step}" if self.step else ""
        return f"[{low}, {high}]{step}"

    def accepts(self, value: int | float) -> bool:
        """rclpy's `_apply_integer_range` / `_apply_floating_point_range`."""
        low, high = sorted((self.from_value, self.to_value))
        if not self.integer:
            value, low, high = float(value), float(low), float(high)
            if math.isclose(value, low, rel_tol=PARAM_REL_TOL) or math.isclose(
                value, high, rel_tol=PARAM_REL_TOL
            ):
                return True
            if not low < value < high:
                return False
            if self.step == 0.0:
                return True
            steps = round((value - low) / self.step)
            return math.isclose(low + steps * self.step, value, rel_tol=PARAM_REL_TOL)
        if value in (low, high):
            return True
        if not low < value < high:
            return False
        return self.step == 0 or (value - low) % self.step == 0


def python_type(value: object) -> str | None:
    """rclpy's `Parameter.Type.from_parameter_value`, by type name."""
    if value is None:
        return None
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, int):
        return "integer"
    if isinstance(value, float):
        return "double"
    if isinstance(value, str):
        return "string"
    if isinstance(value, (list, tuple)):
        for kind, check in (
            ("byte", bytes),
            ("bool", bool),
            ("integer", int),
            ("double", float),
            ("string", str),
        ):
            if all(isinstance(v, check) for v in value):
                return f"{kind}_array"
    return None
