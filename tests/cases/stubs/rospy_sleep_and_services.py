"""A rospy script: rospy.sleep takes seconds, wait_for_service and wait_for_message
take the name (and type) first and the timeout after, Duration and Time convert."""
from typing import Annotated

import rospy
from std_msgs.msg import Bool
from stubs_pkg.srv import Trigger

SETTLE_MS: Annotated[int, "Unit('ms')"] = 200
TIMEOUT_S: Annotated[float, "Unit('s') and _ > 0"] = 5.0
LOOP_HZ: Annotated[float, "Unit('Hz')"] = 10.0

rospy.init_node("homing")
rospy.sleep(SETTLE_MS)  # error: RF201
rospy.sleep(SETTLE_MS / 1000.0)
rospy.sleep(rospy.Duration(0, SETTLE_MS * 1000000))
rospy.wait_for_service("/arm/home", SETTLE_MS)  # error: RF201
rospy.wait_for_service("/arm/home", TIMEOUT_S)
rospy.wait_for_service("/arm/home", timeout=TIMEOUT_S)
ready = rospy.wait_for_message("/arm/ready", Bool, SETTLE_MS)  # error: RF201
ready = rospy.wait_for_message("/arm/ready", Bool, timeout=TIMEOUT_S)
home = rospy.ServiceProxy("/arm/home", Trigger)
home.wait_for_service(timeout=SETTLE_MS)  # error: RF201
home.wait_for_service(timeout=TIMEOUT_S)
start = rospy.Time.now()
deadline_ms: Annotated[float, "Unit('ms')"] = start.to_sec() + TIMEOUT_S  # error: RF201
deadline_ms = (start.to_sec() + TIMEOUT_S) * 1000.0
patience = rospy.Duration.from_sec(SETTLE_MS)  # error: RF201
patience = rospy.Duration.from_sec(SETTLE_MS / 1000.0)
waited_ns: Annotated[float, "Unit('ns')"] = patience.to_nsec()
waited_ns = patience.to_sec()  # error: RF201
elapsed: Annotated[float, "Unit('s')"] = rospy.get_time() - start.to_sec()
rate = rospy.Rate(1.0 / LOOP_HZ)  # error: RF201
rate = rospy.Rate(LOOP_HZ)
while not rospy.is_shutdown():
    rate.sleep()
