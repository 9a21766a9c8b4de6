"""T6 (thesis A.6): decimals are exact; 3.14 is less than the annotated pi."""
from typing_extensions import Annotated

x : Annotated[float, "_ >= 3.141592653589793238 "]
x = 3.14  # error: RF101
