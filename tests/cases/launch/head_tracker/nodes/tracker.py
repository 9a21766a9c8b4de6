#!/usr/bin/env python
from typing import Annotated

import rospy

rospy.init_node("head_tracker")
rate: Annotated[float, "Unit('Hz') and 0 < _ <= 50"] = rospy.get_param("~rate", 10.0)
gain: Annotated[float, "0 <= _ <= 1"] = rospy.get_param("~gain", 0.5)
