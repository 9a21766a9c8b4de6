"""An unannotated variable takes the unit of what is assigned to it."""
from typing import Annotated

speed: Annotated[float, "Unit('km/h')"] = 20
copy = speed
twice = copy * 2
ms: Annotated[float, "Unit('m/s')"] = twice  # error: RF201
literal = 5
ms = literal
