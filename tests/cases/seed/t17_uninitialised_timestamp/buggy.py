"""T17 (thesis A.15): x is declared but never assigned before it sets the timestamp."""
from typing_extensions import Annotated

x : Annotated[int, ""]

timestamp : Annotated[int, "_ < 10"]

timestamp = x  # error: RF301
