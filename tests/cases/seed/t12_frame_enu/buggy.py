"""T12 (thesis A.12): a value in frame NED assigned to a ENU variable."""
from typing_extensions import Annotated

variableFrame : Annotated[int, "Unit('ENU')"]
x : Annotated[int, "Unit('NED')"]
x = 1
variableFrame = x  # error: RF201
