"""T14 (thesis A.14): x must never be 1."""
from typing_extensions import Annotated

x : Annotated[int,"x != 1"]
x = 1  # error: RF101
