"""Frames and tags are dimensions of their own, compared by name."""
from typing import Annotated

in_map: Annotated[float, "Unit('m') and Frame('map')"] = 1
in_odom: Annotated[float, "Unit('m') and Frame('odom')"] = 2
also_map: Annotated[float, "Frame('map') and Unit('m')"] = in_map
in_odom = in_map  # error: RF201
heading: Annotated[float, "Tag('enu_heading')"] = 0
plain = in_map + also_map
bad = in_map + in_odom  # error: RF202
