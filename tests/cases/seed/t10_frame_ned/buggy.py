"""T10 (thesis A.10, as its text and T12 mean it): a value in frame ENU assigned to a NED variable."""
from typing_extensions import Annotated

variableFrame : Annotated[int, "Unit('NED')"]
x : Annotated[int, "Unit('ENU')"]
x = 1
variableFrame = x  # error: RF201
