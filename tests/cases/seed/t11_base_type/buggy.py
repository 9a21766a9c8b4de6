"""T11 (thesis A.11): an int variable must not receive a float."""
from typing_extensions import Annotated

x : Annotated[int, ""]
x = 2.0  # error: RF401
