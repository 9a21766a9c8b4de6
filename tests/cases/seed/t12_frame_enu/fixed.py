"""T12 (thesis A.12): a value in frame ENU assigned to a ENU variable."""
from typing_extensions import Annotated

variableFrame : Annotated[int, "Unit('ENU')"]
x : Annotated[int, "Unit('ENU')"]
x = 1
variableFrame = x
