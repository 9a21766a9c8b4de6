"""A refinement may name other variables in scope (checked when it is assigned)."""
from typing import Annotated

low: Annotated[float, "_ >= 0"] = 1
high: Annotated[float, "_ > low"] = 2
high = 0.5  # error: RF101
