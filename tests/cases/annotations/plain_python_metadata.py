"""Plain Python (no ROS interface import, no refinement): other libraries' metadata
in `Annotated` stays silent."""
from dataclasses import dataclass
from typing import Annotated, Optional


@dataclass
class ValueRange:
    low: float
    high: float


Probability = Annotated[float, ValueRange(0, 1)]
Name = Annotated[str, "const"]


def weight(p: Probability, label: Optional[Annotated[str, "doc"]] = None) -> Annotated[float, ValueRange(0, 10)]:
    scaled: Annotated[float, ValueRange(0, 10), "multiplied"] = p * 10
    return scaled


tag: Name = "x"
pair: tuple[Annotated[int, "count"], Probability] = (1, 0.5)
