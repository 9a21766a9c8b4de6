"""A rospy loop: checks inside loops, rospy.Rate takes Hz."""
from typing import Annotated

import rospy
from geometry_msgs.msg import Twist

speed: Annotated[float, "Unit('km/h') and 0 <= _ <= 5"] = 3
period: Annotated[float, "Unit('s') and _ > 0"] = 0.1

rospy.init_node("driver")
pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
rate = rospy.Rate(period)  # error: RF201
rate = rospy.Rate(1 / period)
msg = Twist()
while not rospy.is_shutdown():
    msg.linear.x = speed  # error: RF201
    msg.linear.x = speed / 3.6
    pub.publish(msg)
    rate.sleep()
