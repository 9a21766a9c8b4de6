"""Unit aliases shared by the package's nodes."""
from typing import Annotated

MetersPerSec = Annotated[float, "Unit('m/s')"]
Radians = Annotated[float, "Unit('rad')"]
Seconds = Annotated[float, "Unit('s') and _ > 0"]
