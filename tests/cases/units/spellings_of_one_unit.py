"""Spellings of one unit are equal: meter = m = metres, seconds = s = sec."""
from typing import Annotated

a: Annotated[float, "Unit('meter')"] = 1
b: Annotated[float, "Unit('m')"] = a
c: Annotated[float, "Unit('metres')"] = b
t: Annotated[float, "Unit('seconds')"] = 2
u: Annotated[float, "Unit('s')"] = t
v: Annotated[float, "Unit('sec')"] = u
w: Annotated[float, "Unit('ms')"] = v  # error: RF201 "multiply by 1000"
