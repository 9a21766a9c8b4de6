"""T3 (thesis A.4): each variable only receives values of its own unit."""
from typing_extensions import Annotated

x : Annotated[float, "Unit('meter')"]
z : Annotated[float, "Unit('quaternion')"]
x = 5
z = 6
a : Annotated[float, "Unit('meter')"]
b : Annotated[float, "Unit('quaternion')"]
a = 10
b = 20
x = a
z = b
