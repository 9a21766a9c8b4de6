"""Chained comparisons, `in`, if-then-else and abs/min/max in annotations."""
from typing import Annotated

mode: Annotated[int, "_ in (1, 2, 3)"] = 2
mode = 4  # error: RF101
band: Annotated[float, "0 <= _ < 20"] = 19.5
band = 20  # error: RF101
gear: Annotated[int, "if _ > 0 then _ < 5 else _ > -2"] = 4
gear = -1
gear = -3  # error: RF101
near: Annotated[float, "abs(_) <= 1"] = -1
near = min(3, 0.5)
near = max(3, 0.5)  # error: RF101
